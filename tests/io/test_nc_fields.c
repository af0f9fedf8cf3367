/*
 * fields.nc round trip. A 5 x 4 x 3 grid (x fastest) holds analytic fields,
 * fluid_fraction = 1 - 0.4 exp(-y / h) and a Poiseuille-like u_fluid =
 * U y (H - y), sampled at cell centres lo + (i + 1/2) h: the coordinate
 * variables must be exactly those centres, and each value must land in its
 * (time, z, y, x) cell, which catches any transposition of the axes.
 */
#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_test.h"
#include "nc_check.h"

enum { NX = 5, NY = 4, NZ = 3, NT = 2, NV = 5 };
static const double lo[3] = {-0.01, 0.0, 0.002}, h[3] = {0.004, 0.0025, 0.003};

static double centre(int axis, int i) { return lo[axis] + (i + 0.5) * h[axis]; }
static double value(int iv, int i, int j, int k, int it)
{
    double x = centre(0, i), y = centre(1, j), z = centre(2, k), t = 0.5 * it;
    switch (iv) {
    case 0: return 1.0 - 0.4 * exp(-y / 0.003);
    case 1: return (1 + t) * 40.0 * y * (0.01 - y);
    case 2: return 1e-3 * x;
    case 3: return 1e-3 * z * t;
    default: return 9.81 * 1000.0 * (0.01 - y) * (1 + 0.1 * t);
    }
}

static void test_fields_round_trip(const char *python)
{
    nc_test_run run;
    nc_test_run_init(&run);
    int n_cells[3] = {NX, NY, NZ};
    char path[1100];
    snprintf(path, sizeof path, "%s/fields.nc", nc_test_dir("fields"));
    const double times[NT] = {0.0, 0.5};
    nc_test_write_fluid_fields(path, &run.meta, n_cells, lo, h, NT, times, value);

    size_t n;
    static const char *const cn[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
        double *c = nc_read_doubles(path, cn[a], &n);
        GF_CHECK(c && n == (size_t)n_cells[a]);
        for (size_t i = 0; c && i < n; ++i)
            GF_CHECK(c[i] == centre(a, (int)i));
        free(c);
    }
    for (int iv = 0; iv < NV; ++iv) {
        double *d = nc_read_doubles(path, nc_test_fluid_fields[iv].name, &n);
        GF_CHECK(d && n == (size_t)NT * NZ * NY * NX);
        int n_exact = 0;
        for (int it = 0; d && it < NT; ++it)
            for (int k = 0; k < NZ; ++k)
                for (int j = 0; j < NY; ++j)
                    for (int i = 0; i < NX; ++i)
                        n_exact += d[((it * NZ + k) * NY + j) * NX + i] == value(iv, i, j, k, it);
        gf_test_check(n_exact == NT * NZ * NY * NX, __FILE__, __LINE__, "%s: %d of %d values exact", nc_test_fluid_fields[iv].name, n_exact,
                      NT * NZ * NY * NX);
        free(d);
    }
    int ncid, var, shuffle, deflate, level, storage;
    size_t chunks[4];
    nc_open(path, NC_NOWRITE, &ncid);
    nc_inq_varid(ncid, "u_fluid", &var);
    nc_inq_var_deflate(ncid, var, &shuffle, &deflate, &level);
    nc_inq_var_chunking(ncid, var, &storage, chunks);
    GF_CHECK(deflate == 1 && storage == NC_CHUNKED);
    GF_CHECK(chunks[0] == 1 && chunks[1] == NZ && chunks[2] == NY && chunks[3] == NX);
    nc_close(ncid);

    nc_check_globals(path, &run, NULL);
    nc_check_time_coordinate(path);
    nc_check_units_and_names(path);
    const char *expect[] = {"double u_fluid(time, z, y, x)", "x:axis = \"X\"", "z:axis = \"Z\"", "x = 5 ;"};
    nc_check_ncdump(path, 4, expect);
    char a1[80], a2[80], a3[80];
    snprintf(a1, sizeof a1, "u_fluid[1,2,3,4]=%.17g", value(1, 4, 3, 2, 1));
    snprintf(a2, sizeof a2, "y[3]=%.17g", centre(1, 3));
    snprintf(a3, sizeof a3, "excess_pressure[0,0,1,2]=%.17g", value(4, 2, 1, 0, 0));
    const char *args[] = {"time=0,0.5", a1, a2, a3};
    nc_check_python(python, "fields", path, 4, args);
}

static void test_fields_errors(void)
{
    nc_test_run run;
    nc_test_run_init(&run);
    gf_ctx ctx = {0};
    gf_var_info vars[1] = {{"fluid_fraction", "1", "fluid volume fraction", NULL}};
    int n_cells[3] = {4, 0, 2};
    char path[1100];
    snprintf(path, sizeof path, "%s/fields.nc", nc_test_dir("fields-errors"));
    gf_nc_writer *w = NULL;
    GF_CHECK(gf_nc_fields_open(&ctx, path, &run.meta, n_cells, lo, h, vars, 1, &w) == GF_ERR_ARG);
    GF_CHECK(strstr(ctx.last_msg, "n_cells[1]") != NULL);
    gf_var_info coord[1] = {{"x", "m", "clash", NULL}};
    n_cells[1] = 2;
    GF_CHECK(gf_nc_fields_open(&ctx, path, &run.meta, n_cells, lo, h, coord, 1, &w) == GF_ERR_ARG);
    GF_CHECK(w == NULL);
}

int main(int argc, char **argv)
{
    return nc_test_main(argc, argv, test_fields_round_trip, test_fields_errors);
}
