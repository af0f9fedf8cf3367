/*
 * probes.nc: gauges at fixed positions, CF featureType "timeSeries" in the
 * orthogonal multidimensional representation (CF 1.10 §9.3.1, H.2.1):
 * dimensions station and time, a station_name(station, name_strlen)
 * character variable with cf_role = "timeseries_id", the station positions
 * x, y, z (station), and one (station, time) variable per probed quantity,
 * e.g. excess_pore_pressure (Pa; pressure minus hydrostatic, the basal
 * gauges of Rondon, Pouliquen & Aussillous, Phys. Fluids 2011).
 *
 * Station positions are checked finite and names unique: post-processing
 * selects gauges by name.
 */
#include <math.h>
#include <netcdf.h>
#include <stdlib.h>
#include <string.h>

#include "io/gf_nc_internal.h"

static gf_status check_stations(gf_ctx *ctx, const char *path, int n_stations, const char *const *names,
                                const double *xyz)
{
    if (n_stations < 1 || !names || !xyz)
        return GF_FAIL(ctx, GF_ERR_ARG, "%s: need at least one station with names and positions (n = %d)", path,
                       n_stations);
    for (int i = 0; i < n_stations; ++i) {
        if (!names[i] || !*names[i])
            return GF_FAIL(ctx, GF_ERR_ARG, "%s: station %d has no name", path, i);
        for (int j = 0; j < i; ++j)
            if (strcmp(names[i], names[j]) == 0)
                return GF_FAIL(ctx, GF_ERR_ARG, "%s: station name \"%s\" used twice", path, names[i]);
        for (int k = 0; k < 3; ++k)
            if (!isfinite(xyz[3 * i + k]))
                return GF_FAIL(ctx, GF_ERR_ARG, "%s: station %s: position is not finite", path, names[i]);
    }
    return GF_OK;
}

static gf_status define_probes(gf_nc_writer *w, int n_stations, const char *const *names, const double *xyz,
                               const gf_var_info *vars)
{
    size_t strlen_max = 1;
    for (int i = 0; i < n_stations; ++i)
        if (strlen(names[i]) > strlen_max)
            strlen_max = strlen(names[i]);
    int dim_station, dim_strlen;
    GF_TRY(gf_nc_check(w, nc_def_dim(w->ncid, "station", (size_t)n_stations, &dim_station), "def_dim station"));
    GF_TRY(gf_nc_check(w, nc_def_dim(w->ncid, "name_strlen", strlen_max, &dim_strlen), "def_dim name_strlen"));
    int dims_name[2] = {dim_station, dim_strlen}, var_name, var_xyz[3];
    static const gf_var_info name_info = {"station_name", NULL, "gauge name", NULL};
    GF_TRY(gf_nc_def_var(w, "station_name", NC_CHAR, 2, dims_name, &name_info, &var_name));
    GF_TRY(gf_nc_check(w, nc_put_att_text(w->ncid, var_name, "cf_role", 13, "timeseries_id"), "cf_role"));
    static const gf_var_info xyz_info[3] = {{"x", "m", "gauge position along x (streamwise)", NULL},
                                            {"y", "m", "gauge position along y (vertical, bed-normal)", NULL},
                                            {"z", "m", "gauge position along z (spanwise)", NULL}};
    static const char axes[3] = {'X', 'Y', 'Z'};
    for (int k = 0; k < 3; ++k) {
        GF_TRY(gf_nc_def_var(w, xyz_info[k].name, NC_DOUBLE, 1, &dim_station, &xyz_info[k], &var_xyz[k]));
        GF_TRY(gf_nc_check(w, nc_put_att_text(w->ncid, var_xyz[k], "axis", 1, &axes[k]), "axis"));
    }
    int dims[2] = {dim_station, w->dim_time};
    for (int i = 0; i < w->n_vars; ++i) {
        GF_TRY(gf_nc_def_var(w, vars[i].name, NC_DOUBLE, 2, dims, &vars[i], &w->varids[i]));
        static const char coords[] = "time z y x station_name";
        GF_TRY(gf_nc_check(w, nc_put_att_text(w->ncid, w->varids[i], "coordinates", sizeof coords - 1, coords),
                           "coordinates"));
    }
    GF_TRY(gf_nc_end_def(w));
    /* static station data */
    char *text = calloc((size_t)n_stations * strlen_max, 1);
    double *pos = malloc((size_t)n_stations * sizeof *pos);
    gf_status st = (text && pos) ? GF_OK : GF_FAIL(w->ctx, GF_ERR_NOMEM, "%s: out of memory", w->path);
    for (int i = 0; i < n_stations && st == GF_OK; ++i)
        memcpy(text + (size_t)i * strlen_max, names[i], strlen(names[i]));
    if (st == GF_OK)
        st = gf_nc_check(w, nc_put_var_text(w->ncid, var_name, text), "put station_name");
    for (int k = 0; k < 3 && st == GF_OK; ++k) {
        for (int i = 0; i < n_stations; ++i)
            pos[i] = xyz[3 * i + k];
        st = gf_nc_check(w, nc_put_var_double(w->ncid, var_xyz[k], pos), "put station position");
    }
    free(text);
    free(pos);
    return st;
}

gf_status gf_nc_probes_open(gf_ctx *ctx, const char *path, const gf_nc_meta *meta, int n_stations,
                            const char *const *station_names, const double *station_xyz_m,
                            const gf_var_info *vars, int n_vars, gf_nc_writer **out)
{
    *out = NULL;
    const char *where = path ? path : "probes";
    GF_TRY(check_stations(ctx, where, n_stations, station_names, station_xyz_m));
    static const char *const coordinates[] = {"x", "y", "z", "station_name", NULL};
    GF_TRY(gf_nc_check_vars(ctx, where, "probed variable", vars, n_vars, coordinates));
    gf_nc_writer *w;
    GF_TRY(gf_nc_begin(ctx, path, meta, GF_NC_PROBES, "timeSeries", &w));
    w->n_stations = n_stations;
    gf_status st = gf_nc_alloc_varids(w, n_vars);
    if (st == GF_OK)
        st = define_probes(w, n_stations, station_names, station_xyz_m, vars);
    return gf_nc_open_done(w, st, out);
}

gf_status gf_nc_probes_append(gf_nc_writer *w, double t_s, const double *values)
{
    if (!w || w->kind != GF_NC_PROBES)
        return GF_FAIL(w ? w->ctx : NULL, GF_ERR_ARG, "probes append: not a probes writer");
    if (!values)
        return GF_FAIL(w->ctx, GF_ERR_ARG, "%s: NULL probe values", w->path);
    GF_TRY(gf_nc_put_time(w, t_s));
    size_t start[2] = {0, w->n_records}, count[2] = {(size_t)w->n_stations, 1};
    for (int i = 0; i < w->n_vars; ++i)
        GF_TRY(gf_nc_check(w,
                           nc_put_vara_double(w->ncid, w->varids[i], start, count,
                                              values + (size_t)i * (size_t)w->n_stations),
                           "put probe record"));
    w->n_records++;
    return GF_OK;
}
