/*
 * What the coupling tiers' checkpoints share (gf_coupling_checkpoint.c for
 * the unresolved tier, gf_coupling_resolved.c): the fluid state as one list
 * of named arrays, written and read back by the same loop so that the two
 * directions cannot drift apart, and the check that a checkpoint was written
 * on the grid the spec builds. Not a public header: the step loop uses
 * gf_coupling_save/gf_coupling_load.
 */
#ifndef GF_COUPLING_RESTART_H
#define GF_COUPLING_RESTART_H

#include <stdint.h>

#include "fluid/gf_grid.h"
#include "io/gf_restart.h"

/* One float64 dataset of a checkpoint: n values at values (borrowed). */
typedef struct gf_restart_array {
    const char *name;
    size_t n;
    double *values;
} gf_restart_array;

/* Writes, or reads exactly, the n_arrays arrays in list order; the first failure is returned. */
gf_status gf_coupling_put_arrays(gf_restart *r, const gf_restart_array *arrays, int n_arrays);
gf_status gf_coupling_get_arrays(gf_restart *r, const gf_restart_array *arrays, int n_arrays);
/* GF_ERR_CONFIG, naming both, when the checkpoint's cells per axis differ from g's. */
gf_status gf_coupling_check_grid(gf_ctx *ctx, const int64_t saved_n_cells[3], const gf_grid *g);

#endif
