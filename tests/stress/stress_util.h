/*
 * Helpers of the stress tests: a spec with the seeds' defaults for a scene,
 * a sim with no output (gf_test_sim.h), the elastic energy of a periodic gas
 * (gf_test_energy.h), and the largest grain speed.
 */
#ifndef STRESS_UTIL_H
#define STRESS_UTIL_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gf_sim.h"
#include "gf_test.h"
#include "gf_test_energy.h"
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

#endif
