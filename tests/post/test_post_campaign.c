/*
 * Lab notebook — gf_post_campaign on a synthetic campaign of five runs:
 *   a_collapse   column collapse, done: particles (40 frames), diagnostics
 *                (front_position, deposit_extent_1D and _2D, ecx_per_grain),
 *                probes (two gauges)
 *   b_avalanche  avalanche, done: particles, diagnostics (grain_flow_rate,
 *                fluid_flow_rate, ecx_per_grain)
 *   c_failed     status "failed: ..." (no analysis, reason in the row)
 *   d_corrupt    marked done, diagnostics.nc truncated to 40 % of its bytes
 *   e_missing    collapse whose diagnostics.nc lacks ecx_per_grain
 * Expected: every run has a row; a and b have status ok and their results;
 * c is "failed" with the reason; d is "corrupt" (a done run whose file does
 * not open) and e "error", each with a message naming the file (and the
 * variable for e), while their other stages still ran
 * (d's deposit from particles.nc; e's deposit and regime). The rows do not
 * depend on n_jobs (stages are pure): summary.csv is byte-identical with 1
 * and 2 workers. --stage energy runs one stage only. summary.nc is read by
 * xarray (check_summary.py) and matches summary.csv; its numeric units
 * parse with UDUNITS-2; the SVG figures parse as XML.
 */
#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <udunits2.h>

#include "gf_post.h"
#include "gf_post_synth.h"
#include "gf_test.h"

static void collapse_run(const char *dir, const char *id, int with_ecx)
{
    synth_meta m;
    synth_meta_default(&m, id, "column_collapse");
    m.D = 7.6e-3, m.rho_p = 8000, m.rho_f = 1000, m.eta = 1.0, m.R0 = 16 * m.D, m.H0 = 8 * m.D;
    m.a = 0.5, m.phi = 0.6;
    const double D = m.D, R = 24 * D, H = 8 * D, R0 = m.R0;
    enum { NMAX = 2000, NT = 40 };
    static double x[NMAX], y[NMAX], r[NMAX], X[NMAX * NT], Y[NMAX * NT], t[NT];
    size_t n = 0;
    for (int i = 0; (i + 0.5) * D < R; ++i) {
        const double xc = (i + 0.5) * D, h = xc < 6 * D ? H : H * (R - xc) / (R - 6 * D);
        for (int j = 0; (j + 1.0) * D <= h + 0.5 * D && n < NMAX; ++j)
            x[n] = xc, y[n] = (j + 0.5) * D, r[n++] = 0.5 * D;
    }
    double front[NT], ecx[NT], ext1[NT], ext2[NT];
    for (int k = 0; k < NT; ++k) {
        t[k] = 0.05 * k;
        const double S = k == NT - 1 ? 1.0 : 0.5 * (1.0 + tanh((t[k] - 0.8) / 0.2));
        const double f = (R0 + (R - R0) * S) / R;
        for (size_t i = 0; i < n; ++i)
            X[i * NT + k] = x[i] * f, Y[i * NT + k] = y[i];
        front[k] = R0 + (R - R0) * S;
        ext1[k] = front[k] - 2.0 * D, ext2[k] = front[k] - 4.0 * D; /* the engine's deposit_extent_1D, _2D */
        ecx[k] = 1e-6 * exp(-(t[k] - 0.8) * (t[k] - 0.8) / 0.04);
    }
    synth_particles(dir, &m, n, NT, t, r, NULL, X, Y, NULL, NULL);
    const char *names[] = {"front_position", "deposit_extent_1D", "deposit_extent_2D", "ecx_per_grain"};
    const char *units[] = {"m", "m", "m", "J"};
    const double *vals[] = {front, ext1, ext2, ecx};
    synth_diagnostics(dir, &m, NT, t, with_ecx ? 4 : 3, names, units, vals);
    double P[2 * NT];
    for (int k = 0; k < NT; ++k) {
        P[k] = 5.0 * exp(-(t[k] - 0.7) * (t[k] - 0.7) / 0.02);
        P[NT + k] = -30.0 * exp(-(t[k] - 0.9) * (t[k] - 0.9) / 0.02);
    }
    const char *st_names[] = {"x05D", "x13D"};
    const double xs[] = {5 * D, 13 * D};
    synth_probes(dir, &m, 2, st_names, xs, NT, t, P);
    synth_status(dir, "done");
}

static void avalanche_run(const char *dir)
{
    synth_meta m;
    synth_meta_default(&m, "b_avalanche", "avalanche");
    m.incline_deg = 25.0, m.St = 5.48, m.r = 2.04;
    const double D = m.D;
    enum { N = 200, NT = 10, ND = 300 };
    static double r[N], X[N * NT], Y[N * NT], Z[N * NT], U[N * NT], tf[NT];
    static unsigned char glued[N];
    for (int i = 0; i < N; ++i) {
        r[i] = 0.5 * D;
        glued[i] = i < 20;
        for (int k = 0; k < NT; ++k) {
            X[i * NT + k] = (i % 10 + 0.5) * D, Y[i * NT + k] = (i / 20 + 0.5) * D;
            Z[i * NT + k] = ((i / 10) % 2 + 0.5) * D, U[i * NT + k] = glued[i] ? 0 : 0.01 * (i / 20);
        }
    }
    for (int k = 0; k < NT; ++k)
        tf[k] = 3.0 * k;
    synth_particles(dir, &m, N, NT, tf, r, glued, X, Y, Z, U);
    const double Vg = 180 * M_PI / 6 * D * D * D, Ti = 2.00501e-2;
    static double t[ND], q[ND], qf[ND], e[ND];
    for (int k = 0; k < ND; ++k) {
        t[k] = 0.1 * k;
        q[k] = Vg / Ti * (t[k] < 5 ? t[k] / 5 : 1.0) * (1 + 0.02 * sin(3.0 * k));
        qf[k] = 2 * q[k];
        e[k] = 1e-7 * (1 + 0.1 * sin(0.5 * k));
    }
    const char *names[] = {"grain_flow_rate", "fluid_flow_rate", "ecx_per_grain"};
    const char *units[] = {"m3 s-1", "m3 s-1", "J"};
    const double *vals[] = {q, qf, e};
    synth_diagnostics(dir, &m, ND, t, 3, names, units, vals);
    synth_status(dir, "done");
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *b = calloc((size_t)n + 1, 1);
    if (b && fread(b, 1, (size_t)n, f) != (size_t)n)
        b[0] = '\0';
    fclose(f);
    return b;
}

/* Field `col` (by header name) of the data line whose first field is run_id. */
static void csv_field(const char *csv, const char *run_id, const char *col, char *out, size_t size)
{
    out[0] = '\0';
    const char *nl = strchr(csv, '\n');
    if (!nl)
        return;
    int idx = -1, k = 0;
    for (const char *p = csv; p < nl; ++k) {
        const char *e = memchr(p, ',', (size_t)(nl - p));
        if (!e)
            e = nl;
        if ((size_t)(e - p) == strlen(col) && strncmp(p, col, strlen(col)) == 0)
            idx = k;
        p = e + 1;
    }
    for (const char *line = nl + 1; idx >= 0 && *line; line = strchr(line, '\n') + 1) {
        const char *end = strchr(line, '\n');
        if (!end)
            break;
        if (strncmp(line, run_id, strlen(run_id)) == 0 && line[strlen(run_id)] == ',') {
            const char *p = line;
            int in_q = 0;
            for (k = 0; k < idx && p < end; ++p) {
                if (*p == '"')
                    in_q = !in_q;
                else if (*p == ',' && !in_q)
                    ++k;
            }
            size_t n = 0;
            in_q = 0;
            for (; p < end && n + 1 < size; ++p) {
                if (*p == '"') {
                    in_q = !in_q;
                    continue;
                }
                if (*p == ',' && !in_q)
                    break;
                out[n++] = *p;
            }
            out[n] = '\0';
            return;
        }
    }
}

int main(void)
{
    char camp[1024], d[1200], p[1300], v[700];
    synth_scratch(camp, sizeof camp, "campaign");
    snprintf(d, sizeof d, "%s/a_collapse", camp);
    synth_mkdir(d);
    collapse_run(d, "a_collapse", 1);
    snprintf(d, sizeof d, "%s/b_avalanche", camp);
    synth_mkdir(d);
    avalanche_run(d);
    snprintf(d, sizeof d, "%s/c_failed", camp);
    synth_mkdir(d);
    synth_status(d, "failed: diverged at t = 1.2 s (max overlap 0.31 D)");
    snprintf(d, sizeof d, "%s/d_corrupt", camp);
    synth_mkdir(d);
    collapse_run(d, "d_corrupt", 1);
    snprintf(p, sizeof p, "%s/diagnostics.nc", d);
    {
        char *b = NULL;
        FILE *f = fopen(p, "rb");
        fseek(f, 0, SEEK_END);
        long n = ftell(f);
        fseek(f, 0, SEEK_SET);
        b = malloc((size_t)n);
        GF_CHECK(fread(b, 1, (size_t)n, f) == (size_t)n);
        fclose(f);
        f = fopen(p, "wb");
        fwrite(b, 1, (size_t)(0.4 * n), f);
        fclose(f);
        free(b);
    }
    snprintf(d, sizeof d, "%s/e_missing", camp);
    synth_mkdir(d);
    collapse_run(d, "e_missing", 0);

    gf_ctx ctx = {0};
    gf_post_options opt = {NULL, 1, 0, 1};
    GF_CHECK_OK(gf_post_campaign(&ctx, camp, &opt), &ctx);
    snprintf(p, sizeof p, "%s/summary.csv", camp);
    char *serial = slurp(p);
    opt.n_jobs = 2;
    opt.figures = 1;
    opt.quiet = 0;
    GF_CHECK_OK(gf_post_campaign(&ctx, camp, &opt), &ctx);
    char *csv = slurp(p);
    GF_CHECK(serial && csv && strcmp(serial, csv) == 0);
    GF_CHECK(csv && strncmp(csv, "run_id,scene,St,r,a,Phi_i,status,error,fluid_model,", 51) == 0);
    static const char *const needed[] = {",regime,", ",regime_confidence,", ",T_over_Tv,", ",T_over_Ti,",
                                         ",T_over_Tff,", ",R_inf_over_R0,", ",H_inf_over_R0,", ",deposit_shape,",
                                         ",flank_angle_deg,", ",Pb_min_Pa,", ",Pb_max_Pa,", ",t_Pb_min_s,",
                                         ",t_Pb_max_s,", ",Ecx_max_over_mgD,", ",Qg_mean,", ",Qg_std,",
                                         ",t_steady_s,", ",runout_norm,"};
    for (size_t k = 0; csv && k < sizeof needed / sizeof needed[0]; ++k)
        gf_test_check(strstr(csv, needed[k]) != NULL, __FILE__, __LINE__, "summary.csv header lacks %s", needed[k]);
    if (csv) {
        const char *runs[] = {"a_collapse", "b_avalanche", "c_failed", "d_corrupt", "e_missing"};
        const char *status[] = {"ok", "ok", "failed", "corrupt", "error"};
        for (int k = 0; k < 5; ++k) {
            csv_field(csv, runs[k], "status", v, sizeof v);
            gf_test_check(strcmp(v, status[k]) == 0, __FILE__, __LINE__, "%s: status '%s', expected '%s'", runs[k],
                          v, status[k]);
            csv_field(csv, runs[k], "error", v, sizeof v);
            printf("%-12s %-7s %s\n", runs[k], status[k], v);
        }
        csv_field(csv, "c_failed", "error", v, sizeof v);
        GF_CHECK(strstr(v, "run failed: diverged at t = 1.2 s") != NULL);
        csv_field(csv, "d_corrupt", "error", v, sizeof v);
        GF_CHECK(strstr(v, "diagnostics.nc") && strstr(v, "corrupt or truncated"));
        csv_field(csv, "d_corrupt", "R_inf_m", v, sizeof v);   /* particles.nc intact: deposit still done */
        GF_CHECK(v[0] != '\0');
        csv_field(csv, "e_missing", "error", v, sizeof v);
        GF_CHECK(strstr(v, "stage energy") && strstr(v, "ecx_per_grain"));
        csv_field(csv, "e_missing", "regime", v, sizeof v);
        GF_CHECK(v[0] != '\0');
        csv_field(csv, "a_collapse", "deposit_shape", v, sizeof v);
        GF_CHECK(strcmp(v, "trapezoid") == 0);
        /* the engine's measures, the same for grains and continuum: (x - R0)/R0 at the last record, R = 24 D */
        csv_field(csv, "a_collapse", "front_D4_norm", v, sizeof v);
        GF_CHECK_ABS(atof(v), 0.5, 1e-12);
        csv_field(csv, "a_collapse", "extent_1D_norm", v, sizeof v);
        GF_CHECK_ABS(atof(v), 0.375, 1e-12);
        csv_field(csv, "a_collapse", "extent_2D_norm", v, sizeof v);
        GF_CHECK_ABS(atof(v), 0.25, 1e-12);
        csv_field(csv, "a_collapse", "Pb_station", v, sizeof v);
        GF_CHECK(strcmp(v, "x13D") == 0);
        csv_field(csv, "a_collapse", "Pb_min_Pa", v, sizeof v);
        GF_CHECK_REL(atof(v), -30.0, 1e-9);
        csv_field(csv, "b_avalanche", "regime", v, sizeof v);
        GF_CHECK(strcmp(v, "inertial") == 0);
        csv_field(csv, "b_avalanche", "T_over_Ti", v, sizeof v);
        GF_CHECK_REL(atof(v), 1.0, 0.01);
    }
    /* one stage only */
    gf_post_options one = {"energy", 2, 0, 1};
    snprintf(d, sizeof d, "%s/one", camp);
    GF_CHECK_OK(gf_post_campaign(&ctx, camp, &one), &ctx);
    char *csv1 = slurp(p);
    csv_field(csv1 ? csv1 : "", "a_collapse", "R_inf_m", v, sizeof v);
    GF_CHECK(v[0] == '\0');
    csv_field(csv1 ? csv1 : "", "a_collapse", "Ecx_max_over_mgD", v, sizeof v);
    GF_CHECK(v[0] != '\0');
    csv_field(csv1 ? csv1 : "", "a_collapse", "stages", v, sizeof v);
    GF_CHECK(strcmp(v, "energy@1") == 0);
    gf_post_options bad = {"no_such_stage", 1, 0, 1};
    gf_ctx c2 = {0};
    GF_CHECK(gf_post_campaign(&c2, camp, &bad) == GF_ERR_CONFIG);
    printf("unknown stage -> %s\n", c2.last_msg);
    /* back to the full summary for the file checks */
    opt.quiet = 1;
    GF_CHECK_OK(gf_post_campaign(&ctx, camp, &opt), &ctx);

    /* units of every numeric summary variable parse with UDUNITS-2 */
    snprintf(p, sizeof p, "%s/summary.nc", camp);
    ut_set_error_message_handler(ut_ignore);
    ut_system *us = ut_read_xml(NULL);
    int ncid, nvars, checked = 0;
    GF_CHECK(nc_open(p, NC_NOWRITE, &ncid) == NC_NOERR);
    nc_inq_nvars(ncid, &nvars);
    for (int k = 0; us && k < nvars; ++k) {
        nc_type type;
        char name[NC_MAX_NAME + 1], units[128] = "";
        size_t len = 0;
        nc_inq_var(ncid, k, name, &type, NULL, NULL, NULL);
        if (type != NC_DOUBLE)
            continue;
        if (nc_inq_attlen(ncid, k, "units", &len) == NC_NOERR && len < sizeof units)
            nc_get_att_text(ncid, k, "units", units);
        ut_unit *u = ut_parse(us, units, UT_ASCII);
        gf_test_check(u != NULL, __FILE__, __LINE__, "summary.nc %s: units '%s' do not parse", name, units);
        ut_free(u);
        ++checked;
    }
    nc_close(ncid);
    ut_free_system(us);
    printf("%d numeric summary variables with UDUNITS-parseable units\n", checked);
    GF_CHECK(checked > 40);

    const char *figs[] = {"regime_diagram.svg", "deposit_shape.svg", "runout.svg", "front_position.svg",
                          "pore_pressure.svg"};
    for (int k = 0; k < 5; ++k) {
        snprintf(d, sizeof d, "%s/figures/%s", camp, figs[k]);
        char *s = slurp(d);
        gf_test_check(s && strstr(s, "<svg") && strstr(s, "</svg>"), __FILE__, __LINE__, "figure %s", figs[k]);
        free(s);
    }
    char cmd[2048];
    const char *src = getenv("GF_SOURCE_DIR");
    snprintf(cmd, sizeof cmd, "/usr/bin/python3 %s/tests/post/check_summary.py %s 5", src ? src : ".", camp);
    const int rc = system(cmd);
    gf_test_check(rc == 0, __FILE__, __LINE__, "%s -> %d", cmd, rc);
    free(serial), free(csv), free(csv1);
    return gf_test_finish();
}
