/*
 * Silo discharge against Djouwe Meffeja (2012) ch. 3, the slow validations.
 * One mode per study (argv[1]); every run is the thesis' silo (§3.3): a
 * 25 d x 25 d x 50 d box, square orifice, fill 25.4 d, reinjection at
 * 45 d, e_n = 0.885, mu = mu_wall = 0.5, k_t = 2 k_n / 7, gamma_t = 0, at
 * Silbert et al. (2001)'s stiffness (t_n = 4.97e-3 sqrt(d/g), dt = t_n / 50),
 * d = 0.5 mm, rho_s = 2500 kg m-3, monodisperse. Q is counted over
 * WINDOW sqrt(d/g) after TRANSIENT sqrt(d/g) of discharge (the thesis
 * averages over "a steady state"; its runs last 1.005 s = 141 sqrt(d/g)).
 *
 *   beverloo     D = 4, 6, 8, 10, 12, 14, 16, 18 d (§3.4.2, Fig. 3.8):
 *                Q^(2/5) linear in D with R^2 > 0.99, k = 1.47 +- 0.15 and
 *                C within 25 % of 1.7 (phi = 0.5 at the orifice, as the thesis
 *                takes it).
 *   height       D = 6 d, fill H = 4, 6, 9, 13, 18, 25.4 d (§3.4.1, Fig. 3.7):
 *                Q = Q0 (1 - exp(-H/H0)) with H0 = 5.7 d +- 30 % and
 *                Q(25.4 d)/Q0 >= 0.97.
 *   friction     D = 6 d, mu = 0, 0.25, 0.5, 0.75, 1 (§3.4.3, Figs. 3.9-3.10):
 *                Q and phi_out decrease with mu; Q linear in phi_out, R^2 > 0.9.
 *   profiles     D = 6 d (§3.5.1, Fig. 3.13): v_y(x) across the orifice's
 *                mid-plane (|z - Ly/2| < d) at heights z = 0.5, 1, 2, 3, 5, 8 d,
 *                fitted by a Gaussian A exp(-(x - x_c)^2 / (4 b z)) (Nedderman &
 *                Tuzun 1979: width^2 = 2 b z): R^2 > 0.95 for z >= 3 d, and b(z)
 *                decreasing from z = d on.
 * Row 11 (Q against e_n) is test_silo_restitution.c: its effect is below
 * one run's noise in this silo (docs/silo.md).
 * Each prints its runs' Q (grains/s and sqrt(g/d)), phi_out, the fits and the
 * CPU time. GF_TEST_WINDOW overrides WINDOW (sqrt(d/g)).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "gf_sim.h"
#include "gf_test.h"
#include "scenes/gf_scene.h"
#include "scenes/gf_silo_thesis.h"
#include "stages/gf_post_stats.h"
#include "stages/gf_silo_flow.h"

#define TRANSIENT 5.0
#define WINDOW 20.0
enum { N_HEIGHTS = 6, N_XBINS = 50 };
static const double profile_z[N_HEIGHTS] = {0.5, 1.0, 2.0, 3.0, 5.0, 8.0};

typedef struct silo_result {
    double Q, Q_nd, phi_out, H_over_d, cpu_s, grains;
    double vsum[N_HEIGHTS][N_XBINS];
    long vcount[N_HEIGHTS][N_XBINS];
    long samples;
} silo_result;

static double cpu_now(void) { return (double)clock() / CLOCKS_PER_SEC; }

static void thesis_spec(gf_run_spec *s, double D_over_d)
{
    gf_silo_thesis_spec(s);
    gf_run_spec_set_param(NULL, s, "orifice_x_over_d", D_over_d);
    gf_run_spec_set_param(NULL, s, "orifice_z_over_d", D_over_d);
    gf_run_spec_set_param(NULL, s, "settle_time_nd", 10.0);
}

/* Mid-plane velocity samples of the mobile grains at the profile heights (bins of d, slabs of d). */
static void sample_profiles(gf_sim *sim, silo_result *r)
{
    const gf_particles *p = gf_sim_particles(sim);
    const double d = gf_sim_spec(sim)->grains.diameter_m, L = 25.0 * d, mid = 0.5 * L;
    for (size_t i = 0; i < p->n_local; ++i) {
        if ((p->flags[i] & GF_P_GLUED) || fabs(p->z_m[i] - mid) >= d)
            continue;
        int b = (int)floor(p->x_m[i] / (L / N_XBINS));
        if (b < 0 || b >= N_XBINS)
            continue;
        for (int h = 0; h < N_HEIGHTS; ++h)
            if (fabs(p->y_m[i] - profile_z[h] * d) < 0.5 * d)
                r->vsum[h][b] -= p->vy_m_s[i], r->vcount[h][b]++;
    }
    r->samples++;
}

static int run_silo(const gf_run_spec *spec, int profiles, silo_result *r)
{
    memset(r, 0, sizeof *r);
    gf_ctx ctx = {0};
    gf_sim *sim = NULL;
    gf_sim_options opt = {.n_threads = 1};
    double c0 = cpu_now();
    GF_CHECK_OK(gf_sim_create(&ctx, spec, &opt, &sim), &ctx);
    if (!sim)
        return 0;
    const gf_scene_desc *desc = gf_scene_find("silo");
    const double d = spec->grains.diameter_m, tg = sqrt(d / spec->gravity_m_s2);
    const double window = getenv("GF_TEST_WINDOW") ? atof(getenv("GF_TEST_WINDOW")) : WINDOW;
    const long every = GF_SCENE_MAINTAIN_EVERY, n_tr = (long)ceil(TRANSIENT * tg / gf_sim_dt_s(sim) / every);
    const long n_win = (long)ceil(window * tg / gf_sim_dt_s(sim) / every);
    double v[5], out0 = 0.0, t0 = 0.0, phi = 0.0, H = 0.0;
    int n_diag = 0, ok = 1;
    r->grains = (double)gf_sim_particles(sim)->n_local;
    for (long k = 0; k < n_tr + n_win && ok; ++k) {
        gf_status st = gf_sim_advance(sim, every);
        if (st == GF_OK)
            st = desc->maintain(sim);
        GF_CHECK_OK(st, &ctx);
        ok = st == GF_OK;
        if (ok && k + 1 == n_tr) {
            desc->diagnose(sim, v);
            out0 = v[0], t0 = gf_sim_time_s(sim);
        } else if (ok && k + 1 > n_tr) {
            if (profiles)
                sample_profiles(sim, r);
            if ((k + 1 - n_tr) % 50 == 0) { /* phi_out and H every 0.5 sqrt(d/g) */
                desc->diagnose(sim, v);
                phi += v[3], H += v[4], ++n_diag;
            }
        }
    }
    if (ok) {
        desc->diagnose(sim, v);
        r->Q = (v[0] - out0) / (gf_sim_time_s(sim) - t0);
        r->Q_nd = r->Q * tg;
        r->phi_out = phi / n_diag;
        r->H_over_d = H / n_diag / d;
    }
    r->cpu_s = cpu_now() - c0;
    gf_sim_destroy(&sim);
    return ok;
}

static void print_run(const char *what, double x, const silo_result *r)
{
    printf("%s %6.3f: %6.0f grains, H %.2f d, Q %.5g grains/s = %.4g sqrt(g/d), phi_out %.4f, %.0f s CPU\n", what, x,
           r->grains, r->H_over_d, r->Q, r->Q_nd, r->phi_out, r->cpu_s);
    fflush(stdout);
}

static void study_beverloo(void)
{
    const double D[] = {4, 6, 8, 10, 12, 14, 16, 18};
    enum { N = sizeof D / sizeof D[0] };
    double Q[N], k, C, R2;
    silo_result r;
    for (int i = 0; i < N; ++i) {
        gf_run_spec s;
        thesis_spec(&s, D[i]);
        if (!run_silo(&s, 0, &r))
            return;
        Q[i] = r.Q_nd;
        print_run("D/d", D[i], &r);
    }
    GF_CHECK(gf_silo_fit_beverloo(D, Q, N, &k, &C, &R2));
    printf("Beverloo: k = %.4f (thesis 1.47 +- 0.15), C = %.4f (thesis 1.7 +- 25 %%), R^2 = %.5f\n", k, C, R2);
    GF_CHECK_ABS(k, 1.47, 0.15);
    GF_CHECK_REL(C, 1.7, 0.25);
    GF_CHECK(R2 > 0.99);
}

static void study_height(void)
{
    const double Hs[] = {4, 6, 9, 13, 18, 25.4};
    enum { N = sizeof Hs / sizeof Hs[0] };
    double H[N], Q[N], Q0, H0, R2;
    silo_result r;
    for (int i = 0; i < N; ++i) {
        gf_run_spec s;
        thesis_spec(&s, 6.0);
        gf_run_spec_set_param(NULL, &s, "fill_height_over_d", Hs[i]);
        if (!run_silo(&s, 0, &r))
            return;
        H[i] = r.H_over_d, Q[i] = r.Q;
        print_run("H/d asked", Hs[i], &r);
    }
    GF_CHECK(gf_silo_fit_saturation(H, Q, N, &Q0, &H0, &R2));
    printf("saturation: Q0 = %.5g grains/s, H0 = %.3f d (thesis 5.7 +- 30 %%), R^2 = %.4f, Q(%.1f d)/Q0 = %.4f\n", Q0,
           H0, R2, H[N - 1], Q[N - 1] / Q0);
    GF_CHECK_REL(H0, 5.7, 0.30);
    GF_CHECK(Q[N - 1] / Q0 >= 0.97);
}

/* Q and phi_out against a contact parameter: both decrease, Q linear in phi_out. */
static void study_trend(const char *name, const double *x, int n)
{
    double Q[16], phi[16], a, b;
    silo_result r;
    for (int i = 0; i < n; ++i) {
        gf_run_spec s;
        thesis_spec(&s, 6.0);
        s.contact.friction = x[i];
        if (!run_silo(&s, 0, &r))
            return;
        Q[i] = r.Q_nd, phi[i] = r.phi_out;
        print_run(name, x[i], &r);
    }
    int q_down = 1, phi_down = 1;
    for (int i = 1; i < n; ++i)
        q_down &= Q[i] < Q[i - 1], phi_down &= phi[i] < phi[i - 1];
    GF_CHECK(gf_stats_linfit(phi, Q, (size_t)n, &a, &b));
    double m = 0, tot = 0, res = 0;
    for (int i = 0; i < n; ++i)
        m += Q[i] / n;
    for (int i = 0; i < n; ++i)
        tot += (Q[i] - m) * (Q[i] - m), res += (Q[i] - a - b * phi[i]) * (Q[i] - a - b * phi[i]);
    printf("%s: Q decreasing %s, phi_out decreasing %s; Q sqrt(d/g) = %.4g + %.4g phi_out, R^2 = %.4f\n", name,
           q_down ? "yes" : "no", phi_down ? "yes" : "no", a, b, 1.0 - res / tot);
    GF_CHECK(q_down);
    GF_CHECK(phi_down);
    GF_CHECK(1.0 - res / tot > 0.9);
}

static void study_profiles(void)
{
    gf_run_spec s;
    thesis_spec(&s, 6.0);
    silo_result *r = calloc(1, sizeof *r);
    if (!r || !run_silo(&s, 1, r)) {
        free(r);
        return;
    }
    print_run("profiles D/d", 6.0, r);
    const double d = s.grains.diameter_m, L = 25.0 * d;
    double b[N_HEIGHTS], R2[N_HEIGHTS], x[N_XBINS], v[N_XBINS];
    for (int h = 0; h < N_HEIGHTS; ++h) {
        for (int i = 0; i < N_XBINS; ++i) {
            x[i] = (i + 0.5) * L / N_XBINS;
            v[i] = r->vcount[h][i] ? r->vsum[h][i] / (double)r->vcount[h][i] : 0.0;
        }
        R2[h] = NAN;
        b[h] = gf_silo_fit_gaussian(x, v, N_XBINS, profile_z[h] * d, &R2[h]);
        double vmax = 0.0;
        for (int i = 0; i < N_XBINS; ++i)
            vmax = fmax(vmax, v[i]);
        printf("z = %.1f d: peak v %.4g sqrt(gd), b = %.4g d, Gaussian R^2 = %.4f\n", profile_z[h],
               vmax / sqrt(9.81 * d), b[h] / d, R2[h]);
        if (profile_z[h] >= 3.0)
            GF_CHECK(R2[h] > 0.95);
    }
    for (int h = 2; h < N_HEIGHTS; ++h)
        GF_CHECK(b[h] < b[h - 1]);
    free(r);
}

static void study_friction(void) { study_trend("mu", (const double[]){0.0, 0.25, 0.5, 0.75, 1.0}, 5); }

int main(int argc, char **argv)
{
    static const gf_test_mode studies[] = {{"beverloo", study_beverloo}, {"height", study_height},
                                           {"friction", study_friction}, {"profiles", study_profiles}};
    if (!gf_test_run_mode(studies, 4, argc > 1 ? argv[1] : "beverloo")) {
        fprintf(stderr, "usage: %s beverloo|height|friction|profiles\n", argv[0]);
        return 2;
    }
    return gf_test_finish();
}
