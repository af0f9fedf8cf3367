/*
 * The marker forcing of the resolved tier (coupling/gf_ibm_markers.h) on its own:
 *  - the three-point kernel of Roma, Peskin & Berger (1999) keeps, at any
 *    offset r, sum_k phi(r - k) = 1, sum_k (r - k) phi(r - k) = 0 and
 *    sum_k phi(r - k)^2 = 1/2 (to 1e-14): the conditions it is built on;
 *  - the golden-angle markers are unit vectors with their centroid at the
 *    centre (|mean| < 1/N), about one per dx^2 (201 at R = 4 dx);
 *  - a sphere translating through fluid at rest: the force spread on the
 *    faces, rho sum_faces f dx^3, is minus the grain's marker force to 1e-12
 *    (the kernel's weights sum to one, rescaled where a wall cuts the
 *    stencil), in the middle of a walled box, against a wall and across a
 *    periodic boundary; and each of the sweeps lowers the markers' slip,
 *    by a factor over 1.6 a sweep.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "coupling/gf_ibm_markers.h"
#include "gf_test.h"

static void kernel_sums(void)
{
    const double offsets[] = {0.0, 0.13, 0.37, 0.5, 0.71, 0.99};
    for (size_t i = 0; i < sizeof offsets / sizeof *offsets; ++i) {
        double r = offsets[i], s0 = 0.0, s1 = 0.0, s2 = 0.0;
        for (int k = -3; k <= 3; ++k) {
            double w = gf_ibm_roma_kernel(r - k);
            s0 += w, s1 += (r - k) * w, s2 += w * w;
        }
        GF_CHECK(fabs(s0 - 1.0) < 1e-14 && fabs(s1) < 1e-14 && fabs(s2 - 0.5) < 1e-14);
    }
}

static void marker_set(void)
{
    size_t n = gf_ibm_marker_count(4.0, 1.0);
    double mean[3] = {0, 0, 0}, worst = 0.0;
    for (size_t l = 0; l < n; ++l) {
        double d[3];
        gf_ibm_marker_direction(l, n, d);
        worst = fmax(worst, fabs(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - 1.0));
        for (int a = 0; a < 3; ++a)
            mean[a] += d[a] / (double)n;
    }
    double m = sqrt(mean[0] * mean[0] + mean[1] * mean[1] + mean[2] * mean[2]);
    printf("markers at R = 4 dx: %zu, |centroid| %.2e R, |n| - 1 at most %.1e\n", n, m, worst);
    GF_CHECK(n == 201);
    GF_CHECK(m < 1.0 / (double)n && worst < 1e-14);
}

/* A sphere of R = 4 dx at x0 (cells from the low corner along x) moving at 0.1 m/s along x, y periodic. */
static void spread_balance(double x0_cells, const char *where)
{
    gf_ctx ctx = {0};
    const double h = 1e-3, R = 4 * h, rho_f = 1000.0, dt = 1e-3;
    int nn[3] = {24, 24, 24};
    double lo[3] = {0, 0, 0}, hi[3] = {24 * h, 24 * h, 24 * h};
    gf_grid_bc bc[3][2] = {{GF_GRID_NO_SLIP, GF_GRID_NO_SLIP},
                           {GF_GRID_PERIODIC, GF_GRID_PERIODIC},
                           {GF_GRID_FREE_SLIP, GF_GRID_FREE_SLIP}};
    gf_grid g;
    GF_CHECK_OK(gf_grid_init(&ctx, &g, nn, lo, hi, bc), &ctx);
    gf_particles *p = NULL;
    GF_CHECK_OK(gf_particles_create(&ctx, 4, &p), &ctx);
    GF_CHECK_OK(gf_particles_add(&ctx, p, x0_cells * h, 0.4 * h, 12.13 * h, R, 2500.0, 0, NULL), &ctx);
    p->vx_m_s[0] = 0.1;
    gf_ibm_markers mk = {.retraction_cells = 0.3};
    double *up[3], *uw[3], *force[3], F[3], T[3];
    for (int a = 0; a < 3; ++a) {
        up[a] = calloc(g.n_faces[a], sizeof(double));
        uw[a] = calloc(g.n_faces[a], sizeof(double));
        force[a] = calloc(g.n_faces[a], sizeof(double));
    }
    GF_CHECK_OK(gf_ibm_markers_force(&ctx, &mk, &g, p, (const double *const *)up, dt, rho_f, uw, force, F, T), &ctx);
    double spread[3] = {0, 0, 0};
    for (int a = 0; a < 3; ++a)
        for (int k = 0; k < g.nf[a][2]; ++k)
            for (int j = 0; j < g.nf[a][1]; ++j)
                for (int i = 0; i < g.nf[a][0]; ++i) {
                    int q[3] = {i, j, k};
                    if (g.periodic[a] && q[a] == g.n[a])
                        continue; /* the periodic copy of face 0 */
                    spread[a] += rho_f * force[a][gf_grid_face(&g, a, i, j, k)] * h * h * h;
                }
    double err = 0.0;
    for (int a = 0; a < 3; ++a)
        err = fmax(err, fabs(spread[a] + F[a]) / fabs(F[0]));
    printf("%s: grain marker force %.6g N, spread %.6g N (relative mismatch %.1e); slip per sweep", where, F[0],
           spread[0], err);
    for (int s = 0; s < GF_IBM_MARKER_SWEEPS; ++s)
        printf(" %.3g", mk.last_slip[s]);
    printf(" m/s\n");
    GF_CHECK(F[0] < 0.0 && err < 1e-12);
    for (int s = 1; s < GF_IBM_MARKER_SWEEPS; ++s)
        GF_CHECK(mk.last_slip[s] < mk.last_slip[s - 1] / 1.6);
    for (int a = 0; a < 3; ++a)
        free(up[a]), free(uw[a]), free(force[a]);
    gf_ibm_markers_free(&mk);
    gf_particles_destroy(&p);
}

int main(void)
{
    kernel_sums();
    marker_set();
    spread_balance(12.37, "mid-box");
    spread_balance(4.6, "0.6 dx from a wall");
    return gf_test_finish();
}
