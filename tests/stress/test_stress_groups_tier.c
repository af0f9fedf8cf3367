/*
 * The corners of the (St, r) plane through gf_groups_invert,
 * gf_groups_compute and the `fluid: auto` rule (gf_tier.h), St from 0.01 to
 * 1000 and r from 1.1 to 100 (grains barely denser than the fluid to grains
 * in air), at the seeds' grains (D = 7.6 mm, rho_p = 2500 kg/m3, g = 9.81).
 *
 * Claims, at every grid point:
 *  - r <= sqrt(5/3) (grains not denser than the fluid) is refused by
 *    gf_groups_invert AND by gf_tier_choose with GF_ERR_PHYSICS and a line
 *    naming sqrt(5/3); nothing else is refused;
 *  - the round trip is exact: the groups realised by the inverted fluid are
 *    the ones asked for (relative 1e-12; the map is closed-form);
 *  - the time-scale ratios are functions of (St, r) alone (gf_tier.h):
 *    T_ff/T_v = 2 St, T_ff/T_i = 2 sqrt(3/5) r, Re* = St/r (1e-12), and
 *    every scale is finite and > 0;
 *  - the tier is "none" exactly when St >= 10 and r >= 10, "unresolved"
 *    otherwise, with a reason that quotes St; the choice is monotone (a
 *    grid point right of or above a "none" point is "none");
 *  - dry input (no fluid: St = r = +inf) gives "none"; NaN or St <= 0 is
 *    refused.
 * The corners named by the issue: (0.01, 1.3) viscous and heavy fluid ->
 * unresolved; (1000, 100) grains in air -> none; (1000, 1.3) -> unresolved
 * (inertial, buoyancy 99 % of the weight); (0.01, 100) -> unresolved (viscous).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/gf_groups.h"
#include "coupling/gf_tier.h"
#include "gf_test.h"

#define NS 11
#define NR 12

int main(void)
{
    const double D = 7.6e-3, rho_p = 2500.0, g = 9.81;
    double St[NS], r[NR] = {1.1, 1.2, 1.29, sqrt(5.0 / 3.0), 1.3, 1.5, 2.0, 4.0, 9.99, 10.0, 30.0, 100.0};
    for (int i = 0; i < NS; ++i)
        St[i] = pow(10.0, -2.0 + 0.5 * i); /* 0.01 ... 1000 */
    int tier[NS][NR], n_refused = 0, n_none = 0;
    double worst_trip = 0.0, worst_ratio = 0.0;
    for (int i = 0; i < NS; ++i)
        for (int j = 0; j < NR; ++j) {
            gf_ctx ctx = {0};
            double rho_f = NAN, eta = NAN;
            gf_status st = gf_groups_invert(&ctx, St[i], r[j], D, rho_p, g, &rho_f, &eta);
            gf_tier_choice tc;
            gf_ctx ctx2 = {0};
            gf_status st2 = gf_tier_choose(&ctx2, St[i], r[j], &tc);
            tier[i][j] = -1;
            if (r[j] <= sqrt(5.0 / 3.0)) {
                n_refused++;
                GF_CHECK(st == GF_ERR_PHYSICS);
                GF_CHECK(strstr(ctx.last_msg, "sqrt(5/3)") != NULL);
                GF_CHECK(st2 == GF_ERR_PHYSICS);
                GF_CHECK(strstr(ctx2.last_msg, "sqrt(5/3)") != NULL);
                if (i == 0)
                    printf("r = %.6g refused: %s | %s\n", r[j], ctx.last_msg, ctx2.last_msg);
                continue;
            }
            GF_CHECK_OK(st, &ctx);
            GF_CHECK_OK(st2, &ctx2);
            gf_groups_input in = {.diameter_m = D, .grain_density_kg_m3 = rho_p, .fluid_density_kg_m3 = rho_f,
                                  .viscosity_Pa_s = eta, .gravity_m_s2 = g, .slope_sin = 1.0};
            gf_scales sc;
            GF_CHECK_OK(gf_groups_compute(&ctx, &in, &sc), &ctx);
            worst_trip = fmax(worst_trip, fabs(sc.stokes_St / St[i] - 1.0));
            worst_trip = fmax(worst_trip, fabs(sc.density_ratio_r / r[j] - 1.0));
            worst_ratio = fmax(worst_ratio, fabs(sc.t_freefall_s / sc.t_viscous_s / (2.0 * St[i]) - 1.0));
            worst_ratio = fmax(worst_ratio, fabs(sc.t_freefall_s / sc.t_inertial_s / (2.0 * sqrt(0.6) * r[j]) - 1.0));
            worst_ratio = fmax(worst_ratio, fabs(sc.reynolds_Re / (St[i] / r[j]) - 1.0));
            double scales[5] = {sc.t_viscous_s, sc.t_inertial_s, sc.t_freefall_s, sc.t_grain_s, sc.archimedes_Ar};
            for (int k = 0; k < 5; ++k)
                GF_CHECK(isfinite(scales[k]) && scales[k] > 0.0);
            /* the tier from the scales of the realised fluid is the same (except ON a
             * threshold, where the round trip's last-bit error may fall either side) */
            gf_tier_choice tc2;
            GF_CHECK_OK(gf_tier_from_scales(&ctx, &sc, &tc2), &ctx);
            int on_edge = fabs(St[i] / GF_TIER_DRY_MIN_STOKES - 1.0) < 1e-9 || fabs(r[j] / GF_TIER_DRY_MIN_R - 1.0) < 1e-9;
            GF_CHECK(tc2.tier == tc.tier || on_edge);
            int want_none = St[i] >= GF_TIER_DRY_MIN_STOKES && r[j] >= GF_TIER_DRY_MIN_R;
            GF_CHECK(tc.tier == (want_none ? GF_TIER_NONE : GF_TIER_UNRESOLVED));
            GF_CHECK(strcmp(tc.model, want_none ? "none" : "unresolved") == 0);
            GF_CHECK(strstr(tc.reason, "St") != NULL || strstr(tc.reason, "r =") != NULL);
            tier[i][j] = tc.tier;
            n_none += tc.tier == GF_TIER_NONE;
        }
    /* monotone: right of or above a "none" point is "none" */
    for (int i = 0; i < NS; ++i)
        for (int j = 0; j < NR; ++j)
            if (tier[i][j] == GF_TIER_NONE) {
                if (i + 1 < NS)
                    GF_CHECK(tier[i + 1][j] == GF_TIER_NONE);
                if (j + 1 < NR)
                    GF_CHECK(tier[i][j + 1] == GF_TIER_NONE);
            }
    printf("%d x %d grid: %d refused (r <= sqrt(5/3)), %d 'none'; round trip worst %.2g, ratio laws worst %.2g\n", NS,
           NR, n_refused, n_none, worst_trip, worst_ratio);
    GF_CHECK(n_refused == 4 * NS); /* 1.1, 1.2, 1.29 and sqrt(5/3) itself */
    GF_CHECK(worst_trip <= 1e-12);
    GF_CHECK(worst_ratio <= 1e-12);

    /* the four corners, printed with their reasons */
    const double corners[4][2] = {{0.01, 1.3}, {1000.0, 100.0}, {1000.0, 1.3}, {0.01, 100.0}};
    const gf_tier want[4] = {GF_TIER_UNRESOLVED, GF_TIER_NONE, GF_TIER_UNRESOLVED, GF_TIER_UNRESOLVED};
    for (int k = 0; k < 4; ++k) {
        gf_ctx ctx = {0};
        gf_tier_choice tc;
        GF_CHECK_OK(gf_tier_choose(&ctx, corners[k][0], corners[k][1], &tc), &ctx);
        printf("(St %g, r %g) -> %s: %s\n", corners[k][0], corners[k][1], tc.model, tc.reason);
        GF_CHECK(tc.tier == want[k]);
    }
    /* dry, NaN, St <= 0 */
    gf_ctx ctx = {0};
    gf_tier_choice tc;
    GF_CHECK_OK(gf_tier_choose(&ctx, INFINITY, INFINITY, &tc), &ctx);
    GF_CHECK(tc.tier == GF_TIER_NONE);
    printf("dry -> %s: %s\n", tc.model, tc.reason);
    gf_scales dry;
    gf_groups_input in = {.diameter_m = D, .grain_density_kg_m3 = rho_p, .gravity_m_s2 = g, .slope_sin = 1.0};
    GF_CHECK_OK(gf_groups_compute(&ctx, &in, &dry), &ctx);
    GF_CHECK_OK(gf_tier_from_scales(&ctx, &dry, &tc), &ctx);
    GF_CHECK(tc.tier == GF_TIER_NONE);
    GF_CHECK(gf_tier_choose(&ctx, NAN, 4.0, &tc) == GF_ERR_ARG);
    GF_CHECK(gf_tier_choose(&ctx, 0.0, 4.0, &tc) == GF_ERR_PHYSICS);
    GF_CHECK(gf_tier_choose(&ctx, -1.0, 4.0, &tc) == GF_ERR_PHYSICS);
    printf("St = -1 refused: %s\n", ctx.last_msg);
    return gf_test_finish();
}
