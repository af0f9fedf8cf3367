/*
 * Elastic gas: N grains in a fully periodic cube with random velocities and
 * no gravity, a conservation check of the contact law and the integrator:
 * with eps = 1 and mu = 0 the total kinetic energy after contacts is
 * conserved to O(dt^2) (symplectic integrator, no drift) and the momentum to
 * round-off (pair forces are equal and opposite). Grains start on a cubic
 * lattice (no overlap) with Gaussian velocities of rms speed_nd sqrt(gD) per
 * component, spins drawn the same way in sqrt(g/D), centre-of-mass velocity
 * removed (CoMD's energy-conservation test, in granular form).
 */
#include <math.h>

#include "scenes/gf_scene.h"

static const gf_param_info gas_params[] = {
    {"n_grains", "1", 64.0, 1.0, 1e6, "number of grains"},
    {"box_over_D", "1", 8.0, 2.0, 1e4, "cube edge / D"},
    {"speed_nd", "1", 1.0, 0.0, 1e3, "rms velocity component / sqrt(g D)"},
};

static gf_status gas_build(gf_sim *sim, const gf_run_spec *spec)
{
    gf_ctx *ctx = gf_sim_ctx(sim);
    gf_particles *p = gf_sim_particles(sim);
    gf_rng *rng = gf_sim_rng(sim);
    double D = spec->grains.diameter_m, rho = spec->grains.density_kg_m3, pd = spec->grains.polydispersity;
    long n = (long)gf_run_spec_param(spec, "n_grains", 64);
    double L = gf_run_spec_param(spec, "box_over_D", 8.0) * D;
    double u = gf_run_spec_param(spec, "speed_nd", 1.0) * sqrt(spec->gravity_m_s2 * D);
    double w = gf_run_spec_param(spec, "speed_nd", 1.0) * sqrt(spec->gravity_m_s2 / D);
    double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {L, L, L}, g[3] = {0.0, 0.0, 0.0};
    int periodic[3] = {1, 1, 1};
    GF_TRY(gf_sim_set_box(sim, lo, hi, periodic));
    GF_TRY(gf_sim_set_gravity(sim, g));
    int m = (int)ceil(cbrt((double)n));
    double a = L / m;
    if (a < D * (1.0 + pd))
        return GF_FAIL(ctx, GF_ERR_PHYSICS, "elastic_gas: %ld grains do not fit a %g D cube without overlap", n, L / D);
    double mom[3] = {0.0, 0.0, 0.0}, mass = 0.0;
    for (long k = 0; k < n; ++k) {
        size_t i;
        double r = 0.5 * D * (1.0 + pd * gf_rng_range(rng, -1.0, 1.0));
        GF_TRY(gf_particles_add(ctx, p, (k % m + 0.5) * a, (k / m % m + 0.5) * a, (k / (m * m) + 0.5) * a, r, rho, 0, &i));
        p->vx_m_s[i] = u * gf_rng_normal(rng), p->vy_m_s[i] = u * gf_rng_normal(rng), p->vz_m_s[i] = u * gf_rng_normal(rng);
        p->wx_rad_s[i] = w * gf_rng_normal(rng), p->wy_rad_s[i] = w * gf_rng_normal(rng), p->wz_rad_s[i] = w * gf_rng_normal(rng);
        mom[0] += p->mass_kg[i] * p->vx_m_s[i], mom[1] += p->mass_kg[i] * p->vy_m_s[i], mom[2] += p->mass_kg[i] * p->vz_m_s[i];
        mass += p->mass_kg[i];
    }
    for (size_t i = 0; i < p->n_local; ++i)
        p->vx_m_s[i] -= mom[0] / mass, p->vy_m_s[i] -= mom[1] / mass, p->vz_m_s[i] -= mom[2] / mass;
    return GF_OK;
}

const gf_scene_desc gf_scene_elastic_gas = {
    .name = "elastic_gas",
    .caption = "periodic granular gas, energy and momentum conservation",
    .needs = GF_NEED_CONTACTS,
    GF_SCENE_PARAMS(gas_params),
    .default_end_time_nd = 10.0,
    .build = gas_build,
};
