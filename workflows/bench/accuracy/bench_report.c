/*
 * Accuracy benchmark report: Pareto front and recommended default per case,
 * the measured convergence order in dt, and the outputs (CSV table, CF
 * netCDF, one SVG per case).
 *
 * Recommended default = the cheapest setting (smallest CPU time) whose error
 * is within the case's tolerance. It is always on the Pareto front: a
 * cheaper setting within tolerance would dominate it or be recommended.
 * Convergence order between two dt of the sweep (other knobs at default):
 *     p = ln(e_1 / e_2) / ln(dt_1 / dt_2),
 * and the error ratio e(dt)/e(dt/2) when the sweep holds both (1/10 -> 1/20,
 * 1/100 -> 1/200): 4 for a second-order observable, 2 for first order.
 * The order in cell size h is the same formula along the cell sweep (at
 * dt = t_c/50): p = ln(e_1 / e_2) / ln(h_1 / h_2).
 */
#include <errno.h>
#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "bench_accuracy.h"
#include "core/gf_build_info.h"
#include "figures/gf_figures.h"

void bench_analyse(bench_point *pts, int n, const bench_case *cases, int n_cases)
{
    double *cost = malloc(sizeof(double) * (size_t)(n > 0 ? n : 1));
    double *err = malloc(sizeof(double) * (size_t)(n > 0 ? n : 1));
    int *idx = malloc(sizeof(int) * (size_t)(n > 0 ? n : 1));
    unsigned char *front = malloc((size_t)(n > 0 ? n : 1));
    if (!cost || !err || !idx || !front) {
        free(cost), free(err), free(idx), free(front);
        return;
    }
    for (int c = 0; c < n_cases; ++c) {
        int m = 0;
        for (int i = 0; i < n; ++i)
            if (pts[i].case_index == c) {
                idx[m] = i;
                int ok = pts[i].status == GF_OK;
                cost[m] = ok ? pts[i].r.cpu_s : NAN;
                err[m] = ok ? pts[i].r.error : NAN;
                m++;
            }
        gf_fig_pareto_front(m, cost, err, front);
        int best = -1;
        for (int q = 0; q < m; ++q) {
            bench_point *p = &pts[idx[q]];
            p->on_front = front[q];
            p->recommended = 0;
            p->within_tolerance = p->status == GF_OK && p->r.error <= cases[c].tolerance;
            if (p->within_tolerance && (best < 0 || p->r.cpu_s < pts[best].r.cpu_s))
                best = idx[q];
        }
        if (best >= 0)
            pts[best].recommended = 1;
    }
    free(cost), free(err), free(idx), free(front);
}

/* Value of one knob (a BENCH_KNOB_* bit) of a setting. */
static double knob_value(const bench_knobs *k, unsigned knob)
{
    return knob == BENCH_KNOB_DT        ? k->dt_over_tc
           : knob == BENCH_KNOB_SKIN    ? k->skin_over_D
           : knob == BENCH_KNOB_TC      ? k->t_contact_nd
           : knob == BENCH_KNOB_RETRACT ? k->retract_dx
           : knob == BENCH_KNOB_FLUID_CFL ? k->fluid_cfl
                                        : k->cell_over_D;
}

static const bench_knobs bench_defaults = {BENCH_DEFAULT_DT_OVER_TC, BENCH_DEFAULT_SKIN_OVER_D, BENCH_DEFAULT_TC_ND,
                                           BENCH_DEFAULT_CELL_OVER_D, BENCH_DEFAULT_RETRACT_DX, BENCH_DEFAULT_FLUID_CFL};

static int list_holds(const double *list, int n, double v)
{
    for (int i = 0; i < n; ++i)
        if (fabs(list[i] - v) <= 1e-12 * fmax(1.0, fabs(v)))
            return 1;
    return 0;
}

double bench_case_default(const bench_case *c, unsigned knob)
{
    double d = knob_value(&bench_defaults, knob);
    const double *own = knob == BENCH_KNOB_DT        ? c->dt_list
                        : knob == BENCH_KNOB_TC      ? c->tc_list
                        : knob == BENCH_KNOB_CELL    ? c->cell_list
                        : knob == BENCH_KNOB_RETRACT ? c->retract_list
                        : knob == BENCH_KNOB_FLUID_CFL ? c->cfl_list
                                                     : NULL;
    int n_own = knob == BENCH_KNOB_DT        ? c->n_dt
                : knob == BENCH_KNOB_TC      ? c->n_tc
                : knob == BENCH_KNOB_CELL    ? c->n_cell
                : knob == BENCH_KNOB_RETRACT ? c->n_retract
                : knob == BENCH_KNOB_FLUID_CFL ? c->n_cfl
                                             : 0;
    if (!(c->knobs & knob) || !own || n_own < 1 || list_holds(own, n_own, d))
        return d;
    return own[0];
}

/* Points of case c that vary only `knob` (every other knob at the case's
 * default), by decreasing value of the knob. */
static int knob_sweep(const bench_point *pts, int n, const bench_case *cases, int c, unsigned knob,
                      const bench_point **out, int cap)
{
    static const unsigned all[6] = {BENCH_KNOB_DT, BENCH_KNOB_SKIN, BENCH_KNOB_TC, BENCH_KNOB_CELL,
                                    BENCH_KNOB_RETRACT, BENCH_KNOB_FLUID_CFL};
    int m = 0;
    for (int i = 0; i < n && m < cap; ++i) {
        const bench_point *p = &pts[i];
        if (p->case_index != c || p->status != GF_OK)
            continue;
        int at_defaults = 1;
        for (int q = 0; q < 6; ++q) {
            double v = knob_value(&p->k, all[q]), d = bench_case_default(&cases[c], all[q]);
            if (all[q] != knob && fabs(v - d) > 1e-9 * fmax(fabs(d), 1e-12))
                at_defaults = 0;
        }
        if (!at_defaults)
            continue;
        int k = m++;
        while (k > 0 && knob_value(&out[k - 1]->k, knob) < knob_value(&p->k, knob)) {
            out[k] = out[k - 1];
            --k;
        }
        out[k] = p;
    }
    return m;
}

void bench_print_orders(const bench_point *pts, int n, const bench_case *cases, int n_cases)
{
    printf("\nmeasured convergence in dt (other knobs at default):\n");
    for (int c = 0; c < n_cases; ++c) {
        const bench_point *s[32];
        int m = knob_sweep(pts, n, cases, c, BENCH_KNOB_DT, s, 32);
        if (m < 2)
            continue;
        printf("  %-17s", cases[c].name);
        for (int i = 0; i + 1 < m; ++i) {
            double e1 = s[i]->r.error, e2 = s[i + 1]->r.error, r = s[i]->k.dt_over_tc / s[i + 1]->k.dt_over_tc;
            double p = (e1 > 0.0 && e2 > 0.0) ? log(e1 / e2) / log(r) : NAN;
            printf("  tc/%.0f->tc/%.0f: ", 1.0 / s[i]->k.dt_over_tc, 1.0 / s[i + 1]->k.dt_over_tc);
            if (fabs(r - 2.0) < 1e-9)
                printf("ratio %.2f (p %.2f)", e1 / e2, p);
            else
                printf("p %.2f", p);
        }
        printf("\n");
    }
}

void bench_print_cell_orders(const bench_point *pts, int n, const bench_case *cases, int n_cases)
{
    printf("\nmeasured convergence in cell size (other knobs at default):\n");
    for (int c = 0; c < n_cases; ++c) {
        const bench_point *s[32];
        if (!(cases[c].knobs & BENCH_KNOB_CELL))
            continue;
        int m = knob_sweep(pts, n, cases, c, BENCH_KNOB_CELL, s, 32);
        if (m < 2)
            continue;
        printf("  %-17s", cases[c].name);
        for (int i = 0; i + 1 < m; ++i) {
            double e1 = s[i]->r.error, e2 = s[i + 1]->r.error, r = s[i]->k.cell_over_D / s[i + 1]->k.cell_over_D;
            double p = (e1 > 0.0 && e2 > 0.0) ? log(e1 / e2) / log(r) : NAN;
            if (cases[c].cell_as_resolution == 2 && (s[i]->k.cell_over_D < 1.0) != (s[i + 1]->k.cell_over_D < 1.0))
                continue; /* two tiers: no order between them */
            if (cases[c].cell_as_resolution == 1 || (cases[c].cell_as_resolution == 2 && s[i]->k.cell_over_D < 1.0))
                printf("  D/dx %g->%g: p %.2f", 1.0 / s[i]->k.cell_over_D, 1.0 / s[i + 1]->k.cell_over_D, p);
            else
                printf("  %gD->%gD: p %.2f", s[i]->k.cell_over_D, s[i + 1]->k.cell_over_D, p);
        }
        printf("\n");
    }
}

static gf_status write_csv(gf_ctx *ctx, const char *path, const bench_point *pts, int n, const bench_case *cases)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return GF_FAIL(ctx, GF_ERR_IO, "bench: cannot write %s", path);
    fprintf(f, "case,dt_over_tc,skin_over_D,t_contact_nd,cell_over_D,ibm_retraction_dx,fluid_cfl,observable,reference,error,tolerance,cpu_time_s,"
               "wall_time_s,on_front,recommended,status,aux_observable\n");
    for (int i = 0; i < n; ++i) {
        const bench_point *p = &pts[i];
        fprintf(f, "%s,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.10g,%.10g,%.6g,%.3g,%.6g,%.6g,%d,%d,%s,", cases[p->case_index].name,
                p->k.dt_over_tc, p->k.skin_over_D, p->k.t_contact_nd, p->k.cell_over_D, p->k.retract_dx, p->k.fluid_cfl,
                p->r.observable,
                p->r.reference, p->r.error, cases[p->case_index].tolerance, p->r.cpu_s, p->wall_s, p->on_front,
                p->recommended,
                p->status == GF_OK ? "ok" : gf_status_str(p->status));
        if (cases[p->case_index].aux && p->status == GF_OK)
            fprintf(f, "%.10g", p->r.aux);
        fprintf(f, "\n");
    }
    if (fclose(f) != 0)
        return GF_FAIL(ctx, GF_ERR_IO, "bench: error closing %s", path);
    return GF_OK;
}

#define NC(call)                                                                                        \
    do {                                                                                                \
        int nc_rc_ = (call);                                                                            \
        if (nc_rc_ != NC_NOERR) {                                                                       \
            nc_close(ncid);                                                                             \
            return GF_FAIL(ctx, GF_ERR_IO, "bench: netCDF %s: %s (%s)", tmp, nc_strerror(nc_rc_), #call); \
        }                                                                                               \
    } while (0)

static int def_double(int ncid, int dim, const char *name, const char *units, const char *long_name, int *varid)
{
    int rc = nc_def_var(ncid, name, NC_DOUBLE, 1, &dim, varid);
    double fill = NAN;
    if (rc == NC_NOERR)
        rc = nc_put_att_double(ncid, *varid, "_FillValue", NC_DOUBLE, 1, &fill);
    if (rc == NC_NOERR)
        rc = nc_put_att_text(ncid, *varid, "units", strlen(units), units);
    if (rc == NC_NOERR)
        rc = nc_put_att_text(ncid, *varid, "long_name", strlen(long_name), long_name);
    return rc;
}

static int put_text(int ncid, int var, const char *name, const char *text)
{
    return nc_put_att_text(ncid, var, name, strlen(text), text);
}

/* CF-1.10 table: dimension `setting`; the case of each setting by name (char
 * array) and by index into the `case` dimension, whose tolerance and
 * recommended setting are variables too. */
static gf_status write_nc(gf_ctx *ctx, const char *path, const bench_point *pts, int n, const bench_case *cases,
                          int n_cases, int full)
{
    char tmp[1100];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    int ncid = -1, d_set, d_case, d_str, v[16], v_name, v_cname, v_tol, v_rec, v_ci;
    if (nc_create(tmp, NC_NETCDF4 | NC_CLOBBER, &ncid) != NC_NOERR)
        return GF_FAIL(ctx, GF_ERR_IO, "bench: cannot create %s", tmp);
    NC(nc_def_dim(ncid, "setting", (size_t)(n > 0 ? n : 1), &d_set));
    NC(nc_def_dim(ncid, "case", (size_t)n_cases, &d_case));
    NC(nc_def_dim(ncid, "name_strlen", 32, &d_str));
    int d_doc, v_cobs, v_cref;
    NC(nc_def_dim(ncid, "doc_strlen", 160, &d_doc));
    char hist[160];
    time_t now = time(NULL);
    strftime(hist, sizeof hist, "%Y-%m-%dT%H:%M:%SZ gf-bench-accuracy", gmtime(&now));
    NC(put_text(ncid, NC_GLOBAL, "Conventions", "CF-1.10"));
    NC(put_text(ncid, NC_GLOBAL, "title", "grainflow accuracy benchmark: error against run time per setting"));
    NC(put_text(ncid, NC_GLOBAL, "history", full ? strcat(hist, " --full") : strcat(hist, " --quick")));
    char source[128];
    snprintf(source, sizeof source, "grainflow %s (%s)", GF_VERSION, gf_build_revision());
    NC(put_text(ncid, NC_GLOBAL, "source", source));
    NC(put_text(ncid, NC_GLOBAL, "institution", "grainflow simulation framework"));
    NC(put_text(ncid, NC_GLOBAL, "references",
                "Izard 2014 (3.13)-(3.17); tolerances from docs/accuracy.md"));
    NC(put_text(ncid, NC_GLOBAL, "comment",
                "cpu_time (the cost used for the fronts) and wall_time are the best of repeated runs of "
                "gf_sim_create + gf_sim_advance, one thread; recommended = cheapest setting within the case tolerance"));
    int dims2[2] = {d_set, d_str}, dimsc[2] = {d_case, d_str};
    NC(nc_def_var(ncid, "case_name", NC_CHAR, 2, dimsc, &v_cname));
    NC(put_text(ncid, v_cname, "long_name", "benchmark case"));
    int dimsd[2] = {d_case, d_doc};
    NC(nc_def_var(ncid, "case_observable", NC_CHAR, 2, dimsd, &v_cobs));
    NC(put_text(ncid, v_cobs, "long_name", "observable of the case (dimensionless)"));
    NC(nc_def_var(ncid, "case_reference", NC_CHAR, 2, dimsd, &v_cref));
    NC(put_text(ncid, v_cref, "long_name", "reference of the case"));
    int v_caux;
    NC(nc_def_var(ncid, "case_aux", NC_CHAR, 2, dimsd, &v_caux));
    NC(put_text(ncid, v_caux, "long_name", "second observable of the case (empty: none)"));
    NC(def_double(ncid, d_case, "tolerance", "1", "error accepted for the recommended default", &v_tol));
    NC(nc_def_var(ncid, "recommended_setting", NC_INT, 1, &d_case, &v_rec));
    NC(put_text(ncid, v_rec, "long_name", "index of the recommended setting (-1: none within tolerance)"));
    NC(put_text(ncid, v_rec, "units", "1"));
    NC(nc_def_var(ncid, "setting_case", NC_CHAR, 2, dims2, &v_name));
    NC(put_text(ncid, v_name, "long_name", "case of the setting"));
    NC(nc_def_var(ncid, "case_index", NC_INT, 1, &d_set, &v_ci));
    NC(put_text(ncid, v_ci, "long_name", "index of the setting's case along dimension case"));
    NC(put_text(ncid, v_ci, "units", "1"));
    struct {
        const char *name, *units, *long_name;
    } dv[] = {
        {"dt_over_tc", "1", "DEM time step / contact duration t_c"},
        {"skin_over_D", "1", "Verlet skin / grain diameter"},
        {"t_contact_nd", "1", "contact duration t_c sqrt(g/D)"},
        {"fluid_cell_over_D", "1", "fluid cell size / grain diameter"},
        {"ibm_retraction_dx", "1", "resolved tier: retraction of the solid fraction's profile / grid spacing"},
        {"fluid_cfl", "1", "resolved tier: the fluid step's advective bound fluid.cfl"},
        {"observable", "1", "measured observable (dimensionless; see case_observable)"},
        {"reference", "1", "reference value of the observable"},
        {"error", "1", "error against the reference"},
        {"cpu_time", "s", "CPU time of the setting's simulation calls, one thread (best of repeats)"},
        {"wall_time", "s", "wall-clock time of the setting (best of repeats)"},
        {"aux_observable", "1", "second observable of the case, recorded not judged (see case_aux); fill: none"},
    };
    const int n_dv = (int)(sizeof dv / sizeof dv[0]);
    for (int k = 0; k < n_dv; ++k)
        NC(def_double(ncid, d_set, dv[k].name, dv[k].units, dv[k].long_name, &v[k]));
    int v_front, v_recd, v_st;
    NC(nc_def_var(ncid, "on_front", NC_BYTE, 1, &d_set, &v_front));
    NC(put_text(ncid, v_front, "long_name", "setting on the Pareto front of its case"));
    NC(put_text(ncid, v_front, "units", "1"));
    {
        signed char fv[2] = {0, 1};
        NC(nc_put_att_schar(ncid, v_front, "flag_values", NC_BYTE, 2, fv));
        NC(put_text(ncid, v_front, "flag_meanings", "dominated pareto_optimal"));
    }
    NC(nc_def_var(ncid, "recommended", NC_BYTE, 1, &d_set, &v_recd));
    NC(put_text(ncid, v_recd, "long_name", "recommended default of its case"));
    NC(put_text(ncid, v_recd, "units", "1"));
    NC(nc_def_var(ncid, "status", NC_INT, 1, &d_set, &v_st));
    NC(put_text(ncid, v_st, "long_name", "gf_status of the run (0: ok)"));
    NC(put_text(ncid, v_st, "units", "1"));
    NC(nc_enddef(ncid));

    for (int c = 0; c < n_cases; ++c) {
        size_t st[2] = {(size_t)c, 0}, ct[2] = {1, 32};
        char buf[32] = {0};
        snprintf(buf, sizeof buf, "%s", cases[c].name);
        NC(nc_put_vara_text(ncid, v_cname, st, ct, buf));
        char doc[160] = {0};
        size_t cd[2] = {1, 160};
        snprintf(doc, sizeof doc, "%s", cases[c].observable);
        NC(nc_put_vara_text(ncid, v_cobs, st, cd, doc));
        memset(doc, 0, sizeof doc);
        snprintf(doc, sizeof doc, "%s", cases[c].reference);
        NC(nc_put_vara_text(ncid, v_cref, st, cd, doc));
        memset(doc, 0, sizeof doc);
        snprintf(doc, sizeof doc, "%s", cases[c].aux ? cases[c].aux : "");
        NC(nc_put_vara_text(ncid, v_caux, st, cd, doc));
        size_t i1 = (size_t)c;
        NC(nc_put_var1_double(ncid, v_tol, &i1, &cases[c].tolerance));
        int rec = -1;
        for (int i = 0; i < n; ++i)
            if (pts[i].case_index == c && pts[i].recommended)
                rec = i;
        NC(nc_put_var1_int(ncid, v_rec, &i1, &rec));
    }
    for (int i = 0; i < n; ++i) {
        const bench_point *p = &pts[i];
        size_t st[2] = {(size_t)i, 0}, ct[2] = {1, 32}, i1 = (size_t)i;
        char buf[32] = {0};
        snprintf(buf, sizeof buf, "%s", cases[p->case_index].name);
        NC(nc_put_vara_text(ncid, v_name, st, ct, buf));
        NC(nc_put_var1_int(ncid, v_ci, &i1, &p->case_index));
        int ok = p->status == GF_OK;
        int has_aux = ok && cases[p->case_index].aux != NULL;
        double vals[12] = {p->k.dt_over_tc, p->k.skin_over_D, p->k.t_contact_nd, p->k.cell_over_D, p->k.retract_dx,
                           p->k.fluid_cfl,
                           ok ? p->r.observable : NAN, ok ? p->r.reference : NAN, ok ? p->r.error : NAN,
                           ok ? p->r.cpu_s : NAN, ok ? p->wall_s : NAN, has_aux ? p->r.aux : NAN};
        for (int k = 0; k < n_dv; ++k)
            NC(nc_put_var1_double(ncid, v[k], &i1, &vals[k]));
        signed char fr = (signed char)p->on_front, rc = (signed char)p->recommended;
        int sti = (int)p->status;
        NC(nc_put_var1_schar(ncid, v_front, &i1, &fr));
        NC(nc_put_var1_schar(ncid, v_recd, &i1, &rc));
        NC(nc_put_var1_int(ncid, v_st, &i1, &sti));
    }
    if (nc_close(ncid) != NC_NOERR)
        return GF_FAIL(ctx, GF_ERR_IO, "bench: cannot close %s", tmp);
    if (rename(tmp, path) != 0)
        return GF_FAIL(ctx, GF_ERR_IO, "bench: cannot rename %s to %s", tmp, path);
    return GF_OK;
}

gf_status bench_write(gf_ctx *ctx, const char *dir, const bench_point *pts, int n, const bench_case *cases,
                      int n_cases, int full)
{
    char path[1024];
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return GF_FAIL(ctx, GF_ERR_IO, "bench: cannot create %s: %s", dir, strerror(errno));
    snprintf(path, sizeof path, "%s/bench_accuracy.csv", dir);
    GF_TRY(write_csv(ctx, path, pts, n, cases));
    snprintf(path, sizeof path, "%s/bench_accuracy.nc", dir);
    GF_TRY(write_nc(ctx, path, pts, n, cases, n_cases, full));
    for (int c = 0; c < n_cases; ++c) {
        double t[256], e[256];
        const char *lab[256];
        int m = 0, rec = -1;
        for (int i = 0; i < n && m < 256; ++i) {
            if (pts[i].case_index != c)
                continue;
            int ok = pts[i].status == GF_OK;
            t[m] = ok ? pts[i].r.cpu_s : NAN;
            e[m] = ok ? pts[i].r.error : NAN;
            lab[m] = pts[i].label;
            if (pts[i].recommended)
                rec = m;
            m++;
        }
        if (m == 0)
            continue;
        char title[160];
        snprintf(title, sizeof title, "%s: error against CPU time", cases[c].name);
        gf_fig_opts opt = {.title = title};
        snprintf(path, sizeof path, "%s/pareto_%s.svg", dir, cases[c].name);
        GF_TRY(gf_fig_pareto(ctx, path, &opt, m, t, e, lab, "CPU time, one thread (s)", cases[c].error_label, cases[c].tolerance, rec, NULL));
    }
    return GF_OK;
}
