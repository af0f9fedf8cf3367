/*
 * Head-on collision of two equal spheres in a viscous fluid (Yang & Hunt,
 * Phys. Fluids 18, 2006; Izard 2014 §3.2): sphere 1 launched along +x at
 * launch_speed_nd sqrt(g D) towards sphere 2 at rest, the surfaces gap_over_D D
 * apart, no gravity (the pendulums of the experiment hold the spheres: their
 * vertical motion is neglected). A closed box length_over_D long along the line
 * of centres and box_over_D across, sphere 1 start_over_D from the low x face;
 * free-slip on every face. Sphere 1 starts impulsively in fluid at rest; the
 * harness discards that transient (it measures just before the contact).
 *
 * Diagnostics: the two spheres' velocities along x and the gap between their
 * surfaces over D.
 */
#include <math.h>

#include "coupling/gf_coupling.h"
#include "scenes/gf_scene.h"

static const gf_param_info head_on_params[] = {
    {"launch_speed_nd", "1", 0.85, 0.0, 1e3, "initial velocity of sphere 1 towards sphere 2 / sqrt(g D)"},
    {"gap_over_D", "1", 2.0, 0.0, 100.0, "initial gap between the spheres' surfaces / D"},
    {"start_over_D", "1", 2.0, 0.5, 100.0, "distance from the low x face to the centre of sphere 1 / D"},
    {"length_over_D", "1", 12.0, 3.0, 1000.0, "box length along the line of centres / D"},
    {"box_over_D", "1", 4.0, 1.0, 1000.0, "box width and depth / D"},
};

static const gf_var_info head_on_diag[] = {
    {"sphere1_velocity_x", "m s-1", "velocity of the launched sphere along the line of centres", NULL},
    {"sphere2_velocity_x", "m s-1", "velocity of the target sphere along the line of centres", NULL},
    {"pair_gap_over_D", "1", "gap between the two spheres' surfaces / D", NULL},
};

static gf_status head_on_build(gf_sim *sim, const gf_run_spec *spec)
{
    gf_ctx *ctx = gf_sim_ctx(sim);
    gf_particles *p = gf_sim_particles(sim);
    double D = spec->grains.diameter_m, rho = spec->grains.density_kg_m3;
    double L = gf_run_spec_param(spec, "length_over_D", 12.0) * D, W = gf_run_spec_param(spec, "box_over_D", 4.0) * D;
    double x1 = gf_run_spec_param(spec, "start_over_D", 2.0) * D;
    double x2 = x1 + D + gf_run_spec_param(spec, "gap_over_D", 2.0) * D;
    if (x2 > L - 0.5 * D)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "head_on: the target sphere at %g D does not fit a box %g D long", x2 / D,
                       L / D);
    double lo[3] = {0, 0, 0}, hi[3] = {L, W, W}, no_gravity[3] = {0, 0, 0};
    int periodic[3] = {0, 0, 0};
    GF_TRY(gf_sim_set_box(sim, lo, hi, periodic));
    GF_TRY(gf_sim_set_gravity(sim, no_gravity));
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side)
            GF_TRY(gf_sim_set_fluid_bc(sim, a, side, GF_BC_FREE_SLIP));
    size_t i;
    GF_TRY(gf_particles_add(ctx, p, x1, 0.5 * W, 0.5 * W, 0.5 * D, rho, 0, &i));
    p->vx_m_s[i] = gf_run_spec_param(spec, "launch_speed_nd", 0.85) * sqrt(spec->gravity_m_s2 * D);
    return gf_particles_add(ctx, p, x2, 0.5 * W, 0.5 * W, 0.5 * D, rho, 0, NULL);
}

static gf_status head_on_diagnose(gf_sim *sim, double *v)
{
    const gf_particles *p = gf_sim_particles(sim);
    double D = gf_sim_spec(sim)->grains.diameter_m;
    v[0] = p->vx_m_s[0];
    v[1] = p->vx_m_s[1];
    v[2] = (p->x_m[1] - p->x_m[0]) / D - 1.0;
    return GF_OK;
}

const gf_scene_desc gf_scene_head_on = {
    .name = "head_on",
    .caption = "two spheres colliding head-on in a viscous fluid (Yang & Hunt 2006; Izard 2014 §3.2)",
    .needs = GF_NEED_CONTACTS | GF_NEED_FLUID,
    GF_SCENE_PARAMS(head_on_params),
    .default_end_time_nd = 10.0,
    .build = head_on_build,
    GF_SCENE_DIAG(head_on_diag),
    .diagnose = head_on_diagnose,
};
