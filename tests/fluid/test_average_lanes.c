/*
 * The interleaved grain <-> grid transfers of the unresolved fluid step
 * (gf_average_interpolate_lanes, gf_average_spread_lanes) against the
 * per-field ones (one gf_average_interpolate and one gf_average_spread per
 * field): bitwise equal for kernels of random grains
 * on grids with walls and periodic axes, a kernel wider than the box
 * included (mirror images folded back), with 4 and 6 fields as the fluid
 * step uses; and the spread conserves: sum over cells of each lane times
 * V_cell is the spread value to round-off.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "coupling/gf_average.h"
#include "fluid/gf_grid.h"
#include "gf_test.h"

static double uniform(unsigned *state)
{
    *state = *state * 1664525u + 1013904223u;
    return (*state >> 8) / 16777216.0;
}

static void check_grid(const int n[3], const gf_grid_bc bc[3][2], double sigma_over_h, unsigned seed)
{
    gf_ctx ctx = {0};
    gf_grid g;
    double lo[3] = {0.0, -0.01, 0.02}, hi[3] = {0.02 * n[0], -0.01 + 0.02 * n[1], 0.02 + 0.02 * n[2]};
    GF_CHECK_OK(gf_grid_init(&ctx, &g, n, lo, hi, bc), &ctx);
    size_t nc = g.n_cells;
    double *field[6], *lanes = aligned_alloc(64, nc * GF_AVERAGE_LANES * sizeof(double));
    double *spread[4], *spread_lanes[4];
    for (int f = 0; f < 6; ++f)
        field[f] = malloc(nc * sizeof(double));
    for (int f = 0; f < 4; ++f)
        spread[f] = calloc(nc, sizeof(double)), spread_lanes[f] = malloc(nc * sizeof(double));
    unsigned st = seed;
    for (int f = 0; f < 6; ++f)
        for (size_t c = 0; c < nc; ++c)
            field[f][c] = 2.0 * uniform(&st) - 1.0;
    double *acc = calloc(nc * GF_AVERAGE_LANES, sizeof(double)), total[4] = {0.0};
    int interp_mismatch = 0;
    for (int grain = 0; grain < 200; ++grain) {
        double x[3];
        for (int d = 0; d < 3; ++d)
            x[d] = lo[d] + (hi[d] - lo[d]) * uniform(&st);
        gf_kernel k;
        gf_average_kernel(&g, sigma_over_h * 0.02, x, &k);
        for (int nf = 4; nf <= 6; nf += 2) {
            double ref[GF_AVERAGE_LANES], got[GF_AVERAGE_LANES];
            gf_average_interleave(nc, (const double *const *)field, nf, lanes);
            for (int f = 0; f < nf; ++f)
                ref[f] = gf_average_interpolate(&g, &k, field[f]);
            gf_average_interpolate_lanes(&g, &k, lanes, got);
            interp_mismatch += memcmp(ref, got, (size_t)nf * sizeof(double)) != 0;
        }
        double value[GF_AVERAGE_LANES] = {0.0};
        for (int f = 0; f < 4; ++f) {
            value[f] = 1e-3 * (uniform(&st) - 0.5);
            gf_average_spread(&g, &k, value[f], spread[f]);
            total[f] += value[f];
        }
        gf_average_spread_lanes(&g, &k, value, acc);
    }
    gf_average_deinterleave(nc, acc, 4, spread_lanes);
    int spread_mismatch = 0;
    double vc = g.h_m[0] * g.h_m[1] * g.h_m[2], worst = 0.0;
    for (int f = 0; f < 4; ++f) {
        spread_mismatch += memcmp(spread[f], spread_lanes[f], nc * sizeof(double)) != 0;
        double s = 0.0, scale = 0.0;
        for (size_t c = 0; c < nc; ++c)
            s += spread_lanes[f][c] * vc, scale += fabs(spread_lanes[f][c] * vc);
        worst = fmax(worst, fabs(s - total[f]) / scale);
    }
    int unused_lanes_zero = 1;
    for (size_t c = 0; c < nc; ++c)
        for (int f = 4; f < GF_AVERAGE_LANES; ++f)
            unused_lanes_zero &= acc[c * GF_AVERAGE_LANES + (size_t)f] == 0.0;
    printf("grid %dx%dx%d, sigma %.1f cells: interpolation mismatches %d, spread mismatches %d, "
           "conservation %.1e relative\n", n[0], n[1], n[2], sigma_over_h, interp_mismatch, spread_mismatch, worst);
    GF_CHECK(interp_mismatch == 0);
    GF_CHECK(spread_mismatch == 0);
    GF_CHECK(unused_lanes_zero);
    GF_CHECK(worst < 1e-13);
    for (int f = 0; f < 6; ++f)
        free(field[f]);
    for (int f = 0; f < 4; ++f)
        free(spread[f]), free(spread_lanes[f]);
    free(lanes), free(acc);
}

int main(void)
{
    const gf_grid_bc walls[3][2] = {{GF_GRID_NO_SLIP, GF_GRID_NO_SLIP},
                                    {GF_GRID_NO_SLIP, GF_GRID_FREE_SLIP},
                                    {GF_GRID_PERIODIC, GF_GRID_PERIODIC}};
    const gf_grid_bc periodic[3][2] = {{GF_GRID_PERIODIC, GF_GRID_PERIODIC},
                                       {GF_GRID_NO_SLIP, GF_GRID_NO_SLIP},
                                       {GF_GRID_PERIODIC, GF_GRID_PERIODIC}};
    check_grid((const int[3]){17, 9, 6}, walls, 1.0, 1u);      /* the collapse's kernel: sigma = one cell */
    check_grid((const int[3]){12, 10, 3}, periodic, 1.5, 7u);  /* a transverse axis narrower than the kernel */
    check_grid((const int[3]){5, 4, 2}, walls, 2.0, 11u);      /* a kernel wider than the box: folded images */
    return gf_test_finish();
}
