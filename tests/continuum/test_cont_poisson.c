/*
 * The continuum solver's Poisson solve inverts the 7-point cell-centred
 * Laplacian exactly for each side combination (periodic, Neumann, Dirichlet
 * p = 0 on the face, mixed): apply the stencil with the ghost rules (Neumann:
 * ghost = cell; Dirichlet: ghost = -cell) to the solution of a random
 * right-hand side and recover it to 1e-10 (the mean removed where the problem
 * has a null space).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "continuum/gf_cont_poisson.h"
#include "core/gf_rng.h"
#include "gf_test.h"

static double ghost_or_cell(const double *p, const int n[3], const gf_cont_poisson_side side[3][2], int idx[3], int d,
                            int dir)
{
    int m[3] = {idx[0], idx[1], idx[2]};
    m[d] += dir;
    double sign = 1.0;
    if (m[d] < 0 || m[d] >= n[d]) {
        int s = m[d] < 0 ? 0 : 1;
        if (side[d][s] == GF_POISSON_PERIODIC)
            m[d] = (m[d] + n[d]) % n[d];
        else {
            m[d] = idx[d];
            sign = side[d][s] == GF_POISSON_DIRICHLET ? -1.0 : 1.0;
        }
    }
    return sign * p[m[0] + n[0] * (m[1] + n[1] * m[2])];
}

static void check(const char *name, gf_cont_poisson_side side[3][2])
{
    gf_ctx ctx = {0};
    int n[3] = {7, 6, 5};
    double h[3] = {0.1, 0.13, 0.17};
    size_t nc = 7 * 6 * 5;
    gf_cont_poisson *pl = NULL;
    GF_CHECK_OK(gf_cont_poisson_create(&ctx, n, h, side, &pl), &ctx);
    if (!pl)
        return;
    double *f = malloc(nc * sizeof *f), *p = malloc(nc * sizeof *p);
    gf_rng rng;
    gf_rng_seed(&rng, 11);
    double mean = 0.0;
    for (size_t c = 0; c < nc; ++c)
        mean += (f[c] = gf_rng_range(&rng, -1, 1)) / nc;
    int null_space = 1;
    for (int d = 0; d < 3; ++d)
        for (int s = 0; s < 2; ++s)
            null_space &= side[d][s] != GF_POISSON_DIRICHLET;
    if (null_space)
        for (size_t c = 0; c < nc; ++c)
            f[c] -= mean;
    gf_cont_poisson_solve(pl, f, p);
    double worst = 0.0;
    for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
            for (int i = 0; i < n[0]; ++i) {
                int idx[3] = {i, j, k};
                size_t c = i + n[0] * (j + n[1] * k);
                double lap = 0.0;
                for (int d = 0; d < 3; ++d)
                    lap += (ghost_or_cell(p, n, side, idx, d, 1) - 2.0 * p[c] + ghost_or_cell(p, n, side, idx, d, -1)) /
                           (h[d] * h[d]);
                worst = fmax(worst, fabs(lap - f[c]));
            }
    printf("%-40s max |L p - f| = %.2e\n", name, worst);
    GF_CHECK(worst < 1e-10);
    free(f), free(p);
    gf_cont_poisson_destroy(&pl);
}

int main(void)
{
    const gf_cont_poisson_side N = GF_POISSON_NEUMANN, D = GF_POISSON_DIRICHLET, P = GF_POISSON_PERIODIC;
    check("Neumann box", (gf_cont_poisson_side[3][2]){{N, N}, {N, N}, {N, N}});
    check("periodic", (gf_cont_poisson_side[3][2]){{P, P}, {P, P}, {P, P}});
    check("channel: N inflow, D outflow, N walls", (gf_cont_poisson_side[3][2]){{N, D}, {N, N}, {P, P}});
    check("D low, N high; D both; periodic", (gf_cont_poisson_side[3][2]){{D, N}, {D, D}, {P, P}});
    check("periodic x, N y, D-N z", (gf_cont_poisson_side[3][2]){{P, P}, {N, N}, {N, D}});
    return gf_test_finish();
}
