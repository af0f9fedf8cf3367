/*
 * The `fluid: auto` rule: which coupling tier a run needs, chosen from its
 * dimensionless groups alone (a pure function, no state, no I/O).
 *
 * Physics. The grain-scale time of a flow is the slowest of three (Izard
 * 2014 §4.1.3, (4.1), (4.12); gf_groups.h):
 *     T_v  = 18 eta_f / (drho g D)            viscous
 *     T_i  = sqrt(rho_f D / (2 drho g))       inertial
 *     T_ff = sqrt(2 rho_p D / (drho g))       free fall
 * and their ratios are functions of (St, r) only:
 *     T_ff / T_v = 2 St,        T_ff / T_i = 2 sqrt(3/5) r = 1.549 r.
 * The fluid can be dropped only when free fall dominates BOTH other times by
 * a wide margin and buoyancy (rho_f / rho_p = 5 / (3 r^2)) is negligible.
 *
 * Published boundaries (Izard 2014 §4.1.4.2; Courrech du Pont et al., PRL 90, 2003):
 *   viscous | free fall: St ≈ 1 for r >= 4 (Izard 2014 §4.1.4.2, sharp),
 *                        St_c ≈ 10 (Courrech du Pont et al. 2003);
 *   inertial | free fall: r_c ≈ 4, "continuous, without a sharp threshold".
 * Conservative choice (when in doubt keep the fluid):
 *   - St >= GF_TIER_DRY_MIN_STOKES = 10, the LARGER of the two published
 *     values (10x Izard's sharp St ≈ 1): viscous drag acts on a time at
 *     least 20 T_ff;
 *   - r >= GF_TIER_DRY_MIN_R = 10, 2.5x the indicative r_c ≈ 4 because that
 *     boundary is a smooth crossover: T_i <= T_ff / 15, and buoyancy
 *     rho_f / rho_p <= 1.7 % of the weight (at r = 4 it would be 10 %).
 * Grains in air (r ≈ 30-60, St >> 10) fall in the "none" tier; grains in water
 * (r ≈ 2) never do. Everywhere else the fluid carries the pore pressure that
 * delays or accelerates a collapse (Rondon et al. 2011; Izard 2014 §5.5), so
 * a fluid tier is needed: the registered tiers (gf_coupling_table.c) are asked
 * in their registry order, cheapest first, and the first whose auto_fits
 * accepts the run is chosen; the reason names the regime and that tier's
 * answer. The resolved tier declines (its cost grows as (D/dx)^3 per grain:
 * it is the accuracy reference, named explicitly), so auto gives "unresolved".
 *
 * Dry input (no fluid: St = r = +inf, gf_groups_compute) gives "none".
 * Refused (GF_ERR_PHYSICS/GF_ERR_ARG, one line naming the value): St or r NaN,
 * St <= 0, r <= sqrt(5/3) (grains not denser than the fluid: gf_groups.h).
 */
#ifndef GF_TIER_H
#define GF_TIER_H

#include "core/gf_groups.h"
#include "core/gf_status.h"

#define GF_TIER_DRY_MIN_STOKES 10.0
#define GF_TIER_DRY_MIN_R 10.0

/* GF_TIER_FLUID: a registered coupling tier, named by gf_tier_choice.model.
 * GF_TIER_UNRESOLVED is its older name (the registry's first row). */
typedef enum gf_tier { GF_TIER_NONE = 0, GF_TIER_FLUID = 1, GF_TIER_UNRESOLVED = GF_TIER_FLUID } gf_tier;

typedef struct gf_tier_choice {
    gf_tier tier;
    const char *model;   /* "none" or a coupling tier's name: the value for spec.fluid.model */
    char reason[320];    /* one line, recorded as the fluid_model_reason attribute */
} gf_tier_choice;

/* Tier for (St, r); out->reason says why, with the numbers. */
gf_status gf_tier_choose(gf_ctx *ctx, double stokes_St, double density_ratio_r, gf_tier_choice *out);
/* Same, from the scales of a run (stokes_St, density_ratio_r). */
gf_status gf_tier_from_scales(gf_ctx *ctx, const gf_scales *scales, gf_tier_choice *out);
/* "none", or the name of the first registered coupling tier. */
const char *gf_tier_name(gf_tier tier);

#endif
