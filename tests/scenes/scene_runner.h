/*
 * Shared driver of the scene tests: a dry run spec for the seeds' grains, a
 * loop that advances a simulation until its scene's done() holds (or a time
 * limit), and wall-clock timing. Header-only, static functions.
 */
#ifndef GF_SCENE_RUNNER_H
#define GF_SCENE_RUNNER_H

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "gf_sim.h"
#include "gf_test.h"
#include "scenes/gf_scene.h"

static inline double runner_now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Dry spec: D = 1 cm, 10 % polydispersity, rho_p = 2500 (Izard §2.1.3.3). */
static inline void runner_dry_spec(gf_run_spec *s, const char *scene)
{
    gf_run_spec_defaults(s);
    snprintf(s->scene, sizeof s->scene, "%s", scene);
    s->grains.diameter_m = 0.01;
    s->grains.polydispersity = 0.10;
    s->grains.density_kg_m3 = 2500.0;
    s->output.particles = s->output.fields = s->output.probes = s->output.diagnostics = 0;
    snprintf(s->fluid.model, sizeof s->fluid.model, "none");
}

/* Advances until done() or t_max_nd (sqrt(D/g)); checks done every `every_nd`. Returns steps run. */
static inline long runner_until_done(gf_sim *sim, double t_max_nd, double every_nd)
{
    const gf_run_spec *s = gf_sim_spec(sim);
    const gf_scene_desc *d = gf_scene_find(s->scene);
    double tg = sqrt(s->grains.diameter_m / s->gravity_m_s2);
    long chunk = (long)ceil(every_nd * tg / gf_sim_dt_s(sim)), steps = 0;
    while (gf_sim_time_s(sim) < t_max_nd * tg) {
        gf_status st = gf_sim_advance(sim, chunk);
        GF_CHECK_OK(st, gf_sim_ctx(sim));
        if (st != GF_OK)
            break;
        steps += chunk;
        if (d->done && d->done(sim))
            break;
    }
    return steps;
}

#endif
