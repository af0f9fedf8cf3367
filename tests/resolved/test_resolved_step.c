/*
 * The resolved fluid step honours fluid.diffusion_number where viscosity
 * bounds it: a sphere in a viscous fluid (nu = 2e-3 m2/s, D/dx 8, so that the
 * advective bound, cfl dx/sqrt(gD), is the looser one) takes
 *   M = floor(d dx^2 / (nu dt_DEM))
 * DEM steps a fluid step at d = 0.25, 0.5 (the default) and 1.0, exactly, as
 * the step loop rounds (gf_sim_choose_substeps). Case A's E_cx^max moves by
 * x1.75 over these steps (docs/notes/resolved-multigrain.md), so the step is
 * part of a figure's configuration.
 */
#include <math.h>
#include <stdio.h>

#include "gf_sim.h"
#include "gf_test.h"

static int substeps(gf_ctx *ctx, double d_number, double *expected)
{
    const double D = 0.01, rho = 1000.0, eta = 2.0, g = 9.81, n = 8.0;
    gf_run_spec spec;
    gf_run_spec_defaults(&spec);
    snprintf(spec.scene, sizeof spec.scene, "bounce");
    spec.gravity_m_s2 = g;
    spec.grains = (gf_grains_spec){.diameter_m = D, .polydispersity = 0.0, .density_kg_m3 = 4.0 * rho};
    snprintf(spec.fluid.model, sizeof spec.fluid.model, "resolved");
    spec.fluid.density_kg_m3 = rho;
    spec.fluid.viscosity_Pa_s = eta;
    spec.fluid.d_over_dx = n;
    spec.fluid.diffusion_number = d_number;
    spec.end_time_nd = 1.0;
    GF_CHECK_OK(gf_run_spec_set_param(ctx, &spec, "box_over_D", 4.0), ctx);
    GF_CHECK_OK(gf_run_spec_set_param(ctx, &spec, "height_over_D", 4.0), ctx);
    GF_CHECK_OK(gf_run_spec_set_param(ctx, &spec, "release_depth_over_D", 2.0), ctx);
    gf_sim *sim = NULL;
    GF_CHECK_OK(gf_sim_create(ctx, &spec, &(gf_sim_options){.n_threads = 1}, &sim), ctx);
    if (!sim)
        return -1;
    GF_CHECK_OK(gf_sim_advance(sim, 1), ctx);
    const double dx = D / n, nu = eta / rho, dt = gf_sim_dt_s(sim);
    GF_CHECK(d_number * dx * dx / nu < spec.fluid.cfl * dx / sqrt(g * D)); /* viscosity bounds the step */
    *expected = floor(d_number * dx * dx / nu / dt);
    int m = gf_sim_fluid_substeps(sim);
    gf_sim_destroy(&sim);
    printf("diffusion_number %.2f: %d DEM steps a fluid step (nu dt/dx^2 %.4f), expected %.0f\n", d_number, m,
           m * dt * nu / (dx * dx), *expected);
    return m;
}

int main(void)
{
    gf_ctx ctx = {0};
    const double numbers[] = {0.25, 0.5, 1.0};
    for (int k = 0; k < 3; ++k) {
        double expected = NAN;
        int m = substeps(&ctx, numbers[k], &expected);
        GF_CHECK(m == (int)expected);
        GF_CHECK(m >= 1);
    }
    return gf_test_finish();
}
