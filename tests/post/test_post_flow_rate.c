/*
 * Lab notebook — stage flow_rate on a synthetic grain flow rate.
 *
 * Series: Q_g(t) = Q0 t / t_s for t < t_s (a ramp standing for the trigger
 * and granular development, Izard §4.1.4.1), then Q0 + AR(1) noise
 * e_k = φ e_{k−1} + σ sqrt(1 − φ²) ξ_k (stationary std σ, correlation time
 * −dt/ln φ). Known answers:
 *   steady start t_s (MSER-5 should cut within the last ~σ/Q0 of the ramp,
 *     i.e. at t_s within 5 % of t_s for σ/Q0 = 0.05: tolerance 10 % of t_s);
 *   steady mean Q0 (tolerance 1 %, ≈ 5 standard errors here);
 *   standard error of the mean: for AR(1), σ/sqrt(n) · sqrt((1 + φ)/(1 − φ))
 *     (large n). Block averaging must give it within 30 % (its own
 *     statistical error at the plateau level is ~15 %).
 * Coverage: over 40 seeds, |mean − Q0| <= 2 SE should hold in about 95 % of
 * the cases; we ask for at least 32/40 (80 %) so that a naive SE that
 * ignored the correlation (3× too small at φ = 0.8) fails clearly.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/gf_rng.h"
#include "gf_post_synth.h"
#include "gf_test.h"
#include "stages/gf_post_stats.h"
#include "stages/gf_stage.h"
#include "synth_stage.h"

#define NT 4000

static void make_series(uint64_t seed, double *t, double *q, double Q0, double ts, double sigma, double phi)
{
    gf_rng rng;
    gf_rng_seed(&rng, seed);
    const double dt = 0.01;
    double e = sigma * gf_rng_normal(&rng);
    for (int k = 0; k < NT; ++k) {
        t[k] = k * dt;
        e = phi * e + sigma * sqrt(1.0 - phi * phi) * gf_rng_normal(&rng);
        q[k] = (t[k] < ts ? Q0 * t[k] / ts : Q0) + (t[k] < ts ? 0.0 : e);
    }
}

int main(void)
{
    static double t[NT], q[NT], qf[NT];
    const double Q0 = 2.0e-4, ts = 10.0, sigma = 0.05 * Q0, phi = 0.8;
    make_series(7, t, q, Q0, ts, sigma, phi);
    for (int k = 0; k < NT; ++k)
        qf[k] = 3.0 * q[k];

    gf_steady s;
    gf_stats_steady(t, q, NT, &s);
    const double n_win = NT - s.i_start;
    const double se_ar1 = sigma / sqrt(n_win) * sqrt((1.0 + phi) / (1.0 - phi));
    printf("steady start %.3f s (true %.3f), mean %.6g (true %.6g), SE %.3g (AR(1) %.3g)\n", s.t_start_s, ts, s.mean,
           Q0, s.sem, se_ar1);
    GF_CHECK(s.ok);
    GF_CHECK_ABS(s.t_start_s, ts, 0.1 * ts);
    GF_CHECK_REL(s.mean, Q0, 0.01);
    GF_CHECK_REL(s.sem, se_ar1, 0.30);
    GF_CHECK_REL(s.std, sigma, 0.15);

    /* coverage of the block-averaging standard error over independent seeds */
    int covered = 0, covered_naive = 0;
    for (uint64_t seed = 100; seed < 140; ++seed) {
        make_series(seed, t, q, Q0, ts, sigma, phi);
        gf_steady c;
        gf_stats_steady(t, q, NT, &c);
        covered += fabs(c.mean - Q0) <= 2.0 * c.sem;
        covered_naive += fabs(c.mean - Q0) <= 2.0 * c.std / sqrt((double)(NT - c.i_start));
    }
    printf("coverage of mean +- 2 SE: block %d/40, naive %d/40\n", covered, covered_naive);
    GF_CHECK(covered >= 32);

    /* the stage on a synthetic diagnostics.nc gives the same numbers */
    make_series(7, t, q, Q0, ts, sigma, phi);
    char dir[1024];
    synth_scratch(dir, sizeof dir, "flow_rate");
    synth_meta m;
    synth_meta_default(&m, "flow1", "avalanche");
    m.incline_deg = 25.0;
    const char *names[] = {"grain_flow_rate", "fluid_flow_rate", "ecx_per_grain"};
    const char *units[] = {"m3 s-1", "m3 s-1", "J"};
    const double *vals[] = {q, qf, q};
    GF_CHECK(synth_diagnostics(dir, &m, NT, t, 3, names, units, vals) == 0);
    gf_ctx ctx = {0};
    gf_post_row row;
    gf_post_row_init(&row, dir);
    GF_CHECK_OK(synth_stage(&ctx, gf_stage_flow_rate, dir, "avalanche", 0, &row), &ctx);
    GF_CHECK_REL(gf_post_row_get(&row, "Qg_mean"), s.mean, 1e-12);
    GF_CHECK_REL(gf_post_row_get(&row, "Qg_sem"), s.sem, 1e-12);
    GF_CHECK_ABS(gf_post_row_get(&row, "t_steady_s"), s.t_start_s, 1e-12);
    GF_CHECK_REL(gf_post_row_get(&row, "Qf_mean"), 3.0 * s.mean, 1e-9);
    GF_CHECK_ABS(gf_post_row_get(&row, "Qg_drift_rel"), 0.0, 0.02);

    /* the stage chooses its runs by what they wrote, not by the scene's name: a
     * run without grain_flow_rate is not a flowing layer, whatever its scene, and
     * the stage leaves its row alone */
    const char *names2[] = {"ecx_per_grain"};
    GF_CHECK(synth_diagnostics(dir, &m, NT, t, 1, names2, units, vals) == 0);
    gf_ctx c2 = {0};
    gf_post_row row2;
    gf_post_row_init(&row2, dir);
    gf_status st = synth_stage(&c2, gf_stage_flow_rate, dir, "avalanche", 0, &row2);
    printf("no grain_flow_rate -> %s\n", gf_status_str(st));
    GF_CHECK(st == GF_ERR_UNSUPPORTED);
    GF_CHECK(!isfinite(gf_post_row_get(&row2, "Qg_mean")));
    return gf_test_finish();
}
