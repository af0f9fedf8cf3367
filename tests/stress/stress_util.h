/*
 * Helpers of the stress tests: a spec with the seeds' defaults for a scene,
 * a sim with no output, and the elastic energy of a periodic gas.
 */
#ifndef STRESS_UTIL_H
#define STRESS_UTIL_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gf_sim.h"
#include "gf_test.h"
#include "gf_test_sim.h"
#include "scenes/gf_scene.h"

/* Largest grain speed (translation), m/s. */
static inline double stress_max_speed(const gf_particles *p)
{
    double m = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        m = fmax(m, sqrt(p->vx_m_s[i] * p->vx_m_s[i] + p->vy_m_s[i] * p->vy_m_s[i] + p->vz_m_s[i] * p->vz_m_s[i]));
    return m;
}

/* (1/2) k_n delta^2 over overlapping pairs, minimum image. k_n is shared by
 * every pair (derived once for the mean pair, gf_contact.h), gamma_n = 0 at
 * eps = 1, so with mu = 0 this is the whole potential energy. */
static inline double stress_spring_energy(gf_sim *sim)
{
    gf_particles *p = gf_sim_particles(sim);
    const gf_run_spec *s = gf_sim_spec(sim);
    double lo[3], hi[3], e = 0.0;
    int per[3];
    gf_sim_box(sim, lo, hi, per);
    double D = s->grains.diameter_m, m = s->grains.density_kg_m3 * M_PI * D * D * D / 6.0;
    double tc = gf_run_spec_t_contact_s(s), kn = 0.5 * m * M_PI * M_PI / (tc * tc);
    for (size_t i = 0; i < p->n_local; ++i)
        for (size_t j = i + 1; j < p->n_local; ++j) {
            double d[3] = {p->x_m[i] - p->x_m[j], p->y_m[i] - p->y_m[j], p->z_m[i] - p->z_m[j]}, r2 = 0.0;
            for (int a = 0; a < 3; ++a) {
                double L = hi[a] - lo[a];
                if (per[a])
                    d[a] -= L * round(d[a] / L);
                r2 += d[a] * d[a];
            }
            double ov = p->radius_m[i] + p->radius_m[j] - sqrt(r2);
            if (ov > 0.0)
                e += 0.5 * kn * ov * ov;
        }
    return e;
}

#endif
