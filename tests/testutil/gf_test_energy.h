/*
 * The potential energy of the linear contact spring, summed here over every
 * pair of a sim by minimum image (not through the engine's neighbour list),
 * for the energy-conservation tests of elastic frictionless gases.
 */
#ifndef GF_TEST_ENERGY_H
#define GF_TEST_ENERGY_H

#include <math.h>

#include "gf_sim.h"

/* (1/2) k_n delta^2 over overlapping pairs (J), minimum image along periodic
 * axes. k_n = m* pi^2 / t_c^2 with m* = m/2 is shared by every pair (derived
 * once for the mean pair, gf_contact.h), gamma_n = 0 at eps = 1, so with
 * mu = 0 this is the whole potential energy. */
static inline double gf_test_spring_energy(gf_sim *sim)
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
