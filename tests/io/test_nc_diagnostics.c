/*
 * diagnostics.nc round trip: a column-collapse diagnostic set with known
 * values (front position x_f(t) = R0 + 0.5 g t^2, the free-fall upper bound
 * of a front, and kinetic energy of a falling block E = m g^2 t^2 / 2) is
 * written at five times, read back with netCDF-C and with xarray, and every
 * unit, standard name and global attribute of docs/output.md is checked.
 * Values are stored as doubles, so they must come back bit for bit
 * (relative tolerance 1e-15 only absorbs the printf in the python path).
 */
#define _XOPEN_SOURCE 700
#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_test.h"
#include "nc_check.h"

static const double g = 9.81, R0 = 0.06, mass = 0.12;

static double front_m(double t) { return R0 + 0.5 * g * t * t; }
static double energy_J(double t) { return 0.5 * mass * g * g * t * t; }

static const gf_var_info diag_vars[] = {
    {"kinetic_energy", "J", "kinetic energy of the mobile grains", NULL},
    {"ecx_per_grain", "J", "horizontal kinetic energy per mobile grain (E_cx, Izard 5.3)", NULL},
    {"n_contacts", "1", "number of grain-grain and grain-wall contacts", NULL},
    {"max_overlap_over_D", "1", "largest overlap divided by the mean diameter", NULL},
    {"front_position", "m", "front position from the back wall", NULL},
    {"deposit_height", "m", "maximum deposit height", NULL},
    {"packing_fraction", "1", "solid volume fraction of the column region", NULL},
};
enum { NV = sizeof diag_vars / sizeof *diag_vars, NT = 5 };

static void test_diagnostics_round_trip(const char *python)
{
    nc_test_run run;
    nc_test_run_init(&run);
    gf_ctx ctx = {0};
    char path[1100];
    snprintf(path, sizeof path, "%s/diagnostics.nc", nc_test_dir("diagnostics"));
    gf_nc_writer *w = NULL;
    GF_CHECK_OK(gf_nc_diagnostics_open(&ctx, path, &run.meta, diag_vars, NV, &w), &ctx);
    double times[NT];
    for (int it = 0; it < NT; ++it) {
        double t = 0.05 * it;
        times[it] = t;
        double v[NV] = {energy_J(t), energy_J(t) / 100, 40 + it, 1e-3 * it, front_m(t), 0.042 - 0.002 * it,
                        0.6 - 0.01 * it};
        GF_CHECK_OK(gf_nc_diagnostics_append(w, t, v), &ctx);
    }
    /* the final name appears only on close */
    FILE *early = fopen(path, "r");
    GF_CHECK(early == NULL);
    if (early)
        fclose(early);
    GF_CHECK_OK(gf_nc_writer_close(&w), &ctx);
    GF_CHECK(w == NULL);

    size_t n;
    double *t_back = nc_read_doubles(path, "time", &n);
    GF_CHECK(n == NT);
    for (size_t i = 0; t_back && i < n; ++i)
        GF_CHECK(t_back[i] == times[i]);
    free(t_back);
    double *front = nc_read_doubles(path, "front_position", &n);
    GF_CHECK(n == NT);
    for (size_t i = 0; front && i < n; ++i)
        GF_CHECK(front[i] == front_m(times[i]));
    free(front);
    double *ke = nc_read_doubles(path, "kinetic_energy", &n);
    for (size_t i = 0; ke && i < n; ++i)
        GF_CHECK(ke[i] == energy_J(times[i]));
    free(ke);

    nc_check_globals(path, &run, NULL);
    nc_check_time_coordinate(path);
    nc_check_units_and_names(path);
    const char *expect[] = {"time = UNLIMITED", "double front_position(time)", ":units = \"s since 2000-01-01 00:00:00\"",
                            ":Conventions = \"CF-1.10\"", ":run_spec_yaml"};
    nc_check_ncdump(path, 5, expect);
    char a1[64], a2[64];
    snprintf(a1, sizeof a1, "front_position[4]=%.17g", front_m(0.2));
    snprintf(a2, sizeof a2, "n_contacts[2]=%d", 42);
    const char *args[] = {"time=0,0.05,0.1,0.15,0.2", a1, a2};
    nc_check_python(python, "diagnostics", path, 3, args);
}

/* Bad input gives one clear error and no file. */
static void test_diagnostics_errors(void)
{
    nc_test_run run;
    nc_test_run_init(&run);
    gf_ctx ctx = {0};
    char path[1100];
    const char *dir = nc_test_dir("diagnostics-errors");
    snprintf(path, sizeof path, "%s/diagnostics.nc", dir);
    gf_nc_writer *w = NULL;

    gf_var_info no_units[] = {{"front_position", NULL, "front", NULL}};
    GF_CHECK(gf_nc_diagnostics_open(&ctx, path, &run.meta, no_units, 1, &w) == GF_ERR_ARG);
    GF_CHECK(strstr(ctx.last_msg, "front_position") && strstr(ctx.last_msg, "units"));
    GF_CHECK(w == NULL);

    char bad_path[1200];
    snprintf(bad_path, sizeof bad_path, "%s/no/such/dir/diagnostics.nc", dir);
    GF_CHECK(gf_nc_diagnostics_open(&ctx, bad_path, &run.meta, diag_vars, NV, &w) == GF_ERR_IO);
    GF_CHECK(strstr(ctx.last_msg, bad_path) != NULL);   /* the message names the file */
    printf("error for a missing directory: %s\n", ctx.last_msg);

    GF_CHECK_OK(gf_nc_diagnostics_open(&ctx, path, &run.meta, diag_vars, NV, &w), &ctx);
    double v[NV] = {0};
    GF_CHECK_OK(gf_nc_diagnostics_append(w, 1.0, v), &ctx);
    /* CF coordinate variables are strictly monotonic */
    GF_CHECK(gf_nc_diagnostics_append(w, 1.0, v) == GF_ERR_ARG);
    GF_CHECK(strstr(ctx.last_msg, "does not increase") != NULL);
    GF_CHECK(gf_nc_diagnostics_append(w, NAN, v) == GF_ERR_ARG);
    gf_nc_writer_abort(&w);
    GF_CHECK(w == NULL);
    FILE *fp = fopen(path, "r");
    GF_CHECK(fp == NULL);
    if (fp)
        fclose(fp);
    char tmp[1200];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    fp = fopen(tmp, "r");
    GF_CHECK(fp == NULL);   /* abort removes the temporary file too */
    if (fp)
        fclose(fp);
    /* NULL handles are accepted */
    GF_CHECK(gf_nc_writer_close(&w) == GF_OK);
    gf_nc_writer_abort(&w);
}

int main(int argc, char **argv)
{
    return nc_test_main(argc, argv, test_diagnostics_round_trip, test_diagnostics_errors);
}
