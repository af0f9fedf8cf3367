/*
 * particles.nc round trip (CF featureType trajectory). Ten grains move
 * ballistically, x = x0 + u t, y = y0 + v t - g t^2 / 2, so every written
 * value has a closed form. Between records the store is reordered and one
 * grain removed (as sorting and outflow do): the writer must follow grains
 * by id, put each value in its own trajectory row, and write NaN for the
 * removed grain. Doubles round-trip exactly, so comparisons are exact.
 */
#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_test.h"
#include "nc_check.h"

enum { N = 10, NT = 3 };
static const double g = 9.81;

static double x_at(int k, double t) { return 0.01 * k + 0.1 * k * t; }
static double y_at(int k, double t) { return 0.02 + 0.003 * k + 0.5 * t - 0.5 * g * t * t; }
static double z_at(int k, double t) { (void)t; return -0.001 * k; }
static double v_at(int k, double t) { (void)k; return 0.5 - g * t; }

static void start(int k, double x[3]) { x[0] = x_at(k, 0), x[1] = y_at(k, 0), x[2] = z_at(k, 0); }

/* set every grain's state from its id (= k, its trajectory at open) */
static void set_state(gf_particles *p, double t)
{
    for (size_t i = 0; i < p->n_local; ++i) {
        int k = (int)p->id[i];
        if (p->flags[i] & GF_P_GLUED)
            continue;
        p->x_m[i] = x_at(k, t);
        p->y_m[i] = y_at(k, t);
        p->z_m[i] = z_at(k, t);
        p->vx_m_s[i] = 0.1 * k;
        p->vy_m_s[i] = v_at(k, t);
        p->vz_m_s[i] = 0.0;
    }
}

static void test_particles_round_trip(const char *python)
{
    nc_test_run run;
    nc_test_run_init(&run);
    gf_ctx ctx = {0};
    gf_particles *p = nc_test_particles(&ctx, N, start);
    GF_CHECK(p->id[3] == 3);   /* ids are assigned in insertion order: trajectory k has id k */
    char path[1100];
    snprintf(path, sizeof path, "%s/particles.nc", nc_test_dir("particles"));
    gf_nc_writer *w = NULL;
    GF_CHECK_OK(gf_nc_particles_open(&ctx, path, &run.meta, p, &w), &ctx);
    double times[NT] = {0.0, 0.02, 0.04};
    for (int it = 0; it < NT; ++it) {
        if (it == 1)
            gf_particles_remove(p, 2);   /* grain 2 leaves; grain 9 takes index 2 */
        set_state(p, times[it]);
        GF_CHECK_OK(gf_nc_particles_append(w, times[it], p), &ctx);
    }
    GF_CHECK_OK(gf_nc_writer_close(&w), &ctx);

    size_t n;
    double *x = nc_read_doubles(path, "x", &n);
    double *y = nc_read_doubles(path, "y", &n);
    double *v = nc_read_doubles(path, "v", &n);
    double *r = nc_read_doubles(path, "radius", &n);
    GF_CHECK(x && y && v && r);
    int n_exact = 0, n_nan_ok = 0;
    for (int k = 0; x && y && v && k < N; ++k)
        for (int it = 0; it < NT; ++it) {
            size_t ij = (size_t)k * NT + (size_t)it;   /* (trajectory, time) */
            if (k == 2 && it > 0) {
                n_nan_ok += isnan(x[ij]) && isnan(y[ij]) && isnan(v[ij]);
                continue;
            }
            double tt = k == 0 ? 0.0 : times[it];   /* the glued grain keeps its place */
            n_exact += x[ij] == x_at(k, tt) && y[ij] == y_at(k, tt) && (k == 0 || v[ij] == v_at(k, tt));
        }
    GF_CHECK(n_exact == N * NT - 2);
    GF_CHECK(n_nan_ok == 2);
    for (int k = 0; r && k < N; ++k)
        GF_CHECK(r[k] == nc_test_radius(k));
    free(x);
    free(y);
    free(v);
    free(r);

    /* static per-grain data: ids, glued flags */
    int ncid, var;
    GF_CHECK(nc_open(path, NC_NOWRITE, &ncid) == NC_NOERR);
    long long ids[N];
    signed char glued[N];
    nc_inq_varid(ncid, "trajectory_id", &var);
    nc_type t;
    nc_inq_vartype(ncid, var, &t);
    GF_CHECK(t == NC_INT64);
    nc_get_var_longlong(ncid, var, ids);
    nc_inq_varid(ncid, "glued", &var);
    nc_get_var_schar(ncid, var, glued);
    for (int k = 0; k < N; ++k)
        GF_CHECK(ids[k] == k && glued[k] == (k == 0));
    /* compression and chunking on the big variables */
    int shuffle, deflate, level, storage;
    size_t chunks[2];
    nc_inq_varid(ncid, "x", &var);
    nc_inq_var_deflate(ncid, var, &shuffle, &deflate, &level);
    nc_inq_var_chunking(ncid, var, &storage, chunks);
    GF_CHECK(deflate == 1 && level >= 1 && shuffle == 1);
    GF_CHECK(storage == NC_CHUNKED && chunks[0] == N && chunks[1] == 1);
    nc_close(ncid);

    nc_check_globals(path, &run, "trajectory");
    nc_check_time_coordinate(path);
    nc_check_units_and_names(path);
    const char *expect[] = {"trajectory = 10", "int64 trajectory_id(trajectory)", "trajectory_id:cf_role = \"trajectory_id\"",
                            "double x(trajectory, time)", ":featureType = \"trajectory\"", "x:axis = \"X\""};
    nc_check_ncdump(path, 6, expect);
    char a1[64], a2[64], a3[64];
    snprintf(a1, sizeof a1, "x[9,2]=%.17g", x_at(9, 0.04));
    snprintf(a2, sizeof a2, "v[5,1]=%.17g", v_at(5, 0.02));
    snprintf(a3, sizeof a3, "y[2,2]=nan");
    const char *args[] = {"time=0,0.02,0.04", a1, a2, a3, "trajectory_id[7]=7"};
    nc_check_python(python, "particles", path, 5, args);
    gf_particles_destroy(&p);
}

/* A grain that was not there at open cannot get a trajectory: error, named. */
static void test_particles_new_grain_is_refused(void)
{
    nc_test_run run;
    nc_test_run_init(&run);
    gf_ctx ctx = {0};
    gf_particles *p = NULL;
    GF_CHECK_OK(gf_particles_create(&ctx, 4, &p), &ctx);
    for (int k = 0; k < 3; ++k)
        gf_particles_add(&ctx, p, 0.01 * k, 0.0, 0.0, 1e-3, 2500.0, 0, NULL);
    char path[1100];
    snprintf(path, sizeof path, "%s/particles.nc", nc_test_dir("particles-new"));
    gf_nc_writer *w = NULL;
    GF_CHECK_OK(gf_nc_particles_open(&ctx, path, &run.meta, p, &w), &ctx);
    gf_particles_add(&ctx, p, 0.05, 0.0, 0.0, 1e-3, 2500.0, 0, NULL);
    GF_CHECK(gf_nc_particles_append(w, 0.0, p) == GF_ERR_ARG);
    GF_CHECK(strstr(ctx.last_msg, "grain id 3") != NULL);
    gf_nc_writer_abort(&w);
    gf_particles_destroy(&p);
    /* an empty store is refused at open */
    gf_particles *empty = NULL;
    gf_particles_create(&ctx, 1, &empty);
    GF_CHECK(gf_nc_particles_open(&ctx, path, &run.meta, empty, &w) == GF_ERR_ARG);
    gf_particles_destroy(&empty);
}

int main(int argc, char **argv)
{
    return nc_test_main(argc, argv, test_particles_round_trip, test_particles_new_grain_is_refused);
}
