/*
 * Helpers shared by the stages: opening a run file, the time scales of a run
 * (only through gf_groups_compute, from the run's attributes), the mobile
 * grains of particles.nc, and the small CF writer of <run>/post_<stage>.nc
 * (temporary name, renamed when complete).
 */
#ifndef GF_STAGE_UTIL_H
#define GF_STAGE_UTIL_H

#include <stddef.h>

#include "core/gf_groups.h"
#include "gf_ncread.h"
#include "stages/gf_stage.h"

/* "<run_dir>/<name>" into buf. */
void gf_stage_path(const gf_stage_in *in, const char *name, char *buf, size_t size);
int gf_stage_has_file(const gf_stage_in *in, const char *name);
/* Opens <run>/name. An absent file is GF_ERR_UNSUPPORTED with a message (the
 * run did not write it: the stage's columns stay empty, the reason in the
 * row's notes); a file that does not read is GF_ERR_IO. */
gf_status gf_stage_open(gf_ctx *ctx, const gf_stage_in *in, const char *name, gf_ncr *f);
/* What a run's files hold, which is how a stage chooses the runs it applies to
 * (the stage table's `reads` column), never the scene's name: a new scene that
 * writes the same variables is post-processed without editing the stages.
 * Non-zero when <run>/file exists and holds the variable var. */
int gf_stage_has_var(const gf_stage_in *in, const char *file, const char *var);
/* Non-zero when the run is a column released against a back wall: its files
 * (diagnostics.nc, else particles.nc, else probes.nc) name a column length
 * R0 > 0 (column_length_m). */
int gf_stage_is_column(const gf_stage_in *in);

/* Groups and time scales of the run from its global attributes (docs/output.md):
 * grain_diameter_m, grain_density_kg_m3, fluid_density_kg_m3, fluid_viscosity_Pa_s,
 * gravity_m_s2, incline_deg, column_height_m, column_length_m. For a column
 * collapse the grains fall vertically (slope_sin = 1, gf_groups.h). */
gf_status gf_stage_scales(gf_ctx *ctx, const gf_ncr *f, const gf_stage_in *in, gf_groups_input *gi, gf_scales *sc);

/* Column length R0 and height H0 of a collapse: the column_length_m and
 * column_height_m attributes (docs/output.md). When a file carries 0 there
 * (an engine that has not filled them), R0 falls back to the scene parameter
 * attribute scene_param_column_length_over_D × grain_diameter_m and H0 to
 * a × R0 with a = aspect_ratio_a (or scene_param_aspect_ratio). NaN if
 * neither is available. */
void gf_stage_column(const gf_ncr *f, double *R0_m, double *H0_m);

/* Mobile grains of particles.nc: count, total solid volume (pi/6 d^3 summed) and
 * mean volume; glued grains are excluded. Optionally returns the radius and a
 * mobile mask (malloc'ed, n_all entries) */
typedef struct gf_grains_info {
    size_t n_all, n_mobile, n_time;
    double solid_volume_m3, mean_volume_m3, mean_diameter_m;
    double *radius;     /* n_all, NULL unless asked */
    unsigned char *mobile;   /* n_all, NULL unless asked */
} gf_grains_info;
gf_status gf_stage_grains(gf_ctx *ctx, const gf_ncr *particles, int keep_arrays, gf_grains_info *g);
void gf_stage_grains_free(gf_grains_info *g);
/* Opens <run>/particles.nc into *p (gf_stage_open) and reads its grains with
 * their arrays (gf_stage_grains) into *g, and the grain diameter D: the
 * grain_diameter_m attribute, else (absent or not > 0) the grains' mean.
 * On failure nothing is left open. */
gf_status gf_stage_open_grains(gf_ctx *ctx, const gf_stage_in *in, gf_ncr *p, gf_grains_info *g, double *D);

/* ---- post_<stage>.nc writer ---- */
typedef struct gf_postnc {
    int ncid;
    char path[560], tmp[576];
} gf_postnc;

/* Creates <run>/post_<stage>.nc.tmp in define mode with the CF global attributes,
 * the stage's name and version, and the source run's identity. */
gf_status gf_postnc_create(gf_ctx *ctx, const gf_stage_in *in, const char *stage, int version, gf_postnc *w);
gf_status gf_postnc_dim(gf_ctx *ctx, gf_postnc *w, const char *name, size_t len, int *dimid);
/* Double variable with units, long_name and (optional) standard_name and axis. */
gf_status gf_postnc_var(gf_ctx *ctx, gf_postnc *w, const char *name, int ndims, const int *dimids,
                        const char *units, const char *long_name, const char *standard_name, int *varid);
gf_status gf_postnc_enddef(gf_ctx *ctx, gf_postnc *w);
gf_status gf_postnc_put(gf_ctx *ctx, gf_postnc *w, int varid, const double *data);
/* Closes and renames into place; gf_postnc_abort removes the temporary file. */
gf_status gf_postnc_close(gf_ctx *ctx, gf_postnc *w);
void gf_postnc_abort(gf_postnc *w);

/* The dimensions and variables of a whole post_<stage>.nc, for
 * gf_postnc_write: a variable names its dimensions by their index in the
 * file's list (at most GF_POSTNC_MAX_DIMS and GF_POSTNC_MAX_VARS). */
#define GF_POSTNC_MAX_DIMS 4
#define GF_POSTNC_MAX_VARS 16
typedef struct gf_postnc_dimension {
    const char *name;
    size_t len;
} gf_postnc_dimension;
typedef struct gf_postnc_series {
    const char *name;
    int ndims;
    int dims[2];
    const char *units, *long_name, *standard_name;   /* standard_name NULL: none */
    const double *data;   /* the values, in the order of the dimensions */
} gf_postnc_series;

/* Writes <run>/post_<stage>.nc: the dimensions, then each variable with its
 * attributes (gf_postnc_var) and values, in list order; the file appears
 * complete or not at all. */
gf_status gf_postnc_write(gf_ctx *ctx, const gf_stage_in *in, const char *stage, int version,
                          const gf_postnc_dimension *dims, int n_dims, const gf_postnc_series *vars, int n_vars);
/* The number of entries of an array (dims, vars). */
#define GF_POSTNC_COUNT(array) ((int)(sizeof(array) / sizeof((array)[0])))

#endif
