/*
 * Settling before t = 0 and the rest test (gf_scene_settle.h). Rest is
 * judged on the kinetic energy per mobile grain against m g D, the energy
 * of a grain lifted by its own diameter: a threshold that does not depend
 * on the grain size or the number of grains.
 */
#include "scenes/gf_scene_settle.h"

#include <math.h>

gf_status gf_scene_settle(gf_sim *sim, const gf_run_spec *spec, double settle_time_nd)
{
    const double t_settle_s = settle_time_nd * sqrt(spec->grains.diameter_m / spec->gravity_m_s2);
    const long steps = (long)ceil(t_settle_s / gf_run_spec_dt_s(spec));
    return steps > 0 ? gf_sim_advance(sim, steps) : GF_OK;
}

int gf_scene_at_rest(gf_sim *sim, double rest_energy_nd)
{
    const gf_run_spec *s = gf_sim_spec(sim);
    const gf_particles *p = gf_sim_particles(sim);
    size_t n = 0;
    double m = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        if (!(p->flags[i] & GF_P_GLUED))
            ++n, m += p->mass_kg[i];
    if (n == 0)
        return 1;
    const double ke = gf_particles_kinetic_energy(p) / (double)n, m_mean = m / (double)n;
    return ke < rest_energy_nd * m_mean * s->gravity_m_s2 * s->grains.diameter_m;
}
