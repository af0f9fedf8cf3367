/*
 * Shared driver of the scene tests: a dry run spec for the seeds' grains, a
 * loop that advances a simulation until its scene's done() holds (or a time
 * limit), wall-clock timing, and the packing-seed ensemble of the
 * validations (published laws are fits to ensemble behaviour, while one
 * realisation of a dense granular flow scatters by several %). Header-only,
 * static functions.
 */
#ifndef GF_SCENE_RUNNER_H
#define GF_SCENE_RUNNER_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
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

/* The simulation of spec on one thread (the validations' figures are one-thread runs); NULL, with the
 * failure counted, when gf_sim_create refuses it. */
static inline gf_sim *runner_create(gf_ctx *ctx, const gf_run_spec *spec)
{
    gf_sim *sim = NULL;
    gf_sim_options opt = {.n_threads = 1};
    GF_CHECK_OK(gf_sim_create(ctx, spec, &opt, &sim), ctx);
    return sim;
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

/*
 * Number of packing seeds of an ensemble: `--seeds N` as argv[1..2] (then
 * consumed: *argi is the index of the first remaining argument), else the
 * environment's GF_TEST_SEEDS, else 1. Clamped to [1, max].
 */
static inline int runner_seeds(int argc, char **argv, int *argi, int max)
{
    int n = getenv("GF_TEST_SEEDS") ? atoi(getenv("GF_TEST_SEEDS")) : 1;
    *argi = 1;
    if (argc > 2 && strcmp(argv[1], "--seeds") == 0)
        n = atoi(argv[2]), *argi = 3;
    return n < 1 ? 1 : n > max ? max : n;
}

/* Mean and sample standard deviation (sd 0 for a single value). */
static inline void runner_mean_sd(const double *x, int n, double *mean, double *sd)
{
    double s = 0.0, q = 0.0;
    for (int k = 0; k < n; ++k)
        s += x[k];
    *mean = s / n;
    for (int k = 0; k < n; ++k)
        q += (x[k] - *mean) * (x[k] - *mean);
    *sd = n > 1 ? sqrt(q / (n - 1)) : 0.0;
}

/* The Janssen silo (scene janssen, side S): the share of the horizontal load its side walls receive that
 * the frictionless safety planes behind the glued grains carry (the scene's walls 2-5: x low, x high,
 * z low, z high), against the glued grains' load normal to their wall (the x walls hold the corners). A
 * grain that leans on a plane meets a wall without friction. */
static inline double runner_silo_plane_share(gf_sim *sim, double S)
{
    const gf_particles *p = gf_sim_particles(sim);
    double planes = 0.0, glued = 0.0, f[3];
    for (int w = 2; w < 6; ++w) {
        gf_sim_wall_force(sim, w, f);
        planes += fabs(f[w < 4 ? 0 : 2]);
    }
    for (size_t i = 0; i < p->n_local; ++i)
        if (p->flags[i] & GF_P_GLUED) {
            int on_x = p->x_m[i] < 0.0 || p->x_m[i] > S;
            glued += fabs(on_x ? p->fx_N[i] : p->fz_N[i]);
        }
    return planes / (planes + glued);
}

#endif
