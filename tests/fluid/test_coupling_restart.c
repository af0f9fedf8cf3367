/*
 * An immersed run restarts bitwise: a dense column collapsing in a viscous
 * fluid (unresolved tier, lubrication, sub-cycled fluid steps), advanced 2N
 * DEM steps in one go, and advanced N steps, checkpointed (HDF5, with the
 * fluid: face velocities, pressure, fluid fraction, the grains' held fluid
 * forces and the fluid-step schedule), re-created from the checkpoint and
 * advanced N more, hold identical bytes in every grain position, velocity and
 * spin and the same excess pore pressure at the basal gauges. N is not a
 * multiple of the substep count, so the checkpoint falls between two fluid
 * steps, where the held forces matter. A checkpoint of a dry run refused by
 * an immersed restart is checked too.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gf_sim.h"
#include "gf_test.h"
#include "gf_test_restart.h"
#include "gf_test_sim.h"

#define D 7.6e-3 /* the grains of gf_test_viscous_collapse_spec */

/* Bitwise the same grains and basal pore pressure; the collapse moves and a pore pressure developed. */
static void compare(gf_ctx *ctx, const gf_run_spec *spec, long N, gf_sim *ref, gf_sim *b)
{
    (void)ctx, (void)spec;
    gf_particles *p = gf_sim_particles(ref), *q = gf_sim_particles(b);
    size_t n = p->n_local;
    double lo[3], hi[3], x[3][3], pr[3], pb[3], vmax = 0.0;
    gf_sim_box(ref, lo, hi, NULL);
    for (int k = 0; k < 3; ++k) { /* basal gauges at 4/16, 8/16 and 13/16 of R0 = 12 D */
        x[k][0] = (4.0 + 4.5 * k) / 16.0 * 12.0 * D, x[k][1] = 0.5 * D, x[k][2] = 0.5 * (lo[2] + hi[2]);
    }
    int ok = gf_test_same_motion(p, q);
    ok = gf_test_same_pressure(ref, b, 3, x, pr, pb) && ok;
    for (size_t i = 0; i < n; ++i)
        vmax = fmax(vmax, fabs(p->vx_m_s[i]));
    printf("immersed collapse: %zu grains, %ld + %ld steps (t = %.4g s), max |u_x| = %.3g sqrt(gD), basal excess "
           "pressure %.4g, %.4g, %.4g Pa (restarted %.4g, %.4g, %.4g): bitwise identical = %d\n",
           n, N, N, gf_sim_time_s(ref), vmax / sqrt(9.81 * D), pr[0], pr[1], pr[2], pb[0], pb[1], pb[2], ok);
    GF_CHECK(ok);
    GF_CHECK(vmax > 1e-3 * sqrt(9.81 * D)); /* it moves: the fluid state matters */
    GF_CHECK(fabs(pr[0]) > 0.0);           /* a pore pressure developed */
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_run_spec spec, dry;
    gf_test_viscous_collapse_spec(&ctx, "unresolved", &spec);
    /* a dry run's checkpoint holds no fluid: an immersed restart from it is refused, naming why */
    gf_test_viscous_collapse_spec(&ctx, "none", &dry);
    const gf_test_restart_case c = {.stem = "coupling_restart", .N = 4001, .compare = compare, .other = &dry,
                                    .why = "no fluid state", .what = "immersed restart from a dry checkpoint"};
    return gf_test_restart(&ctx, &spec, &c);
}
