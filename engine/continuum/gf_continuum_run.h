/*
 * gf_continuum_run: the run the continuum scenes share (method: continuum).
 * A scene describes itself from the run spec (solver, initial volume
 * fraction, diagnostics variables and their sampler, run length); the run
 * builds the solver, initialises the pressure, steps to t_end, appends a
 * diagnostics record every output interval and stops between steps on an
 * interrupt; the scene then takes its measures from the final state.
 */
#ifndef GF_CONTINUUM_RUN_H
#define GF_CONTINUUM_RUN_H

#include "continuum/gf_continuum.h"
#include "core/gf_groups.h"
#include "gf_run_spec.h"
#include "io/gf_nc.h"

/* Fills one diagnostics record of the scene's variables (user: the scene's state). */
typedef void (*gf_continuum_sampler)(const gf_continuum *s, void *user, double *values);

/* The diagnostics a continuum scene records: its variables, one record of them from sample. */
typedef struct gf_continuum_diagnostics {
    const gf_var_info *vars;
    int n_vars;
    gf_continuum_sampler sample;
} gf_continuum_diagnostics;

/* What a continuum scene contributes to its run. Times are in the grain time sqrt(D/g) of the spec, as the
 * spec's output interval is. */
typedef struct gf_continuum_scene {
    const char *what;                           /* names the run in messages: "continuum avalanche" */
    gf_continuum_params params;                 /* the solver */
    void (*fill)(gf_continuum *s, void *user);  /* initial volume fraction; NULL: the solver's (1 everywhere) */
    double t_end_s;                             /* run length */
    gf_groups_input groups;                     /* the run's groups, recorded in diagnostics.nc */
    gf_nc_meta meta;                            /* the scene's attributes; the run adds spec, YAML, method */
    gf_continuum_diagnostics diagnostics;
} gf_continuum_scene;

/* Fills *scene from spec; user is the scene's state, handed to fill and sample. Errors: a spec the scene
 * cannot run. */
typedef gf_status (*gf_continuum_describe)(gf_ctx *ctx, const gf_run_spec *spec, void *user,
                                           gf_continuum_scene *scene);

/* Where a run writes: dir/diagnostics.nc (dir NULL: no file) recording resolved_yaml (may be NULL);
 * interrupt (may be NULL) non-zero stops it between steps with GF_ERR_INTERRUPTED. */
typedef struct gf_continuum_output {
    const char *dir, *resolved_yaml;
    volatile int *interrupt;
} gf_continuum_output;

/* Checks the method, describes the scene, runs it to t_end with a diagnostics record every
 * spec->output.interval_nd grain times sqrt(D/g). Returns the owned solver at t_end for the scene's
 * measures; *steps counts the steps taken, also on error. */
gf_status gf_continuum_scene_run(gf_ctx *ctx, const gf_run_spec *spec, gf_continuum_describe describe, void *user,
                                 const gf_continuum_output *out, gf_continuum **solver, long *steps);

#endif
