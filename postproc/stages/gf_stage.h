/*
 * Post-processing stages: one uniform signature, one table (docs/architecture.md).
 *
 * A stage reads the netCDF files of one run directory (through gf_ncread.h,
 * names from docs/output.md only), writes its scalar results into the run's
 * summary row and, when it produces series, a per-run file
 * <run>/post_<stage>.nc written to a temporary name and renamed. A stage is
 * pure: no globals, no state kept between calls, and the same files give the
 * same row. Each table entry declares what the stage reads and writes, and a
 * version recorded in the row ("stages" column) and in its output file.
 *
 * Return codes: GF_OK (results in the row); GF_ERR_UNSUPPORTED when the stage
 * does not apply to this run (e.g. no probes in a dry run: no message, the
 * row is left as is), or with a message when what the run wrote cannot give
 * the stage's quantities (an input not written, output.particles: false; a
 * record too short for a steady window; an avalanche that did not flow): the
 * message goes to the row's notes, the columns stay empty and the run stays ok; any other code is a per-run failure whose message
 * (ctx) the caller copies into the row's error column.
 */
#ifndef GF_STAGE_H
#define GF_STAGE_H

#include "core/gf_status.h"

/* ---- the per-run summary row: a small POD dictionary (copied across fork) ---- */

#define GF_ROW_MAX_FIELDS 112
#define GF_ROW_NAME_LEN 32
#define GF_ROW_TEXT_LEN 48

typedef struct gf_post_field {
    char name[GF_ROW_NAME_LEN];
    char text[GF_ROW_TEXT_LEN];
    double value;
    int is_text;
} gf_post_field;

typedef struct gf_post_row {
    char run_dir[512];
    char run_id[64];
    char scene[GF_ROW_TEXT_LEN];
    char fluid_model[GF_ROW_TEXT_LEN];
    char status[24];      /* "ok", "failed" (the run), "corrupt" (a done run failing its manifest), "error" (a
                             stage), "incomplete" (no status file, or being written) */
    char error[640];      /* per-run messages, "; "-separated */
    char notes[320];      /* results left empty and why (a stage's input not written), "; "-separated */
    char stages[256];     /* "name@version" of each stage that produced results */
    int n_fields;
    gf_post_field fields[GF_ROW_MAX_FIELDS];
} gf_post_row;

void gf_post_row_init(gf_post_row *row, const char *run_dir);
/* Sets (adds or replaces) a numeric / text result. Silently ignores a full row
 * (GF_ROW_MAX_FIELDS is far above what the stage table declares). */
void gf_post_row_set(gf_post_row *row, const char *name, double value);
void gf_post_row_set_text(gf_post_row *row, const char *name, const char *text);
/* Value by name, NaN (or NULL for text) when absent. */
double gf_post_row_get(const gf_post_row *row, const char *name);
const char *gf_post_row_get_text(const gf_post_row *row, const char *name);
/* Appends "msg" to row->error ("; "-separated) and marks the status. */
void gf_post_row_add_error(gf_post_row *row, const char *status, const char *msg);

/* ---- stages ---- */

typedef struct gf_stage_in {
    const char *run_dir;   /* directory holding the run's netCDF files */
    const char *scene;     /* from the files' "scene" attribute ("" if unknown) */
} gf_stage_in;

typedef struct gf_stage_opts {
    int write_series;      /* non-zero: write <run>/post_<stage>.nc */
} gf_stage_opts;

typedef struct gf_stage_out {
    gf_post_row *row;
} gf_stage_out;

typedef gf_status gf_stage_fn(gf_ctx *ctx, const gf_stage_in *in, const gf_stage_opts *opts, gf_stage_out *out);

/* A summary column a stage writes: name, kind, units (udunits, "1"), meaning. */
typedef struct gf_post_col {
    const char *name;
    int is_text;
    const char *units;
    const char *long_name;
} gf_post_col;

typedef struct gf_stage_info {
    const char *name;
    int version;
    gf_stage_fn *fn;
    const char *reads;      /* files and variables read */
    const char *writes;     /* summary columns (gf_summary_columns.c) and/or post_<stage>.nc */
} gf_stage_info;

/* The stage table (gf_stage_table.c), in execution order. */
extern const gf_stage_info gf_stage_table[];
extern const int gf_stage_count;
/* Entry by name, NULL if unknown. */
const gf_stage_info *gf_stage_find(const char *name);

gf_stage_fn gf_stage_flow_rate, gf_stage_regime, gf_stage_deposit, gf_stage_pore_pressure, gf_stage_profiles,
    gf_stage_energy, gf_stage_bounce;

#endif
