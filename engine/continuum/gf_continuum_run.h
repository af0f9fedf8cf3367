/*
 * gf_continuum_run: what the continuum scenes share (method: continuum): their
 * diagnostics file and the time loop (step to t_end, append a diagnostics
 * record every output interval, the scene's sampler filling it, stop between
 * steps on an interrupt).
 */
#ifndef GF_CONTINUUM_RUN_H
#define GF_CONTINUUM_RUN_H

#include "continuum/gf_continuum.h"
#include "core/gf_groups.h"
#include "io/gf_nc.h"

/* Opens dir/diagnostics.nc with the scene's variables: meta carries the scene's attributes (spec, resolved
 * YAML, geometry), the groups computed from in and the method's fluid model and stages are added here. */
gf_status gf_continuum_diagnostics_open(gf_ctx *ctx, const gf_groups_input *in, gf_nc_meta meta, const char *dir,
                                        const gf_var_info *vars, int n_vars, gf_nc_writer **w);

/* Fills one diagnostics record of the scene's variables. */
typedef void (*gf_continuum_sampler)(const gf_continuum *s, void *user, double *values);

/* Advances s to t_end_s; with w (may be NULL) appends sample's record at t = 0, every_s, ...;
 * interrupt (may be NULL) non-zero stops with GF_ERR_INTERRUPTED naming what. *steps counts the steps. */
gf_status gf_continuum_run_until(gf_ctx *ctx, gf_continuum *s, double t_end_s, double every_s, gf_nc_writer *w,
                                 gf_continuum_sampler sample, void *user, volatile int *interrupt, const char *what,
                                 long *steps);

#endif
