/*
 * Implicit viscous step: the FFT Helmholtz solve must invert exactly the MAC
 * stencil (1 - c L) with the ghost-cell boundary conditions of gf_grid, for
 * every component and every boundary combination the scenes use (periodic,
 * no-slip, free-slip, no-slip bottom + free-slip top). Check: apply the
 * stencil to the solution and recover the right-hand side to 1e-10.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/gf_rng.h"
#include "fluid/gf_grid.h"
#include "fluid/gf_poisson.h"
#include "gf_test.h"

static void check_bc(const char *name, gf_grid_bc bc[3][2])
{
    gf_ctx ctx = {0};
    gf_grid g;
    int n[3] = {7, 6, 5};
    double lo[3] = {0, 0, 0}, hi[3] = {1.0, 0.8, 0.9};
    GF_CHECK_OK(gf_grid_init(&ctx, &g, n, lo, hi, bc), &ctx);
    gf_rng rng;
    gf_rng_seed(&rng, 7);
    double worst = 0.0;
    for (int a = 0; a < 3; ++a) {
        gf_helmholtz_plan *pl = NULL;
        GF_CHECK_OK(gf_helmholtz_plan_create(&ctx, &g, a, &pl), &ctx);
        double *b = calloc(g.n_faces[a], sizeof(double)), *x = calloc(g.n_faces[a], sizeof(double));
        for (int k = 0; k < g.nf[a][2]; ++k)
            for (int j = 0; j < g.nf[a][1]; ++j)
                for (int i = 0; i < g.nf[a][0]; ++i) {
                    int idx[3] = {i, j, k};
                    if (gf_grid_face_free(&g, a, idx[a]))
                        b[gf_grid_face(&g, a, i, j, k)] = gf_rng_range(&rng, -1, 1);
                }
        gf_grid_sync_periodic(&g, a, b);
        for (size_t q = 0; q < g.n_faces[a]; ++q)
            x[q] = b[q];
        double c = 0.05;
        gf_helmholtz_solve(pl, c, x);
        for (int k = 0; k < g.nf[a][2]; ++k)
            for (int j = 0; j < g.nf[a][1]; ++j)
                for (int i = 0; i < g.nf[a][0]; ++i) {
                    int idx[3] = {i, j, k};
                    if (!gf_grid_face_free(&g, a, idx[a]))
                        continue;
                    size_t q = gf_grid_face(&g, a, i, j, k);
                    double r = x[q] - c * gf_grid_face_laplacian(&g, x, a, i, j, k) - b[q];
                    worst = fmax(worst, fabs(r));
                }
        free(b);
        free(x);
        gf_helmholtz_plan_destroy(&pl);
    }
    printf("%-34s max |(1 - cL)x - b| = %.2e\n", name, worst);
    GF_CHECK(worst < 1e-10);
}

int main(void)
{
    gf_grid_bc P = GF_GRID_PERIODIC, N = GF_GRID_NO_SLIP, F = GF_GRID_FREE_SLIP;
    check_bc("periodic", (gf_grid_bc[3][2]){{P, P}, {P, P}, {P, P}});
    check_bc("no-slip box", (gf_grid_bc[3][2]){{N, N}, {N, N}, {N, N}});
    check_bc("free-slip box", (gf_grid_bc[3][2]){{F, F}, {F, F}, {F, F}});
    check_bc("x periodic, no-slip y0, free-slip y1", (gf_grid_bc[3][2]){{P, P}, {N, F}, {P, P}});
    check_bc("free-slip y0, no-slip y1, z walls", (gf_grid_bc[3][2]){{N, N}, {F, N}, {N, N}});
    return gf_test_finish();
}
