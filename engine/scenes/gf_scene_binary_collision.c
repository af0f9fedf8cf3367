/*
 * Binary collision: two equal grains (or one grain and a plane wall) meet
 * with a chosen normal impact speed V and tangential ratio
 * Psi1 = (u_rel . t)/|u_rel . n| of the contact-point relative velocity
 * (Foerster, Louge, Chang & Allia, Phys. Fluids 1994; Izard 2014 §2.1.3.1). No gravity unless asked: the contact alone sets the outcome.
 * Geometry: normal along x, tangent along y. Pair: grain 0 at
 * x = -(R + gap/2) moving +x, grain 1 mirrored (centre-of-mass frame, so
 * u_rel = (V, Psi1 V, 0) at approach). Wall: plane x = 0 (normal +x), one grain
 * at x = R + gap moving (-V, Psi1 V, 0). spin_nd gives grain 0 an initial
 * w_z = spin_nd sqrt(g/D) (changes Psi1 through the surface velocity).
 * gap_over_D < 0 starts overlapped (the impossible-input tests use it).
 */
#include <math.h>

#include "scenes/gf_scene.h"

static const gf_param_info collision_params[] = {
    {"impact_speed_nd", "1", 1.0, 0.0, 1e3, "normal approach speed / sqrt(g D)"},
    {"psi1", "1", 0.0, -50.0, 50.0, "tangential / normal contact-point velocity before impact"},
    {"spin_nd", "1", 0.0, -1e3, 1e3, "initial w_z of grain 0 in sqrt(g/D)"},
    {"with_wall", "1", 0.0, 0.0, 1.0, "1: grain against a plane wall, 0: two grains"},
    {"gap_over_D", "1", 0.01, -0.5, 10.0, "initial surface gap / D (negative: overlap)"},
    {"gravity_on", "1", 0.0, 0.0, 1.0, "1: gravity along -y, 0: none"},
};

static gf_status collision_build(gf_sim *sim, const gf_run_spec *spec)
{
    gf_ctx *ctx = gf_sim_ctx(sim);
    gf_particles *p = gf_sim_particles(sim);
    double D = spec->grains.diameter_m, R = 0.5 * D, rho = spec->grains.density_kg_m3;
    double V = gf_run_spec_param(spec, "impact_speed_nd", 1.0) * sqrt(spec->gravity_m_s2 * D);
    double psi = gf_run_spec_param(spec, "psi1", 0.0);
    double gap = gf_run_spec_param(spec, "gap_over_D", 0.01) * D;
    double spin = gf_run_spec_param(spec, "spin_nd", 0.0) * sqrt(spec->gravity_m_s2 / D);
    int wall = gf_run_spec_param(spec, "with_wall", 0.0) > 0.5;
    double lo[3] = {-20.0 * D, -20.0 * D, -20.0 * D}, hi[3] = {20.0 * D, 20.0 * D, 20.0 * D};
    int periodic[3] = {0, 0, 0};
    GF_TRY(gf_sim_set_box(sim, lo, hi, periodic));
    double g[3] = {0.0, gf_run_spec_param(spec, "gravity_on", 0.0) > 0.5 ? -spec->gravity_m_s2 : 0.0, 0.0};
    GF_TRY(gf_sim_set_gravity(sim, g));
    size_t i;
    if (wall) {
        double pt[3] = {0.0, 0.0, 0.0}, n[3] = {1.0, 0.0, 0.0};
        GF_TRY(gf_sim_add_wall(sim, pt, n, spec->contact.wall_friction, NULL));
        GF_TRY(gf_particles_add(ctx, p, R + gap, 0.0, 0.0, R, rho, 0, &i));
        p->vx_m_s[i] = -V, p->vy_m_s[i] = psi * V, p->wz_rad_s[i] = spin;
    } else {
        GF_TRY(gf_particles_add(ctx, p, -(R + 0.5 * gap), 0.0, 0.0, R, rho, 0, &i));
        p->vx_m_s[i] = 0.5 * V, p->vy_m_s[i] = 0.5 * psi * V, p->wz_rad_s[i] = spin;
        GF_TRY(gf_particles_add(ctx, p, R + 0.5 * gap, 0.0, 0.0, R, rho, 0, &i));
        p->vx_m_s[i] = -0.5 * V, p->vy_m_s[i] = -0.5 * psi * V;
    }
    /* long enough to close the gap, collide (t_c) and separate */
    double t_end = (fabs(gap) + D) / (V > 0.0 ? V : sqrt(spec->gravity_m_s2 * D)) + 3.0 * gf_run_spec_t_contact_s(spec);
    return gf_sim_set_end_time(sim, t_end);
}

const gf_scene_desc gf_scene_binary_collision = {
    .name = "binary_collision",
    .caption = "two grains or grain-wall, oblique impact (Foerster et al. 1994; Izard 2014 §2.1.3.1)",
    .needs = GF_NEED_CONTACTS,
    GF_SCENE_PARAMS(collision_params),
    .default_end_time_nd = 0.0,
    .build = collision_build,
};
