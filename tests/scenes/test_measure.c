/*
 * Measurement helpers on synthetic grains and data with known answers
 * (gf_measure.h). Each check is against an analytic value.
 */
#include <math.h>
#include <stdio.h>

#include "core/gf_rng.h"
#include "gf_test.h"
#include "scenes/gf_measure.h"

static gf_particles *lattice(gf_ctx *ctx, double r, int nx, int ny, int nz, double spacing)
{
    gf_particles *p = NULL;
    gf_particles_create(ctx, 64, &p);
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
            for (int k = 0; k < nz; ++k)
                gf_particles_add(ctx, p, (i + 0.5) * spacing, (j + 0.5) * spacing, (k + 0.5) * spacing, r, 2500, 0,
                                 NULL);
    return p;
}

/* Spherical caps: a sphere cut by slabs sums to 4/3 pi r^3; the lower half is half of it. */
static void test_slab_volumes_add_up(void)
{
    double r = 0.3, full = 4.0 / 3.0 * M_PI * r * r * r, sum = 0.0;
    for (int k = 0; k < 7; ++k)
        sum += gf_measure_sphere_slab_volume_m3(0.1, r, -0.3 + 0.1 * k, -0.2 + 0.1 * k);
    GF_CHECK_REL(sum, full, 1e-12);
    GF_CHECK_REL(gf_measure_sphere_slab_volume_m3(1.0, r, 0.0, 1.0), 0.5 * full, 1e-12);
}

/* Jittered cubic lattice (radius 0.45 D, centres moved by up to 0.05 D, so
 * the grains sit at random against the sampling lattice) in a domain periodic
 * in x and z: over the whole domain Phi = N V / V_box exactly; the sampled
 * estimate at h = D/20 must be within 0.3 %, also for a box straddling the
 * periodic images (same exact value: every grain is inside the y range). */
static void test_sampled_fraction_of_jittered_lattice(void)
{
    gf_ctx ctx = {0};
    gf_rng rng;
    gf_rng_seed(&rng, 3);
    double D = 0.01;
    gf_particles *p = lattice(&ctx, 0.45 * D, 6, 6, 6, D);
    for (size_t i = 0; i < p->n_local; ++i) {
        p->x_m[i] += gf_rng_range(&rng, -0.05, 0.05) * D;
        p->y_m[i] += gf_rng_range(&rng, -0.05, 0.05) * D;
        p->z_m[i] += gf_rng_range(&rng, -0.05, 0.05) * D;
    }
    double exact = 216 * 4.0 / 3.0 * M_PI * pow(0.45 * D, 3) / (216 * D * D * D);
    gf_measure_domain dom = {{0, 0, 0}, {6 * D, 6 * D, 6 * D}, {1, 0, 1}};
    double lo[3] = {0, 0, 0}, hi[3] = {6 * D, 6 * D, 6 * D};
    GF_CHECK_REL(gf_measure_solid_fraction_box(p, &dom, lo, hi, D / 20, 0), exact, 3e-3);
    double lo2[3] = {-2.3 * D, 0, 2.9 * D}, hi2[3] = {3.7 * D, 6 * D, 8.9 * D};
    GF_CHECK_REL(gf_measure_solid_fraction_box(p, &dom, lo2, hi2, D / 20, 0), exact, 3e-3);
    gf_particles_destroy(&p);
}

/* Slab profile of the lattice: layer-averaged Phi = pi/6 on slabs of one
 * cell; velocity u_x = 2 y_centre (a shear) is returned exactly per layer. */
static void test_profile_of_sheared_lattice(void)
{
    gf_ctx ctx = {0};
    double D = 0.01;
    gf_particles *p = lattice(&ctx, D / 2, 4, 5, 4, D);
    for (size_t i = 0; i < p->n_local; ++i)
        p->vx_m_s[i] = 2.0 * p->y_m[i];
    gf_measure_domain dom = {{0, 0, 0}, {4 * D, 5 * D, 4 * D}, {1, 0, 1}};
    double phi[5], u[15];
    GF_CHECK_OK(gf_measure_profile_y(&ctx, p, &dom, 0.0, D, 5, phi, u), &ctx);
    for (int k = 0; k < 5; ++k) {
        GF_CHECK_REL(phi[k], M_PI / 6, 1e-12);
        GF_CHECK_REL(u[3 * k], 2.0 * (k + 0.5) * D, 1e-12);
    }
    /* Q_g = (1/L) sum V_i u_i: 16 grains per layer */
    double v = M_PI * D * D * D / 6, q = 0.0;
    for (int k = 0; k < 5; ++k)
        q += 16 * v * 2.0 * (k + 0.5) * D;
    GF_CHECK_REL(gf_measure_grain_flow_rate(p, &dom), q / (4 * D), 1e-12);
    /* bed height: plateau pi/6 up to y = 5D, half level crossed between the last slab centre and the top */
    double bh = gf_measure_bed_height_m(phi, 5, 0.0, D, 0.5);
    GF_CHECK_ABS(bh, 4.5 * D, 1e-12); /* top slab still full: returns its centre */
    double phi2[7] = {0.5, 0.6, 0.6, 0.6, 0.3, 0.0, 0.0};
    GF_CHECK_ABS(gf_measure_bed_height_m(phi2, 7, 0.0, D, 0.5), 4.5 * D, 1e-12); /* 0.3 = level exactly */
    gf_particles_destroy(&p);
}

/* Deposit: a staircase pile 10 D long and a single saltating grain at x = 20 D.
 * The front must be the end of the pile (10 D), not the lone grain. */
static void test_front_ignores_saltating_grain(void)
{
    gf_ctx ctx = {0};
    double D = 0.01, W = 3 * D;
    gf_particles *p = NULL;
    gf_particles_create(&ctx, 64, &p);
    for (int b = 0; b < 10; ++b)
        for (int layer = 0; layer < 10 - b; ++layer)
            for (int k = 0; k < 3; ++k)
                gf_particles_add(&ctx, p, (b + 0.5) * D, (layer + 0.5) * D, (k + 0.5) * D, D / 2, 2500, 0, NULL);
    gf_particles_add(&ctx, p, 20.5 * D, 0.5 * D, 1.5 * D, D / 2, 2500, 0, NULL);
    gf_measure_domain dom = {{0, 0, 0}, {40 * D, 20 * D, W}, {0, 0, 1}};
    gf_measure_deposit dep;
    double top[40], solid[40];
    GF_CHECK_OK(gf_measure_deposit_profile(&ctx, p, &dom, 0.0, D, 40, 0.25 * D, 1, top, solid, &dep), &ctx);
    GF_CHECK_ABS(dep.front_m, 10 * D, 1e-12);
    GF_CHECK_ABS(dep.height_m, 10 * D, 1e-12);
    GF_CHECK_REL(solid[0], 10 * M_PI / 6 * D, 1e-12); /* 10 layers of 3 grains over D x 3D */
    gf_particles_destroy(&p);
}

/* Extent of a profile: exact on a linear flank (the interpolation is linear),
 * 0 when the first bin is below the depth, the whole length when none is. */
static void test_profile_extent(void)
{
    enum { N = 40 };
    const double dx = 0.01, L = 30.3 * dx, H = 12.0 * dx;
    double h[N];
    for (int i = 0; i < N; ++i)
        h[i] = fmax(0.0, H * (1.0 - (i + 0.5) * dx / L));
    GF_CHECK_ABS(gf_measure_profile_extent(h, N, dx, 2.0 * dx), L * (1.0 - 2.0 / 12.0), 1e-12);
    GF_CHECK_ABS(gf_measure_profile_extent(h, N, dx, 13.0 * dx), 0.0, 0.0);
    GF_CHECK_ABS(gf_measure_profile_extent(h, N, dx, -1.0), N * dx, 0.0);
}

/* mu(I) with I0 fixed is linear in (mu1, mu2): exact recovery of Jop et al.
 * (2006) glass-bead values from noiseless points. */
static void test_mu_of_I_fit_recovers_jop(void)
{
    gf_ctx ctx = {0};
    double I[6] = {0.01, 0.05, 0.1, 0.2, 0.3, 0.5}, mu[6], mu1, mu2, I0 = 0.279;
    for (int k = 0; k < 6; ++k)
        mu[k] = 0.38186 + (0.64347 - 0.38186) / (I0 / I[k] + 1.0);
    GF_CHECK_OK(gf_measure_fit_mu_of_I(&ctx, I, mu, 6, I0, &mu1, &mu2), &ctx);
    GF_CHECK_ABS(mu1, 0.38186, 1e-10);
    GF_CHECK_ABS(mu2, 0.64347, 1e-10);
    GF_CHECK(gf_measure_fit_mu_of_I(&ctx, I, mu, 1, I0, &mu1, &mu2) == GF_ERR_ARG);
}

/* Janssen profile with the thesis' plateau (700 Pa) and lambda = S/(f_p K P_m)
 * for f_p K = 0.30, S = 0.01 m2, P_m = 0.4 m, plus 2 % noise: lambda within 3 %. */
static void test_janssen_fit_recovers_lambda(void)
{
    gf_ctx ctx = {0};
    gf_rng rng;
    gf_rng_seed(&rng, 5);
    double lambda = 0.01 / (0.30 * 0.4), d[60], s[60];
    for (int k = 0; k < 60; ++k) {
        d[k] = 0.01 * (k + 0.5);
        s[k] = 700.0 * (1.0 - exp(-d[k] / lambda)) * (1.0 + 0.02 * gf_rng_normal(&rng));
    }
    double s_inf, l_fit, rms;
    GF_CHECK_OK(gf_measure_fit_janssen(&ctx, d, s, 60, 0.005, 1.0, &s_inf, &l_fit, &rms), &ctx);
    GF_CHECK_REL(l_fit, lambda, 0.03);
    GF_CHECK_REL(s_inf, 700.0, 0.02);
}

/* Run-out law coefficients from exact points of Lube et al. (2005). */
static void test_runout_fit(void)
{
    double a[5] = {0.5, 1.0, 1.5, 3.0, 6.0}, r[5], l1, l2;
    for (int k = 0; k < 5; ++k)
        r[k] = a[k] < 1.8 ? 1.2 * a[k] : 1.9 * pow(a[k], 2.0 / 3.0);
    gf_measure_fit_runout(a, r, 5, 1.8, &l1, &l2);
    GF_CHECK_REL(l1, 1.2, 1e-12);
    GF_CHECK_REL(l2, 1.9, 1e-12);
}

/* Method of planes on a synthetic stack: one grain per slab (A = 1 m2,
 * dy = 1 m) pushed by fx = -1 N, fy = +2 N; the plane at slab centre k has
 * (n - 1 - k) grains above plus half of its own slab: tau = n - k - 1/2,
 * sigma = 2 (n - k - 1/2). Two extra grains in slab 0 with u = +-(1, 1) m/s
 * and m = m0 carry a kinetic flux sum m u'x u'y = 2 m0 over V = 1 m3. */
static void test_stress_planes_on_a_stack(void)
{
    gf_ctx ctx = {0};
    gf_particles *p = NULL;
    gf_particles_create(&ctx, 16, &p);
    for (int k = 0; k < 4; ++k) {
        size_t i;
        gf_particles_add(&ctx, p, 0.5, k + 0.5, 0.5, 0.1, 1000, 0, &i);
        p->fx_N[i] = -1.0, p->fy_N[i] = 2.0;
    }
    size_t a, b;
    gf_particles_add(&ctx, p, 0.2, 0.3, 0.5, 0.1, 1000, 0, &a);
    gf_particles_add(&ctx, p, 0.8, 0.3, 0.5, 0.1, 1000, 0, &b);
    p->vx_m_s[a] = p->vy_m_s[a] = 1.0, p->vx_m_s[b] = p->vy_m_s[b] = -1.0;
    double m0 = p->mass_kg[a];
    gf_measure_domain dom = {{0, 0, 0}, {1, 4, 1}, {1, 0, 1}};
    double tau[4], sig[4];
    GF_CHECK_OK(gf_measure_stress_planes(&ctx, p, &dom, 0.0, 1.0, 4, tau, sig), &ctx);
    for (int k = 1; k < 4; ++k) {
        GF_CHECK_ABS(tau[k], 4 - k - 0.5, 1e-12);
        GF_CHECK_ABS(sig[k], 2 * (4 - k - 0.5), 1e-12);
    }
    /* slab 0: mean velocity 0 (grain 0 at rest, the pair opposite): kinetic terms 2 m0 */
    GF_CHECK_ABS(tau[0], 3.5 - 2 * m0, 1e-12);
    GF_CHECK_ABS(sig[0], 7.0 + 2 * m0, 1e-12);
    gf_particles_destroy(&p);
}

/* Bagnold profile: exact recovery of A and the slip velocity B. */
static void test_bagnold_fit(void)
{
    gf_ctx ctx = {0};
    double h = 0.1, y[20], u[20], A, B, rel;
    for (int k = 0; k < 20; ++k) {
        y[k] = h * (k + 0.5) / 20;
        u[k] = 3.0 * (pow(h, 1.5) - pow(h - y[k], 1.5)) + 0.01;
    }
    GF_CHECK_OK(gf_measure_fit_bagnold(&ctx, y, u, 20, h, &A, &B, &rel), &ctx);
    GF_CHECK_REL(A, 3.0, 1e-9);
    GF_CHECK_REL(B, 0.01, 1e-6);
    GF_CHECK(rel < 1e-9);
}

/* The seed's chute reading (2.23) of slab profiles: a bed of 12 slabs of D at phi = 0.6 has its top at 12 D
 * (half-plateau between the centres of slabs 11 and 12), so h = 11.5 D above the glued layer's top; a
 * Bagnold profile sampled at the slab centres (y = k D from D/2) is recovered exactly, and I follows from its
 * amplitude with the bulk phi (reading the samples half a slab higher would give A 5.5 % high). */
static void test_chute_reading(void)
{
    gf_ctx ctx = {0};
    enum { N = 20 };
    const double D = 0.01, g = 9.81, th = 25.0 * M_PI / 180.0, A = 40.0, B = 0.02, h = 11.5 * D;
    double phi[N] = {0}, u[N] = {0};
    for (int k = 0; k < 12; ++k)
        phi[k] = 0.6, u[k] = A * (pow(h, 1.5) - pow(h - k * D, 1.5)) + B;
    gf_measure_chute c;
    GF_CHECK_OK(gf_measure_chute_bagnold(&ctx, phi, u, N, D, g, th, &c), &ctx);
    GF_CHECK_REL(c.h_m, h, 1e-12);
    GF_CHECK_REL(c.A, A, 1e-9);
    GF_CHECK_REL(c.B, B, 1e-7);
    GF_CHECK_REL(c.phi_bulk, 0.6, 1e-12);
    GF_CHECK_REL(c.I, 1.5 * A * D / sqrt(0.6 * g * cos(th)), 1e-9);
    GF_CHECK_REL(c.slip_over_h, -B / (1.5 * A * sqrt(h)) / h, 1e-7);
    GF_CHECK(c.rel_rms < 1e-9);
    double thin[N] = {0.6, 0.6, 0.6}; /* a bed too thin for a bulk fraction is refused */
    GF_CHECK(gf_measure_chute_bagnold(&ctx, thin, u, N, D, g, th, &c) != GF_OK);
}

int main(void)
{
    test_slab_volumes_add_up();
    test_sampled_fraction_of_jittered_lattice();
    test_profile_of_sheared_lattice();
    test_front_ignores_saltating_grain();
    test_profile_extent();
    test_mu_of_I_fit_recovers_jop();
    test_janssen_fit_recovers_lambda();
    test_runout_fit();
    test_bagnold_fit();
    test_chute_reading();
    test_stress_planes_on_a_stack();
    return gf_test_finish();
}
