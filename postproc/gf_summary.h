/*
 * Campaign summary: summary.nc (CF-1.10, one entry per run along dimension
 * "run") and summary.csv (same columns, header line first). Columns: the
 * run's identity and inputs (run_id, scene, St, r, a, Phi_i, fluid_model,
 * status, error, ...), then every column declared in the stage table, in
 * table order. Missing values are NaN (_FillValue) in netCDF and empty in
 * CSV. Both files are written to "<name>.tmp" and renamed.
 */
#ifndef GF_SUMMARY_H
#define GF_SUMMARY_H

#include "core/gf_status.h"
#include "stages/gf_stage.h"

/* Every column, identity then the stages' in stage-table order, terminated by
 * an entry with name NULL (gf_summary_columns.c). */
extern const gf_post_col gf_summary_columns[];

gf_status gf_summary_write(gf_ctx *ctx, const char *dir, const gf_post_row *rows, int n_rows);

/* Reads summary.nc back into rows (the figures are drawn from it). *rows is malloc'ed. */
gf_status gf_summary_read(gf_ctx *ctx, const char *path, gf_post_row **rows, int *n_rows);

/* The row of run_id among rows[0..n_rows), NULL if absent. */
const gf_post_row *gf_summary_find(const gf_post_row *rows, int n_rows, const char *run_id);

#endif
