/* Conformance checks for the netCDF writer tests; see nc_check.h. */
#define _XOPEN_SOURCE 700
#include "nc_check.h"

#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <udunits2.h>

#include "core/gf_build_info.h"
#include "gf_test.h"

const gf_var_info nc_test_fluid_fields[NC_TEST_N_FLUID_FIELDS] = {
    {"fluid_fraction", "1", "fluid volume fraction of the cell", NULL},
    {"u_fluid", "m s-1", "cell-centred fluid velocity along x", NULL},
    {"v_fluid", "m s-1", "cell-centred fluid velocity along y", NULL},
    {"w_fluid", "m s-1", "cell-centred fluid velocity along z", NULL},
    {"excess_pressure", "Pa", "fluid pressure minus hydrostatic", NULL}};

void nc_test_write_fluid_fields(const char *path, const gf_nc_meta *meta, const int n_cells[3], const double lo[3],
                                const double h[3], int nt, const double *times, nc_test_field_fn value)
{
    gf_ctx ctx = {0};
    gf_nc_writer *w = NULL;
    const size_t nx = (size_t)n_cells[0], ny = (size_t)n_cells[1], nz = (size_t)n_cells[2];
    double *f = malloc(NC_TEST_N_FLUID_FIELDS * nz * ny * nx * sizeof *f);
    if (!f) {
        GF_CHECK(f != NULL);
        return;
    }
    const double *ptr[NC_TEST_N_FLUID_FIELDS];
    for (int iv = 0; iv < NC_TEST_N_FLUID_FIELDS; ++iv)
        ptr[iv] = f + iv * nz * ny * nx;
    GF_CHECK_OK(gf_nc_fields_open(&ctx, path, meta, n_cells, lo, h, nc_test_fluid_fields, NC_TEST_N_FLUID_FIELDS, &w),
                &ctx);
    for (int it = 0; it < nt; ++it) {
        for (int iv = 0; iv < NC_TEST_N_FLUID_FIELDS; ++iv)
            for (size_t k = 0; k < nz; ++k)
                for (size_t j = 0; j < ny; ++j)
                    for (size_t i = 0; i < nx; ++i)
                        f[iv * nz * ny * nx + (k * ny + j) * nx + i] = value(iv, (int)i, (int)j, (int)k, it);
        GF_CHECK_OK(gf_nc_fields_append(w, times[it], ptr), &ctx);
    }
    GF_CHECK_OK(gf_nc_writer_close(&w), &ctx);
    free(f);
}

double nc_test_radius(int k) { return 1e-3 * (1 + 0.01 * k); }

gf_particles *nc_test_particles(gf_ctx *ctx, int n, nc_test_place_fn place)
{
    gf_particles *p = NULL;
    GF_CHECK_OK(gf_particles_create(ctx, (size_t)n, &p), ctx);
    for (int k = 0; p && k < n; ++k) {
        double x[3];
        place(k, x);
        GF_CHECK_OK(gf_particles_add(ctx, p, x[0], x[1], x[2], nc_test_radius(k), 2500.0, k == 0 ? GF_P_GLUED : 0,
                                     NULL),
                    ctx);
    }
    return p;
}

int nc_test_main(int argc, char **argv, void (*round_trip)(const char *python), void (*errors)(void))
{
    round_trip(argc > 1 ? argv[1] : "python3");
    errors();
    return gf_test_finish();
}

void nc_test_run_init(nc_test_run *run)
{
    memset(run, 0, sizeof *run);
    gf_run_spec_defaults(&run->spec);
    snprintf(run->spec.run_id, sizeof run->spec.run_id, "t3st1d");
    run->spec.stokes_St = 0.5;
    run->spec.density_ratio_r = 2.0;
    run->spec.aspect_ratio_a = 0.7;
    run->spec.phi_initial = 0.6;
    /* (St, r) -> (rho_f, eta_f) by the inverse map of gf_groups (the pipeline's job) */
    double rho_f, eta_f;
    gf_ctx ctx = {0};
    gf_groups_invert(&ctx, 0.5, 2.0, run->spec.grains.diameter_m, run->spec.grains.density_kg_m3, 9.81, &rho_f,
                     &eta_f);
    run->spec.fluid.density_kg_m3 = rho_f;
    run->spec.fluid.viscosity_Pa_s = eta_f;
    snprintf(run->spec.fluid.model, sizeof run->spec.fluid.model, "unresolved");
    gf_run_spec_set_param(&ctx, &run->spec, "aspect_ratio", 0.7);
    gf_groups_input in = {.diameter_m = run->spec.grains.diameter_m,
                          .grain_density_kg_m3 = run->spec.grains.density_kg_m3,
                          .fluid_density_kg_m3 = rho_f,
                          .viscosity_Pa_s = eta_f,
                          .gravity_m_s2 = 9.81,
                          .slope_sin = 1.0,
                          .column_height_m = 0.042,
                          .column_length_m = 0.06};
    gf_groups_compute(&ctx, &in, &run->scales);
    snprintf(run->yaml, sizeof run->yaml,
             "scene: column_collapse\nrun_id: t3st1d\ngroups: {St: 0.5, r: 2, a: 0.7, phi_initial: 0.6}\n"
             "note: \"quotes, <angle> & ampersand\"\n");
    run->meta = (gf_nc_meta){.spec = &run->spec,
                             .scales = &run->scales,
                             .resolved_yaml = run->yaml,
                             .fluid_model = "unresolved",
                             .fluid_model_reason = "St >= 0.1 and cell/D >= 2",
                             .stages = "contacts,integrate,coupling",
                             .column_length_m = 0.06,
                             .column_height_m = 0.042,
                             .incline_deg = 0.0,
                             .phi_initial_measured = 0.598,
                             .phi_initial_local = NAN};
}

const char *nc_test_dir(const char *name)
{
    static char dir[1024];
    const char *base = getenv("GF_BINARY_DIR");
    snprintf(dir, sizeof dir, "%s/test-io-%s", base ? base : "/tmp", name);
    char cmd[2200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s'", dir, dir);
    if (system(cmd) != 0)
        fprintf(stderr, "cannot create %s\n", dir);
    return dir;
}

static char *get_text_att(int ncid, int varid, const char *name)
{
    size_t len;
    nc_type t;
    if (nc_inq_att(ncid, varid, name, &t, &len) != NC_NOERR || t != NC_CHAR)
        return NULL;
    char *s = calloc(len + 1, 1);
    nc_get_att_text(ncid, varid, name, s);
    return s;
}

static double get_double_att(int ncid, const char *name)
{
    double v = NAN;
    if (nc_get_att_double(ncid, NC_GLOBAL, name, &v) != NC_NOERR)
        return -12345.0;
    return v;
}

static int text_att_is(int ncid, int varid, const char *name, const char *want)
{
    char *s = get_text_att(ncid, varid, name);
    int ok = s && strcmp(s, want) == 0;
    if (!ok)
        fprintf(stderr, "  attribute %s = \"%s\", expected \"%s\"\n", name, s ? s : "(absent)", want);
    free(s);
    return ok;
}

void nc_check_globals(const char *path, const nc_test_run *run, const char *feature_type)
{
    int ncid;
    int rc = nc_open(path, NC_NOWRITE, &ncid);
    GF_CHECK(rc == NC_NOERR);
    if (rc != NC_NOERR)
        return;
    int format;
    nc_inq_format(ncid, &format);
    GF_CHECK(format == NC_FORMAT_NETCDF4);
    GF_CHECK(text_att_is(ncid, NC_GLOBAL, "Conventions", "CF-1.10"));
    char source[128];
    snprintf(source, sizeof source, "grainflow %s (%s)", GF_VERSION, gf_build_revision());
    GF_CHECK(text_att_is(ncid, NC_GLOBAL, "source", source));
    GF_CHECK(text_att_is(ncid, NC_GLOBAL, "run_spec_yaml", run->yaml));
    GF_CHECK(text_att_is(ncid, NC_GLOBAL, "run_id", run->spec.run_id));
    GF_CHECK(text_att_is(ncid, NC_GLOBAL, "scene", run->spec.scene));
    GF_CHECK(text_att_is(ncid, NC_GLOBAL, "fluid_model", "unresolved"));
    GF_CHECK(text_att_is(ncid, NC_GLOBAL, "stages", "contacts,integrate,coupling"));
    if (feature_type)
        GF_CHECK(text_att_is(ncid, NC_GLOBAL, "featureType", feature_type));
    else
        GF_CHECK(nc_inq_att(ncid, NC_GLOBAL, "featureType", NULL, NULL) == NC_ENOTATT);
    /* history starts with the creation time in UTC: within an hour of now */
    char *hist = get_text_att(ncid, NC_GLOBAL, "history");
    GF_CHECK(hist != NULL);
    if (hist) {
        struct tm tm = {0};
        char *end = strptime(hist, "%Y-%m-%dT%H:%M:%SZ", &tm);
        GF_CHECK(end != NULL);
        if (end) {
            double age_s = difftime(time(NULL), timegm(&tm));
            GF_CHECK(age_s >= -5.0 && age_s < 3600.0);
        }
        free(hist);
    }
    static const char *const required_text[] = {"title", "references", "institution", "comment",
                                                "fluid_model_reason", "drag_closure", "contact_law"};
    for (size_t i = 0; i < sizeof required_text / sizeof *required_text; ++i) {
        char *s = get_text_att(ncid, NC_GLOBAL, required_text[i]);
        gf_test_check(s && *s, __FILE__, __LINE__, "global attribute %s present and non-empty", required_text[i]);
        free(s);
    }
    /* groups asked for and realised, time scales, inputs: the values passed in */
    GF_CHECK_REL(get_double_att(ncid, "stokes_St"), 0.5, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "density_ratio_r"), 2.0, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "aspect_ratio_a"), 0.7, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "phi_initial"), 0.6, 1e-15);
    /* realised St, r from the inverse map must come back to the asked groups */
    GF_CHECK_REL(get_double_att(ncid, "realised_St"), 0.5, 1e-12);
    GF_CHECK_REL(get_double_att(ncid, "realised_r"), 2.0, 1e-12);
    GF_CHECK_REL(get_double_att(ncid, "realised_Re"), 0.25, 1e-12);
    GF_CHECK_REL(get_double_att(ncid, "realised_Ar"), run->scales.archimedes_Ar, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "t_viscous_s"), run->scales.t_viscous_s, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "t_inertial_s"), run->scales.t_inertial_s, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "t_freefall_s"), run->scales.t_freefall_s, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "t_visq_s"), run->scales.t_visq_s, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "t_grain_s"), sqrt(7.6e-3 / 9.81), 1e-12);
    GF_CHECK_REL(get_double_att(ncid, "grain_diameter_m"), 7.6e-3, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "fluid_density_kg_m3"), run->spec.fluid.density_kg_m3, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "fluid_viscosity_Pa_s"), run->spec.fluid.viscosity_Pa_s, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "restitution"), 0.87, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "dt_s"), gf_run_spec_dt_s(&run->spec), 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "t_contact_s"), gf_run_spec_t_contact_s(&run->spec), 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "column_length_m"), 0.06, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "column_height_m"), 0.042, 1e-15);
    GF_CHECK_REL(get_double_att(ncid, "phi_initial_measured"), 0.598, 1e-15);
    GF_CHECK(isnan(get_double_att(ncid, "phi_initial_local")));
    GF_CHECK_REL(get_double_att(ncid, "scene_param_aspect_ratio"), 0.7, 1e-15);
    static const char *const required_num[] = {"polydispersity", "grain_density_kg_m3", "friction",
                                               "wall_friction",  "kt_over_kn",          "gravity_m_s2",
                                               "incline_deg"};
    for (size_t i = 0; i < sizeof required_num / sizeof *required_num; ++i)
        gf_test_check(get_double_att(ncid, required_num[i]) != -12345.0, __FILE__, __LINE__,
                      "global attribute %s present", required_num[i]);
    nc_close(ncid);
}

/* canonical_units of a CF standard name, from the v80 XML table; NULL if absent. */
static char *cf_canonical_units(const char *name)
{
    static char *table = NULL;
    if (!table) {
        /* the CF table (version 80, as published by the CF conventions project)
         * travels with the tests, so a clone checks names without anything beside it */
        const char *src = getenv("GF_SOURCE_DIR");
        char path[1024];
        snprintf(path, sizeof path, "%s/tests/io/data/cf-standard-name-table-v80.xml", src ? src : ".");
        FILE *fp = fopen(path, "rb");
        if (!fp) {
            fprintf(stderr, "cannot read %s\n", path);
            return NULL;
        }
        fseek(fp, 0, SEEK_END);
        long n = ftell(fp);
        fseek(fp, 0, SEEK_SET);
        table = malloc((size_t)n + 1);
        size_t got = fread(table, 1, (size_t)n, fp);
        table[got] = '\0';
        fclose(fp);
    }
    char key[300];
    snprintf(key, sizeof key, "<entry id=\"%s\">", name);
    const char *e = strstr(table, key);
    if (!e)
        return NULL;
    const char *u = strstr(e, "<canonical_units>");
    const char *uend = u ? strstr(u, "</canonical_units>") : NULL;
    if (!u || !uend)
        return NULL;
    u += strlen("<canonical_units>");
    char *out = calloc((size_t)(uend - u) + 1, 1);
    memcpy(out, u, (size_t)(uend - u));
    return out;
}

void nc_check_units_and_names(const char *path)
{
    static ut_system *sys = NULL;
    if (!sys) {
        ut_set_error_message_handler(ut_ignore);
        sys = ut_read_xml(NULL);
    }
    GF_CHECK(sys != NULL);
    if (!sys)
        return;
    int ncid, nvars;
    if (nc_open(path, NC_NOWRITE, &ncid) != NC_NOERR) {
        GF_CHECK(!"nc_open");
        return;
    }
    nc_inq_nvars(ncid, &nvars);
    for (int v = 0; v < nvars; ++v) {
        char name[NC_MAX_NAME + 1];
        nc_type t;
        nc_inq_var(ncid, v, name, &t, NULL, NULL, NULL);
        char *units = get_text_att(ncid, v, "units");
        char *sn = get_text_att(ncid, v, "standard_name");
        char *ln = get_text_att(ncid, v, "long_name");
        gf_test_check(sn || (ln && *ln), __FILE__, __LINE__, "%s: %s has a long_name or standard_name", path, name);
        if (t != NC_CHAR) {
            gf_test_check(units != NULL, __FILE__, __LINE__, "%s: %s has units", path, name);
            ut_unit *u = units ? ut_parse(sys, units, UT_ASCII) : NULL;
            gf_test_check(u != NULL, __FILE__, __LINE__, "%s: units \"%s\" of %s parse with udunits2", path,
                          units ? units : "", name);
            if (sn && u) {
                char *canon = cf_canonical_units(sn);
                gf_test_check(canon != NULL, __FILE__, __LINE__, "%s: standard_name %s of %s is in the CF table v80",
                              path, sn, name);
                ut_unit *cu = canon ? ut_parse(sys, canon, UT_ASCII) : NULL;
                /* a reference-time unit "s since T0" is a time interval with an
                 * origin: compare the canonical unit with its interval part */
                ut_unit *iu = NULL;
                const char *since = strstr(units, " since ");
                if (since) {
                    char interval[64];
                    snprintf(interval, sizeof interval, "%.*s", (int)(since - units), units);
                    iu = ut_parse(sys, interval, UT_ASCII);
                }
                gf_test_check(cu && ut_are_convertible(cu, iu ? iu : u), __FILE__, __LINE__,
                              "%s: %s: canonical units \"%s\" of %s convert to \"%s\"", path, name,
                              canon ? canon : "", sn, units);
                ut_free(cu);
                ut_free(iu);
                free(canon);
            }
            ut_free(u);
        }
        free(units);
        free(sn);
        free(ln);
    }
    nc_close(ncid);
}

void nc_check_time_coordinate(const char *path)
{
    int ncid, var;
    if (nc_open(path, NC_NOWRITE, &ncid) != NC_NOERR) {
        GF_CHECK(!"nc_open");
        return;
    }
    GF_CHECK(nc_inq_varid(ncid, "time", &var) == NC_NOERR);
    GF_CHECK(text_att_is(ncid, var, "units", "s since 2000-01-01 00:00:00"));
    GF_CHECK(text_att_is(ncid, var, "standard_name", "time"));
    GF_CHECK(text_att_is(ncid, var, "axis", "T"));
    GF_CHECK(text_att_is(ncid, var, "calendar", "standard"));
    int dim, unlimited;
    nc_inq_dimid(ncid, "time", &dim);
    nc_inq_unlimdim(ncid, &unlimited);
    GF_CHECK(dim == unlimited);
    nc_close(ncid);
}

void nc_check_ncdump(const char *path, int n_expect, const char *const *expect)
{
    char cmd[1200], out[1100];
    snprintf(out, sizeof out, "%s.ncdump.txt", path);
    snprintf(cmd, sizeof cmd, "ncdump -h '%s' > '%s' 2>&1", path, out);
    int rc = system(cmd);
    gf_test_check(rc == 0, __FILE__, __LINE__, "ncdump -h %s exits 0 (got %d)", path, rc);
    FILE *fp = fopen(out, "r");
    if (!fp) {
        GF_CHECK(!"ncdump output readable");
        return;
    }
    static char text[1 << 16];
    size_t n = fread(text, 1, sizeof text - 1, fp);
    text[n] = '\0';
    fclose(fp);
    for (int i = 0; i < n_expect; ++i)
        gf_test_check(strstr(text, expect[i]) != NULL, __FILE__, __LINE__, "ncdump -h %s shows: %s", path,
                      expect[i]);
}

void nc_check_python(const char *python, const char *kind, const char *path, int n_args, const char *const *args)
{
    const char *src = getenv("GF_SOURCE_DIR");
    char cmd[4096];
    int len = snprintf(cmd, sizeof cmd, "'%s' '%s/tests/io/check_cf.py' %s '%s'", python ? python : "python3",
                       src ? src : ".", kind, path);
    for (int i = 0; i < n_args && len < (int)sizeof cmd - 100; ++i)
        len += snprintf(cmd + len, sizeof cmd - (size_t)len, " '%s'", args[i]);
    int rc = system(cmd);
    gf_test_check(rc == 0, __FILE__, __LINE__, "xarray check of %s (%s) exits 0 (got %d)", path, kind, rc);
}

double *nc_read_doubles(const char *path, const char *var, size_t *n)
{
    *n = 0;
    int ncid, v, ndims, dims[NC_MAX_VAR_DIMS];
    if (nc_open(path, NC_NOWRITE, &ncid) != NC_NOERR)
        return NULL;
    if (nc_inq_varid(ncid, var, &v) != NC_NOERR) {
        nc_close(ncid);
        return NULL;
    }
    nc_inq_varndims(ncid, v, &ndims);
    nc_inq_vardimid(ncid, v, dims);
    size_t total = 1;
    for (int d = 0; d < ndims; ++d) {
        size_t len;
        nc_inq_dimlen(ncid, dims[d], &len);
        total *= len;
    }
    double *buf = malloc((total ? total : 1) * sizeof *buf);
    if (nc_get_var_double(ncid, v, buf) != NC_NOERR) {
        free(buf);
        buf = NULL;
    } else {
        *n = total;
    }
    nc_close(ncid);
    return buf;
}
