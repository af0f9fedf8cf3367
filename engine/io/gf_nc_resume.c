/*
 * Suspending a run's files at an interrupt and continuing them after a
 * restart from its checkpoint (gf_nc.h).
 *
 * An interrupted run (signal, Slurm time limit) writes checkpoint.h5 and
 * closes each of its files under "<path>.partial": a complete netCDF file
 * holding the records written so far, under a name that cannot be taken for
 * a finished file. The restarted run opens its writers as a fresh run does
 * (same spec, same variables), then gf_nc_writer_continue copies into each
 * the partial file's global attributes, its variables without a time
 * dimension (for particles.nc the trajectory order, ids and radii, which
 * the restored store, sorted since, no longer has) and its records before
 * the checkpoint's time, one record at a time (a record of particles.nc or
 * fields.nc may be large; the whole series may not fit in memory). The
 * run then appends the following records as if it had never stopped, and a
 * successful close removes the partial file.
 */
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "io/gf_nc_internal.h"

static char *partial_path(const gf_nc_writer *w)
{
    size_t n = strlen(w->path) + sizeof ".partial";
    char *p = malloc(n);
    if (p)
        snprintf(p, n, "%s.partial", w->path);
    return p;
}

gf_status gf_nc_writer_suspend(gf_nc_writer **pw)
{
    if (!pw || !*pw)
        return GF_OK;
    gf_nc_writer *w = *pw;
    *pw = NULL;
    char *partial = partial_path(w);
    int rc = nc_close(w->ncid);
    gf_status st = GF_OK;
    if (!partial)
        st = GF_FAIL(w->ctx, GF_ERR_NOMEM, "%s: out of memory", w->path);
    else if (rc != NC_NOERR)
        st = GF_FAIL(w->ctx, GF_ERR_IO, "netCDF close %s: %s", w->tmp, nc_strerror(rc));
    else if (rename(w->tmp, partial) != 0)
        st = GF_FAIL(w->ctx, GF_ERR_IO, "cannot rename %s to %s", w->tmp, partial);
    if (st != GF_OK)
        remove(w->tmp);
    free(partial);
    gf_nc_free(w);
    return st;
}

void gf_nc_remove_partial(const gf_nc_writer *w)
{
    char *partial = partial_path(w);
    if (partial)
        remove(partial);
    free(partial);
}

/* Bytes of one value of a netCDF atomic type (the writers use these only). */
static size_t type_size(nc_type t)
{
    switch (t) {
    case NC_BYTE: case NC_UBYTE: case NC_CHAR: return 1;
    case NC_SHORT: case NC_USHORT: return 2;
    case NC_INT: case NC_UINT: case NC_FLOAT: return 4;
    case NC_INT64: case NC_UINT64: case NC_DOUBLE: return 8;
    default: return 0;
    }
}

/* Global attributes of the partial file over those of the new one: the
 * metadata of the original start (creation time, the Phi_i measured by the
 * preparation, which a restarted run does not repeat). */
static gf_status copy_globals(gf_nc_writer *w, int src)
{
    int n_att;
    GF_TRY(gf_nc_check(w, nc_inq_natts(src, &n_att), "inq global attributes of the partial file"));
    GF_TRY(gf_nc_check(w, nc_redef(w->ncid), "redef")); /* left by gf_nc_writer_continue */
    for (int a = 0; a < n_att; ++a) {
        char name[NC_MAX_NAME + 1];
        GF_TRY(gf_nc_check(w, nc_inq_attname(src, NC_GLOBAL, a, name), "inq attribute name"));
        GF_TRY(gf_nc_check(w, nc_copy_att(src, NC_GLOBAL, name, w->ncid, NC_GLOBAL), "copy global attribute"));
    }
    return GF_OK;
}

/* Appends "<UTC now> continued from the checkpoint at t = ... s" to the
 * history attribute (CF §2.6.2: one line per processing step). */
static gf_status note_history(gf_nc_writer *w, double t_s)
{
    size_t len = 0;
    char *old = NULL;
    if (nc_inq_attlen(w->ncid, NC_GLOBAL, "history", &len) == NC_NOERR) {
        old = calloc(len + 1, 1);
        if (!old)
            return GF_FAIL(w->ctx, GF_ERR_NOMEM, "%s: out of memory", w->path);
        if (nc_get_att_text(w->ncid, NC_GLOBAL, "history", old) != NC_NOERR)
            old[0] = '\0';
    }
    char stamp[32];
    time_t now = time(NULL);
    struct tm utc;
    strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", gmtime_r(&now, &utc));
    size_t n = (old ? strlen(old) : 0) + 128;
    char *text = malloc(n);
    if (!text) {
        free(old);
        return GF_FAIL(w->ctx, GF_ERR_NOMEM, "%s: out of memory", w->path);
    }
    snprintf(text, n, "%s%s%s: continued from checkpoint.h5 at t = %.17g s", old ? old : "", old && *old ? "\n" : "",
             stamp, t_s);
    gf_status st = gf_nc_check(w, nc_put_att_text(w->ncid, NC_GLOBAL, "history", strlen(text), text), "history");
    free(text);
    free(old);
    return st;
}

/* Variable v of src into the same-named variable of w: whole when it has no
 * time dimension, else its first n_rec records. */
static gf_status copy_var(gf_nc_writer *w, int src, int src_time_dim, int v, size_t n_rec, void **buf, size_t *cap)
{
    char name[NC_MAX_NAME + 1];
    nc_type type;
    int ndims, dims[NC_MAX_VAR_DIMS], dst;
    GF_TRY(gf_nc_check(w, nc_inq_var(src, v, name, &type, &ndims, dims, NULL), "inq variable of the partial file"));
    if (nc_inq_varid(w->ncid, name, &dst) != NC_NOERR)
        return GF_FAIL(w->ctx, GF_ERR_IO, "%s: the partial file's variable %s is not in the restarted run's file "
                       "(was the spec changed?)", w->path, name);
    size_t count[NC_MAX_VAR_DIMS], start[NC_MAX_VAR_DIMS] = {0}, values = 1;
    int time_axis = -1;
    for (int d = 0; d < ndims; ++d) {
        GF_TRY(gf_nc_check(w, nc_inq_dimlen(src, dims[d], &count[d]), "inq dimension of the partial file"));
        if (dims[d] == src_time_dim) {
            time_axis = d;
            count[d] = 1;
        }
        values *= count[d];
    }
    size_t bytes = values * type_size(type);
    if (bytes == 0 && values > 0)
        return GF_FAIL(w->ctx, GF_ERR_IO, "%s: variable %s has a type the writers do not use", w->path, name);
    if (bytes > *cap) {
        void *q = realloc(*buf, bytes);
        if (!q)
            return GF_FAIL(w->ctx, GF_ERR_NOMEM, "%s: out of memory copying %s", w->path, name);
        *buf = q, *cap = bytes;
    }
    const size_t n_copies = time_axis < 0 ? 1 : n_rec;
    for (size_t r = 0; r < n_copies && values > 0; ++r) {
        if (time_axis >= 0)
            start[time_axis] = r;
        GF_TRY(gf_nc_check(w, nc_get_vara(src, v, start, count, *buf), "read the partial file"));
        GF_TRY(gf_nc_check(w, nc_put_vara(w->ncid, dst, start, count, *buf), "copy from the partial file"));
    }
    return GF_OK;
}

/* Records of src whose time is below t_before_s (they increase). */
static gf_status records_before(gf_nc_writer *w, int src, int time_dim, double t_before_s, size_t *n_rec,
                                double *last_t_s)
{
    size_t n;
    int var_time;
    GF_TRY(gf_nc_check(w, nc_inq_dimlen(src, time_dim, &n), "inq time of the partial file"));
    GF_TRY(gf_nc_check(w, nc_inq_varid(src, "time", &var_time), "inq time variable of the partial file"));
    double *t = malloc((n ? n : 1) * sizeof *t);
    if (!t)
        return GF_FAIL(w->ctx, GF_ERR_NOMEM, "%s: out of memory", w->path);
    gf_status st = n ? gf_nc_check(w, nc_get_var_double(src, var_time, t), "read time of the partial file") : GF_OK;
    size_t k = 0;
    while (st == GF_OK && k < n && t[k] < t_before_s)
        ++k;
    *n_rec = k;
    *last_t_s = k ? t[k - 1] : w->last_t_s;
    free(t);
    return st;
}

gf_status gf_nc_writer_continue(gf_nc_writer *w, double t_before_s)
{
    char *partial = partial_path(w);
    if (!partial)
        return GF_FAIL(w->ctx, GF_ERR_NOMEM, "%s: out of memory", w->path);
    int src;
    int rc = nc_open(partial, NC_NOWRITE, &src);
    if (rc != NC_NOERR) {
        gf_status st = GF_FAIL(w->ctx, GF_ERR_IO, "cannot continue %s: %s: %s", w->path, partial, nc_strerror(rc));
        free(partial);
        return st;
    }
    free(partial);
    int time_dim, n_vars;
    size_t n_rec = 0, cap = 0;
    void *buf = NULL;
    gf_status st = gf_nc_check(w, nc_inq_dimid(src, "time", &time_dim), "inq time dimension of the partial file");
    if (st == GF_OK)
        st = records_before(w, src, time_dim, t_before_s, &n_rec, &w->last_t_s);
    if (st == GF_OK)
        st = copy_globals(w, src);
    if (st == GF_OK)
        st = note_history(w, t_before_s);
    if (st == GF_OK)
        st = gf_nc_end_def(w);
    if (st == GF_OK)
        st = gf_nc_check(w, nc_inq_nvars(src, &n_vars), "inq variables of the partial file");
    for (int v = 0; st == GF_OK && v < n_vars; ++v)
        st = copy_var(w, src, time_dim, v, n_rec, &buf, &cap);
    free(buf);
    nc_close(src);
    if (st != GF_OK)
        return st;
    w->n_records = n_rec;
    return w->kind == GF_NC_PARTICLES ? gf_nc_particles_reload_ids(w) : GF_OK;
}
