/*
 * Checkpoint files (HDF5): the one HDF5 caller of the engine. A checkpoint is
 * a flat set of named 1-D datasets (float64, int64, uint64, uint8) in the root
 * group; gf_sim decides what goes in (gf_sim.c, "checkpoint"). Writing goes to
 * "<path>.tmp.<pid>" and renames on success, so a killed run never leaves a
 * truncated checkpoint under the final name, a failed write leaves the
 * previous file in place, and processes writing the same path at once each
 * rename a complete file.
 * Owner: the caller of open/create, released by gf_restart_close.
 */
#ifndef GF_RESTART_H
#define GF_RESTART_H

#include <stddef.h>
#include <stdint.h>

#include "core/gf_status.h"

typedef struct gf_restart gf_restart;

gf_status gf_restart_create(gf_ctx *ctx, const char *path, gf_restart **out);
gf_status gf_restart_open(gf_ctx *ctx, const char *path, gf_restart **out);
/* Closes; for a file being written, renames the temporary file to path,
 * unless a dataset failed to write (then GF_ERR_IO, path untouched). Accepts NULL. */
gf_status gf_restart_close(gf_restart **r);
/* Closes a file being written without committing it (removes the temporary
 * file): for a caller whose own part of the writing failed. Accepts NULL. */
void gf_restart_abort(gf_restart **r);

gf_status gf_restart_put_f64(gf_restart *r, const char *name, size_t n, const double *v);
gf_status gf_restart_put_i64(gf_restart *r, const char *name, size_t n, const int64_t *v);
gf_status gf_restart_put_u64(gf_restart *r, const char *name, size_t n, const uint64_t *v);
gf_status gf_restart_put_u8(gf_restart *r, const char *name, size_t n, const uint8_t *v);

/* 1 when dataset name exists (optional datasets added after the first format). */
int gf_restart_has(gf_restart *r, const char *name);
/* Length of dataset name (GF_ERR_IO naming the dataset when absent). */
gf_status gf_restart_len(gf_restart *r, const char *name, size_t *n);
/* Reads exactly n values (GF_ERR_IO when the length differs). */
gf_status gf_restart_get_f64(gf_restart *r, const char *name, size_t n, double *v);
gf_status gf_restart_get_i64(gf_restart *r, const char *name, size_t n, int64_t *v);
gf_status gf_restart_get_u64(gf_restart *r, const char *name, size_t n, uint64_t *v);
gf_status gf_restart_get_u8(gf_restart *r, const char *name, size_t n, uint8_t *v);

#endif
