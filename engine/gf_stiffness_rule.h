/*
 * Contact stiffness from the scene's confining pressure (issue #6), the
 * opt-in alternative to a fixed contact duration t_c (contact.t_contact_nd):
 * contact.overlap_target_over_D = x > 0 asks for the softest contacts whose
 * static overlaps stay below x D, hence the largest stable time step.
 *
 * Rule. A pack under confining pressure p carries a mean normal force of
 * order p D^2 per contact, so its overlaps are delta/D ~ p D / k_n = 1/kappa,
 * kappa = k_n / (p D) the stiffness number of da Cruz, Emam, Prochnow, Roux &
 * Chevoir (PRE 72, 021309, 2005; kappa >= 1e4 is their rigid-grain limit,
 * delta/D <= 1e-4). Forces are not uniform: the force distribution of a
 * static pack has an exponential tail (Radjai, Jean, Moreau & Roux, PRL 77,
 * 274, 1996; Mueth, Jaeger & Nagel, PRE 57, 3164, 1998), the largest forces
 * a few times the mean. Hence
 *     k_n = C_f p D / x,   C_f = GF_STIFFNESS_CHAIN_FACTOR,
 * with p the scene's largest static pressure: the weight of a column of
 * height H and solid fraction phi, p = phi rho_p g H (no Janssen screening:
 * an upper bound). The contact duration follows from k_n and the mean pair's
 * m* = m_D/2 by inverting Izard (3.17):
 *     t_c = sqrt(m* (pi^2 + ln^2 eps) / k_n).
 * The rule bounds static (confined) overlaps. A collision at speed v
 * overlaps by v sqrt(m* / k_n), which the rule does not bound; the run-time
 * guard of gf_sim (overlap > 0.1 D stops the run) still applies, and the
 * dynamic overlap is measured in docs/notes/benchmarks.md. Nor does the rule undo
 * overlaps that a scene's preparation locked in by friction: column_collapse
 * prepares with t_c = 0.02 sqrt(D/g) (gf_packing.h) and a settled column
 * keeps ~0.006 D of them under any stiffer run contacts, so targets below
 * ~0.01 D are not met there (measured 0.0058-0.0063 D at x = 0.005).
 */
#ifndef GF_STIFFNESS_RULE_H
#define GF_STIFFNESS_RULE_H

#include "gf_run_spec.h"

/* The largest contact force of a static pack / p D^2: measured 2.1-4.6 in
 * the settled columns of tests/stress/test_stiffness_rule.c (docs/notes/benchmarks.md). */
#define GF_STIFFNESS_CHAIN_FACTOR 6.0

/* Static pressure at the base of a column of height H_m: phi rho_p g H. */
double gf_stiffness_column_pressure_Pa(const gf_run_spec *spec, double phi, double height_m);

/* Normal stiffness (N/m) of the rule for pressure p_Pa and target overlap x = overlap_over_D. */
double gf_stiffness_k_n(const gf_run_spec *spec, double p_Pa, double overlap_over_D);

/* t_c sqrt(g/D) of the linear law with stiffness k_n_N_m for the mean pair (restitution of spec). */
double gf_stiffness_t_contact_nd(const gf_run_spec *spec, double k_n_N_m);

#endif
