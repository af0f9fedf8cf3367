/* HDF5 checkpoint container; see gf_restart.h. */
#include "io/gf_restart.h"

#include <hdf5.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

struct gf_restart {
    gf_ctx *ctx;
    hid_t file;
    int writing, failed; /* failed: a dataset could not be written, the file is not committed */
    char path[1024], tmp[1064];
};

gf_status gf_restart_create(gf_ctx *ctx, const char *path, gf_restart **out)
{
    *out = NULL;
    gf_restart *r = calloc(1, sizeof *r);
    if (!r)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "checkpoint: cannot allocate");
    r->ctx = ctx;
    r->writing = 1;
    snprintf(r->path, sizeof r->path, "%s", path);
    /* one temporary name per process: workers of a campaign may write the
     * same shared preparation at once, each renaming a complete file */
    snprintf(r->tmp, sizeof r->tmp, "%s.tmp.%ld", path, (long)getpid());
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL); /* errors become status codes, not stderr dumps */
    r->file = H5Fcreate(r->tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (r->file < 0) {
        free(r);
        return GF_FAIL(ctx, GF_ERR_IO, "checkpoint: cannot create %s", path);
    }
    *out = r;
    return GF_OK;
}

gf_status gf_restart_open(gf_ctx *ctx, const char *path, gf_restart **out)
{
    *out = NULL;
    gf_restart *r = calloc(1, sizeof *r);
    if (!r)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "checkpoint: cannot allocate");
    r->ctx = ctx;
    snprintf(r->path, sizeof r->path, "%s", path);
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    r->file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (r->file < 0) {
        free(r);
        return GF_FAIL(ctx, GF_ERR_IO, "checkpoint: cannot open %s (missing or not HDF5)", path);
    }
    *out = r;
    return GF_OK;
}

static gf_status finish(gf_restart **pr, int commit)
{
    if (!pr || !*pr)
        return GF_OK;
    gf_restart *r = *pr;
    gf_status st = GF_OK;
    if (H5Fclose(r->file) < 0)
        st = GF_FAIL(r->ctx, GF_ERR_IO, "checkpoint: cannot close %s", r->path);
    if (r->writing) {
        if (commit && r->failed && st == GF_OK)
            st = GF_FAIL(r->ctx, GF_ERR_IO, "checkpoint: %s left as it was (a dataset could not be written)",
                         r->path);
        if (commit && st == GF_OK && rename(r->tmp, r->path) != 0)
            st = GF_FAIL(r->ctx, GF_ERR_IO, "checkpoint: cannot rename %s to %s", r->tmp, r->path);
        if (!commit || st != GF_OK)
            remove(r->tmp);
    }
    free(r);
    *pr = NULL;
    return st;
}

gf_status gf_restart_close(gf_restart **pr)
{
    return finish(pr, 1);
}

void gf_restart_abort(gf_restart **pr)
{
    finish(pr, 0);
}

static gf_status put(gf_restart *r, const char *name, size_t n, hid_t file_type, hid_t mem_type, const void *v)
{
    hsize_t dims[1] = {(hsize_t)n};
    hid_t space = H5Screate_simple(1, dims, NULL);
    hid_t set = H5Dcreate2(r->file, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    herr_t e = set >= 0 && n > 0 ? H5Dwrite(set, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) : 0;
    if (set >= 0)
        H5Dclose(set);
    H5Sclose(space);
    if (set < 0 || e < 0) {
        r->failed = 1;
        return GF_FAIL(r->ctx, GF_ERR_IO, "checkpoint %s: cannot write dataset '%s'", r->path, name);
    }
    return GF_OK;
}

int gf_restart_has(gf_restart *r, const char *name)
{
    return H5Lexists(r->file, name, H5P_DEFAULT) > 0;
}

gf_status gf_restart_len(gf_restart *r, const char *name, size_t *n)
{
    if (H5Lexists(r->file, name, H5P_DEFAULT) <= 0)
        return GF_FAIL(r->ctx, GF_ERR_IO, "checkpoint %s: dataset '%s' is missing", r->path, name);
    hid_t set = H5Dopen2(r->file, name, H5P_DEFAULT);
    hid_t space = H5Dget_space(set);
    hsize_t dims[1] = {0};
    int rank = H5Sget_simple_extent_dims(space, dims, NULL);
    H5Sclose(space);
    H5Dclose(set);
    if (rank != 1)
        return GF_FAIL(r->ctx, GF_ERR_IO, "checkpoint %s: dataset '%s' is not 1-D", r->path, name);
    *n = (size_t)dims[0];
    return GF_OK;
}

static gf_status get(gf_restart *r, const char *name, size_t n, hid_t mem_type, void *v)
{
    size_t len = 0;
    GF_TRY(gf_restart_len(r, name, &len));
    if (len != n)
        return GF_FAIL(r->ctx, GF_ERR_IO, "checkpoint %s: dataset '%s' has %zu values, expected %zu", r->path,
                       name, len, n);
    if (n == 0)
        return GF_OK;
    hid_t set = H5Dopen2(r->file, name, H5P_DEFAULT);
    herr_t e = H5Dread(set, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v);
    H5Dclose(set);
    if (e < 0)
        return GF_FAIL(r->ctx, GF_ERR_IO, "checkpoint %s: cannot read dataset '%s'", r->path, name);
    return GF_OK;
}

gf_status gf_restart_put_f64(gf_restart *r, const char *name, size_t n, const double *v)
{
    return put(r, name, n, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, v);
}
gf_status gf_restart_put_i64(gf_restart *r, const char *name, size_t n, const int64_t *v)
{
    return put(r, name, n, H5T_STD_I64LE, H5T_NATIVE_INT64, v);
}
gf_status gf_restart_put_u64(gf_restart *r, const char *name, size_t n, const uint64_t *v)
{
    return put(r, name, n, H5T_STD_U64LE, H5T_NATIVE_UINT64, v);
}
gf_status gf_restart_put_u8(gf_restart *r, const char *name, size_t n, const uint8_t *v)
{
    return put(r, name, n, H5T_STD_U8LE, H5T_NATIVE_UINT8, v);
}
gf_status gf_restart_get_f64(gf_restart *r, const char *name, size_t n, double *v)
{
    return get(r, name, n, H5T_NATIVE_DOUBLE, v);
}
gf_status gf_restart_get_i64(gf_restart *r, const char *name, size_t n, int64_t *v)
{
    return get(r, name, n, H5T_NATIVE_INT64, v);
}
gf_status gf_restart_get_u64(gf_restart *r, const char *name, size_t n, uint64_t *v)
{
    return get(r, name, n, H5T_NATIVE_UINT64, v);
}
gf_status gf_restart_get_u8(gf_restart *r, const char *name, size_t n, uint8_t *v)
{
    return get(r, name, n, H5T_NATIVE_UINT8, v);
}
