/*
 * Lab notebook — time scales and regime classification (stage regime).
 *
 * 1. Time scales for hand-computed parameters, read from synthetic attributes
 *    (D = 5 mm, ρ_p = 2500, ρ_f = 1000 kg m-3, η = 0.01 Pa s, g = 9.81, θ = 25°,
 *    g sinθ = 4.14588 m s-2, Δρ = 1500):
 *      T_v  = 18 η / (Δρ g sinθ D)          = 0.18 / 31.0941          = 5.78887e-3 s
 *      T_i  = sqrt(ρ_f D) / sqrt(2 Δρ g sinθ) = 2.23607 / 111.526     = 2.00501e-2 s
 *      T_ff = sqrt(2 ρ_p D / (Δρ g sinθ))   = sqrt(25 / 6218.82)      = 6.34039e-2 s
 *    Tolerance 1e-5 relative (printed digits).
 * 2. The classifier on the seed's Table 4.2 (Izard 2014 §4.1.4.2), fed the seed's
 *    own (St, r, T): D = 5 mm, θ = 25°, ρ_p/ρ from the table (r recomputed as
 *    sqrt(5 ρ_p / 3ρ): the table prints r = 11.2 for ρ_p/ρ = 100, where 12.91 is meant), T from T (ms). Ranges are paired as
 *    (St_min, T_max) and (St_max, T_min): slower flows at lower St.
 *    Expected labels from the seed's boundaries: r >= 4: viscous for St < 1,
 *    free fall above; r < 4: viscous for St < r/4 (the line r = 4 St),
 *    inertial above. Ambiguous (reported, not asserted):
 *      - St within a factor 2 of the viscous boundary (the validation band,
 *        factor 2 of Fig. 4.7-4.10): ρ_p/ρ = 16, St = 0.7 and 0.75;
 *      - 3.5 <= r <= 4.5 above the viscous boundary (inertial ↔ free fall is
 *        continuous, r_c ≈ 4 indicative): ρ_p/ρ = 7.5 St 79, 10 St 107;
 *      - pairing doubtful: ρ_p/ρ = 2.7, St = 0.03 with T = 130 ms gives
 *        T/T_v = 0.13, eight times faster than a bed of 8 D that follows
 *        Boyer et al. (2011) in a tank (7.15). Driven as the thesis' eq.
 *        (4.6) drives it, such a bed gives 0.16 (test_post_regime_boyer),
 *        so the pairing may be right; it stays out of the assertions.
 *    Assertions: the nearest-scale label agrees on every unambiguous point;
 *    the label with the transitional rule (more than a factor 2 from every
 *    scale, or two scales within 0.1 decade; gf_regime.h) agrees on at least
 *    17 of the 19 unambiguous points. The two it calls transitional are
 *    genuinely between scales: ρ_p/ρ = 7, St = 23 (T/T_i = 2.29 and
 *    T/T_ff = 0.434, equidistant in decades) and ρ_p/ρ = 10, St = 0.4
 *    (T_ff/T_v = 2 St = 0.8: the two scales themselves lie 0.1 decade
 *    apart). The count with a narrower threshold, 0.2 decade, is
 *    printed beside it.
 * 3. Stage regime on a synthetic avalanche: N grains, constant Q_g chosen so
 *    that T = V_g/Q_g = T_i exactly (plus 1 % noise): label inertial,
 *    T/T_i = 1 within 1 % (noise averages out to < 0.1 %).
 *    Same with no particles.nc (a regime-map campaign writes no trajectories):
 *    V_g = φ̄ L W h̄ from bed_packing_fraction = 0.58, bed_height = 8 D and
 *    L = W = 5 D (scene_param_* attributes); Q_g set from that volume so that
 *    T = T_i: T/T_i = 1 within 1 %.
 *    The same run's T_over_Tv_boyer (the μ(I_v) reference, gf_boyer.h) with
 *    slope_gravity_exponent 2: the layer's value for 8 D, 5 D, 25° and the
 *    drive (2500/1500)^2, to 1e-9 (the stage passes the right inputs).
 * 4. Stage regime on a synthetic collapse: front x(t) = R0 + ΔR (1 + tanh((t −
 *    t_c)/τ))/2 with t_rest (front within D/2 of final) placed exactly at the
 *    viscous scale over H0, T_v (H0/D): label viscous, t_rest within one
 *    sample, and the max front speed ΔR/(2τ) within 1 %.
 */
#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/gf_boyer.h"
#include "core/gf_groups.h"
#include "core/gf_rng.h"
#include "gf_post_synth.h"
#include "gf_test.h"
#include "stages/gf_regime.h"
#include "stages/gf_stage.h"
#include "synth_stage.h"
#include "table42.h"

static void table_check(void)
{
    const double D = 5e-3, g = 9.81, s = sin(25.0 * M_PI / 180.0), rho_p = 2500.0;
    const int n = TABLE42_N;
    int agree_nearest = 0, agree_strict = 0, unamb = 0, unamb_agree = 0, unamb_strict = 0, unamb_02 = 0;
    printf("%6s %6s %8s %7s %9s %9s %9s  %-9s %-9s %-12s %s\n", "rho_p/rho", "r", "St", "T(ms)", "T/Tv", "T/Ti",
           "T/Tff", "expected", "nearest", "strict", "note");
    for (int k = 0; k < n; ++k) {
        const table_pt *p = &table42[k];
        const double r = sqrt(5.0 * p->ratio / 3.0);
        double rho_f, eta;
        gf_ctx ctx = {0};
        GF_CHECK_OK(gf_groups_invert(&ctx, p->St, r, D, rho_p, g * s, &rho_f, &eta), &ctx);
        gf_groups_input in = {D, rho_p, rho_f, eta, g, s, 0, 0};
        gf_scales sc;
        GF_CHECK_OK(gf_groups_compute(&ctx, &in, &sc), &ctx);
        GF_CHECK_REL(sc.stokes_St, p->St, 1e-9);
        const double T = p->T_ms * 1e-3;
        gf_regime_result res;
        GF_CHECK_OK(gf_regime_classify(&ctx, T, &sc, &res), &ctx);
        const gf_regime_label want = table42_expected(p->St, r);
        agree_nearest += res.nearest == want;
        agree_strict += res.label == want;
        if (!p->ambiguous) {
            ++unamb;
            unamb_agree += res.nearest == want;
            unamb_strict += res.label == want;
            /* the same rule with a 0.2-decade band, for comparison only */
            unamb_02 += res.nearest == want && res.best_decades <= 0.2 &&
                        res.confidence_decades >= GF_REGIME_MIN_SEPARATION;
            gf_test_check(res.nearest == want, __FILE__, __LINE__, "Table 4.2 rho_p/rho = %g St = %g: nearest %s, "
                          "expected %s", p->ratio, p->St, gf_regime_name(res.nearest), gf_regime_name(want));
        }
        static const char *notes[] = {"", "ambiguous: St near boundary", "ambiguous: r ~ r_c",
                                      "ambiguous: T/T_v below the tank's Boyer plateau"};
        printf("%6g %6.2f %8g %7g %9.3g %9.3g %9.3g  %-9s %-9s %-12s %s\n", p->ratio, r, p->St, p->T_ms,
               T / sc.t_viscous_s, T / sc.t_inertial_s, T / sc.t_freefall_s, gf_regime_name(want),
               gf_regime_name(res.nearest), gf_regime_name(res.label), notes[p->ambiguous]);
    }
    printf("Table 4.2: nearest-scale label agrees on %d/%d points (%d/%d unambiguous); with the transitional "
           "rule %d/%d (%d/%d unambiguous; %d/%d with a 0.2-decade band)\n",
           agree_nearest, n, unamb_agree, unamb, agree_strict, n, unamb_strict, unamb, unamb_02, unamb);
    GF_CHECK(unamb_agree == unamb);
    GF_CHECK(unamb_strict >= 17);
    GF_CHECK(agree_nearest >= 21);
}

static void hand_scales_and_avalanche(void)
{
    char dir[1024];
    synth_scratch(dir, sizeof dir, "regime_avalanche");
    synth_meta m;
    synth_meta_default(&m, "aval1", "avalanche");
    m.incline_deg = 25.0;
    const size_t N = 200, NT = 600;
    double *rad = malloc(N * sizeof *rad), *x = calloc(N * 2, sizeof *x), *y = calloc(N * 2, sizeof *y);
    unsigned char *glued = calloc(N, 1);
    for (size_t i = 0; i < N; ++i) {
        rad[i] = 0.5 * m.D;
        glued[i] = i < 20;   /* 20 glued base grains do not count in V_g */
        x[2 * i] = x[2 * i + 1] = (double)(i % 10) * m.D;
        y[2 * i] = y[2 * i + 1] = (double)(i / 10) * m.D;
    }
    double tp[2] = {0.0, 1.0};
    GF_CHECK(synth_particles(dir, &m, N, 2, tp, rad, glued, x, y, NULL, NULL) == 0);
    const double Ti = 2.00501e-2;
    const double Vg = 180.0 * M_PI / 6.0 * m.D * m.D * m.D;
    const double Q = Vg / Ti;
    double *t = malloc(NT * sizeof *t), *q = malloc(NT * sizeof *q), *e = calloc(NT, sizeof *e);
    gf_rng rng;
    gf_rng_seed(&rng, 3);
    for (size_t k = 0; k < NT; ++k) {
        t[k] = 0.01 * (double)k;
        q[k] = Q * (1.0 + 0.01 * gf_rng_normal(&rng));
    }
    const char *names[] = {"grain_flow_rate", "ecx_per_grain"};
    const char *units[] = {"m3 s-1", "J"};
    const double *vals[] = {q, e};
    GF_CHECK(synth_diagnostics(dir, &m, NT, t, 2, names, units, vals) == 0);
    gf_ctx ctx = {0};
    gf_post_row row;
    gf_post_row_init(&row, dir);
    GF_CHECK_OK(synth_stage(&ctx, gf_stage_regime, dir, "avalanche", 0, &row), &ctx);
    GF_CHECK_REL(gf_post_row_get(&row, "Tv_s"), 5.78887e-3, 1e-5);
    GF_CHECK_REL(gf_post_row_get(&row, "Ti_s"), 2.00501e-2, 1e-5);
    GF_CHECK_REL(gf_post_row_get(&row, "Tff_s"), 6.34039e-2, 1e-5);
    GF_CHECK_REL(gf_post_row_get(&row, "Vg_m3"), Vg, 1e-12);
    GF_CHECK_REL(gf_post_row_get(&row, "T_over_Ti"), 1.0, 0.01);
    const char *lab = gf_post_row_get_text(&row, "regime");
    printf("avalanche: T/Ti = %.5f, T/Tv = %.4g, T/Tff = %.4g, regime %s, confidence %.3f decade\n",
           gf_post_row_get(&row, "T_over_Ti"), gf_post_row_get(&row, "T_over_Tv"),
           gf_post_row_get(&row, "T_over_Tff"), lab, gf_post_row_get(&row, "regime_confidence"));
    GF_CHECK(lab && strcmp(lab, "inertial") == 0);
    /* confidence: the next scale is T_ff, log10(T_ff/T_i) = 0.4998 decade away */
    GF_CHECK_ABS(gf_post_row_get(&row, "regime_confidence"), log10(6.34039e-2 / 2.00501e-2), 0.01);
    /* without particles.nc: the bed volume from the diagnostics */
    synth_scratch(dir, sizeof dir, "regime_avalanche_nopart");
    const double Vb = 0.58 * 25.0 * m.D * m.D * 8.0 * m.D;
    double *hb = malloc(NT * sizeof *hb), *pb = malloc(NT * sizeof *pb);
    for (size_t k = 0; k < NT; ++k) {
        q[k] = Vb / Ti * (1.0 + 0.01 * gf_rng_normal(&rng));
        hb[k] = 8.0 * m.D;
        pb[k] = 0.58;
    }
    const char *names2[] = {"grain_flow_rate", "ecx_per_grain", "bed_height", "bed_packing_fraction"};
    const char *units2[] = {"m3 s-1", "J", "m", "1"};
    const double *vals2[] = {q, e, hb, pb};
    GF_CHECK(synth_diagnostics(dir, &m, NT, t, 4, names2, units2, vals2) == 0);
    char p[1100];
    snprintf(p, sizeof p, "%s/diagnostics.nc", dir);
    int ncid;
    const double five = 5.0;
    GF_CHECK(nc_open(p, NC_WRITE, &ncid) == NC_NOERR);
    nc_redef(ncid);
    nc_put_att_double(ncid, NC_GLOBAL, "scene_param_length_over_D", NC_DOUBLE, 1, &five);
    nc_put_att_double(ncid, NC_GLOBAL, "scene_param_width_over_D", NC_DOUBLE, 1, &five);
    const double two = 2.0;
    nc_put_att_double(ncid, NC_GLOBAL, "scene_param_slope_gravity_exponent", NC_DOUBLE, 1, &two);
    GF_CHECK(nc_close(ncid) == NC_NOERR);
    gf_post_row_init(&row, dir);
    GF_CHECK_OK(synth_stage(&ctx, gf_stage_regime, dir, "avalanche", 0, &row), &ctx);
    printf("avalanche without particles.nc: V_g = %.4g m3 (true %.4g), T/Ti = %.5f, regime %s\n",
           gf_post_row_get(&row, "Vg_m3"), Vb, gf_post_row_get(&row, "T_over_Ti"),
           gf_post_row_get_text(&row, "regime"));
    GF_CHECK_REL(gf_post_row_get(&row, "Vg_m3"), Vb, 1e-9);
    GF_CHECK_REL(gf_post_row_get(&row, "T_over_Ti"), 1.0, 0.01);
    /* the μ(I_v) reference for this bed: depth 8 D, cell 5 D, 25°, drive (2500/1500)^2 (exponent 2) */
    const double th = 25.0 * M_PI / 180.0;
    const double boyer = gf_boyer_layer_T_over_Tv(&GF_BOYER_2011, tan(th) * pow(2500.0 / 1500.0, 2.0), tan(th), 8.0,
                                                  5.0, 0);
    printf("avalanche without particles.nc: mu(I_v) T/T_v %.5g (expected %.5g)\n",
           gf_post_row_get(&row, "T_over_Tv_boyer"), boyer);
    GF_CHECK_REL(gf_post_row_get(&row, "T_over_Tv_boyer"), boyer, 1e-9);
    free(hb), free(pb);
    free(rad), free(x), free(y), free(glued), free(t), free(q), free(e);
}

static void collapse(void)
{
    char dir[1024];
    synth_scratch(dir, sizeof dir, "regime_collapse");
    synth_meta m;
    synth_meta_default(&m, "coll1", "column_collapse");
    m.D = 7.6e-3, m.rho_p = 8000.0, m.rho_f = 1000.0, m.eta = 1.0;
    m.R0 = 16 * m.D, m.H0 = 8 * m.D, m.a = 0.5, m.phi = 0.6;
    gf_groups_input gi = {m.D, m.rho_p, m.rho_f, m.eta, m.g, 1.0, m.H0, m.R0};
    gf_scales sc;
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_groups_compute(&ctx, &gi, &sc), &ctx);
    const double TvH = sc.t_viscous_s * 8.0;                     /* viscous scale over H0 */
    const double dR = 1.25 * m.R0, tau = 0.05, du = atanh(1.0 - m.D / dR);
    const double tc = TvH - tau * du;                            /* puts t_rest at TvH */
    const size_t NT = 2001;
    const double dt = 2.0 * TvH / (NT - 1);
    double *t = malloc(NT * sizeof *t), *xf = malloc(NT * sizeof *xf), *e = calloc(NT, sizeof *e);
    for (size_t k = 0; k < NT; ++k) {
        t[k] = dt * (double)k;
        xf[k] = m.R0 + dR * 0.5 * (1.0 + tanh((t[k] - tc) / tau));
    }
    const char *names[] = {"front_position", "ecx_per_grain"};
    const char *units[] = {"m", "J"};
    const double *vals[] = {xf, e};
    GF_CHECK(synth_diagnostics(dir, &m, NT, t, 2, names, units, vals) == 0);
    gf_post_row row;
    gf_post_row_init(&row, dir);
    GF_CHECK_OK(synth_stage(&ctx, gf_stage_regime, dir, "column_collapse", 0, &row), &ctx);
    const double umax = dR / (2.0 * tau);
    printf("collapse: t_rest = %.5f s (set %.5f), T/Tv,H0 = %.4f, T/Ti,H0 = %.3g, T/Tff,H0 = %.3g, regime %s; "
           "Umax = %.5f m/s (true %.5f), Umax T_visq/R0 = %.3g\n",
           gf_post_row_get(&row, "T_s"), TvH, gf_post_row_get(&row, "T_over_Tv"), gf_post_row_get(&row, "T_over_Ti"),
           gf_post_row_get(&row, "T_over_Tff"), gf_post_row_get_text(&row, "regime"),
           gf_post_row_get(&row, "Ufront_max_m_s"), umax, gf_post_row_get(&row, "Ufront_max_over_R0_per_Tvisq"));
    GF_CHECK_ABS(gf_post_row_get(&row, "T_s"), TvH, dt);
    /* the peak speed, read as if the positions were in bins of D (the scene's): resolved to 10 %, and
     * within its uncertainty of the truth (the window it needs averages over the peak) */
    const double u = gf_post_row_get(&row, "Ufront_max_m_s"), du_err = gf_post_row_get(&row, "Ufront_max_err_m_s");
    printf("collapse: Umax %.5f +- %.5f m/s, true %.5f (error %+.2f %%)\n", u, du_err, umax, 100.0 * (u / umax - 1.0));
    GF_CHECK(du_err <= 0.1 * u);
    GF_CHECK(fabs(u - umax) <= du_err);
    GF_CHECK_REL(gf_post_row_get(&row, "Ufront_max_over_R0_per_Tvisq"), u * sc.t_visq_s / m.R0, 1e-12);
    GF_CHECK(strcmp(gf_post_row_get_text(&row, "regime_nearest"), "viscous") == 0);
    free(t), free(xf), free(e);
}

int main(void)
{
    table_check();
    hand_scales_and_avalanche();
    collapse();
    return gf_test_finish();
}
