/*
 * diagnostics.nc: scalar time series of a run (docs/output.md). One double
 * variable per diagnostic along the unlimited `time` dimension; the scene
 * chooses the list (kinetic_energy, ecx_per_grain, n_contacts, ... plus its
 * own, e.g. front_position for a column collapse). The file is small, so
 * it is left uncompressed with the library's default chunking.
 */
#include <netcdf.h>

#include "io/gf_nc_internal.h"

gf_status gf_nc_diagnostics_open(gf_ctx *ctx, const char *path, const gf_nc_meta *meta, const gf_var_info *vars,
                                 int n_vars, gf_nc_writer **out)
{
    *out = NULL;
    if (n_vars < 0 || (n_vars > 0 && !vars))
        return GF_FAIL(ctx, GF_ERR_ARG, "%s: bad diagnostic list (n_vars = %d)", path ? path : "diagnostics",
                       n_vars);
    for (int i = 0; i < n_vars; ++i)
        GF_TRY(gf_nc_check_info(ctx, path, &vars[i], i));
    gf_nc_writer *w;
    GF_TRY(gf_nc_begin(ctx, path, meta, GF_NC_DIAGNOSTICS, NULL, &w));
    gf_status st = gf_nc_alloc_varids(w, n_vars);
    for (int i = 0; i < n_vars && st == GF_OK; ++i)
        st = gf_nc_def_var(w, vars[i].name, NC_DOUBLE, 1, &w->dim_time, &vars[i], &w->varids[i]);
    if (st == GF_OK)
        st = gf_nc_end_def(w);
    return gf_nc_open_done(w, st, out);
}

gf_status gf_nc_diagnostics_append(gf_nc_writer *w, double t_s, const double *values)
{
    if (!w || w->kind != GF_NC_DIAGNOSTICS)
        return GF_FAIL(w ? w->ctx : NULL, GF_ERR_ARG, "diagnostics append: not a diagnostics writer");
    if (w->n_vars > 0 && !values)
        return GF_FAIL(w->ctx, GF_ERR_ARG, "%s: NULL values for %d diagnostics", w->path, w->n_vars);
    GF_TRY(gf_nc_put_time(w, t_s));
    size_t start = w->n_records;
    for (int i = 0; i < w->n_vars; ++i)
        GF_TRY(gf_nc_check(w, nc_put_var1_double(w->ncid, w->varids[i], &start, &values[i]), "put diagnostic"));
    w->n_records++;
    return GF_OK;
}
