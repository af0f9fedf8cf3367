/*
 * hindered_settling_tiers: the random suspension of resolved_hindered_tiers
 * (tests/resolved/resolved_suspension.c) at phi = 0.1, 41 grains in a 6 D
 * periodic cube (the settling scene, arrangement 1), rho_p/rho = 2, Ar = 20
 * (isolated Re_T 0.97 by Schiller-Naumann), run by either tier: the cell knob
 * picks it, as in settling_terminal_tiers (cell/D >= 1: the unresolved tier,
 * its default closure di_felice, cells of 3, 2, 1.5 D; cell/D < 1: the
 * resolved tier at D/dx = D/cell, 8, with its mean pressure gradient on the
 * periodic gravity axis).
 *
 * Observable: U/U_T, the grains' settling speed relative to the
 * zero-volume-flux frame (tests/testutil/gf_test_suspension.h) averaged over
 * 10-20 sqrt(D/g), over the isolated grain's Schiller-Naumann velocity.
 * Reference: Richardson & Zaki (1954), (1 - phi)^n with n = 4.4 Re_T^-0.03
 * (0.2 < Re_T < 1); tolerance 10 % (that of the hindered_settling case).
 */
#include <math.h>

#include "bench_accuracy.h"
#include "gf_bench_clock.h"
#include "gf_test_suspension.h"

#define SUSPENSION_PHI 0.1
#define SUSPENSION_BOX_OVER_D 6.0
#define SUSPENSION_AR 20.0
#define SUSPENSION_T_END_ND 20.0
#define SUSPENSION_SAMPLE_ND 0.1

const double bench_suspension_cells[] = {3.0, 2.0, 1.5, 1.0 / 8};

/* <j - v_p> over the second half of the run, m/s (downwards positive). */
static gf_status mean_settling_speed(gf_sim *sim, double *U)
{
    const double tg = sqrt(GF_TEST_SUSP_D_M / GF_TEST_SUSP_G);
    double excess, sum = 0.0;
    double phi = gf_test_suspension_phi(sim, &excess);
    long chunk = (long)ceil(SUSPENSION_SAMPLE_ND * tg / gf_sim_dt_s(sim)), n = 0;
    while (gf_sim_time_s(sim) < SUSPENSION_T_END_ND * tg) {
        GF_TRY(gf_sim_advance(sim, chunk));
        if (gf_sim_time_s(sim) < 0.5 * SUSPENSION_T_END_ND * tg)
            continue;
        double vp, j;
        gf_test_suspension_flux(sim, phi, &vp, &j);
        if (!isfinite(vp) || !isfinite(j))
            return GF_ERR_NUMERIC;
        sum += j - vp, n++;
    }
    *U = n ? sum / (double)n : NAN;
    return GF_OK;
}

gf_status bench_suspension_measure(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out)
{
    (void)full;
    const int resolved = k->cell_over_D < 1.0;
    const gf_test_suspension su = {.model = resolved ? "resolved" : "unresolved", .mode = 1, .arrangement = 1,
                                   .box = SUSPENSION_BOX_OVER_D, .phi = SUSPENSION_PHI, .ar = SUSPENSION_AR,
                                   .d_over_dx = resolved ? 1.0 / k->cell_over_D : 8.0,
                                   .cell_over_D = resolved ? 0.0 : k->cell_over_D};
    gf_run_spec spec;
    GF_TRY(gf_test_suspension_spec(ctx, &su, SUSPENSION_T_END_ND, &spec));
    gf_sim *sim = NULL;
    double U = NAN, t0 = gf_bench_cpu_time_s();
    GF_TRY(gf_sim_create(ctx, &spec, &(gf_sim_options){.n_threads = 1}, &sim));
    double excess, phi = gf_test_suspension_phi(sim, &excess);
    gf_status st = mean_settling_speed(sim, &U);
    double cost = gf_bench_cpu_time_s() - t0;
    gf_sim_destroy(&sim);
    if (st == GF_ERR_NUMERIC)
        return GF_FAIL(ctx, st, "hindered_settling_tiers: non-finite velocity (%s tier)", su.model);
    GF_TRY(st);
    double re_t, n;
    double ut = gf_test_suspension_terminal(SUSPENSION_AR, &re_t, &n), rz = pow(1.0 - phi, n);
    *out = (bench_result){U / ut, rz, fabs(U / ut / rz - 1.0), cost, NAN};
    return GF_OK;
}
