/* Helpers shared by the stages (gf_stage_util.h). */
#include "stages/gf_stage_util.h"

#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "core/gf_build_info.h"

void gf_stage_path(const gf_stage_in *in, const char *name, char *buf, size_t size)
{
    snprintf(buf, size, "%s/%s", in->run_dir, name);
}

int gf_stage_has_file(const gf_stage_in *in, const char *name)
{
    char p[1024];
    gf_stage_path(in, name, p, sizeof p);
    return gf_ncr_exists(p);
}

gf_status gf_stage_open(gf_ctx *ctx, const gf_stage_in *in, const char *name, gf_ncr *f)
{
    char p[1024];
    gf_stage_path(in, name, p, sizeof p);
    if (!gf_ncr_exists(p)) /* e.g. output.particles: false; a file the run listed and lost fails its manifest first */
        return GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "not computed: %s was not written by this run", name);
    return gf_ncr_open(ctx, p, f);
}

int gf_stage_has_var(const gf_stage_in *in, const char *file, const char *var)
{
    if (!gf_stage_has_file(in, file))
        return 0;
    gf_ctx c = {0};
    gf_ncr f;
    if (gf_stage_open(&c, in, file, &f) != GF_OK)
        return 0;
    const int has = gf_ncr_has_var(&f, var);
    gf_ncr_close(&f);
    return has;
}

int gf_stage_is_column(const gf_stage_in *in)
{
    static const char *const files[] = {"diagnostics.nc", "particles.nc", "probes.nc"};
    for (size_t k = 0; k < sizeof files / sizeof files[0]; ++k) {
        if (!gf_stage_has_file(in, files[k]))
            continue;
        gf_ctx c = {0};
        gf_ncr f;
        if (gf_stage_open(&c, in, files[k], &f) != GF_OK)
            continue;
        const double R0 = gf_ncr_att_double_or(&f, "column_length_m", NAN);
        gf_ncr_close(&f);
        return R0 > 0.0;   /* every file of a run carries the same attributes */
    }
    return 0;
}

void gf_stage_column(const gf_ncr *f, double *R0_m, double *H0_m)
{
    double R0 = gf_ncr_att_double_or(f, "column_length_m", NAN);
    double H0 = gf_ncr_att_double_or(f, "column_height_m", NAN);
    if (!(R0 > 0.0)) {
        const double n = gf_ncr_att_double_or(f, "scene_param_column_length_over_D", NAN);
        const double D = gf_ncr_att_double_or(f, "grain_diameter_m", NAN);
        R0 = n * D;
    }
    if (!(H0 > 0.0)) {
        double a = gf_ncr_att_double_or(f, "aspect_ratio_a", NAN);
        if (!(a > 0.0))
            a = gf_ncr_att_double_or(f, "scene_param_aspect_ratio", NAN);
        H0 = a * R0;
    }
    *R0_m = R0 > 0.0 ? R0 : NAN;
    *H0_m = H0 > 0.0 ? H0 : NAN;
}

gf_status gf_stage_scales(gf_ctx *ctx, const gf_ncr *f, const gf_stage_in *in, gf_groups_input *gi, gf_scales *sc)
{
    memset(gi, 0, sizeof *gi);
    GF_TRY(gf_ncr_att_double(ctx, f, "grain_diameter_m", &gi->diameter_m));
    GF_TRY(gf_ncr_att_double(ctx, f, "grain_density_kg_m3", &gi->grain_density_kg_m3));
    GF_TRY(gf_ncr_att_double(ctx, f, "gravity_m_s2", &gi->gravity_m_s2));
    gi->fluid_density_kg_m3 = gf_ncr_att_double_or(f, "fluid_density_kg_m3", 0.0);
    gi->viscosity_Pa_s = gf_ncr_att_double_or(f, "fluid_viscosity_Pa_s", 0.0);
    if (!isfinite(gi->fluid_density_kg_m3))
        gi->fluid_density_kg_m3 = 0.0;
    if (!isfinite(gi->viscosity_Pa_s))
        gi->viscosity_Pa_s = 0.0;
    const double theta = gf_ncr_att_double_or(f, "incline_deg", 0.0);
    /* a column falls vertically; a layer on an incline feels g sin(theta) */
    const int column = gf_ncr_att_double_or(f, "column_length_m", 0.0) > 0.0;
    gi->slope_sin = (!column && isfinite(theta) && theta > 0.0) ? sin(theta * M_PI / 180.0) : 1.0;
    double R0 = 0.0, H0 = 0.0;
    if (column)
        gf_stage_column(f, &R0, &H0);
    gi->column_height_m = isfinite(H0) ? H0 : 0.0;
    gi->column_length_m = isfinite(R0) ? R0 : 0.0;
    gf_status st = gf_groups_compute(ctx, gi, sc);
    if (st != GF_OK)
        return GF_FAIL(ctx, st, "%s: time scales from the attributes: %s", f->path, ctx ? ctx->last_msg : "");
    return GF_OK;
}

gf_status gf_stage_grains(gf_ctx *ctx, const gf_ncr *p, int keep, gf_grains_info *g)
{
    memset(g, 0, sizeof *g);
    double *rad = NULL, *glued = NULL;
    size_t n, ng = 0;
    GF_TRY(gf_ncr_dim_len(ctx, p, "time", &g->n_time));
    GF_TRY(gf_ncr_var_1d(ctx, p, "radius", &rad, &n));
    if (gf_ncr_has_var(p, "glued")) {
        gf_status st = gf_ncr_var_1d(ctx, p, "glued", &glued, &ng);
        if (st != GF_OK) {
            free(rad);
            return st;
        }
    }
    g->n_all = n;
    unsigned char *mob = malloc(n ? n : 1);
    if (!mob) {
        free(rad);
        free(glued);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "grains: out of memory");
    }
    double dsum = 0.0;
    for (size_t i = 0; i < n; ++i) {
        mob[i] = !(glued && i < ng && glued[i] != 0.0) && isfinite(rad[i]);
        if (mob[i]) {
            const double d = 2.0 * rad[i];
            g->solid_volume_m3 += M_PI / 6.0 * d * d * d;
            dsum += d;
            ++g->n_mobile;
        }
    }
    free(glued);
    if (g->n_mobile) {
        g->mean_volume_m3 = g->solid_volume_m3 / (double)g->n_mobile;
        g->mean_diameter_m = dsum / (double)g->n_mobile;
    }
    if (keep) {
        g->radius = rad;
        g->mobile = mob;
    } else {
        free(rad);
        free(mob);
    }
    if (g->n_mobile == 0) {
        gf_stage_grains_free(g);
        return GF_FAIL(ctx, GF_ERR_IO, "%s: no mobile grain (radius/glued)", p->path);
    }
    return GF_OK;
}

void gf_stage_grains_free(gf_grains_info *g)
{
    free(g->radius);
    free(g->mobile);
    g->radius = NULL;
    g->mobile = NULL;
}

gf_status gf_stage_open_grains(gf_ctx *ctx, const gf_stage_in *in, gf_ncr *p, gf_grains_info *g, double *D)
{
    GF_TRY(gf_stage_open(ctx, in, "particles.nc", p));
    gf_status st = gf_stage_grains(ctx, p, 1, g);
    if (st != GF_OK) {
        gf_ncr_close(p);
        return st;
    }
    *D = gf_ncr_att_double_or(p, "grain_diameter_m", g->mean_diameter_m);
    if (!(*D > 0.0))
        *D = g->mean_diameter_m;
    return GF_OK;
}

#define NC_CHECK(call, what)                                                                              \
    do {                                                                                                  \
        int rc_ = (call);                                                                                 \
        if (rc_ != NC_NOERR)                                                                              \
            return GF_FAIL(ctx, GF_ERR_IO, "%s: %s: %s", w->tmp, (what), nc_strerror(rc_));               \
    } while (0)

static int put_text(int ncid, int varid, const char *name, const char *text)
{
    return nc_put_att_text(ncid, varid, name, strlen(text), text);
}

gf_status gf_postnc_create(gf_ctx *ctx, const gf_stage_in *in, const char *stage, int version, gf_postnc *w)
{
    w->ncid = -1;
    snprintf(w->path, sizeof w->path, "%s/post_%s.nc", in->run_dir, stage);
    snprintf(w->tmp, sizeof w->tmp, "%s.tmp", w->path);
    NC_CHECK(nc_create(w->tmp, NC_CLOBBER | NC_NETCDF4, &w->ncid), "create");
    char buf[256];
    put_text(w->ncid, NC_GLOBAL, "Conventions", "CF-1.10");
    snprintf(buf, sizeof buf, "grainflow post-processing stage %s", stage);
    put_text(w->ncid, NC_GLOBAL, "title", buf);
#ifdef GF_VERSION
    snprintf(buf, sizeof buf, "grainflow %s (%s)", GF_VERSION, gf_build_revision());
#else
    snprintf(buf, sizeof buf, "grainflow");
#endif
    put_text(w->ncid, NC_GLOBAL, "source", buf);
    time_t now = time(NULL);
    struct tm tmv;
    gmtime_r(&now, &tmv);
    char stamp[64];
    strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", &tmv);
    snprintf(buf, sizeof buf, "%s: stage %s version %d from the run files in %s", stamp, stage, version, in->run_dir);
    put_text(w->ncid, NC_GLOBAL, "history", buf);
    put_text(w->ncid, NC_GLOBAL, "post_stage", stage);
    nc_put_att_int(w->ncid, NC_GLOBAL, "post_stage_version", NC_INT, 1, &version);
    put_text(w->ncid, NC_GLOBAL, "scene", in->scene ? in->scene : "");
    return GF_OK;
}

gf_status gf_postnc_dim(gf_ctx *ctx, gf_postnc *w, const char *name, size_t len, int *dimid)
{
    NC_CHECK(nc_def_dim(w->ncid, name, len, dimid), name);
    return GF_OK;
}

gf_status gf_postnc_var(gf_ctx *ctx, gf_postnc *w, const char *name, int ndims, const int *dimids,
                        const char *units, const char *long_name, const char *standard_name, int *varid)
{
    NC_CHECK(nc_def_var(w->ncid, name, NC_DOUBLE, ndims, dimids, varid), name);
    const double fill = NAN;
    NC_CHECK(nc_put_att_double(w->ncid, *varid, "_FillValue", NC_DOUBLE, 1, &fill), name);
    if (units)
        put_text(w->ncid, *varid, "units", units);
    if (long_name)
        put_text(w->ncid, *varid, "long_name", long_name);
    if (standard_name)
        put_text(w->ncid, *varid, "standard_name", standard_name);
    if (strcmp(name, "time") == 0) {
        put_text(w->ncid, *varid, "axis", "T");
        put_text(w->ncid, *varid, "calendar", "standard");
    }
    return GF_OK;
}

gf_status gf_postnc_enddef(gf_ctx *ctx, gf_postnc *w)
{
    NC_CHECK(nc_enddef(w->ncid), "enddef");
    return GF_OK;
}

gf_status gf_postnc_put(gf_ctx *ctx, gf_postnc *w, int varid, const double *data)
{
    NC_CHECK(nc_put_var_double(w->ncid, varid, data), "write");
    return GF_OK;
}

gf_status gf_postnc_close(gf_ctx *ctx, gf_postnc *w)
{
    int rc = nc_close(w->ncid);
    w->ncid = -1;
    if (rc != NC_NOERR) {
        unlink(w->tmp);
        return GF_FAIL(ctx, GF_ERR_IO, "%s: close: %s", w->tmp, nc_strerror(rc));
    }
    if (rename(w->tmp, w->path) != 0) {
        unlink(w->tmp);
        return GF_FAIL(ctx, GF_ERR_IO, "%s: cannot rename into place", w->path);
    }
    return GF_OK;
}

void gf_postnc_abort(gf_postnc *w)
{
    if (w->ncid >= 0)
        nc_close(w->ncid);
    w->ncid = -1;
    unlink(w->tmp);
}

gf_status gf_postnc_write(gf_ctx *ctx, const gf_stage_in *in, const char *stage, int version,
                          const gf_postnc_dimension *dims, int n_dims, const gf_postnc_series *vars, int n_vars)
{
    int dimid[GF_POSTNC_MAX_DIMS], varid[GF_POSTNC_MAX_VARS];
    if (n_dims > GF_POSTNC_MAX_DIMS || n_vars > GF_POSTNC_MAX_VARS)
        return GF_FAIL(ctx, GF_ERR_ARG, "post_%s.nc: %d dimensions and %d variables (at most %d and %d)", stage,
                       n_dims, n_vars, GF_POSTNC_MAX_DIMS, GF_POSTNC_MAX_VARS);
    gf_postnc w;
    GF_TRY(gf_postnc_create(ctx, in, stage, version, &w));
    gf_status st = GF_OK;
    for (int k = 0; st == GF_OK && k < n_dims; ++k)
        st = gf_postnc_dim(ctx, &w, dims[k].name, dims[k].len, &dimid[k]);
    for (int k = 0; st == GF_OK && k < n_vars; ++k) {
        const gf_postnc_series *s = &vars[k];
        const int ids[2] = {dimid[s->dims[0]], s->ndims > 1 ? dimid[s->dims[1]] : -1};
        st = gf_postnc_var(ctx, &w, s->name, s->ndims, ids, s->units, s->long_name, s->standard_name, &varid[k]);
    }
    if (st == GF_OK)
        st = gf_postnc_enddef(ctx, &w);
    for (int k = 0; st == GF_OK && k < n_vars; ++k)
        st = gf_postnc_put(ctx, &w, varid[k], vars[k].data);
    if (st == GF_OK)
        return gf_postnc_close(ctx, &w);
    gf_postnc_abort(&w);
    return st;
}
