/*
 * netCDF reading for post-processing (see gf_ncread.h): thin wrappers on
 * netCDF-C that turn every failure into one line "file: what: reason".
 */
#include "gf_ncread.h"

#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int gf_ncr_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

gf_status gf_ncr_open(gf_ctx *ctx, const char *path, gf_ncr *f)
{
    f->ncid = -1;
    snprintf(f->path, sizeof f->path, "%s", path);
    if (!gf_ncr_exists(path))
        return GF_FAIL(ctx, GF_ERR_IO, "%s: file not found", path);
    int rc = nc_open(path, NC_NOWRITE, &f->ncid);
    if (rc != NC_NOERR) {
        f->ncid = -1;
        return GF_FAIL(ctx, GF_ERR_IO, "%s: cannot open as netCDF (%s): corrupt or truncated file?", path,
                       nc_strerror(rc));
    }
    return GF_OK;
}

void gf_ncr_close(gf_ncr *f)
{
    if (f && f->ncid >= 0)
        nc_close(f->ncid);
    if (f)
        f->ncid = -1;
}

int gf_ncr_has_var(const gf_ncr *f, const char *name)
{
    int varid;
    return nc_inq_varid(f->ncid, name, &varid) == NC_NOERR;
}

int gf_ncr_has_att(const gf_ncr *f, const char *name)
{
    nc_type t;
    size_t len;
    return nc_inq_att(f->ncid, NC_GLOBAL, name, &t, &len) == NC_NOERR;
}

gf_status gf_ncr_att_double(gf_ctx *ctx, const gf_ncr *f, const char *name, double *out)
{
    nc_type t;
    size_t len;
    *out = NAN;
    int rc = nc_inq_att(f->ncid, NC_GLOBAL, name, &t, &len);
    if (rc != NC_NOERR)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: missing global attribute '%s'", f->path, name);
    if (t == NC_CHAR || t == NC_STRING || len < 1)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: global attribute '%s' is not numeric", f->path, name);
    double buf[8];
    if (len > 8)
        len = 8;
    rc = nc_get_att_double(f->ncid, NC_GLOBAL, name, buf);
    if (rc != NC_NOERR)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: attribute '%s': %s", f->path, name, nc_strerror(rc));
    *out = buf[0];
    return GF_OK;
}

double gf_ncr_att_double_or(const gf_ncr *f, const char *name, double fallback)
{
    double v;
    if (!gf_ncr_has_att(f, name) || gf_ncr_att_double(NULL, f, name, &v) != GF_OK)
        return fallback;
    return v;
}

static void att_text(int ncid, int varid, const char *name, char *buf, size_t size, int *found)
{
    nc_type t;
    size_t len;
    *found = 0;
    if (size == 0)
        return;
    buf[0] = '\0';
    if (nc_inq_att(ncid, varid, name, &t, &len) != NC_NOERR)
        return;
    if (t == NC_CHAR) {
        char *tmp = malloc(len + 1);
        if (!tmp)
            return;
        if (nc_get_att_text(ncid, varid, name, tmp) == NC_NOERR) {
            tmp[len] = '\0';
            snprintf(buf, size, "%s", tmp);
            *found = 1;
        }
        free(tmp);
    } else if (t == NC_STRING && len >= 1) {
        char **tmp = calloc(len, sizeof *tmp);
        if (!tmp)
            return;
        if (nc_get_att_string(ncid, varid, name, tmp) == NC_NOERR) {
            snprintf(buf, size, "%s", tmp[0] ? tmp[0] : "");
            *found = 1;
            nc_free_string(len, tmp);
        }
        free(tmp);
    }
}

gf_status gf_ncr_att_text(gf_ctx *ctx, const gf_ncr *f, const char *name, char *buf, size_t size)
{
    int found;
    att_text(f->ncid, NC_GLOBAL, name, buf, size, &found);
    if (!found)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: missing text attribute '%s'", f->path, name);
    return GF_OK;
}

void gf_ncr_var_att_text(const gf_ncr *f, const char *var, const char *att, char *buf, size_t size)
{
    int varid, found;
    if (size)
        buf[0] = '\0';
    if (nc_inq_varid(f->ncid, var, &varid) != NC_NOERR)
        return;
    att_text(f->ncid, varid, att, buf, size, &found);
}

gf_status gf_ncr_dim_len(gf_ctx *ctx, const gf_ncr *f, const char *name, size_t *len)
{
    int dimid, rc = nc_inq_dimid(f->ncid, name, &dimid);
    if (rc == NC_NOERR)
        rc = nc_inq_dimlen(f->ncid, dimid, len);
    if (rc != NC_NOERR)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: dimension '%s': %s", f->path, name, nc_strerror(rc));
    return GF_OK;
}

/* Variable id, rank and shape; checks the rank. */
static gf_status var_shape(gf_ctx *ctx, const gf_ncr *f, const char *name, int want_rank, int *varid, size_t *shape)
{
    int rc = nc_inq_varid(f->ncid, name, varid);
    if (rc != NC_NOERR)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: missing variable '%s'", f->path, name);
    int ndims, dimids[NC_MAX_VAR_DIMS];
    rc = nc_inq_var(f->ncid, *varid, NULL, NULL, &ndims, dimids, NULL);
    if (rc != NC_NOERR)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: variable '%s': %s", f->path, name, nc_strerror(rc));
    if (ndims != want_rank)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: variable '%s' has %d dimensions, expected %d", f->path, name, ndims,
                       want_rank);
    for (int d = 0; d < ndims; ++d)
        if ((rc = nc_inq_dimlen(f->ncid, dimids[d], &shape[d])) != NC_NOERR)
            return GF_FAIL(ctx, GF_ERR_IO, "%s: variable '%s': %s", f->path, name, nc_strerror(rc));
    return GF_OK;
}

/* _FillValue -> NaN, so that statistics skip unwritten records. */
static void fill_to_nan(const gf_ncr *f, int varid, double *v, size_t n)
{
    double fill;
    if (nc_get_att_double(f->ncid, varid, "_FillValue", &fill) != NC_NOERR)
        return;
    for (size_t i = 0; i < n; ++i)
        if (v[i] == fill)
            v[i] = NAN;
}

static gf_status read_failed(gf_ctx *ctx, const gf_ncr *f, const char *name, int rc)
{
    return GF_FAIL(ctx, GF_ERR_IO, "%s: reading variable '%s' failed (%s): corrupt or truncated file?", f->path,
                   name, nc_strerror(rc));
}

/* The whole variable name, of rank 1 or 2 (its shape into shape[]), into
 * *data (malloc'ed; NULL on failure), fill values as NaN. */
static gf_status read_whole(gf_ctx *ctx, const gf_ncr *f, const char *name, int rank, size_t *shape, double **data)
{
    int varid;
    *data = NULL;
    GF_TRY(var_shape(ctx, f, name, rank, &varid, shape));
    size_t n = rank == 2 ? shape[0] * shape[1] : shape[0];
    double *v = malloc((n ? n : 1) * sizeof *v);
    if (!v)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "%s: '%s': out of memory", f->path, name);
    int rc = n ? nc_get_var_double(f->ncid, varid, v) : NC_NOERR;
    if (rc != NC_NOERR) {
        free(v);
        return read_failed(ctx, f, name, rc);
    }
    fill_to_nan(f, varid, v, n);
    *data = v;
    return GF_OK;
}

gf_status gf_ncr_var_1d(gf_ctx *ctx, const gf_ncr *f, const char *name, double **data, size_t *n)
{
    size_t shape[1];
    *n = 0;
    GF_TRY(read_whole(ctx, f, name, 1, shape, data));
    *n = shape[0];
    return GF_OK;
}

gf_status gf_ncr_var_2d(gf_ctx *ctx, const gf_ncr *f, const char *name, double **data, size_t *n0, size_t *n1)
{
    size_t shape[2];
    GF_TRY(read_whole(ctx, f, name, 2, shape, data));
    *n0 = shape[0];
    *n1 = shape[1];
    return GF_OK;
}

/* Line k of the 2-d variable name into out (n values, fill values as NaN):
 * a row (k along dimension fixed_dim = 0) or a column (fixed_dim = 1). */
static gf_status read_line(gf_ctx *ctx, const gf_ncr *f, const char *name, int fixed_dim, size_t k, double *out,
                           size_t n)
{
    int varid;
    size_t shape[2];
    GF_TRY(var_shape(ctx, f, name, 2, &varid, shape));
    const int free_dim = 1 - fixed_dim;
    if (k >= shape[fixed_dim] || n != shape[free_dim])
        return GF_FAIL(ctx, GF_ERR_IO, "%s: '%s': %s %zu of %zu x %zu requested with %zu %s", f->path, name,
                       fixed_dim ? "column" : "row", k, shape[0], shape[1], n, fixed_dim ? "rows" : "columns");
    size_t start[2] = {0, 0}, count[2] = {1, 1};
    start[fixed_dim] = k;
    count[free_dim] = n;
    int rc = n ? nc_get_vara_double(f->ncid, varid, start, count, out) : NC_NOERR;
    if (rc != NC_NOERR)
        return read_failed(ctx, f, name, rc);
    fill_to_nan(f, varid, out, n);
    return GF_OK;
}

gf_status gf_ncr_var_2d_col(gf_ctx *ctx, const gf_ncr *f, const char *name, size_t k, double *out, size_t n0)
{
    return read_line(ctx, f, name, 1, k, out, n0);
}

gf_status gf_ncr_var_2d_row(gf_ctx *ctx, const gf_ncr *f, const char *name, size_t k, double *out, size_t n1)
{
    return read_line(ctx, f, name, 0, k, out, n1);
}

gf_status gf_ncr_char_row(gf_ctx *ctx, const gf_ncr *f, const char *name, size_t k, char *buf, size_t size)
{
    int varid;
    size_t shape[2];
    if (size)
        buf[0] = '\0';
    GF_TRY(var_shape(ctx, f, name, 2, &varid, shape));
    if (k >= shape[0])
        return GF_FAIL(ctx, GF_ERR_IO, "%s: '%s': row %zu of %zu", f->path, name, k, shape[0]);
    size_t n = shape[1] < size - 1 ? shape[1] : size - 1;
    size_t start[2] = {k, 0}, count[2] = {1, n};
    int rc = nc_get_vara_text(f->ncid, varid, start, count, buf);
    if (rc != NC_NOERR)
        return read_failed(ctx, f, name, rc);
    buf[n] = '\0';
    return GF_OK;
}

gf_status gf_ncr_var_record(gf_ctx *ctx, const gf_ncr *f, const char *name, size_t k, double *out, size_t n)
{
    int varid, ndims, dimids[NC_MAX_VAR_DIMS];
    int rc = nc_inq_varid(f->ncid, name, &varid);
    if (rc != NC_NOERR)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: missing variable '%s'", f->path, name);
    if ((rc = nc_inq_var(f->ncid, varid, NULL, NULL, &ndims, dimids, NULL)) != NC_NOERR || ndims < 1)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: variable '%s': bad shape", f->path, name);
    size_t start[NC_MAX_VAR_DIMS] = {0}, count[NC_MAX_VAR_DIMS], total = 1, len0;
    nc_inq_dimlen(f->ncid, dimids[0], &len0);
    if (k >= len0)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: '%s': record %zu of %zu", f->path, name, k, len0);
    start[0] = k;
    count[0] = 1;
    for (int d = 1; d < ndims; ++d) {
        nc_inq_dimlen(f->ncid, dimids[d], &count[d]);
        total *= count[d];
    }
    if (total != n)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: '%s': record has %zu values, expected %zu", f->path, name, total, n);
    if ((rc = nc_get_vara_double(f->ncid, varid, start, count, out)) != NC_NOERR)
        return read_failed(ctx, f, name, rc);
    fill_to_nan(f, varid, out, n);
    return GF_OK;
}
