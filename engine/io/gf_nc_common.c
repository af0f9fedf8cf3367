/*
 * Common part of the CF-1.10 netCDF-4 writers: file creation under a
 * temporary name, global attributes, the time coordinate, close/rename and
 * abort. The names are the contract of docs/output.md.
 *
 * Atomicity. Every file is created as "<path>.tmp" and renamed to <path>
 * only after nc_close succeeded (rename(2) within one directory is atomic
 * on POSIX file systems). A run killed at any moment therefore leaves at
 * most a "*.tmp" file (an HDF5 file whose superblock was never finalised,
 * often unreadable) and never a file at the final name that looks complete.
 *
 * Time. CF (Eaton et al., CF Conventions 1.10, §4.4) wants a coordinate
 * with a reference date; the simulated clock has none, so the convention of
 * docs/output.md puts the release instant at 2000-01-01 00:00:00 and writes
 * seconds since then. A coordinate variable must be strictly monotonic
 * (CF §1.3), so gf_nc_put_time refuses a time that does not increase.
 *
 * Provenance. `source` is "grainflow <version> (<git hash>)" from the build,
 * `history` starts with the UTC creation time (ISO 8601), and the resolved
 * run spec is stored verbatim as `run_spec_yaml` next to its main numbers
 * as typed attributes, so a file alone says how it was made.
 */
#include "io/gf_nc_internal.h"

#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/gf_build_info.h"

#ifndef GF_VERSION
#define GF_VERSION "unknown"
#endif

/* First error wins: OR-ing netCDF codes would garble the message. */
#define NC_SEQ(rc, call)          \
    do {                          \
        if ((rc) == NC_NOERR)     \
            (rc) = (call);        \
    } while (0)

static const char *const kind_names[] = {"diagnostics", "particles", "probes", "fields"};

gf_status gf_nc_check(gf_nc_writer *w, int rc, const char *what)
{
    if (rc == NC_NOERR)
        return GF_OK;
    return GF_FAIL(w->ctx, GF_ERR_IO, "netCDF %s in %s: %s", what, w->tmp, nc_strerror(rc));
}

gf_status gf_nc_check_info(gf_ctx *ctx, const char *path, const gf_var_info *info, int index)
{
    if (!info->name || !*info->name)
        return GF_FAIL(ctx, GF_ERR_ARG, "%s: variable %d has no name", path, index);
    if (!info->units || !*info->units)
        return GF_FAIL(ctx, GF_ERR_ARG, "%s: variable %s has no units (use \"1\" for dimensionless)", path,
                       info->name);
    if (strcmp(info->name, "time") == 0)
        return GF_FAIL(ctx, GF_ERR_ARG, "%s: variable name \"time\" is reserved for the coordinate", path);
    return GF_OK;
}

gf_status gf_nc_check_vars(gf_ctx *ctx, const char *where, const char *what, const gf_var_info *vars, int n_vars,
                           const char *const *reserved)
{
    if (n_vars < 1 || !vars)
        return GF_FAIL(ctx, GF_ERR_ARG, "%s: need at least one %s (n_vars = %d)", where, what, n_vars);
    for (int i = 0; i < n_vars; ++i) {
        GF_TRY(gf_nc_check_info(ctx, where, &vars[i], i));
        for (const char *const *r = reserved; *r; ++r)
            if (strcmp(vars[i].name, *r) == 0)
                return GF_FAIL(ctx, GF_ERR_ARG, "%s: %s name \"%s\" is reserved for a coordinate", where, what,
                               vars[i].name);
    }
    return GF_OK;
}

void gf_nc_free(gf_nc_writer *w)
{
    if (!w)
        return;
    free(w->path);
    free(w->tmp);
    free(w->varids);
    free(w->sorted_id);
    free(w->sorted_slot);
    free(w->buf);
    free(w);
}

/* ---------------------------------------------------------------- attributes */

static int put_text(int ncid, const char *name, const char *value)
{
    if (!value)
        value = "";
    return nc_put_att_text(ncid, NC_GLOBAL, name, strlen(value), value);
}

static int put_double(int ncid, const char *name, double value)
{
    return nc_put_att_double(ncid, NC_GLOBAL, name, NC_DOUBLE, 1, &value);
}

static int put_int(int ncid, const char *name, int value)
{
    return nc_put_att_int(ncid, NC_GLOBAL, name, NC_INT, 1, &value);
}

/* CF descriptive attributes and provenance. */
static int put_cf_globals(int ncid, const gf_run_spec *spec, gf_nc_kind kind, const char *feature_type)
{
    int rc = NC_NOERR;
    char buf[512];
    NC_SEQ(rc, put_text(ncid, "Conventions", "CF-1.10"));
    snprintf(buf, sizeof buf, "grainflow %s run %s: %s", spec->scene, spec->run_id[0] ? spec->run_id : "(no id)",
             kind_names[kind]);
    NC_SEQ(rc, put_text(ncid, "title", buf));
    time_t now = time(NULL);
    struct tm utc;
    gmtime_r(&now, &utc);
    char stamp[32];
    strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", &utc);
    snprintf(buf, sizeof buf, "%s: created by grainflow %s (%s), scene %s", stamp, GF_VERSION, gf_build_revision(),
             spec->scene);
    NC_SEQ(rc, put_text(ncid, "history", buf));
    snprintf(buf, sizeof buf, "grainflow %s (%s)", GF_VERSION, gf_build_revision());
    NC_SEQ(rc, put_text(ncid, "source", buf));
    NC_SEQ(rc, put_text(ncid, "references",
                   "Izard E., PhD thesis, INP Toulouse (2014); Courrech du Pont S. et al., Phys. Rev. Lett. 90, "
                   "044301 (2003); variable names: grainflow docs/output.md"));
    NC_SEQ(rc, put_text(ncid, "institution", "grainflow simulation framework"));
    NC_SEQ(rc, put_text(ncid, "comment",
                   "Soft-sphere DEM of dense granular flow, dry or immersed. SI units. Time origin "
                   "2000-01-01 00:00:00 is the release instant by convention, not a calendar date."));
    if (feature_type)
        NC_SEQ(rc, put_text(ncid, "featureType", feature_type));
    return rc;
}

/* The run inputs and realised groups (docs/output.md, global attribute table). */
static int put_run_globals(int ncid, const gf_nc_meta *m)
{
    const gf_run_spec *s = m->spec;
    const gf_scales *g = m->scales;
    int rc = NC_NOERR;
    NC_SEQ(rc, put_text(ncid, "run_id", s->run_id));
    NC_SEQ(rc, put_text(ncid, "scene", s->scene));
    NC_SEQ(rc, put_double(ncid, "stokes_St", s->stokes_St));
    NC_SEQ(rc, put_double(ncid, "density_ratio_r", s->density_ratio_r));
    NC_SEQ(rc, put_double(ncid, "aspect_ratio_a", s->aspect_ratio_a));
    NC_SEQ(rc, put_double(ncid, "phi_initial", s->phi_initial));
    NC_SEQ(rc, put_double(ncid, "realised_St", g ? g->stokes_St : NAN));
    NC_SEQ(rc, put_double(ncid, "realised_r", g ? g->density_ratio_r : NAN));
    NC_SEQ(rc, put_double(ncid, "realised_Ar", g ? g->archimedes_Ar : NAN));
    NC_SEQ(rc, put_double(ncid, "realised_Re", g ? g->reynolds_Re : NAN));
    NC_SEQ(rc, put_double(ncid, "t_viscous_s", g ? g->t_viscous_s : NAN));
    NC_SEQ(rc, put_double(ncid, "t_inertial_s", g ? g->t_inertial_s : NAN));
    NC_SEQ(rc, put_double(ncid, "t_freefall_s", g ? g->t_freefall_s : NAN));
    NC_SEQ(rc, put_double(ncid, "t_visq_s", g ? g->t_visq_s : NAN));
    NC_SEQ(rc, put_double(ncid, "t_grain_s", g ? g->t_grain_s : sqrt(s->grains.diameter_m / s->gravity_m_s2)));
    NC_SEQ(rc, put_double(ncid, "grain_diameter_m", s->grains.diameter_m));
    NC_SEQ(rc, put_double(ncid, "grain_density_kg_m3", s->grains.density_kg_m3));
    NC_SEQ(rc, put_double(ncid, "polydispersity", s->grains.polydispersity));
    NC_SEQ(rc, put_double(ncid, "fluid_density_kg_m3", s->fluid.density_kg_m3));
    NC_SEQ(rc, put_double(ncid, "fluid_viscosity_Pa_s", s->fluid.viscosity_Pa_s));
    NC_SEQ(rc, put_text(ncid, "fluid_model", m->fluid_model ? m->fluid_model : s->fluid.model));
    NC_SEQ(rc, put_text(ncid, "fluid_model_reason", m->fluid_model_reason ? m->fluid_model_reason : "as requested"));
    NC_SEQ(rc, put_text(ncid, "drag_closure", s->fluid.drag));
    NC_SEQ(rc, put_text(ncid, "contact_law", s->contact.law));
    NC_SEQ(rc, put_double(ncid, "restitution", s->contact.restitution));
    NC_SEQ(rc, put_double(ncid, "friction", s->contact.friction));
    NC_SEQ(rc, put_double(ncid, "wall_friction", s->contact.wall_friction));
    NC_SEQ(rc, put_double(ncid, "kt_over_kn", s->contact.kt_over_kn));
    NC_SEQ(rc, put_double(ncid, "t_contact_s", gf_run_spec_t_contact_s(s)));
    NC_SEQ(rc, put_double(ncid, "dt_s", gf_run_spec_dt_s(s)));
    NC_SEQ(rc, put_double(ncid, "gravity_m_s2", s->gravity_m_s2));
    NC_SEQ(rc, put_double(ncid, "incline_deg", m->incline_deg));
    NC_SEQ(rc, put_double(ncid, "column_length_m", m->column_length_m));
    NC_SEQ(rc, put_double(ncid, "column_height_m", m->column_height_m));
    NC_SEQ(rc, put_double(ncid, "phi_initial_measured", m->phi_initial_measured));
    NC_SEQ(rc, put_double(ncid, "phi_initial_local", m->phi_initial_local));
    NC_SEQ(rc, put_text(ncid, "stages", m->stages ? m->stages : ""));
    NC_SEQ(rc, put_text(ncid, "skipped_work", m->skipped_work ? m->skipped_work : ""));
    /* further inputs (additive to docs/output.md): enough to rerun without run.yaml */
    unsigned long long seed = s->seed;
    NC_SEQ(rc, nc_put_att_ulonglong(ncid, NC_GLOBAL, "seed", NC_UINT64, 1, &seed));
    NC_SEQ(rc, put_double(ncid, "end_time_nd", s->end_time_nd));
    NC_SEQ(rc, put_double(ncid, "output_interval_nd", s->output.interval_nd));
    NC_SEQ(rc, put_double(ncid, "t_contact_nd", s->contact.t_contact_nd));
    NC_SEQ(rc, put_double(ncid, "overlap_target_over_D", s->contact.overlap_target_over_D));
    NC_SEQ(rc, put_double(ncid, "dt_over_tc", s->contact.dt_over_tc));
    NC_SEQ(rc, put_int(ncid, "lubrication", s->fluid.lubrication));
    NC_SEQ(rc, put_double(ncid, "roughness_over_R", s->fluid.roughness_over_R));
    NC_SEQ(rc, put_double(ncid, "fluid_cell_over_D", s->fluid.cell_over_D));
    for (int i = 0; i < s->n_scene_params && i < GF_MAX_SCENE_PARAMS; ++i) {
        char name[GF_NAME_LEN + 16];
        snprintf(name, sizeof name, "scene_param_%s", s->scene_params[i].key);
        NC_SEQ(rc, put_double(ncid, name, s->scene_params[i].value));
    }
    if (m->resolved_yaml)
        NC_SEQ(rc, put_text(ncid, "run_spec_yaml", m->resolved_yaml));
    return rc;
}

/* ---------------------------------------------------------------- create */

gf_status gf_nc_begin(gf_ctx *ctx, const char *path, const gf_nc_meta *meta, gf_nc_kind kind,
                      const char *feature_type, gf_nc_writer **out)
{
    *out = NULL;
    if (!path || !*path)
        return GF_FAIL(ctx, GF_ERR_ARG, "netCDF %s writer: empty path", kind_names[kind]);
    if (!meta || !meta->spec)
        return GF_FAIL(ctx, GF_ERR_ARG, "%s: run metadata (meta->spec) is required", path);
    gf_nc_writer *w = calloc(1, sizeof *w);
    if (!w)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "%s: out of memory", path);
    w->ctx = ctx;
    w->kind = kind;
    w->last_t_s = -INFINITY;
    size_t n = strlen(path);
    w->path = malloc(n + 1);
    w->tmp = malloc(n + 5);
    if (!w->path || !w->tmp) {
        gf_nc_free(w);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "%s: out of memory", path);
    }
    memcpy(w->path, path, n + 1);
    snprintf(w->tmp, n + 5, "%s.tmp", path);

    int rc = nc_create(w->tmp, NC_NETCDF4 | NC_CLOBBER, &w->ncid);
    if (rc != NC_NOERR) {
        gf_status st = GF_FAIL(ctx, GF_ERR_IO, "netCDF create %s: %s", w->tmp, nc_strerror(rc));
        gf_nc_free(w);
        return st;
    }
    gf_status st = gf_nc_check(w, put_cf_globals(w->ncid, meta->spec, kind, feature_type), "global attributes");
    if (st == GF_OK)
        st = gf_nc_check(w, put_run_globals(w->ncid, meta), "run attributes");
    if (st == GF_OK)
        st = gf_nc_check(w, nc_def_dim(w->ncid, "time", NC_UNLIMITED, &w->dim_time), "def_dim time");
    if (st == GF_OK) {
        static const gf_var_info time_info = {"time", "s since 2000-01-01 00:00:00", "time since release", "time"};
        st = gf_nc_def_var(w, "time", NC_DOUBLE, 1, &w->dim_time, &time_info, &w->var_time);
    }
    if (st == GF_OK)
        st = gf_nc_check(w, nc_put_att_text(w->ncid, w->var_time, "axis", 1, "T"), "time axis");
    if (st == GF_OK)
        st = gf_nc_check(w, nc_put_att_text(w->ncid, w->var_time, "calendar", 8, "standard"), "time calendar");
    return gf_nc_open_done(w, st, out);
}

gf_status gf_nc_alloc_varids(gf_nc_writer *w, int n_vars)
{
    w->n_vars = n_vars;
    w->varids = calloc((size_t)(n_vars > 0 ? n_vars : 1), sizeof *w->varids);
    return w->varids ? GF_OK : GF_FAIL(w->ctx, GF_ERR_NOMEM, "%s: out of memory", w->path);
}

gf_status gf_nc_open_done(gf_nc_writer *w, gf_status st, gf_nc_writer **out)
{
    if (st != GF_OK) {
        gf_nc_writer_abort(&w);
        return st;
    }
    *out = w;
    return GF_OK;
}

gf_status gf_nc_def_var(gf_nc_writer *w, const char *name, int xtype, int ndims, const int *dimids,
                        const gf_var_info *info, int *varid)
{
    char what[96];
    snprintf(what, sizeof what, "def_var %s", name);
    GF_TRY(gf_nc_check(w, nc_def_var(w->ncid, name, xtype, ndims, dimids, varid), what));
    int id = *varid, rc = NC_NOERR;
    if (info->units)
        NC_SEQ(rc, nc_put_att_text(w->ncid, id, "units", strlen(info->units), info->units));
    if (info->long_name)
        NC_SEQ(rc, nc_put_att_text(w->ncid, id, "long_name", strlen(info->long_name), info->long_name));
    if (info->standard_name)
        NC_SEQ(rc, nc_put_att_text(w->ncid, id, "standard_name", strlen(info->standard_name), info->standard_name));
    /* NaN marks "no value" (a grain absent at that record, a probe outside the
     * fluid); explicit so that every client masks it the same way. Not on the
     * time coordinate, which CF forbids to have missing values. */
    if (xtype == NC_DOUBLE && strcmp(name, "time") != 0) {
        double fill = NAN;
        NC_SEQ(rc, nc_def_var_fill(w->ncid, id, 0, &fill));
    }
    return gf_nc_check(w, rc, what);
}

gf_status gf_nc_compress(gf_nc_writer *w, int varid, const size_t *chunks)
{
    GF_TRY(gf_nc_check(w, nc_def_var_chunking(w->ncid, varid, NC_CHUNKED, chunks), "def_var_chunking"));
    return gf_nc_check(w, nc_def_var_deflate(w->ncid, varid, 1, 1, 1), "def_var_deflate");
}

gf_status gf_nc_end_def(gf_nc_writer *w)
{
    return gf_nc_check(w, nc_enddef(w->ncid), "enddef");
}

gf_status gf_nc_put_time(gf_nc_writer *w, double t_s)
{
    if (!isfinite(t_s))
        return GF_FAIL(w->ctx, GF_ERR_ARG, "%s: record %zu: time is not finite", w->path, w->n_records);
    if (!(t_s > w->last_t_s))
        return GF_FAIL(w->ctx, GF_ERR_ARG, "%s: record %zu: time %.17g s does not increase (previous %.17g s)",
                       w->path, w->n_records, t_s, w->last_t_s);
    size_t start = w->n_records;
    GF_TRY(gf_nc_check(w, nc_put_var1_double(w->ncid, w->var_time, &start, &t_s), "put time"));
    w->last_t_s = t_s;
    return GF_OK;
}

/* ---------------------------------------------------------------- close / abort */

gf_status gf_nc_writer_close(gf_nc_writer **pw)
{
    if (!pw || !*pw)
        return GF_OK;
    gf_nc_writer *w = *pw;
    *pw = NULL;
    int rc = nc_close(w->ncid);
    gf_status st = GF_OK;
    if (rc != NC_NOERR) {
        st = GF_FAIL(w->ctx, GF_ERR_IO, "netCDF close %s: %s", w->tmp, nc_strerror(rc));
        remove(w->tmp);
    } else if (rename(w->tmp, w->path) != 0) {
        st = GF_FAIL(w->ctx, GF_ERR_IO, "cannot rename %s to %s", w->tmp, w->path);
        remove(w->tmp);
    } else {
        gf_nc_remove_partial(w); /* a restarted run's records now hold it all */
        st = gf_nc_sidecar_write(w);
    }
    gf_nc_free(w);
    return st;
}

void gf_nc_writer_abort(gf_nc_writer **pw)
{
    if (!pw || !*pw)
        return;
    gf_nc_writer *w = *pw;
    *pw = NULL;
    nc_close(w->ncid);
    remove(w->tmp);
    gf_nc_free(w);
}
