/*
 * From the dimensionless groups a campaign asks for to the physical values a
 * run needs, and back (what a run realises).
 *
 * The map (Izard 2014 §4.1.1; Rondon et al. 2011 for a, Phi_i):
 *
 *   D, rho_p          fixed by grains:
 *   r  -> rho_f     = 5 rho_p / (3 r^2)                         needs r > sqrt(5/3)
 *   St -> eta_f     = sqrt(rho_p (rho_p - rho_f) g_eff D) D / (18 sqrt(2) St)
 *   a  -> scene parameter aspect_ratio (H0 = a R0, R0 = column_length_over_D D)
 *   Phi_i -> scene parameter phi_initial, or phi_target (the packing target of the preparation)
 *
 * with g_eff = g sin(theta) when the scene has an incline (parameter
 * incline_deg, the avalanche) and g otherwise (the collapse: grains fall
 * vertically, Izard §5.3). Both inversions go through gf_groups_invert, the
 * one place the formulas live. When only St is asked, r is the one of the
 * configured fluid density; when only r is asked, the configured viscosity is
 * kept (St then follows). Asking for St or r with fluid.model = none is an
 * error: the groups describe a fluid the run would not have.
 */
#ifndef GF_GROUPS_MAP_H
#define GF_GROUPS_MAP_H

#include "core/gf_groups.h"
#include "gf_run_spec.h"

/* g_eff / g for the spec's scene: sin(incline_deg) or 1. */
double gf_groups_map_slope_sin(const gf_run_spec *spec);

/* Applies the asked groups of spec (non-NaN stokes_St, density_ratio_r,
 * aspect_ratio_a, phi_initial) to its physical values and scene parameters.
 * Errors (message without location): GF_ERR_CONFIG (group not applicable to
 * the scene, fluid model none), GF_ERR_PHYSICS (impossible corner, e.g.
 * r <= sqrt(5/3): grains not denser than the fluid). */
gf_status gf_groups_map_apply(gf_ctx *ctx, gf_run_spec *spec);

/* The groups and time scales the physical values of spec realise
 * (gf_groups_compute with the scene's g_eff and column geometry). */
gf_status gf_groups_map_realised(gf_ctx *ctx, const gf_run_spec *spec, gf_scales *out);

#endif
