/*
 * The avalanche scene's set-up switches, exact properties of the built
 * scene (no flow):
 *   rough_base 0          no glued grains;
 *   base_spacing_over_D   a square lattice of glued half-grains fitted to
 *                         L and W: (L/s)(W/s) grains with centres on y = 0
 *                         at ((i + 1/2) L/n_x, 0, (k + 1/2) W/n_z);
 *   default               glued grains centred on y = 0, none overlapping
 *                         (random sequential adsorption);
 *   slope_gravity_exponent n  the downslope gravity after start() is
 *                         g sin(theta) (rho_p/(rho_p - rho_f))^n in an
 *                         immersed run (Izard 2014 (4.5)-(4.6) readings),
 *                         g sin(theta) whatever n in a dry one; the normal
 *                         component is -g cos(theta).
 */
#include <math.h>

#include "scene_runner.h"

static gf_sim *build(gf_ctx *ctx, gf_run_spec *spec)
{
    gf_run_spec_set_param(ctx, spec, "bed_height_over_D", 5.0);
    gf_run_spec_set_param(ctx, spec, "height_over_D", 10.0);
    gf_run_spec_set_param(ctx, spec, "phi_tolerance", 0.05);
    gf_run_spec_set_param(ctx, spec, "settle_time_nd", 0.0);
    return runner_create(ctx, spec);
}

static int count_glued(const gf_particles *p, double *max_abs_y)
{
    int n = 0;
    *max_abs_y = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        if (p->flags[i] & GF_P_GLUED) {
            ++n;
            *max_abs_y = fmax(*max_abs_y, fabs(p->y_m[i]));
        }
    return n;
}

static void test_bases(void)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    double y;
    runner_dry_spec(&spec, "avalanche");
    gf_run_spec_set_param(&ctx, &spec, "rough_base", 0.0);
    gf_sim *sim = build(&ctx, &spec);
    GF_CHECK(sim && count_glued(gf_sim_particles(sim), &y) == 0);
    gf_sim_destroy(&sim);

    runner_dry_spec(&spec, "avalanche");
    gf_run_spec_set_param(&ctx, &spec, "base_spacing_over_D", 1.25);   /* 5 D / 1.25 D: a 4 x 4 lattice */
    sim = build(&ctx, &spec);
    const gf_particles *p = sim ? gf_sim_particles(sim) : NULL;
    GF_CHECK(p && count_glued(p, &y) == 16 && y == 0.0);
    const double a = 5.0 * spec.grains.diameter_m / 4.0;
    for (size_t i = 0; p && i < p->n_local; ++i)
        if (p->flags[i] & GF_P_GLUED) {
            double fx = p->x_m[i] / a - 0.5, fz = p->z_m[i] / a - 0.5;
            GF_CHECK_ABS(fx - round(fx), 0.0, 1e-12);
            GF_CHECK_ABS(fz - round(fz), 0.0, 1e-12);
        }
    gf_sim_destroy(&sim);

    runner_dry_spec(&spec, "avalanche");
    sim = build(&ctx, &spec);
    p = sim ? gf_sim_particles(sim) : NULL;
    int n = p ? count_glued(p, &y) : 0;
    GF_CHECK(n > 0 && y == 0.0);
    printf("random base: %d glued grains on 25 D^2\n", n);
    gf_sim_destroy(&sim);
}

/* Downslope and normal gravity after start() for exponent n, immersed (rho_f = rho_p / 4) or dry. */
static void gravity_after_start(int immersed, double n, double g_out[3])
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    runner_dry_spec(&spec, "avalanche");
    if (immersed) {
        snprintf(spec.fluid.model, sizeof spec.fluid.model, "unresolved");
        spec.fluid.density_kg_m3 = 0.25 * spec.grains.density_kg_m3;
        spec.fluid.viscosity_Pa_s = 1e-3;
    }
    gf_run_spec_set_param(&ctx, &spec, "slope_gravity_exponent", n);
    gf_sim *sim = build(&ctx, &spec);
    g_out[0] = g_out[1] = NAN;
    if (!sim)
        return;
    GF_CHECK_OK(gf_scene_find("avalanche")->start(sim), &ctx);
    gf_sim_gravity(sim, g_out);
    gf_sim_destroy(&sim);
}

static void test_slope_gravity(void)
{
    const double g = 9.81, th = 25.0 * M_PI / 180.0, ratio = 4.0 / 3.0; /* rho_p / (rho_p - rho_f) */
    double gv[3];
    for (int n = 0; n <= 2; ++n) {
        gravity_after_start(1, n, gv);
        GF_CHECK_REL(gv[0], g * sin(th) * pow(ratio, n), 1e-12);
        GF_CHECK_REL(gv[1], -g * cos(th), 1e-12);
        gravity_after_start(0, n, gv);
        GF_CHECK_REL(gv[0], g * sin(th), 1e-12);
    }
}

int main(void)
{
    test_bases();
    test_slope_gravity();
    return gf_test_finish();
}
