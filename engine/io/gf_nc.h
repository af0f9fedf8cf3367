/*
 * CF-1.10 netCDF-4 writers for a run: particles.nc (featureType trajectory),
 * fields.nc (gridded), probes.nc (featureType timeSeries), diagnostics.nc
 * (scalar time series). Variable and attribute names are the ones in
 * docs/output.md; post-processing reads them and nothing else.
 *
 * Every writer creates "<path>.tmp", appends records, and gf_nc_writer_close
 * renames it to <path> only on success: a killed run never leaves a file that
 * looks complete. gf_nc_writer_abort removes the temporary file; an
 * interrupted run keeps it as "<path>.partial" (gf_nc_writer_suspend) for
 * the restart to continue.
 * The only netCDF caller in the engine is this module.
 */
#ifndef GF_NC_H
#define GF_NC_H

#include <stddef.h>

#include "core/gf_groups.h"
#include "core/gf_status.h"
#include "gf_run_spec.h"
#include "particles/gf_particles.h"

typedef struct gf_var_info {
    const char *name;
    const char *units;           /* udunits-parseable; "1" for dimensionless */
    const char *long_name;
    const char *standard_name;   /* CF standard name table v80, or NULL */
} gf_var_info;

/* What every file of a run records as global attributes (borrowed). */
typedef struct gf_nc_meta {
    const gf_run_spec *spec;
    const gf_scales *scales;
    const char *resolved_yaml;       /* may be NULL */
    const char *fluid_model;         /* "none", "unresolved", ... as run */
    const char *fluid_model_reason;  /* why this tier (fluid: auto) */
    const char *stages;              /* stages that ran, e.g. "contacts,integrate" */
    const char *skipped_work;        /* work left out as not needed (gf_sim_skips), may be NULL */
    double column_length_m;          /* R0 (0 if not a collapse) */
    double column_height_m;          /* H0 */
    double incline_deg;              /* theta */
    double phi_initial_measured;     /* achieved Phi_i (solid volume / container), NaN if none */
    double phi_initial_local;        /* achieved Phi_i by local averaging, NaN if none */
} gf_nc_meta;

typedef struct gf_nc_writer gf_nc_writer;

gf_status gf_nc_diagnostics_open(gf_ctx *ctx, const char *path, const gf_nc_meta *meta, const gf_var_info *vars,
                                 int n_vars, gf_nc_writer **out);
gf_status gf_nc_diagnostics_append(gf_nc_writer *w, double t_s, const double *values);

/* Trajectories of the n_local grains present at open (count fixed per run). */
gf_status gf_nc_particles_open(gf_ctx *ctx, const char *path, const gf_nc_meta *meta, const gf_particles *p,
                               gf_nc_writer **out);
gf_status gf_nc_particles_append(gf_nc_writer *w, double t_s, const gf_particles *p);

/* Stations (gauges) at fixed positions; values[n_vars * n_stations], var-major. */
gf_status gf_nc_probes_open(gf_ctx *ctx, const char *path, const gf_nc_meta *meta, int n_stations,
                            const char *const *station_names, const double *station_xyz_m,
                            const gf_var_info *vars, int n_vars, gf_nc_writer **out);
gf_status gf_nc_probes_append(gf_nc_writer *w, double t_s, const double *values);

/* Cell-centred fields on a uniform grid; fields[n_vars][nz*ny*nx], x fastest. */
gf_status gf_nc_fields_open(gf_ctx *ctx, const char *path, const gf_nc_meta *meta, const int n_cells[3],
                            const double lo_m[3], const double cell_m[3], const gf_var_info *vars, int n_vars,
                            gf_nc_writer **out);
gf_status gf_nc_fields_append(gf_nc_writer *w, double t_s, const double *const *fields);

/* Flushes, closes and renames the temporary file into place. Accepts NULL *w. */
gf_status gf_nc_writer_close(gf_nc_writer **w);
/* Closes and deletes the temporary file. Accepts NULL *w. */
void gf_nc_writer_abort(gf_nc_writer **w);
/* Interrupted run: closes the file and renames it to "<path>.partial", a
 * complete file with the records so far that gf_nc_writer_continue can
 * extend (gf_nc_resume.c). Accepts NULL *w. */
gf_status gf_nc_writer_suspend(gf_nc_writer **w);
/* Restarted run: copies into the freshly opened writer w (same spec) the
 * global attributes, the time-independent variables and the records with
 * time < t_before_s of "<path>.partial", which a successful close of w then
 * removes. Fails with a message naming the file when it is missing. */
gf_status gf_nc_writer_continue(gf_nc_writer *w, double t_before_s);

#endif
