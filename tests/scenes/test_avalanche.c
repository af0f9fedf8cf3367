/*
 * Dry granular flow on a rough periodic incline: mu(I) and the Bagnold
 * profile (Izard 2014 §2.1.3.3, (2.21)-(2.23)).
 *
 * Grains as the thesis' chute: R = 5 mm +- 10 %, rho_p = 2500, mu_c = 0.25,
 * eps = 0.5, on glued half-grains, prepared at theta = 0 and tilted at t = 0.
 * Unsteady run as the seed's: a bed 34 D deep (16 000 grains settled on its
 * 0.1 x 0.4 m footprint at Phi ~ 0.6) and the thesis' dry-run contact
 * t_c = 1e-4 s = 3.1e-3 sqrt(D/g) (t_c is not stated for the chute;
 * the collapse uses it), run for 76 sqrt(D/g), until the bulk I reaches the
 * thesis' 0.25. What moves the fitted mu2 (mu1 within 0.29-0.36 throughout):
 *   bed 12 D, t_c 0.01, I <= 0.25 reached at t ~ 13:   mu2 0.616 (seed 21),
 *     0.632 (5), 0.559 (77): the I range is swept in a strongly accelerating
 *     start and the thin bed shears up to I ~ 0.5;
 *   bed 12 D, t_c 3e-3:   mu2 0.799 (seed 21), 0.735 (5), mu1 0.291, 0.309;
 *   bed 34 D, t_c 3.1e-3: mu2 0.654 over 40 sqrt(D/g) (bulk I <= 0.15),
 *     0.641 over 76 (I up to 0.25, mu1 0.334), 0.647 over 80.
 * With the seed's depth and stiffness the transient fit lands on the seed's
 * steady mu2 (0.64), not on its unsteady 0.76: mu2 is an extrapolation at
 * fixed I0 = 0.3 from I <= 0.25 (mu(0.25) = mu1 + 0.45 (mu2 - mu1)), so 0.03
 * on mu2 is 0.014 on the measured mu; the row stays open.
 * Steady runs keep a 12 D bed (cost; at t_c = 0.01 a 24 D bed at 25 deg flows
 * at I_bulk = 0.233 against ~0.22 at 12 D) with the thesis' t_c (at 25 deg
 * I_bulk rises from ~0.22 at t_c = 0.01 to 0.257).
 *
 * Stresses as the seed defines them (Izard 2014 (2.16)-(2.20)):
 * the full tensor sigma_G = sigma^p + sigma^k (contact virial with the
 * branch vector shared among the slabs it crosses, plus the kinetic stress
 * about the slab mean velocity; gf_sim_stress_tensor_slabs) on slabs
 * 1 D thick, averaged over windows of 2 sqrt(D/g) (4 snapshots);
 * P_G = -tr(sigma_G)/3, tau = the x-y (flow-plane) shear component,
 * mu = |tau|/P_G, I = |gamma_dot| D/sqrt(P_G/rho_p) with |gamma_dot| =
 * |du/dy| (simple shear) from the window-averaged velocity profile;
 * mu(I) = mu1 + (mu2 - mu1)/(I0/I + 1) with I0 = 0.3 fixed, the thesis' fit.
 * Bulk = planes from 2 D above the glued layer to 3 D below the surface.
 *
 * Modes (argv[1]):
 *   unsteady  (default suite) theta = 40 deg, the accelerating transient
 *             sweeps I; fitted mu1, mu2 vs 0.34, 0.76 within +-0.03 (row 7).
 *   steady    (slow) theta = 22.5, 25, 27.5 deg after 200 sqrt(D/g), averaged
 *             over 50: per angle I from the Bagnold amplitude (hydrostatic
 *             P, measured Phi) and mu = tan(theta), the seed's per-angle
 *             fits (gf_measure_chute_bagnold); mu1, mu2 vs 0.29, 0.64 within
 *             +-0.02 (row 8; Debian LAMMPS from the same state, read the same
 *             way, gives 0.281, 0.703 as grainflow's 0.280, 0.703:
 *             workflows/bench/lammps_avalanche.sh); the
 *             coarse-grained tau/P_G vs I fit is printed (the thesis finds
 *             it close to the unsteady law, above the profile fits);
 *             Bagnold profile (2.23) fits the velocity with rms < 10 % of
 *             the surface speed; slip length lambda/h reported. (20 deg
 *             arrests a 12 D bed: below h_stop.)
 *   length    (slow) theta = 25 deg, L = 5 D and 10 D after 400 sqrt(D/g),
 *             averaged over 100, packing seeds 1-5 (GF_TEST_SEEDS): the
 *             seed means of Q_g agree within 5 % (Izard §4.1.2.2 domain
 *             tests, Table 4.1).
 * GF_TEST_TC overrides t_c sqrt(g/D), GF_TEST_SEED the packing seed, GF_TEST_EPS the restitution;
 * GF_TEST_BED the steady bed depth / D, GF_TEST_ANGLE runs one steady angle;
 * GF_TEST_VERBOSE prints the transient, GF_TEST_DEBUG the stress components.
 */
#include <stdlib.h>

#include "scene_runner.h"
#include "scenes/gf_measure.h"
#include "stages/gf_post_stats.h"

enum { NS = 64 }; /* slabs of 1 D: up to a 50 D deep bed with its 10 D headroom */

typedef struct flow {
    gf_sim *sim;
    double D, theta, rho, dy, tg;
    gf_measure_domain dom;
} flow;

static int flow_open(flow *f, double theta_deg, double length_over_D, double bed_over_D, unsigned seed,
                     double tc_nd)
{
    gf_ctx *ctx = calloc(1, sizeof *ctx);
    gf_run_spec spec;
    runner_dry_spec(&spec, "avalanche");
    spec.seed = getenv("GF_TEST_SEED") ? (unsigned)atoi(getenv("GF_TEST_SEED")) : seed;
    spec.contact.restitution = getenv("GF_TEST_EPS") ? atof(getenv("GF_TEST_EPS")) : 0.5;
    spec.contact.friction = 0.25;
    spec.contact.wall_friction = 0.25;
    spec.contact.t_contact_nd = getenv("GF_TEST_TC") ? atof(getenv("GF_TEST_TC")) : tc_nd;
    gf_run_spec_set_param(ctx, &spec, "incline_deg", theta_deg);
    gf_run_spec_set_param(ctx, &spec, "length_over_D", length_over_D);
    gf_run_spec_set_param(ctx, &spec, "width_over_D", 6.0);
    gf_run_spec_set_param(ctx, &spec, "bed_height_over_D", bed_over_D);
    gf_run_spec_set_param(ctx, &spec, "height_over_D", bed_over_D + 10.0);
    f->sim = runner_create(ctx, &spec);
    if (!f->sim)
        return 0;
    f->D = spec.grains.diameter_m, f->theta = theta_deg * M_PI / 180.0, f->rho = spec.grains.density_kg_m3;
    f->dy = f->D, f->tg = sqrt(f->D / spec.gravity_m_s2);
    gf_sim_box(f->sim, f->dom.lo_m, f->dom.hi_m, f->dom.periodic);
    return 1;
}

static void flow_close(flow *f)
{
    gf_ctx *ctx = gf_sim_ctx(f->sim);
    gf_sim_destroy(&f->sim);
    free(ctx);
}

static void flow_advance(flow *f, double dt_nd)
{
    long n = (long)ceil(dt_nd * f->tg / gf_sim_dt_s(f->sim));
    GF_CHECK_OK(gf_sim_advance(f->sim, n), gf_sim_ctx(f->sim));
}

static void flow_profile(flow *f, double *phi, double *ux)
{
    double u[3 * NS];
    gf_measure_profile_y(gf_sim_ctx(f->sim), gf_sim_particles(f->sim), &f->dom, 0.0, f->dy, NS, phi, u);
    for (int k = 0; k < NS; ++k)
        ux[k] = isnan(u[3 * k]) ? 0.0 : u[3 * k];
}

static int bed_top_slab(const double *phi)
{
    double bh = gf_measure_bed_height_m(phi, NS, 0.0, 1.0, 0.5); /* in slab units */
    return (int)floor(bh);
}

/* Window-averaged profiles: solid fraction, velocity, shear and normal stress on planes at slab centres. */
typedef struct window {
    double phi[NS], u[NS], tau[NS], sig[NS]; /* sig: P_G */
    int n;
} window;

static void window_add(flow *f, window *w)
{
    double phi[NS], u[NS], tau[NS], sig[NS], S[6 * NS];
    flow_profile(f, phi, u);
    GF_CHECK_OK(gf_sim_stress_tensor_slabs(f->sim, 0.0, f->dy, NS, S), gf_sim_ctx(f->sim));
    for (int k = 0; k < NS; ++k) { /* compression-positive S: P_G = tr(S)/3, tau = -S_xy */
        sig[k] = (S[6 * k] + S[6 * k + 1] + S[6 * k + 2]) / 3.0;
        tau[k] = -S[6 * k + 3];
    }
    if (getenv("GF_TEST_DEBUG")) { /* cross-check against the method of planes (same yy and xy rows) */
        double tp[NS], sp[NS];
        gf_measure_stress_planes(gf_sim_ctx(f->sim), gf_sim_particles(f->sim), &f->dom, 0.0, f->dy, NS, tp, sp);
        for (int k = 1; k < 12; ++k)
            printf("    k=%d planes: tau %.1f syy %.1f | tensor: sxx %.1f syy %.1f szz %.1f -sxy %.1f\n", k, tp[k],
                   sp[k], S[6 * k], S[6 * k + 1], S[6 * k + 2], tau[k]);
    }
    for (int k = 0; k < NS; ++k)
        w->phi[k] += phi[k], w->u[k] += u[k], w->tau[k] += tau[k], w->sig[k] += sig[k];
    w->n++;
}

/* Bulk (I, mu) points of a window; returns their number. */
static int window_points(const flow *f, window *w, double *I, double *mu, int max)
{
    for (int k = 0; k < NS; ++k)
        w->phi[k] /= w->n, w->u[k] /= w->n, w->tau[k] /= w->n, w->sig[k] /= w->n;
    int top = bed_top_slab(w->phi), n = 0;
    for (int k = 2; k <= top - 3 && k < NS - 1 && n < max; ++k) {
        if (w->sig[k] <= 0.0)
            continue;
        double gd = (w->u[k + 1] - w->u[k - 1]) / (2.0 * f->dy);
        I[n] = fabs(gd) * f->D / sqrt(w->sig[k] / f->rho);
        mu[n] = fabs(w->tau[k]) / w->sig[k];
        ++n;
    }
    return n;
}

static void test_unsteady_40deg(void)
{
    flow f;
    double t0 = runner_now_s();
    /* the seed's bed: 16 000 grains settled on a 0.1 x 0.4 m footprint, ~34 D deep at Phi 0.6; its
     * dry-run contact t_c = 1e-4 s = 3.1e-3 sqrt(D/g) */
    if (!flow_open(&f, 40.0, 6.0, 34.0, 21, 3.1e-3))
        return;
    double t1 = runner_now_s();
    enum { MAXP = 4000 };
    static double I[MAXP], mu[MAXP];
    int n = 0;
    for (int win = 0; win < 38; ++win) { /* 76 sqrt(D/g): the bulk I reaches the thesis' 0.25 */
        window w = {0};
        for (int s = 0; s < 4; ++s) {
            flow_advance(&f, 0.5);
            window_add(&f, &w);
        }
        double Ib[NS], mb[NS];
        int m = window_points(&f, &w, Ib, mb, NS);
        double ib = 0.0, mbar = 0.0;
        for (int q = 0; q < m; ++q)
            ib += Ib[q] / m, mbar += mb[q] / m;
        if (getenv("GF_TEST_VERBOSE"))
            printf("  t = %.0f: bulk <I> = %.3f, <mu> = %.3f (%d planes), surface u = %.2f sqrt(gD)\n", 2.0 * win + 1,
                   ib, mbar, m, w.u[bed_top_slab(w.phi) - 1] / sqrt(9.81 * f.D));
        for (int q = 0; q < m && n < MAXP; ++q)
            if (Ib[q] > 1e-3 && Ib[q] < 0.25) /* the thesis' range [0, 0.25] */
                I[n] = Ib[q], mu[n] = mb[q], ++n;
    }
    double mu1 = NAN, mu2 = NAN;
    GF_CHECK_OK(gf_measure_fit_mu_of_I(gf_sim_ctx(f.sim), I, mu, n, 0.3, &mu1, &mu2), gf_sim_ctx(f.sim));
    printf("unsteady 40 deg: %d (I, mu) points, mu1 = %.3f (thesis 0.34), mu2 = %.3f (thesis 0.76), "
           "%zu grains, build %.1f s, run %.1f s\n",
           n, mu1, mu2, gf_sim_particles(f.sim)->n_local, t1 - t0, runner_now_s() - t1);
    GF_CHECK_ABS(mu1, 0.34, 0.03);
    GF_CHECK_ABS(mu2, 0.76, 0.03);
    flow_close(&f);
}

/* Steady flow at theta: returns bulk I and tau/P_G (means over the bulk slabs
 * and the averaging window), the seed's I from the Bagnold amplitude, the
 * time-averaged Q_g, and prints the Bagnold fit. */
static void steady(double theta_deg, double length_over_D, double tc_nd, double t_spin_nd, double t_avg_nd,
                   unsigned seed, double *I_bulk, double *mu_bulk, double *I_profile, double *q_mean,
                   double *bagnold_rms, double *slip_over_h)
{
    flow f;
    double t0 = runner_now_s();
    *I_bulk = *mu_bulk = *I_profile = *q_mean = *bagnold_rms = *slip_over_h = NAN;
    double bed = getenv("GF_TEST_BED") ? atof(getenv("GF_TEST_BED")) : 12.0;
    if (!flow_open(&f, theta_deg, length_over_D, bed, seed, tc_nd))
        return;
    if (getenv("GF_TEST_SPIN"))
        t_spin_nd = atof(getenv("GF_TEST_SPIN"));
    if (getenv("GF_TEST_AVG"))
        t_avg_nd = atof(getenv("GF_TEST_AVG"));
    for (double t = 0.0; t < t_spin_nd - 1e-9; t += 25.0) { /* spin-up, Q_g(t) printed to judge steadiness */
        flow_advance(&f, fmin(25.0, t_spin_nd - t));
        if (getenv("GF_TEST_VERBOSE")) {
            double v[4];
            gf_scene_find("avalanche")->diagnose(f.sim, v);
            printf("    t = %.0f sqrt(D/g): Q_g = %.4e m3/s\n", fmin(t + 25.0, t_spin_nd), v[0]);
        }
    }
    window w = {0};
    double q = 0.0;
    int samples = (int)(t_avg_nd / 1.0);
    for (int s = 0; s < samples; ++s) {
        flow_advance(&f, 1.0);
        window_add(&f, &w);
        double v[4];
        gf_scene_find("avalanche")->diagnose(f.sim, v);
        q += v[0] / samples;
    }
    double Ib[NS], mb[NS];
    int m = window_points(&f, &w, Ib, mb, NS);
    int top = bed_top_slab(w.phi);
    double isum = 0.0, msum = 0.0;
    for (int k = 0; k < m; ++k)
        isum += Ib[k] / m, msum += mb[k] / m;
    *I_bulk = isum;
    *mu_bulk = msum;
    *q_mean = q;
    printf("  bulk mu = tau/P = %.3f (tan theta = %.3f)\n", msum, tan(theta_deg * M_PI / 180.0));
    /* the seed's per-angle reading: Bagnold fit over the flowing layer, I from its amplitude */
    gf_measure_chute c;
    if (gf_measure_chute_bagnold(gf_sim_ctx(f.sim), w.phi, w.u, NS, f.D, f.D / (f.tg * f.tg), f.theta, &c) == GF_OK)
        *bagnold_rms = c.rel_rms, *slip_over_h = c.slip_over_h, *I_profile = c.I;
    double h = c.h_m;
    printf("steady %.1f deg, L = %.0f D: I_bulk = %.4f (%d slabs), I from the Bagnold fit = %.4f, "
           "Q_g = %.4e m3/s, h = %.2f D, Bagnold rms %.3f, lambda/h = %.3f, %.1f s\n",
           theta_deg, length_over_D, *I_bulk, m, *I_profile, q, h / f.D, *bagnold_rms, *slip_over_h,
           runner_now_s() - t0);
    printf("  u/sqrt(gD) by slab:");
    for (int k = 0; k <= top && k < NS; ++k)
        printf(" %.2f", w.u[k] / sqrt(9.81 * f.D));
    printf("\n");
    fflush(stdout);
    flow_close(&f);
}

/* Row 8 as the seed measures it (§2.1.3.3): per angle, I from the amplitude of the
 * Bagnold profile with hydrostatic pressure and the measured Phi, mu = tan(theta)
 * (steady uniform flow); (2.21) fitted at I0 = 0.3 over the angles. The thesis
 * finds these "slightly below" the coarse-grained mu(I) of its Fig. 2.10, which is
 * "almost identical" to the unsteady law: the coarse-grained fit (tau/P_G against
 * the stress-based I) is printed for that comparison. */
static void test_steady_mu_of_I(void)
{
    /* 20 deg arrests a 12 D bed (h_stop), so the angles start above it */
    double th[3] = {22.5, 25.0, 27.5}, I[3], mu[3], Ip[3], Ik[3], muk[3], Ipk[3], tk[3], q, rms, slip;
    int n = 0;
    for (int k = 0; k < 3; ++k) {
        if (getenv("GF_TEST_ANGLE") && fabs(th[k] - atof(getenv("GF_TEST_ANGLE"))) > 1e-9)
            continue;
        /* the thesis' t_c = 1e-4 s; Q_g (GF_TEST_VERBOSE) is flat within ~7 % from 100-125 sqrt(D/g)
         * on at 22.5 and 25 deg, and from 225 on at 27.5 deg (within 3 % up to 600; I averaged over
         * [600, 650] is 0.383 against 0.379 over [200, 250], so the spin-up is long enough) */
        steady(th[k], 6.0, 3.1e-3, 200.0, 50.0, 31, &I[k], &mu[k], &Ip[k], &q, &rms, &slip);
        if (I[k] > 1e-3) { /* flowing */
            Ik[n] = I[k], muk[n] = mu[k], Ipk[n] = Ip[k], tk[n] = tan(th[k] * M_PI / 180.0), ++n;
            GF_CHECK(rms < 0.10);
        }
    }
    double mu1 = NAN, mu2 = NAN, c1 = NAN, c2 = NAN;
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_measure_fit_mu_of_I(&ctx, Ipk, tk, n, 0.3, &mu1, &mu2), &ctx);
    GF_CHECK_OK(gf_measure_fit_mu_of_I(&ctx, Ik, muk, n, 0.3, &c1, &c2), &ctx);
    printf("steady fit, seed's method (%d flowing angles): mu1 = %.3f (thesis 0.29), mu2 = %.3f (thesis 0.64); "
           "coarse-grained tau/P_G vs I: mu1 = %.3f, mu2 = %.3f (thesis: close to the unsteady 0.34, 0.76)\n",
           n, mu1, mu2, c1, c2);
    GF_CHECK_ABS(mu1, 0.29, 0.02);
    GF_CHECK_ABS(mu2, 0.64, 0.02);
}

/* Mean and standard error of x[0..n) (gf_post_stats.h's mean and sd). */
static void mean_sem(const double *x, int n, double *mean, double *sem)
{
    double sd;
    gf_stats_mean_std(x, (size_t)n, mean, &sd);
    *sem = n > 1 ? sd / sqrt(n) : 0.0;
}

/* Q_g does not depend on the periodic length (Izard 2014 §4.1.2.2, Table 4.1), on seed means: one seed
 * decides nothing, the random base and packing scatter Q_g by 3.7 % (sd) at L = 5 D, and the single-seed
 * comparison this test made (seed 31) read 0.899 where seeds 1-5 read 0.995, 0.929, 1.061, 0.996, 1.083. */
static void test_flow_rate_independent_of_length(void)
{
    enum { MAX_SEEDS = 16 };
    int n = getenv("GF_TEST_SEEDS") ? atoi(getenv("GF_TEST_SEEDS")) : 5;
    n = n < 1 ? 1 : n > MAX_SEEDS ? MAX_SEEDS : n;
    double q5[MAX_SEEDS], q10[MAX_SEEDS], I, m, p, r, s, m5, e5, m10, e10;
    /* 400 sqrt(D/g) of spin-up: at L = 5 D, Q_g(t) overshoots by ~12 % between
     * t = 150 and 250 before settling (GF_TEST_VERBOSE prints it); averaged over [400, 500] */
    for (int k = 0; k < n; ++k) {
        steady(25.0, 5.0, 0.01, 400.0, 100.0, (unsigned)(k + 1), &I, &m, &p, &q5[k], &r, &s);
        steady(25.0, 10.0, 0.01, 400.0, 100.0, (unsigned)(k + 1), &I, &m, &p, &q10[k], &r, &s);
        printf("seed %d: Q_g(L = 10 D) / Q_g(L = 5 D) = %.4f\n", k + 1, q10[k] / q5[k]);
    }
    mean_sem(q5, n, &m5, &e5);
    mean_sem(q10, n, &m10, &e10);
    printf("%d seeds: Q_g(5 D) = %.4e +- %.1e, Q_g(10 D) = %.4e +- %.1e m3/s (sem); ratio %.4f +- %.4f\n", n, m5, e5,
           m10, e10, m10 / m5, m10 / m5 * sqrt(e5 * e5 / (m5 * m5) + e10 * e10 / (m10 * m10)));
    GF_CHECK_REL(m10, m5, 0.05);
}

int main(int argc, char **argv)
{
    static const gf_test_mode studies[] = {{"unsteady", test_unsteady_40deg}, {"steady", test_steady_mu_of_I},
                                           {"length", test_flow_rate_independent_of_length}};
    gf_test_run_mode(studies, 3, argc > 1 ? argv[1] : "unsteady"); /* an unknown name runs nothing */
    return gf_test_finish();
}
