/*
 * Helpers shared by the netCDF writer tests: a synthetic run description,
 * and the conformance checks every output file must pass (CF attributes,
 * udunits-parseable units, standard names from the CF table v80, readable
 * by ncdump and by xarray).
 */
#ifndef GF_TEST_NC_CHECK_H
#define GF_TEST_NC_CHECK_H

#include "core/gf_groups.h"
#include "gf_run_spec.h"
#include "io/gf_nc.h"
#include "particles/gf_particles.h"

typedef struct nc_test_run {
    gf_run_spec spec;
    gf_scales scales;
    gf_nc_meta meta;
    char yaml[512];
} nc_test_run;

/* The fluid fields of an immersed run as the writer declares them: fraction,
 * cell-centred velocity along x, y, z, excess pressure. */
enum { NC_TEST_N_FLUID_FIELDS = 5 };
extern const gf_var_info nc_test_fluid_fields[NC_TEST_N_FLUID_FIELDS];

/* Writes path as the fluid fields of meta's run on an n_cells grid (origin lo,
 * cells h): nt records, record it at times[it] holding value(iv, i, j, k, it)
 * in cell (i, j, k) of field iv (each call checked). */
typedef double (*nc_test_field_fn)(int iv, int i, int j, int k, int it);
void nc_test_write_fluid_fields(const char *path, const gf_nc_meta *meta, const int n_cells[3], const double lo[3],
                                const double h[3], int nt, const double *times, nc_test_field_fn value);

/* The grains of the particles writer tests: radius of grain k (m), and a
 * store of n grains, grain k at place(k) (m, t = 0) with that radius and
 * 2500 kg m-3, grain 0 glued, ids 0..n-1 in order (each call checked).
 * Owner: the caller (gf_particles_destroy); NULL when it could not be made. */
typedef void (*nc_test_place_fn)(int k, double x[3]);
double nc_test_radius(int k);
gf_particles *nc_test_particles(gf_ctx *ctx, int n, nc_test_place_fn place);

/* The main of a writer test: the round trip, checked with the python of
 * argv[1] (default python3), then the refused inputs; the exit code. */
int nc_test_main(int argc, char **argv, void (*round_trip)(const char *python), void (*errors)(void));

/* Immersed column collapse, St = 0.5, r = 2: a run as the pipeline would pass it. */
void nc_test_run_init(nc_test_run *run);

/* A fresh scratch directory under GF_BINARY_DIR (or /tmp); returns its path. */
const char *nc_test_dir(const char *name);

/* Global attributes of docs/output.md present and right (Conventions, source,
 * history timestamp within 1 h of now, run_spec_yaml verbatim, groups). */
void nc_check_globals(const char *path, const nc_test_run *run, const char *feature_type);

/* Every numeric variable: units parse with udunits2; long_name or
 * standard_name present; a standard_name is in the CF table v80 and its
 * canonical units convert to the variable's units. */
void nc_check_units_and_names(const char *path);

/* Time coordinate attributes (units, standard_name, axis, calendar). */
void nc_check_time_coordinate(const char *path);

/* `ncdump -h path` succeeds and its header contains each of the strings. */
void nc_check_ncdump(const char *path, int n_expect, const char *const *expect);

/* Runs tests/io/check_cf.py with the given python (argv[1] of the test) on
 * path; extra arguments are the per-file checks ("var[i,j]=value" ...). */
void nc_check_python(const char *python, const char *kind, const char *path, int n_args, const char *const *args);

/* Reads a whole double variable; returns malloc'd array (count in *n). */
double *nc_read_doubles(const char *path, const char *var, size_t *n);

#endif
