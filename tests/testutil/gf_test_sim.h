/*
 * Sims for tests: a run spec of a scene with the seeds' defaults and small
 * acetate-like grains (D = 3 mm, rho_p = 1319 kg m-3, monodisperse: the
 * Foerster et al. 1994 collision material), and a sim that writes no file.
 */
#ifndef GF_TEST_SIM_H
#define GF_TEST_SIM_H

#include <stdio.h>
#include <string.h>

#include "gf_sim.h"

static inline gf_run_spec gf_test_spec(const char *scene)
{
    gf_run_spec s;
    gf_run_spec_defaults(&s);
    snprintf(s.scene, sizeof s.scene, "%s", scene);
    s.grains.diameter_m = 3e-3;
    s.grains.density_kg_m3 = 1319.0;
    s.grains.polydispersity = 0.0;
    return s;
}

/* Sim with no output directory and `threads` OpenMP threads (0: default). */
static inline gf_status gf_test_sim(gf_ctx *ctx, const gf_run_spec *spec, int threads, gf_sim **out)
{
    gf_sim_options opt;
    memset(&opt, 0, sizeof opt);
    opt.n_threads = threads;
    return gf_sim_create(ctx, spec, &opt, out);
}

#endif
