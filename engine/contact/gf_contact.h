/*
 * Contact laws: a registry table of pure kernels on a small parameter struct
 * (as LAMMPS' pair granular sub-models).  A law is normal (+) damping
 * (+) tangential; the step loop evaluates the geometry (unit normal n from j
 * to i, overlap delta > 0, relative surface velocity at the contact point)
 * and the kernel returns the force on grain i. The force on j is its
 * opposite; torques are r_c x F_t with r_c = -R_i n for i and +R_j n for j
 * (Izard 2014 (2.6), (3.12), in a sign-safe form).
 *
 * Linear spring-dashpot of the seeds (Schäfer, Dippel & Wolf, J. Phys. I 1996;
 * Izard 2014 (2.4), (3.13), (3.16)-(3.17)), for a pair of effective mass m*:
 *     F_n     = max(0, k_n delta - gamma_n v_n)          (v_n = u_rel . n, > 0 separating)
 *     gamma_n = -(2 m* / t_c) ln eps_max,   k_n = m* pi^2/t_c^2 + gamma_n^2/(4 m*).
 * Choice for polydisperse grains: k_n is derived ONCE, for the mean pair
 * (two grains of the mean diameter D: m* = m_D/2), so every pair shares the
 * stiffness of one material, as a physical material does; the damping of a
 * pair is then gamma_n = 2 zeta sqrt(m* k_n) with the damping ratio
 * zeta = -ln eps / sqrt(pi^2 + ln^2 eps) (Djouwe Meffeja 2012 §2.4.3, (2.8)), so that every
 * pair (walls included, m* = m_i) has the same restitution eps_max of the
 * unclipped law, while its contact duration scales as sqrt(m*). For the mean
 * pair these formulas are exactly (3.16)-(3.17).
 *
 * Tangential: vector spring (Cundall & Strack 1979; Silbert et al. PRE 2001),
 * as Izard 2014 (2.5) leaves open: the history delta_t is rotated back onto the current
 * tangent plane keeping its length, incremented by u_t dt (u_t the tangential
 * part of the relative surface velocity, rotation included, which the printed (3.15) omits), then
 * F_t = -k_t delta_t with k_t = kt_over_kn k_n; when |F_t| > mu |F_n| the
 * force is capped at mu |F_n| and delta_t rescaled to -F_t/k_t (slip). No
 * tangential dashpot (Izard §1.3).
 *
 * Hertz-Mindlin row (not a thesis law; Djouwe Meffeja 2012 §2.4.3): F_n =
 * k_n delta (delta/delta_ref)^(1/2) - gamma_n (delta/delta_ref)^(1/4) v_n with
 * the same k_n and delta_ref = the overlap that the mean pair reaches at the
 * free-fall speed sqrt(gD) under the linear law, so the two laws coincide there;
 * the tangential stiffness scales as (delta/delta_ref)^(1/2) too (Mindlin
 * no-slip stiffness ~ a). The restitution is then velocity-independent
 * (damping ~ delta^(1/4), Tsuji et al. 1992).
 */
#ifndef GF_CONTACT_H
#define GF_CONTACT_H

#include <stddef.h>

#include "core/gf_status.h"
#include "gf_run_spec.h"

#define GF_CONTACT_HISTORY 3 /* doubles of tangential history per contact (delta_t vector, m) */

/* Parameters of one law, derived at set-up from gf_contact_spec and the mean grain. */
typedef struct gf_contact_params {
    double k_n_N_m;          /* normal stiffness, shared by every pair */
    double zeta;             /* damping ratio: gamma_n = 2 zeta sqrt(m* k_n) */
    double kt_over_kn;       /* tangential / normal stiffness */
    double mu_grain, mu_wall;/* Coulomb coefficients */
    int allow_attraction;    /* 0: F_n clipped at 0 */
    double t_contact_s;      /* t_c of the mean pair */
    double m_eff_mean_kg;    /* m* of the mean pair */
    double delta_ref_m;      /* Hertz reference overlap */
    double law_constant;     /* a law's own constant, set by its derive hook (hertz_kk: A, s) */
} gf_contact_params;

/* Geometry of one contact, computed by the pair loop. */
typedef struct gf_contact_geom {
    double n[3];             /* unit normal, from j (or the wall) to i */
    double overlap_m;        /* delta > 0 */
    double v_rel_m_s[3];     /* u_i - u_j + w_i x (-R_i n) - w_j x (R_j n), half-step (tangential increment) */
    double v_n_m_s;          /* (u_i - u_j).n from the predicted velocities (dashpot), > 0 separating */
    double m_eff_kg;         /* m* (m_i for a wall or a glued partner) */
    double sqrt_mk;          /* sqrt(m* k_n), precomputed per pair at neighbour builds (damping scale) */
    double mu;               /* Coulomb coefficient of this pair */
} gf_contact_geom;

/* Kernel: force on i (N) from its geometry; updates the history (3 doubles).
 * f_n_out: the normal force magnitude (signed, >0 repulsive); f_t_out the
 * tangential force vector; both on i. */
typedef void gf_contact_kernel(const gf_contact_params *p, const gf_contact_geom *g, double dt_s, double *hist,
                               double *f_n_out, double f_t_out[3]);

/* A contact law: one file (its kernel and its row) plus one entry in the
 * registry (gf_contact_table.c), which is the only list of laws: the YAML
 * schema, the error messages and the step loop read it. What differs between
 * laws is asked of the row's hooks; a NULL hook is the linear law's answer. */
typedef struct gf_contact_info {
    const char *name;        /* spec.contact.law */
    gf_contact_kernel *kernel;
    int n_history;           /* doubles per contact */
    const char *doc;
    /* Law-specific parameters, after the shared ones (k_n, zeta, ...) are set
     * from the spec. NULL: none. */
    void (*derive)(const gf_run_spec *spec, gf_contact_params *cp);
    /* Ratio of the contact's oscillation frequency at overlap delta to the
     * frequency pi/t_c of the stiffness k_n, for the step's stability limit
     * t_c/5 (engine/sim/gf_step.c). NULL: 1 at every overlap. */
    double (*frequency_factor)(const gf_contact_params *cp, double overlap_m);
    /* Elastic energy stored at overlap delta (normal) and in the tangential
     * spring xi (|xi|^2 given) at that overlap, for energy audits. */
    double (*normal_energy)(const gf_contact_params *cp, double overlap_m);
    double (*tangential_energy)(const gf_contact_params *cp, double overlap_m, double xi2_m2);
} gf_contact_info;

/* Row of the table for law (spec.contact.law), NULL when unknown. */
const gf_contact_info *gf_contact_find(const char *law);
/* All rows (pointers into the laws' files), *n set to their count. */
const gf_contact_info *const *gf_contact_all(int *n);
/* The laws' names, NULL-terminated, in the registry's order (the schema's
 * allowed values). Not for concurrent first calls: read at configuration. */
const char *const *gf_contact_law_names(void);

/* Derives the law parameters from the run spec: t_c = t_contact_nd sqrt(D/g),
 * mean pair of diameter D and density rho_p. Errors (GF_ERR_CONFIG) name the
 * bad field: eps outside (0, 1], t_c <= 0, friction < 0, kt_over_kn <= 0. */
gf_status gf_contact_params_from_spec(gf_ctx *ctx, const gf_run_spec *spec, gf_contact_params *out);

/* Damping ratio of the linear law for restitution eps (unclipped): -ln eps / sqrt(pi^2 + ln^2 eps). */
double gf_contact_damping_ratio(double eps);

/* Closed form of the clipped linear law (exact integration of one collision):
 * restitution and contact duration / t_c for restitution eps_max. */
void gf_contact_clipped_restitution(double eps_max, double *eps_eff, double *duration_over_tc);

/* Shared tangential sub-model (vector spring with a Coulomb cap), used by
 * every normal law: k_t_N_m the current tangential stiffness, f_n the normal
 * force magnitude. Writes the tangential force on i. */
void gf_contact_tangential(const gf_contact_geom *g, double k_t_N_m, double f_n_N, double dt_s, double *hist,
                           double f_t_out[3]);

/* The registered laws (rows of the table). */
extern const gf_contact_info gf_contact_law_linear;
extern const gf_contact_info gf_contact_law_hertz;
extern const gf_contact_info gf_contact_law_hertz_kk;

/* The Hertz spring's hooks (gf_contact_hertz.c), shared by the laws built on it. */
void gf_contact_hertz_derive(const gf_run_spec *spec, gf_contact_params *cp);
double gf_contact_hertz_frequency_factor(const gf_contact_params *p, double overlap_m);
double gf_contact_hertz_normal_energy(const gf_contact_params *p, double overlap_m);
double gf_contact_hertz_tangential_energy(const gf_contact_params *p, double overlap_m, double xi2_m2);

/* Kernels, also called directly by the fast pair loops (gf_contact_kernels.h). */
void gf_contact_linear(const gf_contact_params *p, const gf_contact_geom *g, double dt_s, double *hist,
                       double *f_n_out, double f_t_out[3]);
void gf_contact_hertz(const gf_contact_params *p, const gf_contact_geom *g, double dt_s, double *hist,
                      double *f_n_out, double f_t_out[3]);
void gf_contact_hertz_kk(const gf_contact_params *p, const gf_contact_geom *g, double dt_s, double *hist,
                         double *f_n_out, double f_t_out[3]);

#endif
