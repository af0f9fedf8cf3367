/*
 * fields.nc: cell-centred fluid fields on a uniform grid (docs/output.md).
 * Dimensions (time, z, y, x) in C order, so a field stored x-fastest as
 * f[(k ny + j) nx + i] is written as is. Coordinate variables x, y, z hold
 * the cell centres lo + (i + 1/2) h with axis X/Y/Z (CF 1.10 §4, §5): a
 * reader recovers the grid without knowing the solver.
 *
 * Chunking: one time record and whole (y, x) planes, as many z planes as
 * fit in about 1 Mi values (8 MiB), so a snapshot is a few chunks and an
 * append never rewrites a chunk. Shuffle + deflate level 1: fluid fields
 * are smooth and the fluid fraction is constant (1) away from the grains,
 * which compresses well.
 */
#include <math.h>
#include <netcdf.h>
#include <stdlib.h>

#include "io/gf_nc_internal.h"

enum { CHUNK_VALUES = 1 << 20 };

static gf_status check_grid(gf_ctx *ctx, const char *path, const int n_cells[3], const double lo_m[3],
                            const double cell_m[3])
{
    if (!n_cells || !lo_m || !cell_m)
        return GF_FAIL(ctx, GF_ERR_ARG, "%s: grid description missing", path);
    for (int k = 0; k < 3; ++k) {
        if (n_cells[k] < 1)
            return GF_FAIL(ctx, GF_ERR_ARG, "%s: n_cells[%d] = %d must be >= 1", path, k, n_cells[k]);
        if (!(cell_m[k] > 0.0) || !isfinite(cell_m[k]) || !isfinite(lo_m[k]))
            return GF_FAIL(ctx, GF_ERR_ARG, "%s: cell size %g m / origin %g m along axis %d not valid", path,
                           cell_m[k], lo_m[k], k);
    }
    return GF_OK;
}

static gf_status define_fields(gf_nc_writer *w, const double lo_m[3], const double cell_m[3],
                               const gf_var_info *vars)
{
    static const char *const names[3] = {"x", "y", "z"};
    static const char axes[3] = {'X', 'Y', 'Z'};
    static const gf_var_info coord_info[3] = {{"x", "m", "cell-centre coordinate along x (streamwise)", NULL},
                                              {"y", "m", "cell-centre coordinate along y (vertical)", NULL},
                                              {"z", "m", "cell-centre coordinate along z (spanwise)", NULL}};
    int dim[3], var_coord[3];
    for (int k = 0; k < 3; ++k) {
        GF_TRY(gf_nc_check(w, nc_def_dim(w->ncid, names[k], w->n_cells[k], &dim[k]), "def_dim"));
        GF_TRY(gf_nc_def_var(w, names[k], NC_DOUBLE, 1, &dim[k], &coord_info[k], &var_coord[k]));
        GF_TRY(gf_nc_check(w, nc_put_att_text(w->ncid, var_coord[k], "axis", 1, &axes[k]), "axis"));
        /* coordinate variables have no missing values (CF §5) */
        GF_TRY(gf_nc_check(w, nc_def_var_fill(w->ncid, var_coord[k], 1, NULL), "no fill"));
    }
    int dims[4] = {w->dim_time, dim[2], dim[1], dim[0]};
    size_t plane = w->n_cells[0] * w->n_cells[1];
    size_t nz_chunk = plane >= CHUNK_VALUES ? 1 : CHUNK_VALUES / plane;
    if (nz_chunk > w->n_cells[2])
        nz_chunk = w->n_cells[2];
    size_t chunks[4] = {1, nz_chunk, w->n_cells[1], w->n_cells[0]};
    for (int i = 0; i < w->n_vars; ++i) {
        GF_TRY(gf_nc_def_var(w, vars[i].name, NC_DOUBLE, 4, dims, &vars[i], &w->varids[i]));
        GF_TRY(gf_nc_compress(w, w->varids[i], chunks));
    }
    GF_TRY(gf_nc_end_def(w));
    size_t n_max = w->n_cells[0];
    for (int k = 1; k < 3; ++k)
        if (w->n_cells[k] > n_max)
            n_max = w->n_cells[k];
    double *c = malloc(n_max * sizeof *c);
    if (!c)
        return GF_FAIL(w->ctx, GF_ERR_NOMEM, "%s: out of memory", w->path);
    gf_status st = GF_OK;
    for (int k = 0; k < 3 && st == GF_OK; ++k) {
        for (size_t i = 0; i < w->n_cells[k]; ++i)
            c[i] = lo_m[k] + ((double)i + 0.5) * cell_m[k];
        st = gf_nc_check(w, nc_put_var_double(w->ncid, var_coord[k], c), "put cell centres");
    }
    free(c);
    return st;
}

gf_status gf_nc_fields_open(gf_ctx *ctx, const char *path, const gf_nc_meta *meta, const int n_cells[3],
                            const double lo_m[3], const double cell_m[3], const gf_var_info *vars, int n_vars,
                            gf_nc_writer **out)
{
    *out = NULL;
    const char *where = path ? path : "fields";
    GF_TRY(check_grid(ctx, where, n_cells, lo_m, cell_m));
    static const char *const coordinates[] = {"x", "y", "z", NULL};
    GF_TRY(gf_nc_check_vars(ctx, where, "field", vars, n_vars, coordinates));
    gf_nc_writer *w;
    GF_TRY(gf_nc_begin(ctx, path, meta, GF_NC_FIELDS, NULL, &w));
    for (int k = 0; k < 3; ++k) {
        w->n_cells[k] = (size_t)n_cells[k];
        w->grid_lo_m[k] = lo_m[k];
        w->grid_cell_m[k] = cell_m[k];
    }
    gf_status st = gf_nc_alloc_varids(w, n_vars);
    if (st == GF_OK)
        st = define_fields(w, lo_m, cell_m, vars);
    return gf_nc_open_done(w, st, out);
}

gf_status gf_nc_fields_append(gf_nc_writer *w, double t_s, const double *const *fields)
{
    if (!w || w->kind != GF_NC_FIELDS)
        return GF_FAIL(w ? w->ctx : NULL, GF_ERR_ARG, "fields append: not a fields writer");
    if (!fields)
        return GF_FAIL(w->ctx, GF_ERR_ARG, "%s: NULL field array", w->path);
    for (int i = 0; i < w->n_vars; ++i)
        if (!fields[i])
            return GF_FAIL(w->ctx, GF_ERR_ARG, "%s: field %d is NULL", w->path, i);
    GF_TRY(gf_nc_put_time(w, t_s));
    size_t start[4] = {w->n_records, 0, 0, 0};
    size_t count[4] = {1, w->n_cells[2], w->n_cells[1], w->n_cells[0]};
    for (int i = 0; i < w->n_vars; ++i)
        GF_TRY(gf_nc_check(w, nc_put_vara_double(w->ncid, w->varids[i], start, count, fields[i]),
                           "put field record"));
    w->n_records++;
    return GF_OK;
}
