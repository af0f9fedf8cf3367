/*
 * The netCDF reading layer of post-processing.
 *
 * Stages read run files only through these calls, and only the names that
 * docs/output.md lists (the contract with the engine). Every failure records
 * one line naming the file, the variable or attribute, and netCDF's own
 * reason ("NetCDF: HDF error", "NetCDF: Unknown file format", ...), so a
 * corrupt or truncated file, or a missing variable, gives a per-run message
 * the campaign summary can print next to the run.
 *
 * Arrays are returned malloc'ed (caller frees); values are converted to
 * double whatever the stored type (netCDF converts), and the variable's
 * _FillValue, if any, is turned into NaN.
 */
#ifndef GF_NCREAD_H
#define GF_NCREAD_H

#include <stddef.h>

#include "core/gf_status.h"

typedef struct gf_ncr {
    int ncid;
    char path[512];
} gf_ncr;

/* Opens path read-only. GF_ERR_IO with "path: reason" if it cannot. */
gf_status gf_ncr_open(gf_ctx *ctx, const char *path, gf_ncr *f);
void gf_ncr_close(gf_ncr *f);

/* Non-zero if the file exists (stat), whatever its content. */
int gf_ncr_exists(const char *path);

int gf_ncr_has_var(const gf_ncr *f, const char *name);
int gf_ncr_has_att(const gf_ncr *f, const char *name);

/* Global numeric attribute. GF_ERR_IO if absent or not numeric. */
gf_status gf_ncr_att_double(gf_ctx *ctx, const gf_ncr *f, const char *name, double *out);
/* Global numeric attribute, or fallback when absent (never fails). */
double gf_ncr_att_double_or(const gf_ncr *f, const char *name, double fallback);
/* Global text attribute into buf (truncated, NUL-terminated); "" and GF_ERR_IO if absent. */
gf_status gf_ncr_att_text(gf_ctx *ctx, const gf_ncr *f, const char *name, char *buf, size_t size);

/* Length of a dimension. */
gf_status gf_ncr_dim_len(gf_ctx *ctx, const gf_ncr *f, const char *name, size_t *len);

/* Whole 1-D variable: *data (malloc'ed, n values). */
gf_status gf_ncr_var_1d(gf_ctx *ctx, const gf_ncr *f, const char *name, double **data, size_t *n);
/* Whole 2-D variable, row-major [n0][n1] in the file's dimension order. */
gf_status gf_ncr_var_2d(gf_ctx *ctx, const gf_ncr *f, const char *name, double **data, size_t *n0, size_t *n1);
/* Column k of a 2-D variable var(d0, d1): the n0 values var[:, k] (e.g. all grains at frame k). */
gf_status gf_ncr_var_2d_col(gf_ctx *ctx, const gf_ncr *f, const char *name, size_t k, double *out, size_t n0);
/* Row k of a 2-D variable var(d0, d1): the n1 values var[k, :] (e.g. one station's series). */
gf_status gf_ncr_var_2d_row(gf_ctx *ctx, const gf_ncr *f, const char *name, size_t k, double *out, size_t n1);
/* Row k of a 2-D char variable (e.g. station_name(station, name_strlen)) as a C string. */
gf_status gf_ncr_char_row(gf_ctx *ctx, const gf_ncr *f, const char *name, size_t k, char *buf, size_t size);
/* Record k of a variable whose first dimension is time: its n values (product of the other
 * dimensions, checked against n) in file order. */
gf_status gf_ncr_var_record(gf_ctx *ctx, const gf_ncr *f, const char *name, size_t k, double *out, size_t n);
/* Text attribute of a variable ("" if absent). */
void gf_ncr_var_att_text(const gf_ncr *f, const char *var, const char *att, char *buf, size_t size);

#endif
