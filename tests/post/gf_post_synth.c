/* Synthetic run files following docs/output.md (see gf_post_synth.h). */
#include "gf_post_synth.h"

#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define CK(call)                                                                   \
    do {                                                                           \
        int rc_ = (call);                                                          \
        if (rc_ != NC_NOERR) {                                                     \
            fprintf(stderr, "synth %s:%d: %s\n", __FILE__, __LINE__, nc_strerror(rc_)); \
            return -1;                                                             \
        }                                                                          \
    } while (0)

void synth_meta_default(synth_meta *m, const char *run_id, const char *scene)
{
    memset(m, 0, sizeof *m);
    m->run_id = run_id;
    m->scene = scene;
    m->fluid_model = "resolved";
    m->St = m->r = m->a = m->phi = NAN;
    m->D = 5e-3;
    m->rho_p = 2500.0;
    m->rho_f = 1000.0;
    m->eta = 0.01;
    m->g = 9.81;
}

static int txt(int ncid, int var, const char *name, const char *v)
{
    return nc_put_att_text(ncid, var, name, strlen(v), v);
}

static int dbl(int ncid, const char *name, double v)
{
    return nc_put_att_double(ncid, NC_GLOBAL, name, NC_DOUBLE, 1, &v);
}

static int globals(int ncid, const synth_meta *m)
{
    CK(txt(ncid, NC_GLOBAL, "Conventions", "CF-1.10"));
    CK(txt(ncid, NC_GLOBAL, "title", "synthetic test run"));
    CK(txt(ncid, NC_GLOBAL, "run_id", m->run_id));
    CK(txt(ncid, NC_GLOBAL, "scene", m->scene));
    CK(txt(ncid, NC_GLOBAL, "fluid_model", m->fluid_model));
    const struct {
        const char *name;
        double value;
    } numbers[] = {{"stokes_St", m->St}, {"density_ratio_r", m->r}, {"aspect_ratio_a", m->a},
                   {"phi_initial", m->phi}, {"grain_diameter_m", m->D}, {"grain_density_kg_m3", m->rho_p},
                   {"fluid_density_kg_m3", m->rho_f}, {"fluid_viscosity_Pa_s", m->eta}, {"gravity_m_s2", m->g},
                   {"incline_deg", m->incline_deg}, {"column_length_m", m->R0}, {"column_height_m", m->H0}};
    for (size_t k = 0; k < sizeof numbers / sizeof numbers[0]; ++k)
        CK(dbl(ncid, numbers[k].name, numbers[k].value));
    return 0;
}

static int time_var(int ncid, int dim, int *var)
{
    CK(nc_def_var(ncid, "time", NC_DOUBLE, 1, &dim, var));
    CK(txt(ncid, *var, "units", "s since 2000-01-01 00:00:00"));
    CK(txt(ncid, *var, "standard_name", "time"));
    CK(txt(ncid, *var, "axis", "T"));
    CK(txt(ncid, *var, "calendar", "standard"));
    return 0;
}

/* An output file being written: dir/name, written as dir/name.tmp until finish renames it. */
typedef struct synth_file {
    char path[1024], tmp[1100];
    int ncid;
} synth_file;

/* Creates f for dir/name with the run's global attributes and, unless NULL, its CF featureType. */
static int create(synth_file *f, const char *dir, const char *name, const synth_meta *m, const char *feature_type)
{
    snprintf(f->path, sizeof f->path, "%s/%s", dir, name);
    snprintf(f->tmp, sizeof f->tmp, "%s.tmp", f->path);
    CK(nc_create(f->tmp, NC_CLOBBER | NC_NETCDF4, &f->ncid));
    if (globals(f->ncid, m))
        return -1;
    if (feature_type)
        CK(txt(f->ncid, NC_GLOBAL, "featureType", feature_type));
    return 0;
}

static int finish(const synth_file *f)
{
    CK(nc_close(f->ncid));
    return rename(f->tmp, f->path);
}

int synth_diagnostics(const char *dir, const synth_meta *m, size_t nt, const double *t, int n_vars,
                      const char *const *names, const char *const *units, const double *const *values)
{
    synth_file f;
    if (create(&f, dir, "diagnostics.nc", m, NULL))
        return -1;
    int ncid = f.ncid, dt, vt, v[32];
    CK(nc_def_dim(ncid, "time", NC_UNLIMITED, &dt));
    if (time_var(ncid, dt, &vt))
        return -1;
    for (int k = 0; k < n_vars; ++k) {
        CK(nc_def_var(ncid, names[k], NC_DOUBLE, 1, &dt, &v[k]));
        CK(txt(ncid, v[k], "units", units[k]));
    }
    CK(nc_enddef(ncid));
    size_t start = 0, count = nt;
    CK(nc_put_vara_double(ncid, vt, &start, &count, t));
    for (int k = 0; k < n_vars; ++k)
        CK(nc_put_vara_double(ncid, v[k], &start, &count, values[k]));
    return finish(&f);
}

int synth_particles(const char *dir, const synth_meta *m, size_t n, size_t nt, const double *t, const double *radius,
                    const unsigned char *glued, const double *x, const double *y, const double *z, const double *u)
{
    synth_file f;
    if (create(&f, dir, "particles.nc", m, "trajectory"))
        return -1;
    int ncid = f.ncid, dtr, dt, vt, vid, vr, vg, vx, vy, vz, vu, vv, vw;
    CK(nc_def_dim(ncid, "trajectory", n, &dtr));
    CK(nc_def_dim(ncid, "time", nt, &dt));
    if (time_var(ncid, dt, &vt))
        return -1;
    int d2[2] = {dtr, dt};
    CK(nc_def_var(ncid, "trajectory_id", NC_INT64, 1, &dtr, &vid));
    CK(txt(ncid, vid, "cf_role", "trajectory_id"));
    CK(nc_def_var(ncid, "radius", NC_DOUBLE, 1, &dtr, &vr));
    CK(txt(ncid, vr, "units", "m"));
    CK(nc_def_var(ncid, "glued", NC_BYTE, 1, &dtr, &vg));
    const char *nm[6] = {"x", "y", "z", "u", "v", "w"};
    int *ids[6] = {&vx, &vy, &vz, &vu, &vv, &vw};
    for (int k = 0; k < 6; ++k) {
        CK(nc_def_var(ncid, nm[k], NC_DOUBLE, 2, d2, ids[k]));
        CK(txt(ncid, *ids[k], "units", k < 3 ? "m" : "m s-1"));
    }
    CK(nc_enddef(ncid));
    long long *id = malloc(n * sizeof *id + 1);
    signed char *gl = malloc(n + 1);
    double *zero = calloc(n * nt + 1, sizeof *zero);
    for (size_t i = 0; i < n; ++i) {
        id[i] = (long long)i;
        gl[i] = glued ? (signed char)glued[i] : 0;
    }
    CK(nc_put_var_double(ncid, vt, t));
    CK(nc_put_var_longlong(ncid, vid, id));
    CK(nc_put_var_double(ncid, vr, radius));
    CK(nc_put_var_schar(ncid, vg, gl));
    const double *values[6] = {x, y, z ? z : zero, u ? u : zero, zero, zero}; /* nm's order */
    for (int k = 0; k < 6; ++k)
        CK(nc_put_var_double(ncid, *ids[k], values[k]));
    free(id), free(gl), free(zero);
    return finish(&f);
}

int synth_probes(const char *dir, const synth_meta *m, size_t ns, const char *const *names, const double *xs,
                 size_t nt, const double *t, const double *P)
{
    synth_file f;
    if (create(&f, dir, "probes.nc", m, "timeSeries"))
        return -1;
    int ncid = f.ncid, dst, dt, dl, vt, vn, vx, vy, vz, vp;
    CK(nc_def_dim(ncid, "station", ns, &dst));
    CK(nc_def_dim(ncid, "time", nt, &dt));
    CK(nc_def_dim(ncid, "name_strlen", 16, &dl));
    if (time_var(ncid, dt, &vt))
        return -1;
    int dn[2] = {dst, dl}, dp[2] = {dst, dt};
    CK(nc_def_var(ncid, "station_name", NC_CHAR, 2, dn, &vn));
    CK(txt(ncid, vn, "cf_role", "timeseries_id"));
    CK(nc_def_var(ncid, "x", NC_DOUBLE, 1, &dst, &vx));
    CK(nc_def_var(ncid, "y", NC_DOUBLE, 1, &dst, &vy));
    CK(nc_def_var(ncid, "z", NC_DOUBLE, 1, &dst, &vz));
    CK(nc_def_var(ncid, "excess_pore_pressure", NC_DOUBLE, 2, dp, &vp));
    CK(txt(ncid, vp, "units", "Pa"));
    CK(txt(ncid, vp, "long_name", "pressure minus hydrostatic"));
    CK(nc_enddef(ncid));
    char *nb = calloc(ns * 16 + 1, 1);
    double *zero = calloc(ns + 1, sizeof *zero);
    for (size_t s = 0; s < ns; ++s)
        strncpy(nb + 16 * s, names[s], 16);
    CK(nc_put_var_double(ncid, vt, t));
    CK(nc_put_var_text(ncid, vn, nb));
    CK(nc_put_var_double(ncid, vx, xs));
    CK(nc_put_var_double(ncid, vy, zero));
    CK(nc_put_var_double(ncid, vz, zero));
    CK(nc_put_var_double(ncid, vp, P));
    free(nb), free(zero);
    return finish(&f);
}

int synth_fields(const char *dir, const synth_meta *m, size_t nx, size_t ny, size_t nz, double dx, size_t nt,
                 const double *t, const double *eps, const double *u)
{
    synth_file f;
    if (create(&f, dir, "fields.nc", m, NULL))
        return -1;
    int ncid = f.ncid, d[4], vt, vc[3], ve, vu;
    CK(nc_def_dim(ncid, "time", nt, &d[0]));
    CK(nc_def_dim(ncid, "z", nz, &d[1]));
    CK(nc_def_dim(ncid, "y", ny, &d[2]));
    CK(nc_def_dim(ncid, "x", nx, &d[3]));
    if (time_var(ncid, d[0], &vt))
        return -1;
    const char *cn[3] = {"z", "y", "x"}, *ax[3] = {"Z", "Y", "X"};
    for (int k = 0; k < 3; ++k) {
        CK(nc_def_var(ncid, cn[k], NC_DOUBLE, 1, &d[k + 1], &vc[k]));
        CK(txt(ncid, vc[k], "units", "m"));
        CK(txt(ncid, vc[k], "axis", ax[k]));
    }
    CK(nc_def_var(ncid, "fluid_fraction", NC_DOUBLE, 4, d, &ve));
    CK(txt(ncid, ve, "units", "1"));
    CK(nc_def_var(ncid, "u_fluid", NC_DOUBLE, 4, d, &vu));
    CK(txt(ncid, vu, "units", "m s-1"));
    CK(nc_enddef(ncid));
    const size_t len[3] = {nz, ny, nx};
    for (int k = 0; k < 3; ++k) {
        double c[4096];
        for (size_t i = 0; i < len[k] && i < 4096; ++i)
            c[i] = (i + 0.5) * dx;
        CK(nc_put_var_double(ncid, vc[k], c));
    }
    CK(nc_put_var_double(ncid, vt, t));
    CK(nc_put_var_double(ncid, ve, eps));
    CK(nc_put_var_double(ncid, vu, u));
    return finish(&f);
}

int synth_status(const char *dir, const char *line)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/status", dir);
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fprintf(f, "%s\n", line);
    return fclose(f);
}

int synth_mkdir(const char *dir)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", dir);
    for (char *p = buf + 1; *p; ++p)
        if (*p == '/') {
            *p = '\0';
            mkdir(buf, 0777);
            *p = '/';
        }
    mkdir(buf, 0777);   /* may already exist */
    return 0;
}

void synth_scratch(char *buf, size_t size, const char *name)
{
    const char *base = getenv("GF_BINARY_DIR");
    snprintf(buf, size, "%s/post_scratch/%s", base ? base : "/tmp", name);
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", buf);
    if (system(cmd) != 0)
        fprintf(stderr, "synth: could not clear %s\n", buf);
    synth_mkdir(buf);
}
