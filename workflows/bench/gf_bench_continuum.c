/*
 * Cost of the continuum mu(I) solver's step (engine/continuum) on the channel
 * of Djouwe Meffeja 2012, §4.5 (3H x H, parabolic inflow, outflow), at
 * ny = 30 (the thesis' 90 x 30 grid), 60 and 120: CPU ms per step and CPU us per
 * velocity unknown per step, for a Newtonian viscosity (the LU factored once)
 * and for the mu(I) law (refactored every step, as the thesis' Matlab code
 * did). Usage: gf-bench-continuum [steps] (default 50).
 */
#include <stdio.h>
#include <stdlib.h>

#include "continuum/gf_continuum.h"
#include "gf_bench_clock.h"

static int bench(int ny, gf_rheology rh, int steps)
{
    gf_ctx ctx = {0};
    gf_continuum_params p = {
        .n = {3 * ny, ny, 1},
        .length_m = {3.0, 1.0, 1.0},
        .side = {{GF_SIDE_INFLOW, GF_SIDE_OUTFLOW}, {GF_SIDE_WALL, GF_SIDE_WALL}, {GF_SIDE_PERIODIC, GF_SIDE_PERIODIC}},
        .inflow_umax_m_s = rh == GF_RHEOLOGY_NEWTONIAN ? 1.0 : 1e-2,
        .density_kg_m3 = rh == GF_RHEOLOGY_NEWTONIAN ? 1.0 : 1500.0,
        .rheology = rh,
        .viscosity_Pa_s = 0.01,
        .mui = {.law = gf_mui_thesis_matlab(), .diameter_m = 2.5e-3, .grain_density_kg_m3 = 2500, .gdot_min_1_s = 1e-5},
        .pressure_ref_Pa = 1000.0,
        .dt_s = 0.4 / ny,
    };
    gf_continuum *s = NULL;
    if (gf_continuum_create(&ctx, &p, &s) != GF_OK) {
        fprintf(stderr, "gf-bench-continuum: %s\n", ctx.last_msg);
        return 1;
    }
    gf_continuum_step(s); /* the first step pays the symbolic analysis */
    double t0 = gf_bench_cpu_time_s();
    for (int k = 0; k < steps; ++k)
        if (gf_continuum_step(s) != GF_OK) {
            fprintf(stderr, "gf-bench-continuum: %s\n", ctx.last_msg);
            return 1;
        }
    double cpu = (gf_bench_cpu_time_s() - t0) / steps;
    long unknowns = (long)(3 * ny + 1) * ny + (long)(3 * ny) * (ny - 1);
    printf("%-9s %4d x %3d  %6ld unknowns  %8.2f ms/step  %6.3f us/unknown-step\n",
           rh == GF_RHEOLOGY_NEWTONIAN ? "newtonian" : "mu(I)", 3 * ny, ny, unknowns, 1e3 * cpu, 1e6 * cpu / unknowns);
    gf_continuum_destroy(&s);
    return 0;
}

int main(int argc, char **argv)
{
    int steps = argc > 1 ? atoi(argv[1]) : 50;
    int rc = 0;
    for (int ny = 30; ny <= 120; ny *= 2)
        for (int rh = 0; rh < 2; ++rh)
            rc |= bench(ny, rh ? GF_RHEOLOGY_MU_I : GF_RHEOLOGY_NEWTONIAN, steps);
    return rc;
}
