/*
 * Newtonian channel of Djouwe Meffeja 2012, §4.5.1: 3H x H, parabolic inflow
 * U = 4 U_max y (1 - y) (cell averages), outflow at p = 0, no-slip walls, from
 * rest to the steady state. Exact: U = 4 y (1 - y), V = 0, dp/dx = -8/Re
 * (H = U_max = rho = 1). Criteria: max |U - U_exact| at the outlet
 * <= 3e-3 U_max at ny = 30, second order in h over ny = 10, 20, 40 (observed
 * order >= 1.8 on each refinement), |V| at the outlet < 1e-4 and dp/dx
 * within 1 % (Re = 100); Re = 1000 at ny = 30 to t = 16 (the thesis' steady time).
 */
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "continuum_channel.h"
#include "gf_test.h"

typedef struct result { double err, vmax, dpdx, cpu_s; } result;

static result run(int ny, double Re, double t_end)
{
    gf_ctx ctx = {0};
    gf_continuum_params p = channel_newtonian(ny, Re, 0.8);
    gf_continuum *s = NULL;
    result r = {NAN, NAN, NAN, 0};
    GF_CHECK_OK(gf_continuum_create(&ctx, &p, &s), &ctx);
    if (!s)
        return r;
    clock_t c0 = clock();
    double change = 0.0;
    GF_CHECK_OK(gf_continuum_run(s, t_end, 1e-10, &change), &ctx);
    r.cpu_s = (double)(clock() - c0) / CLOCKS_PER_SEC;
    const gf_grid *g = gf_continuum_grid(s);
    const double *v = gf_continuum_velocity(s, 1), *pr = gf_continuum_pressure(s);
    r.err = outlet_error(s);
    r.vmax = 0.0;
    for (int j = 1; j < g->n[1]; ++j)
        r.vmax = fmax(r.vmax, fabs(v[gf_grid_face(g, 1, g->n[0] - 1, j, 0)]));
    int i = g->n[0] - 3, j = g->n[1] / 2;
    r.dpdx = (pr[gf_grid_cell(g, i + 1, j, 0)] - pr[gf_grid_cell(g, i, j, 0)]) / g->h_m[0];
    printf("Re = %4.0f ny = %2d: max|U - U_exact| = %.4e U_max, max|V| = %.2e, dp/dx = %.6f (exact %.6f), t = %.2f, "
           "%.2f s CPU\n",
           Re, ny, r.err, r.vmax, r.dpdx, -8.0 / Re, gf_continuum_time(s), r.cpu_s);
    gf_continuum_destroy(&s);
    return r;
}

int main(void)
{
    const int grids[3] = {10, 20, 40};
    result r[3];
    for (int k = 0; k < 3; ++k)
        r[k] = run(grids[k], 100.0, 20.0);
    for (int k = 1; k < 3; ++k) {
        double order = log(r[k - 1].err / r[k].err) / log(2.0);
        printf("observed order %d -> %d: %.3f\n", grids[k - 1], grids[k], order);
        GF_CHECK(order >= 1.8);
    }
    result r30 = run(30, 100.0, 20.0);
    GF_CHECK(r30.err <= 3e-3);
    GF_CHECK(r30.vmax < 1e-4);
    GF_CHECK_REL(r30.dpdx, -0.08, 0.01);
    result r1000 = run(30, 1000.0, 16.0);
    GF_CHECK(r1000.err <= 3e-3);
    GF_CHECK_REL(r1000.dpdx, -0.008, 0.01);
    return gf_test_finish();
}
