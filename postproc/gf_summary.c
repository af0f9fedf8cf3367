/*
 * summary.nc and summary.csv of a campaign (gf_summary.h).
 *
 * netCDF-4 with CF-1.10 global attributes; text columns are NC_STRING
 * variables (allowed since CF-1.8), numeric columns doubles with units
 * (udunits syntax, "1" for dimensionless), long_name and _FillValue = NaN.
 */
#include "gf_summary.h"

#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "core/gf_build_info.h"
#include "gf_ncread.h"

/* Text of an identity column held in the row's fixed fields. */
static const char *ident_text(const gf_post_row *row, const char *name)
{
    if (strcmp(name, "run_id") == 0) return row->run_id;
    if (strcmp(name, "scene") == 0) return row->scene;
    if (strcmp(name, "status") == 0) return row->status;
    if (strcmp(name, "error") == 0) return row->error;
    if (strcmp(name, "notes") == 0) return row->notes;
    if (strcmp(name, "fluid_model") == 0) return row->fluid_model;
    if (strcmp(name, "stages") == 0) return row->stages;
    if (strcmp(name, "run_dir") == 0) return row->run_dir;
    const char *t = gf_post_row_get_text(row, name);
    return t ? t : "";
}

/* Every column (gf_summary_columns), as a list of pointers. */
static int all_columns(const gf_post_col **cols, int cap)
{
    int n = 0;
    for (const gf_post_col *c = gf_summary_columns; c->name && n < cap; ++c)
        cols[n++] = c;
    return n;
}

static void csv_text(FILE *f, const char *s)
{
    if (!strpbrk(s, ",\"\n\r")) {
        fputs(s, f);
        return;
    }
    fputc('"', f);
    for (; *s; ++s) {
        if (*s == '"')
            fputc('"', f);
        fputc(*s == '\n' || *s == '\r' ? ' ' : *s, f);
    }
    fputc('"', f);
}

static gf_status write_csv(gf_ctx *ctx, const char *dir, const gf_post_row *rows, int n_rows,
                           const gf_post_col **cols, int nc)
{
    char path[1024], tmp[1040];
    snprintf(path, sizeof path, "%s/summary.csv", dir);
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    FILE *f = fopen(tmp, "w");
    if (!f)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: cannot write", tmp);
    for (int c = 0; c < nc; ++c)
        fprintf(f, "%s%s", c ? "," : "", cols[c]->name);
    fputc('\n', f);
    for (int r = 0; r < n_rows; ++r) {
        for (int c = 0; c < nc; ++c) {
            if (c)
                fputc(',', f);
            if (cols[c]->is_text) {
                csv_text(f, ident_text(&rows[r], cols[c]->name));
            } else {
                const double v = gf_post_row_get(&rows[r], cols[c]->name);
                if (isfinite(v))
                    fprintf(f, "%.10g", v);
                else if (isinf(v))
                    fputs(v > 0 ? "inf" : "-inf", f);
            }
        }
        fputc('\n', f);
    }
    if (fclose(f) != 0 || rename(tmp, path) != 0) {
        unlink(tmp);
        return GF_FAIL(ctx, GF_ERR_IO, "%s: write failed", path);
    }
    return GF_OK;
}

#define NCW(call)                                                                                 \
    do {                                                                                          \
        int rc_ = (call);                                                                         \
        if (rc_ != NC_NOERR) {                                                                    \
            st = GF_FAIL(ctx, GF_ERR_IO, "%s: %s (line %d)", tmp, nc_strerror(rc_), __LINE__);    \
            goto done;                                                                            \
        }                                                                                         \
    } while (0)

static int att(int ncid, int var, const char *name, const char *text)
{
    return nc_put_att_text(ncid, var, name, strlen(text), text);
}

static gf_status write_nc(gf_ctx *ctx, const char *dir, const gf_post_row *rows, int n_rows,
                          const gf_post_col **cols, int nc)
{
    char path[1024], tmp[1040];
    snprintf(path, sizeof path, "%s/summary.nc", dir);
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    gf_status st = GF_OK;
    int ncid = -1, dim, *varids = calloc((size_t)nc + 1, sizeof *varids);
    double *col = malloc(((size_t)n_rows + 1) * sizeof *col);
    const char **txt = malloc(((size_t)n_rows + 1) * sizeof *txt);
    if (!varids || !col || !txt) {
        st = GF_FAIL(ctx, GF_ERR_NOMEM, "summary: out of memory");
        goto done;
    }
    NCW(nc_create(tmp, NC_CLOBBER | NC_NETCDF4, &ncid));
    NCW(att(ncid, NC_GLOBAL, "Conventions", "CF-1.10"));
    NCW(att(ncid, NC_GLOBAL, "title", "grainflow campaign summary: one entry per run"));
    char buf[1200];
    time_t now = time(NULL);
    struct tm tmv;
    gmtime_r(&now, &tmv);
    char stamp[64];
    strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", &tmv);
    snprintf(buf, sizeof buf, "%s: grainflow post %s", stamp, dir);
    NCW(att(ncid, NC_GLOBAL, "history", buf));
#ifdef GF_VERSION
    snprintf(buf, sizeof buf, "grainflow %s (%s)", GF_VERSION, gf_build_revision());
#else
    snprintf(buf, sizeof buf, "grainflow");
#endif
    NCW(att(ncid, NC_GLOBAL, "source", buf));
    NCW(att(ncid, NC_GLOBAL, "institution", "grainflow project"));
    NCW(att(ncid, NC_GLOBAL, "references",
            "Izard 2014 (immersed granular flows, DEM/IBM), Courrech du Pont et al. PRL 90 044301 (2003), "
            "Rondon et al. Phys. Fluids 23 073301 (2011)"));
    NCW(att(ncid, NC_GLOBAL, "comment",
            "Scalar results of the post-processing stages (postproc/stages); regime rule in "
            "postproc/stages/gf_regime.h, deposit criteria in postproc/stages/gf_deposit.h"));
    NCW(nc_def_dim(ncid, "run", (size_t)n_rows, &dim));
    for (int c = 0; c < nc; ++c) {
        NCW(nc_def_var(ncid, cols[c]->name, cols[c]->is_text ? NC_STRING : NC_DOUBLE, 1, &dim, &varids[c]));
        if (!cols[c]->is_text) {
            const double fill = NAN;
            NCW(nc_put_att_double(ncid, varids[c], "_FillValue", NC_DOUBLE, 1, &fill));
            NCW(att(ncid, varids[c], "units", cols[c]->units));
        }
        NCW(att(ncid, varids[c], "long_name", cols[c]->long_name));
    }
    NCW(nc_enddef(ncid));
    for (int c = 0; c < nc && n_rows > 0; ++c) {
        if (cols[c]->is_text) {
            for (int r = 0; r < n_rows; ++r)
                txt[r] = ident_text(&rows[r], cols[c]->name);
            NCW(nc_put_var_string(ncid, varids[c], txt));
        } else {
            for (int r = 0; r < n_rows; ++r)
                col[r] = gf_post_row_get(&rows[r], cols[c]->name);
            NCW(nc_put_var_double(ncid, varids[c], col));
        }
    }
    NCW(nc_close(ncid));
    ncid = -1;
    if (rename(tmp, path) != 0)
        st = GF_FAIL(ctx, GF_ERR_IO, "%s: cannot rename into place", path);
done:
    if (ncid >= 0)
        nc_close(ncid);
    if (st != GF_OK)
        unlink(tmp);
    free(varids), free(col), free(txt);
    return st;
}

gf_status gf_summary_write(gf_ctx *ctx, const char *dir, const gf_post_row *rows, int n_rows)
{
    const gf_post_col *cols[GF_ROW_MAX_FIELDS + 32];
    const int nc = all_columns(cols, (int)(sizeof cols / sizeof cols[0]));
    GF_TRY(write_nc(ctx, dir, rows, n_rows, cols, nc));
    return write_csv(ctx, dir, rows, n_rows, cols, nc);
}

gf_status gf_summary_read(gf_ctx *ctx, const char *path, gf_post_row **rows_out, int *n_out)
{
    *rows_out = NULL;
    *n_out = 0;
    gf_ncr f;
    GF_TRY(gf_ncr_open(ctx, path, &f));
    size_t n = 0;
    gf_status st = gf_ncr_dim_len(ctx, &f, "run", &n);
    gf_post_row *rows = st == GF_OK ? calloc(n + 1, sizeof *rows) : NULL;
    if (st == GF_OK && !rows)
        st = GF_FAIL(ctx, GF_ERR_NOMEM, "summary: out of memory");
    for (size_t r = 0; st == GF_OK && r < n; ++r)
        gf_post_row_init(&rows[r], "");
    const gf_post_col *cols[GF_ROW_MAX_FIELDS + 32];
    const int nc = all_columns(cols, (int)(sizeof cols / sizeof cols[0]));
    for (int c = 0; st == GF_OK && c < nc; ++c) {
        int varid;
        if (nc_inq_varid(f.ncid, cols[c]->name, &varid) != NC_NOERR)
            continue;
        if (cols[c]->is_text) {
            char **s = calloc(n + 1, sizeof *s);
            if (!s || (n && nc_get_var_string(f.ncid, varid, s) != NC_NOERR)) {
                free(s);
                continue;
            }
            for (size_t r = 0; r < n; ++r) {
                const char *v = s[r] ? s[r] : "";
                gf_post_row *row = &rows[r];
                if (strcmp(cols[c]->name, "run_id") == 0) snprintf(row->run_id, sizeof row->run_id, "%s", v);
                else if (strcmp(cols[c]->name, "scene") == 0) snprintf(row->scene, sizeof row->scene, "%s", v);
                else if (strcmp(cols[c]->name, "status") == 0) snprintf(row->status, sizeof row->status, "%s", v);
                else if (strcmp(cols[c]->name, "error") == 0) snprintf(row->error, sizeof row->error, "%s", v);
                else if (strcmp(cols[c]->name, "notes") == 0) snprintf(row->notes, sizeof row->notes, "%s", v);
                else if (strcmp(cols[c]->name, "fluid_model") == 0)
                    snprintf(row->fluid_model, sizeof row->fluid_model, "%s", v);
                else if (strcmp(cols[c]->name, "stages") == 0) snprintf(row->stages, sizeof row->stages, "%s", v);
                else if (strcmp(cols[c]->name, "run_dir") == 0) snprintf(row->run_dir, sizeof row->run_dir, "%s", v);
                else gf_post_row_set_text(row, cols[c]->name, v);
            }
            if (n)
                nc_free_string(n, s);
            free(s);
        } else {
            double *v = NULL;
            size_t m = 0;
            if (gf_ncr_var_1d(NULL, &f, cols[c]->name, &v, &m) != GF_OK || m != n) {
                free(v);
                continue;
            }
            for (size_t r = 0; r < n; ++r)
                if (!isnan(v[r]))
                    gf_post_row_set(&rows[r], cols[c]->name, v[r]);
            free(v);
        }
    }
    gf_ncr_close(&f);
    if (st != GF_OK) {
        free(rows);
        return st;
    }
    *rows_out = rows;
    *n_out = (int)n;
    return GF_OK;
}

const gf_post_row *gf_summary_find(const gf_post_row *rows, int n_rows, const char *run_id)
{
    for (int i = 0; i < n_rows; ++i)
        if (strcmp(rows[i].run_id, run_id) == 0)
            return &rows[i];
    return NULL;
}
