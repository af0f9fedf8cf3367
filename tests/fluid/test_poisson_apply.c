/*
 * The variable-coefficient Laplacian y = div(a grad x) of the projection
 * (gf_poisson_apply_var, row-wise) against its definition cell by cell:
 * for every cell and axis, the two faces' fluxes a_f (x_nb - x_c)/h^2,
 * none across a wall, the neighbour wrapped on a periodic axis, summed in
 * the order x-, x+, y-, y+, z-, z+. Bitwise equal on every combination of
 * wall and periodic axes, on grids with an axis of one and two cells, for
 * random coefficients and fields; and the operator conserves: the sum of y
 * over a closed or periodic box is zero to round-off (fluxes cancel pairwise).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fluid/gf_grid.h"
#include "fluid/gf_poisson.h"
#include "gf_test.h"

static void reference(const gf_grid *g, const double *const a[3], const double *x, double *y)
{
    for (int k = 0; k < g->n[2]; ++k)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i) {
                int idx[3] = {i, j, k};
                size_t c = gf_grid_cell(g, i, j, k);
                double s = 0.0;
                for (int d = 0; d < 3; ++d)
                    for (int dir = 0; dir < 2; ++dir) {
                        int face = idx[d] + dir;
                        if (!g->periodic[d] && (face == 0 || face == g->n[d]))
                            continue;
                        int nb[3] = {i, j, k}, fi[3] = {i, j, k};
                        nb[d] = gf_grid_wrap(g, d, idx[d] + (dir ? 1 : -1));
                        fi[d] = face;
                        double af = a[d][gf_grid_face(g, d, fi[0], fi[1], fi[2])];
                        s += af * (x[gf_grid_cell(g, nb[0], nb[1], nb[2])] - x[c]) * (1.0 / (g->h_m[d] * g->h_m[d]));
                    }
                y[c] = s;
            }
}

static double uniform(unsigned *state)
{
    *state = *state * 1664525u + 1013904223u;
    return (*state >> 8) / 16777216.0;
}

int main(void)
{
    const int sizes[3][3] = {{7, 5, 4}, {1, 6, 3}, {4, 2, 1}};
    unsigned rng = 12345u;
    int n_grids = 0;
    for (int sz = 0; sz < 3; ++sz)
        for (int combo = 0; combo < 8; ++combo) {
            gf_ctx ctx = {0};
            gf_grid g;
            gf_grid_bc bc[3][2];
            for (int d = 0; d < 3; ++d)
                bc[d][0] = bc[d][1] = (combo >> d) & 1 ? GF_GRID_PERIODIC : GF_GRID_NO_SLIP;
            const double lo[3] = {0.0, -1.0, 0.5}, hi[3] = {1.3, 0.7, 2.0};
            GF_CHECK_OK(gf_grid_init(&ctx, &g, sizes[sz], lo, hi, bc), &ctx);
            double *a[3], *x = malloc(g.n_cells * sizeof *x), *y = malloc(g.n_cells * sizeof *y),
                          *y_ref = malloc(g.n_cells * sizeof *y_ref);
            for (int d = 0; d < 3; ++d) {
                a[d] = malloc(g.n_faces[d] * sizeof(double));
                for (size_t f = 0; f < g.n_faces[d]; ++f)
                    a[d][f] = 0.2 + uniform(&rng);
                gf_grid_sync_periodic(&g, d, a[d]);
            }
            for (size_t c = 0; c < g.n_cells; ++c)
                x[c] = uniform(&rng) - 0.5;
            const double *const ac[3] = {a[0], a[1], a[2]};
            gf_poisson_apply_var(&g, ac, x, y);
            reference(&g, ac, x, y_ref);
            gf_test_check(memcmp(y, y_ref, g.n_cells * sizeof *y) == 0, __FILE__, __LINE__,
                          "grid %dx%dx%d, periodic axes mask %d: row-wise operator differs from its definition",
                          g.n[0], g.n[1], g.n[2], combo);
            double sum = 0.0, scale = 0.0;
            for (size_t c = 0; c < g.n_cells; ++c)
                sum += y[c], scale += fabs(y[c]);
            gf_test_check(fabs(sum) <= 1e-13 * (scale > 0.0 ? scale : 1.0), __FILE__, __LINE__,
                          "grid %dx%dx%d, mask %d: sum of div(a grad x) = %.3g (scale %.3g)", g.n[0], g.n[1], g.n[2],
                          combo, sum, scale);
            ++n_grids;
            for (int d = 0; d < 3; ++d)
                free(a[d]);
            free(x), free(y), free(y_ref);
        }
    printf("%d grids: row-wise div(a grad x) bitwise equal to its cell-by-cell definition\n", n_grids);
    return gf_test_finish();
}
