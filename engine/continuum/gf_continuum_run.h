/*
 * gf_continuum_run: the time loop the continuum scenes share (method:
 * continuum): step to t_end, append a diagnostics record every output
 * interval (the scene's sampler fills it), stop between steps on an interrupt.
 */
#ifndef GF_CONTINUUM_RUN_H
#define GF_CONTINUUM_RUN_H

#include "continuum/gf_continuum.h"
#include "io/gf_nc.h"

/* Fills one diagnostics record of the scene's variables. */
typedef void (*gf_continuum_sampler)(const gf_continuum *s, void *user, double *values);

/* Advances s to t_end_s; with w (may be NULL) appends sample's record at t = 0, every_s, ...;
 * interrupt (may be NULL) non-zero stops with GF_ERR_INTERRUPTED naming what. *steps counts the steps. */
gf_status gf_continuum_run_until(gf_ctx *ctx, gf_continuum *s, double t_end_s, double every_s, gf_nc_writer *w,
                                 gf_continuum_sampler sample, void *user, volatile int *interrupt, const char *what,
                                 long *steps);

#endif
