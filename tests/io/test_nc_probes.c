/*
 * probes.nc round trip (CF featureType timeSeries). Three basal gauges
 * under a collapsing column record an excess pore pressure with a known
 * trace, p_e(x, t) = -P0 exp(-t / tau) cos(pi x / (2 L0)) (a decaying
 * negative pulse, the dense-column signature of Rondon et al. 2011), and
 * must come back exactly, with the gauge names as timeseries_id.
 */
#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_test.h"
#include "nc_check.h"

enum { NS = 3, NT = 4 };
static const double P0 = 35.0, tau = 0.4, L0 = 0.06;

static double pe_Pa(double x, double t) { return -P0 * exp(-t / tau) * cos(M_PI * x / (2 * L0)); }

static void test_probes_round_trip(const char *python)
{
    nc_test_run run;
    nc_test_run_init(&run);
    gf_ctx ctx = {0};
    const char *names[NS] = {"gauge_back", "gauge_mid", "gauge_front_long_name"};
    double xyz[3 * NS] = {0.005, 0.0, 0.0, 0.03, 0.0, 0.0, 0.055, 0.0, 0.0};
    gf_var_info vars[] = {{"excess_pore_pressure", "Pa", "pore pressure minus hydrostatic at the gauge", NULL}};
    char path[1100];
    snprintf(path, sizeof path, "%s/probes.nc", nc_test_dir("probes"));
    gf_nc_writer *w = NULL;
    GF_CHECK_OK(gf_nc_probes_open(&ctx, path, &run.meta, NS, names, xyz, vars, 1, &w), &ctx);
    for (int it = 0; it < NT; ++it) {
        double t = 0.1 * it, val[NS];
        for (int s = 0; s < NS; ++s)
            val[s] = pe_Pa(xyz[3 * s], t);
        GF_CHECK_OK(gf_nc_probes_append(w, t, val), &ctx);
    }
    GF_CHECK_OK(gf_nc_writer_close(&w), &ctx);

    size_t n;
    double *pe = nc_read_doubles(path, "excess_pore_pressure", &n);
    GF_CHECK(n == NS * NT);
    int n_exact = 0;
    for (int s = 0; pe && s < NS; ++s)
        for (int it = 0; it < NT; ++it)
            n_exact += pe[s * NT + it] == pe_Pa(xyz[3 * s], 0.1 * it);
    GF_CHECK(n_exact == NS * NT);
    free(pe);
    double *xs = nc_read_doubles(path, "x", &n);
    GF_CHECK(n == NS && xs && xs[2] == 0.055);
    free(xs);

    int ncid, var;
    nc_open(path, NC_NOWRITE, &ncid);
    nc_inq_varid(ncid, "station_name", &var);
    size_t len;
    int dim;
    nc_inq_dimid(ncid, "name_strlen", &dim);
    nc_inq_dimlen(ncid, dim, &len);
    GF_CHECK(len == strlen("gauge_front_long_name"));
    char *text = calloc(NS * len + 1, 1);
    nc_get_var_text(ncid, var, text);
    GF_CHECK(strncmp(text + len, "gauge_mid", len) == 0);
    free(text);
    nc_close(ncid);

    nc_check_globals(path, &run, "timeSeries");
    nc_check_time_coordinate(path);
    nc_check_units_and_names(path);
    const char *expect[] = {"station = 3", "char station_name(station, name_strlen)",
                            "station_name:cf_role = \"timeseries_id\"", "double excess_pore_pressure(station, time)",
                            ":featureType = \"timeSeries\""};
    nc_check_ncdump(path, 5, expect);
    char a1[80];
    snprintf(a1, sizeof a1, "excess_pore_pressure[1,3]=%.17g", pe_Pa(0.03, 0.3));
    const char *args[] = {"time=0,0.1,0.2,0.3", a1, "station_name[2]=gauge_front_long_name"};
    nc_check_python(python, "probes", path, 3, args);
}

static void test_probes_errors(void)
{
    nc_test_run run;
    nc_test_run_init(&run);
    gf_ctx ctx = {0};
    const char *names[2] = {"a", "a"};
    double xyz[6] = {0};
    gf_var_info vars[] = {{"excess_pore_pressure", "Pa", "excess pore pressure", NULL}};
    char path[1100];
    snprintf(path, sizeof path, "%s/probes.nc", nc_test_dir("probes-errors"));
    gf_nc_writer *w = NULL;
    GF_CHECK(gf_nc_probes_open(&ctx, path, &run.meta, 2, names, xyz, vars, 1, &w) == GF_ERR_ARG);
    GF_CHECK(strstr(ctx.last_msg, "used twice") != NULL);
    names[1] = "b";
    xyz[4] = NAN;
    GF_CHECK(gf_nc_probes_open(&ctx, path, &run.meta, 2, names, xyz, vars, 1, &w) == GF_ERR_ARG);
    GF_CHECK(strstr(ctx.last_msg, "station b") != NULL);
    GF_CHECK(w == NULL);
}

int main(int argc, char **argv)
{
    return nc_test_main(argc, argv, test_probes_round_trip, test_probes_errors);
}
