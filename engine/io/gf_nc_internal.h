/*
 * Shared state of the netCDF writers (private to engine/io/gf_nc_*.c).
 *
 * One writer = one netCDF-4 file being written under "<path>.tmp". The
 * common part (gf_nc_common.c) creates the file, writes the global
 * attributes of docs/output.md, defines the unlimited `time` coordinate,
 * appends time values and closes/renames or aborts; each file kind adds
 * its own dimensions and variables and keeps its ids in the union below.
 */
#ifndef GF_NC_INTERNAL_H
#define GF_NC_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "io/gf_nc.h"

typedef enum gf_nc_kind { GF_NC_DIAGNOSTICS, GF_NC_PARTICLES, GF_NC_PROBES, GF_NC_FIELDS } gf_nc_kind;

struct gf_nc_writer {
    gf_ctx *ctx;
    gf_nc_kind kind;
    int ncid;
    char *path, *tmp;
    int dim_time, var_time;
    size_t n_records;        /* time records written */
    double last_t_s;
    int n_vars;              /* user variables (diagnostics, probes, fields) */
    int *varids;             /* n_vars ids (owned) */
    /* particles */
    size_t n_traj;
    int64_t *sorted_id;      /* ids present at open, ascending (owned) */
    size_t *sorted_slot;     /* trajectory index of sorted_id[k] (owned) */
    int var_pos[3], var_vel[3];
    double *buf;             /* n_traj * 6 (owned) */
    /* probes */
    int n_stations;
    /* fields */
    size_t n_cells[3];       /* nx, ny, nz */
    double grid_lo_m[3];     /* grid corner (x, y, z) */
    double grid_cell_m[3];   /* cell size (x, y, z) */
};

/* Creates "<path>.tmp" (netCDF-4, clobber), writes the global attributes
 * (feature_type may be NULL) and defines time(time). Leaves the file in
 * define mode. On error nothing is left on disk. */
gf_status gf_nc_begin(gf_ctx *ctx, const char *path, const gf_nc_meta *meta, gf_nc_kind kind,
                      const char *feature_type, gf_nc_writer **out);
/* Leaves define mode. */
gf_status gf_nc_end_def(gf_nc_writer *w);
/* w->varids, zeroed, for the n_vars variables of a record (one slot at
 * least); GF_ERR_NOMEM naming the file. */
gf_status gf_nc_alloc_varids(gf_nc_writer *w, int n_vars);
/* The last step of an open: on st == GF_OK hands w to *out (returns owned);
 * otherwise aborts w, so that nothing is left on disk, and returns st. */
gf_status gf_nc_open_done(gf_nc_writer *w, gf_status st, gf_nc_writer **out);
/* Checks t_s (finite, not decreasing) and writes time[n_records]. The caller
 * increments n_records after its own variables of the record are written. */
gf_status gf_nc_put_time(gf_nc_writer *w, double t_s);
/* Defines a variable with units, long_name, standard_name (when given) and
 * a fill value for doubles. */
gf_status gf_nc_def_var(gf_nc_writer *w, const char *name, int xtype, int ndims, const int *dimids,
                        const gf_var_info *info, int *varid);
/* Chunking + shuffle + deflate (level 1: 2-4x on smooth data, fast). */
gf_status gf_nc_compress(gf_nc_writer *w, int varid, const size_t *chunks);
/* GF_FAIL with "netCDF <what> <tmp path>: <nc_strerror(rc)>" when rc != NC_NOERR. */
gf_status gf_nc_check(gf_nc_writer *w, int rc, const char *what);
/* Validates one gf_var_info (name and units present). */
gf_status gf_nc_check_info(gf_ctx *ctx, const char *path, const gf_var_info *info, int index);
/* Validates a writer's list of n_vars variables (what: "field", ...): at
 * least one, each valid, none named as one of the file's coordinates in
 * reserved (NULL-terminated). */
gf_status gf_nc_check_vars(gf_ctx *ctx, const char *where, const char *what, const gf_var_info *vars, int n_vars,
                           const char *const *reserved);
/* particles.nc: rebuilds the id -> trajectory table from the file's
 * trajectory_id variable (after gf_nc_writer_continue copied it). */
gf_status gf_nc_particles_reload_ids(gf_nc_writer *w);
/* Removes "<path>.partial" if present (gf_nc_resume.c). */
void gf_nc_remove_partial(const gf_nc_writer *w);
/* particles.nc, fields.nc: writes the XDMF sidecar "<name>.xmf" beside the
 * closed file (gf_nc_sidecar.c); other kinds: nothing. */
gf_status gf_nc_sidecar_write(gf_nc_writer *w);
/* Frees a writer after its file was closed or removed. */
void gf_nc_free(gf_nc_writer *w);

#endif
