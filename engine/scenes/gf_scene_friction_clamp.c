/*
 * Friction clamp: one grain squeezed between two glued grains (centres on
 * the x axis, overlap squeeze_over_D each side) under gravity -y. The two
 * contact normals are opposite, so the grain cannot roll out (rolling on one
 * partner is slipping on the other): only the tangential springs and their
 * Coulomb caps hold it. With F_n = k_n delta on each side the grain stays
 * stuck while m g < 2 mu k_n delta (the static-friction limit), sagging by the
 * spring deflection m g / (2 k_t); above the limit it slides down at
 * g - 2 mu k_n delta/m. A minimal static-friction and contact-history check.
 */
#include <math.h>

#include "scenes/gf_scene.h"
#include "scenes/gf_scene_box.h"

static const gf_param_info clamp_params[] = {
    {"squeeze_over_D", "1", 2e-3, 0.0, 0.04, "overlap with each glued partner / D"},
};

static gf_status clamp_build(gf_sim *sim, const gf_run_spec *spec)
{
    gf_ctx *ctx = gf_sim_ctx(sim);
    gf_particles *p = gf_sim_particles(sim);
    double D = spec->grains.diameter_m, R = 0.5 * D, rho = spec->grains.density_kg_m3;
    double d = D - gf_run_spec_param(spec, "squeeze_over_D", 2e-3) * D; /* centre distance */
    const double lo[3] = {-5.0 * D, -5.0 * D, -5.0 * D}, hi[3] = {5.0 * D, 5.0 * D, 5.0 * D};
    GF_TRY(gf_scene_box_under_gravity(sim, lo, hi, (const int[3]){0, 0, 0}, spec->gravity_m_s2));
    GF_TRY(gf_particles_add(ctx, p, -d, 0.0, 0.0, R, rho, GF_P_GLUED, NULL));
    GF_TRY(gf_particles_add(ctx, p, 0.0, 0.0, 0.0, R, rho, 0, NULL));
    GF_TRY(gf_particles_add(ctx, p, d, 0.0, 0.0, R, rho, GF_P_GLUED, NULL));
    return GF_OK;
}

const gf_scene_desc gf_scene_friction_clamp = {
    .name = "friction_clamp",
    .caption = "a grain held by friction between two glued grains (static friction, contact history)",
    .needs = GF_NEED_CONTACTS,
    GF_SCENE_PARAMS(clamp_params),
    .default_end_time_nd = 10.0,
    .build = clamp_build,
};
