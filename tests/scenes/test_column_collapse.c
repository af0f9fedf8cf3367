/*
 * Dry granular column collapse in a quasi-2D periodic slab (Izard 2014
 * §2.1.3.3, Fig. 2.12-2.13).
 *
 * Set-up as the thesis' 3-D dry runs: R = 5 mm +- 10 %, rho_p = 2500,
 * eps = 0.5, mu_c = 1.0 grain-grain and grain-wall (Staron & Hinch 2005),
 * transverse periodic width 3 D (the thesis uses 24 R = 12 D; the transverse
 * direction "has no effect", Izard 2014 §2.1.3.3), column length R0 = 16 D on a rough base,
 * Phi_i = 0.60, the thesis' contact duration t_c = 1e-4 s (t_c sqrt(g/D) =
 * 3.1e-3). The thesis notes that softening k_n does not alter dry dynamics
 * (Izard 2014 §3.1.2.2), but here it does: at t_c sqrt(g/D) = 0.02 the columns of a >= 2
 * run out 4-10 % farther (lambda2 2.65 over 8 packing seeds against 2.46;
 * docs/notes/validation-dem.md), the tall columns' impact overlaps reaching ~0.1 D.
 *
 * Claims, against the published planar laws (Lube et al. 2005; Lajeunesse et al. 2005):
 *   (R_inf - R0)/R0 = lambda1 a for a below the crossover a0 ~ 2-3, with
 *   lambda1 in [1.2, 1.8] (Lube et al. 2005 / Lajeunesse et al. 2005), and
 *   lambda2 a^(2/3) above it with lambda2 in [1.9, 2.3]. Each fitted
 *   coefficient must lie inside the published band widened by 15 %
 *   (the 15 % is the brief's tolerance: the thesis quotes agreement "within
 *   their scatter", ~10 %, and the published coefficients themselves differ
 *   by 50 %).
 *   For a = 0.5 the deposit keeps the initial height (a trapezoid:
 *   H_inf = H0 below a ~ 0.7-1.15, Lube 2005, Lajeunesse 2005): H_inf/H0 within 10 %.
 * Arguments: [--seeds N] and the aspect ratios to run (default 0.5 1 2: the
 * `slow` variant adds 4 and 6 and fits lambda2). With N packing seeds
 * (1 .. N, GF_TEST_SEED moves the first; GF_TEST_SEEDS=N without the
 * argument) every aspect ratio runs once per seed and the claims are checked
 * on the per-a mean run-out and H_inf: the published coefficients are fits to
 * ensemble behaviour, and one collapse is chaotic (a 1e-7 change of g moves a
 * run-out by several %). The lambdas of each seed alone are printed to show
 * that scatter.
 * GF_TEST_MU overrides mu_c, GF_TEST_WIDTH the slab width W/D and
 * GF_TEST_TC t_c sqrt(g/D) (exploration: the thesis' dry runs are 12 D wide).
 */
#include <stdlib.h>

#include "scene_runner.h"
#include "scenes/gf_measure.h"

enum { NA = 8, NS = 16 };

static void collapse(double a, unsigned seed, double *runout, double *h_over_r0, double *phi_i)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    runner_dry_spec(&spec, "column_collapse");
    spec.seed = seed;
    spec.contact.restitution = 0.5;
    spec.contact.friction = getenv("GF_TEST_MU") ? atof(getenv("GF_TEST_MU")) : 1.0;
    spec.contact.wall_friction = spec.contact.friction;
    const double t_c_s = 1e-4; /* the thesis' dry runs */
    spec.contact.t_contact_nd = getenv("GF_TEST_TC") ? atof(getenv("GF_TEST_TC"))
                                                     : t_c_s / sqrt(spec.grains.diameter_m / spec.gravity_m_s2);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "aspect_ratio", a), &ctx);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "phi_target", 0.60), &ctx);
    if (getenv("GF_TEST_WIDTH"))
        GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "width_over_D", atof(getenv("GF_TEST_WIDTH"))), &ctx);
    double t0 = runner_now_s();
    gf_sim *sim = runner_create(&ctx, &spec);
    if (!sim) {
        *runout = *h_over_r0 = *phi_i = NAN;
        return;
    }
    double t1 = runner_now_s();
    const gf_scene_desc *d = gf_scene_find("column_collapse");
    double phi_m, phi_l, v[5]; /* the scene's diagnostics (gf_scene_column_collapse.c) */
    d->initial_packing(sim, &phi_m, &phi_l);
    *phi_i = phi_l;
    /* at t = 0 the material height is the column's H0 over bins of D up to R0 = 16 D: its extents are
     * the continuum's, R0 + D/2 - D depth/H0 (test_continuum_method), to the packing's grain-scale
     * unevenness (0.1 D) */
    const double D = spec.grains.diameter_m, R0 = 16 * D, H0 = a * R0;
    GF_CHECK_OK(d->diagnose(sim, v), &ctx);
    GF_CHECK_ABS(v[3], R0 + 0.5 * D - D * D / H0, 0.1 * D);
    GF_CHECK_ABS(v[4], R0 + 0.5 * D - 2.0 * D * D / H0, 0.1 * D);
    double T0_nd = sqrt(2.0 * a * 16.0);
    long steps = runner_until_done(sim, 10.0 * T0_nd + 40.0, 1.0);
    GF_CHECK_OK(d->diagnose(sim, v), &ctx);
    *runout = (v[0] - R0) / R0;
    *h_over_r0 = v[1] / R0;
    /* the final profile, for the notebook: envelope (top of grains) and solid height per D bin */
    gf_measure_domain dom;
    gf_sim_box(sim, dom.lo_m, dom.hi_m, dom.periodic);
    double top[400], solid[400];
    gf_measure_deposit dep;
    int nb = (int)fmin(400, ceil(dom.hi_m[0] / D));
    gf_measure_deposit_profile(&ctx, gf_sim_particles(sim), &dom, 0.0, D, nb, 0.25 * D, 1, top, solid, &dep);
    printf("  deposit (x/D: top/D, solid/D):");
    for (int b = 0; b < nb && b * D < v[0] + 4 * D; b += 2)
        printf(" %d:%.1f,%.2f", b, top[b] / D, solid[b] / D);
    printf("\n");
    size_t n = gf_sim_particles(sim)->n_local;
    printf("seed %u, a = %.2f: Phi_i %.4f (global %.4f), (R_inf - R0)/R0 = %.3f, H_inf/R0 = %.3f, "
           "t_stop = %.1f sqrt(D/g), %zu grains, build %.1f s, run %.1f s (%ld steps)\n",
           seed, a, phi_l, phi_m, *runout, *h_over_r0, gf_sim_time_s(sim) / sqrt(D / 9.81), n, t1 - t0,
           runner_now_s() - t1, steps);
    fflush(stdout);
    gf_sim_destroy(&sim);
}

/* One sweep over the aspect ratios with one packing seed; prints that seed's own fit. */
static void sweep(const double *a, int n, unsigned seed, double *r, double *h)
{
    for (int k = 0; k < n; ++k) {
        double phi;
        collapse(a[k], seed, &r[k], &h[k], &phi);
        GF_CHECK_ABS(phi, 0.60, 0.02); /* re-equilibrated column stays near the request */
    }
    double l1, l2;
    gf_measure_fit_runout(a, r, n, 2.5, &l1, &l2);
    printf("seed %u alone: lambda1 = %.3f, lambda2 = %.3f\n", seed, l1, l2);
    fflush(stdout);
}

/* Per-a mean and sd over the seeds of the run-out and H_inf/R0 (means into rm, hm). */
static void ensemble(const double *a, int n, int ns, double r[][NA], double h[][NA], double *rm, double *hm)
{
    for (int k = 0; k < n; ++k) {
        double rk[NS], hk[NS], rsd, hsd;
        for (int s = 0; s < ns; ++s)
            rk[s] = r[s][k], hk[s] = h[s][k];
        runner_mean_sd(rk, ns, &rm[k], &rsd);
        runner_mean_sd(hk, ns, &hm[k], &hsd);
        printf("a = %.2f over %d seeds: (R_inf - R0)/R0 = %.3f +- %.3f (sd), H_inf/R0 = %.3f +- %.3f\n", a[k], ns,
               rm[k], rsd, hm[k], hsd);
    }
}

int main(int argc, char **argv)
{
    int argi, ns = runner_seeds(argc, argv, &argi, NS);
    double a[NA] = {0.5, 1.0, 2.0}, rm[NA], hm[NA];
    static double r[NS][NA], h[NS][NA];
    int n = 3;
    if (argc > argi) {
        n = argc - argi > NA ? NA : argc - argi;
        for (int k = 0; k < n; ++k)
            a[k] = atof(argv[argi + k]);
    }
    unsigned seed0 = getenv("GF_TEST_SEED") ? (unsigned)atoi(getenv("GF_TEST_SEED")) : 1u;
    double t0 = runner_now_s();
    for (int s = 0; s < ns; ++s)
        sweep(a, n, seed0 + (unsigned)s, r[s], h[s]);
    ensemble(a, n, ns, r, h, rm, hm);
    for (int k = 0; k < n; ++k)
        if (a[k] <= 0.5)
            GF_CHECK_REL(hm[k], a[k], 0.10); /* trapezoid: H_inf = H0 */
    double lambda1, lambda2;
    gf_measure_fit_runout(a, rm, n, 2.5, &lambda1, &lambda2);
    printf("fit on the mean of %d seed(s): lambda1 = %.3f (published 1.2-1.8), lambda2 = %.3f (published 1.9-2.3); "
           "%.0f s wall\n",
           ns, lambda1, lambda2, runner_now_s() - t0);
    GF_CHECK(lambda1 >= 1.2 * 0.85 && lambda1 <= 1.8 * 1.15);
    if (!isnan(lambda2))
        GF_CHECK(lambda2 >= 1.9 * 0.85 && lambda2 <= 2.3 * 1.15);
    return gf_test_finish();
}
