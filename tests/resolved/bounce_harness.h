/*
 * Pieces of the bounce harnesses (resolved_oblique.c, resolved_head_on.c, resolved_approach.c):
 * their key=value arguments, and the sampled trace, one growing array per
 * quantity, so that the columns go straight to gf_bounce_measure
 * (postproc/stages/gf_bounce_measure.h).
 */
#ifndef BOUNCE_HARNESS_H
#define BOUNCE_HARNESS_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_run_spec.h"
#include "gf_sim.h"
#include "gf_test.h"

typedef struct harness_arg {
    const char *key;
    double *value;
} harness_arg;

/* The text after "key=" in the last argument naming key, or NULL. */
static inline const char *harness_text(int argc, char **argv, const char *key)
{
    const char *found = NULL;
    size_t n = strlen(key);
    for (int i = 1; i < argc; ++i)
        if (!strncmp(argv[i], key, n) && argv[i][n] == '=')
            found = argv[i] + n + 1;
    return found;
}

/* Sets every numeric argument of table that argv names (key=value). */
static inline void harness_parse(int argc, char **argv, const harness_arg *table, int n)
{
    for (int k = 0; k < n; ++k) {
        const char *v = harness_text(argc, argv, table[k].key);
        if (v)
            *table[k].value = atof(v);
    }
}

#define BOUNCE_TRACE_MAX_COLS 8

typedef struct bounce_trace {
    int n_cols;
    double *col[BOUNCE_TRACE_MAX_COLS];
    size_t n, cap;
} bounce_trace;

/* Appends one sample of n_cols values; -1 when out of memory. */
static inline int bounce_trace_push(bounce_trace *s, const double *x)
{
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 4096;
        for (int c = 0; c < s->n_cols; ++c) {
            double *grown = realloc(s->col[c], s->cap * sizeof *grown);
            if (!grown)
                return -1;
            s->col[c] = grown;
        }
    }
    for (int c = 0; c < s->n_cols; ++c)
        s->col[c][s->n] = x[c];
    s->n++;
    return 0;
}

static inline void bounce_trace_free(bounce_trace *s)
{
    for (int c = 0; c < s->n_cols; ++c)
        free(s->col[c]);
    *s = (bounce_trace){0};
}

/* The resolved tier with the thesis' lubrication (Izard 2014 §3.1.2.2): Brenner's
 * force with roughness eta_e/R, cut-off R/2, off while the surfaces overlap (the
 * contact law alone acts there, as in resolved_bounce_st60). */
static inline void harness_resolved_fluid(gf_run_spec *spec, double rho_kg_m3, double eta_Pa_s, double eta_e_over_R,
                                          double d_over_dx)
{
    snprintf(spec->fluid.model, sizeof spec->fluid.model, "resolved");
    spec->fluid.density_kg_m3 = rho_kg_m3;
    spec->fluid.viscosity_Pa_s = eta_Pa_s;
    spec->fluid.lubrication = 1;
    spec->fluid.roughness_over_R = eta_e_over_R;
    spec->fluid.lub_cutoff_over_R = 0.5;
    snprintf(spec->fluid.lub_overlap, sizeof spec->fluid.lub_overlap, "off");
    spec->fluid.d_over_dx = d_over_dx;
}

/* Sets n scene parameters of spec. */
static inline void harness_scene_params(gf_ctx *ctx, gf_run_spec *spec, const char *const *keys, const double *values,
                                        int n)
{
    for (int k = 0; k < n; ++k)
        GF_CHECK_OK(gf_run_spec_set_param(ctx, spec, keys[k], values[k]), ctx);
}

/* The simulation of spec on n_threads OpenMP threads (0: the library default); NULL, with the failure
 * recorded, when it cannot be built. */
static inline gf_sim *harness_sim_create(gf_ctx *ctx, const gf_run_spec *spec, double n_threads)
{
    gf_sim_options opt = {.n_threads = (int)n_threads};
    gf_sim *sim = NULL;
    GF_CHECK_OK(gf_sim_create(ctx, spec, &opt, &sim), ctx);
    return sim;
}

#endif /* BOUNCE_HARNESS_H */
