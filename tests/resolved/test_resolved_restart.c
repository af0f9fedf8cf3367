/*
 * A resolved-tier run restarts bitwise (issue #32): a sphere falling in a
 * closed box through the resolved tier (D/dx = 8, fluid steps with the
 * immersed-boundary forcing, sub-cycled DEM), advanced 2N DEM steps in one go,
 * and advanced N, checkpointed (HDF5: face velocities, pressure, the previous
 * advection rates of AB2, the fields, the grain's held force and torque, the
 * fluid-step schedule), re-created from the checkpoint and advanced N more,
 * hold identical bytes in the grain's position, velocity and spin and in the
 * excess pressure at three points. N is not a multiple of the substep count,
 * so the checkpoint falls between two fluid steps. A checkpoint of the
 * unresolved tier is refused by a resolved restart, naming why.
 * The same 2N steps on two OpenMP threads hold the same bytes as on one:
 * the stencils write each face alone, the immersed boundary sums in grain
 * order, and the FFTs run by slabs of one shape (fluid/gf_poisson.h).
 * Both time schemes: AB2 (the default, whose checkpoint carries the previous
 * advection rates) and RK3 (three forced substeps a step, no history); and
 * the marker forcing with AB2 (fluid.ibm_forcing: markers, whose internal
 * momentum is measured within each step: no state of its own).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gf_sim.h"
#include "gf_test.h"
#include "gf_test_restart.h"
#include "gf_test_sim.h"

static gf_run_spec bounce_spec(gf_ctx *ctx, const char *model)
{
    gf_run_spec spec;
    gf_run_spec_defaults(&spec);
    snprintf(spec.scene, sizeof spec.scene, "bounce");
    spec.grains.diameter_m = 0.01;
    spec.grains.density_kg_m3 = 4000.0;
    snprintf(spec.fluid.model, sizeof spec.fluid.model, "%s", model);
    spec.fluid.density_kg_m3 = 1000.0;
    spec.fluid.viscosity_Pa_s = 0.19183; /* Ar = 800 (Izard 2014 §2.2.3) */
    spec.fluid.d_over_dx = 8.0;
    spec.fluid.cell_over_D = 1.0;
    spec.contact.t_contact_nd = 0.05;
    const gf_test_param box[] = {{"box_over_D", 3.0}, {"height_over_D", 5.0}, {"release_depth_over_D", 1.5}};
    gf_test_set_params(ctx, &spec, box, sizeof box / sizeof box[0]);
    return spec;
}

static const double gauges[3][3] = {{0.015, 0.005, 0.012}, {0.015, 0.015, 0.012}, {0.015, 0.025, 0.012}}; /* m */

/* Bitwise the same grain and pressure, restarted and on 2 threads; the sphere falls, slower than in vacuum. */
static void compare(gf_ctx *ctx, const gf_run_spec *spec, long N, gf_sim *ref, gf_sim *b)
{
    double pr[3], pb[3];
    gf_particles *p = gf_sim_particles(ref), *q = gf_sim_particles(b);
    int ok = gf_test_same_motion(p, q);
    ok = gf_test_same_pressure(ref, b, 3, gauges, pr, pb) && ok;
    double u = -p->vy_m_s[0] / sqrt(9.81 * 0.01);
    const char *mk = strcmp(spec->fluid.ibm_forcing, "markers") == 0 ? ", markers" : "";
    printf("resolved sphere, %s%s: %ld + %ld steps (t = %.4g s), u = %.4f sqrt(gD), excess pressure %.4g, %.4g, %.4g Pa "
           "(restarted %.4g, %.4g, %.4g): bitwise identical = %d\n",
           spec->fluid.time_scheme, mk, N, N, gf_sim_time_s(ref), u, pr[0], pr[1], pr[2], pb[0], pb[1], pb[2], ok);
    GF_CHECK(ok);
    GF_CHECK(u > 0.05);                  /* it falls */
    GF_CHECK(u < 9.81 * gf_sim_time_s(ref) / sqrt(9.81 * 0.01)); /* slower than free fall */
    GF_CHECK(fabs(pr[1]) > 0.0);         /* a pressure field developed */
    gf_sim *two = NULL;
    GF_CHECK_OK(gf_test_sim(ctx, spec, 2, &two), ctx);
    if (two) {
        GF_CHECK_OK(gf_sim_advance(two, 2 * N), ctx);
        int same = gf_test_same_motion(p, gf_sim_particles(two));
        same = gf_test_same_pressure(ref, two, 3, gauges, pr, pb) && same;
        printf("resolved sphere, %s%s, on 2 threads: %ld steps, bitwise identical to 1 thread = %d\n",
               spec->fluid.time_scheme, mk, 2 * N, same);
        GF_CHECK(same);
        gf_sim_destroy(&two);
    }
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_run_spec spec = bounce_spec(&ctx, "resolved");
    /* an unresolved checkpoint holds no resolved fluid: refused, naming why */
    gf_run_spec un = bounce_spec(&ctx, "unresolved");
    const gf_test_restart_case c = {.stem = "resolved_restart", .N = 1001, .compare = compare, .other = &un,
                                    .other_steps = 10, .why = "no resolved-tier fluid state",
                                    .what = "resolved restart from an unresolved checkpoint"};
    int fails = gf_test_restart(&ctx, &spec, &c);
    snprintf(spec.fluid.time_scheme, sizeof spec.fluid.time_scheme, "rk3");
    const gf_test_restart_case c3 = {.stem = "resolved_restart_rk3", .N = 1001, .compare = compare, .other = &un,
                                     .other_steps = 10, .why = "no resolved-tier fluid state",
                                     .what = "resolved restart (rk3) from an unresolved checkpoint"};
    fails = gf_test_restart(&ctx, &spec, &c3) || fails;
    snprintf(spec.fluid.time_scheme, sizeof spec.fluid.time_scheme, "ab2");
    snprintf(spec.fluid.ibm_forcing, sizeof spec.fluid.ibm_forcing, "markers");
    spec.fluid.ibm_retraction_dx = 0.3;
    const gf_test_restart_case cm = {.stem = "resolved_restart_markers", .N = 1001, .compare = compare, .other = &un,
                                     .other_steps = 10, .why = "no resolved-tier fluid state",
                                     .what = "resolved restart (markers) from an unresolved checkpoint"};
    return gf_test_restart(&ctx, &spec, &cm) || fails;
}
