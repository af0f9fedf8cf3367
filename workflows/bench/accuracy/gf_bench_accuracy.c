/*
 * gf-bench-accuracy: run time against error for the validation scenes that
 * have a reference (bench_cases.c), the Pareto front of each, the
 * recommended default (cheapest setting within the scene's tolerance) and the
 * measured convergence orders in dt and in fluid cell size.
 *
 *   gf-bench-accuracy [--quick | --full] [--out DIR] [--repeats N] [--case NAME]...
 *
 * Knobs swept (each case sweeps those that change its error or its cost):
 *   dt/t_c        in {1/10, 1/20, 1/50, 1/100, 1/200}
 *   skin/D        in {0.05, 0.1, 0.2, 0.4}   (cost only: the Verlet list)
 *   t_c sqrt(g/D) in {1e-2, 5e-3}            (where the physics sees it)
 *   fluid cell/D  in {1.5, 2, 3, 4}          (where the fluid works)
 *   fluid.ibm_retraction_dx                   (resolved tier only, its own list)
 *   fluid.cfl                                 (resolved tier only, its own list)
 * unless a case lists its own values (bench_case.dt_list, cell_list): the
 * fluid cases take cell/D in {4, 2, 1, 0.5} of a nominal D, the immersed
 * collapse cell/D in {4, 2, 1.5, 1} and dt/t_c in {1/20, 1/50}, the settling
 * sphere cell/D in {4, 3, 2.5, 2}, the Janssen column dt/t_c in
 * {1/20, 1/50, 1/100} and t_c sqrt(g/D) in {2e-2, 1e-2, 5e-3}, the resolved
 * sphere D/dx in {8, 12, 16} (--quick: 8, 12) and the retraction in {0, 0.3}
 * dx, the resolved sphere's fluid step fluid.cfl in {0.3, 0.15, 0.075}. A knob's default is the common one, or the first of the case's own
 * list when that list does not hold it. A case that
 * does not sweep dt (the grain-free fluid cases) runs at one dt.
 * --quick (default): the dt sweep with the other knobs at default, plus the
 *   sweep of each other knob at the default dt (t_c/50); a minute or two on
 *   one core.
 * --full: every combination, longer runs, more onset phases, and the cases
 *   marked full_only (the dry and the immersed collapse, the Janssen column).
 * Each setting runs `repeats` times (default 3; once when a run takes more
 * than 5 CPU s, where timer noise no longer matters); its cost is the best
 * CPU time of them (bench_accuracy.h: CPU, not wall, so that other processes
 * on a shared machine do not move the fronts; the best wall time is recorded
 * too), its error that of the first run (the runs are deterministic).
 * Outputs in DIR (default "."): bench_accuracy.csv, bench_accuracy.nc (CF),
 * pareto_<case>.svg. Exit status 0 when every setting ran (a refused or
 * failed setting is reported, not hidden: status 1).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_accuracy.h"
#include "core/gf_timer.h"

static const double dt_sweep[] = {1.0 / 10, 1.0 / 20, 1.0 / 50, 1.0 / 100, 1.0 / 200};
static const double skin_sweep[] = {0.05, 0.1, 0.2, 0.4};
static const double tc_sweep[] = {1e-2, 5e-3};
static const double cell_sweep[] = {1.5, 2.0, 3.0, 4.0};
static const double retract_none[] = {BENCH_DEFAULT_RETRACT_DX}; /* no common sweep: only resolved cases list theirs */
static const double cfl_none[] = {BENCH_DEFAULT_FLUID_CFL};

static void label_of(const bench_case *c, const bench_knobs *k, char *buf, size_t len)
{
    int n = 0;
    buf[0] = '\0';
    if (c->knobs & BENCH_KNOB_DT)
        n += snprintf(buf, len, "dt=tc/%.0f", 1.0 / k->dt_over_tc);
    if (c->knobs & BENCH_KNOB_SKIN)
        n += snprintf(buf + n, len - (size_t)n, " skin=%g", k->skin_over_D);
    if (c->knobs & BENCH_KNOB_TC)
        n += snprintf(buf + n, len - (size_t)n, " tc=%g", k->t_contact_nd);
    int resolved_grid = c->cell_as_resolution == 1 || (c->cell_as_resolution == 2 && k->cell_over_D < 1.0);
    if (c->cell_as_resolution == 2)
        n += snprintf(buf + n, len - (size_t)n, "%s%s", n ? " " : "", resolved_grid ? "resolved " : "unresolved ");
    if ((c->knobs & BENCH_KNOB_CELL) && resolved_grid)
        n += snprintf(buf + n, len - (size_t)n, "%sD/dx=%g", n && buf[n - 1] != ' ' ? " " : "", 1.0 / k->cell_over_D);
    else if (c->knobs & BENCH_KNOB_CELL)
        n += snprintf(buf + n, len - (size_t)n, "%scell=%gD", n && buf[n - 1] != ' ' ? " " : "", k->cell_over_D);
    if (c->knobs & BENCH_KNOB_RETRACT)
        n += snprintf(buf + n, len - (size_t)n, "%sretract=%gdx", n ? " " : "", k->retract_dx);
    if (c->knobs & BENCH_KNOB_FLUID_CFL)
        snprintf(buf + n, len - (size_t)n, "%scfl=%g", n ? " " : "", k->fluid_cfl);
}

/* Values of one knob for case c: the case's own list, else the common sweep.
 * A knob the case does not sweep has one value, its default (knobs_at). */
static int knob_values(unsigned knobs, unsigned bit, const double *own, int n_own, const double *common,
                       int n_common, const double **out)
{
    *out = own ? own : common;
    if (!(knobs & bit))
        return 1;
    return own ? n_own : n_common;
}

/* A setting of case c: index a of dt, q of cell, b of skin, t of t_c, r of
 * the retraction, f of the fluid CFL; -1: that knob at the case's default. */
typedef struct knob_lists {
    const double *dt, *cell, *tc, *retract, *cfl;
} knob_lists;

static bench_knobs knobs_at(const bench_case *c, const knob_lists *l, int a, int q, int b, int t, int r, int f)
{
    bench_knobs k = {bench_case_default(c, BENCH_KNOB_DT), BENCH_DEFAULT_SKIN_OVER_D, bench_case_default(c, BENCH_KNOB_TC),
                     bench_case_default(c, BENCH_KNOB_CELL), bench_case_default(c, BENCH_KNOB_RETRACT),
                     bench_case_default(c, BENCH_KNOB_FLUID_CFL)};
    if (a >= 0 && (c->knobs & BENCH_KNOB_DT))
        k.dt_over_tc = l->dt[a];
    if (q >= 0 && (c->knobs & BENCH_KNOB_CELL))
        k.cell_over_D = l->cell[q];
    if (b >= 0 && (c->knobs & BENCH_KNOB_SKIN))
        k.skin_over_D = skin_sweep[b];
    if (t >= 0 && (c->knobs & BENCH_KNOB_TC))
        k.t_contact_nd = l->tc[t];
    if (r >= 0 && (c->knobs & BENCH_KNOB_RETRACT))
        k.retract_dx = l->retract[r];
    if (f >= 0 && (c->knobs & BENCH_KNOB_FLUID_CFL))
        k.fluid_cfl = l->cfl[f];
    return k;
}

static int differs(double v, double d) { return fabs(v - d) > 1e-12 * fmax(1.0, fabs(d)); }

/* Settings of case c: appends to ks (capacity cap), returns the count. */
static int settings_of(const bench_case *c, int full, bench_knobs *ks, int cap)
{
    knob_lists l;
    int n_dt = knob_values(c->knobs, BENCH_KNOB_DT, c->dt_list, c->n_dt, dt_sweep, 5, &l.dt);
    int n_cell = knob_values(c->knobs, BENCH_KNOB_CELL, c->cell_list, c->n_cell, cell_sweep, 4, &l.cell);
    int n_tc = knob_values(c->knobs, BENCH_KNOB_TC, c->tc_list, c->n_tc, tc_sweep, 2, &l.tc);
    int n_ret = knob_values(c->knobs, BENCH_KNOB_RETRACT, c->retract_list, c->n_retract, retract_none, 1, &l.retract);
    int n_cfl = knob_values(c->knobs, BENCH_KNOB_FLUID_CFL, c->cfl_list, c->n_cfl, cfl_none, 1, &l.cfl);
    int n_skin = (c->knobs & BENCH_KNOB_SKIN) ? 4 : 1;
    int n = 0;
    if (full) {
        for (int a = 0; a < n_dt; ++a)
            for (int b = 0; b < n_skin; ++b)
                for (int t = 0; t < n_tc; ++t)
                    for (int r = 0; r < n_ret; ++r)
                        for (int f = 0; f < n_cfl; ++f)
                            for (int q = 0; q < n_cell && n < cap; ++q)
                                ks[n++] = knobs_at(c, &l, a, q, b, t, r, f);
        return n;
    }
    /* --quick: the dt sweep at the other defaults, then each other knob's sweep at the default dt */
    if (c->cell_list && c->n_cell_quick > 0 && c->n_cell_quick < n_cell)
        n_cell = c->n_cell_quick;
    for (int a = 0; a < n_dt && n < cap; ++a)
        ks[n++] = knobs_at(c, &l, a, -1, -1, -1, -1, -1);
    for (int b = 0; (c->knobs & BENCH_KNOB_SKIN) && b < 4 && n < cap; ++b)
        if (differs(skin_sweep[b], BENCH_DEFAULT_SKIN_OVER_D))
            ks[n++] = knobs_at(c, &l, -1, -1, b, -1, -1, -1);
    for (int t = 0; (c->knobs & BENCH_KNOB_TC) && t < n_tc && n < cap; ++t)
        if (differs(l.tc[t], bench_case_default(c, BENCH_KNOB_TC)))
            ks[n++] = knobs_at(c, &l, -1, -1, -1, t, -1, -1);
    for (int q = 0; (c->knobs & BENCH_KNOB_CELL) && q < n_cell && n < cap; ++q)
        if (differs(l.cell[q], bench_case_default(c, BENCH_KNOB_CELL)))
            ks[n++] = knobs_at(c, &l, -1, q, -1, -1, -1, -1);
    for (int r = 0; (c->knobs & BENCH_KNOB_RETRACT) && r < n_ret && n < cap; ++r)
        if (differs(l.retract[r], bench_case_default(c, BENCH_KNOB_RETRACT)))
            ks[n++] = knobs_at(c, &l, -1, -1, -1, -1, r, -1);
    for (int f = 0; (c->knobs & BENCH_KNOB_FLUID_CFL) && f < n_cfl && n < cap; ++f)
        if (differs(l.cfl[f], bench_case_default(c, BENCH_KNOB_FLUID_CFL)))
            ks[n++] = knobs_at(c, &l, -1, -1, -1, -1, -1, f);
    return n;
}

static void usage(void)
{
    fprintf(stderr, "usage: gf-bench-accuracy [--quick | --full] [--out DIR] [--repeats N] [--case NAME]...\n");
}

int main(int argc, char **argv)
{
    int full = 0, repeats = 3, n_only = 0;
    const char *out_dir = ".", *only[16];
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--quick") == 0)
            full = 0;
        else if (strcmp(argv[i], "--full") == 0)
            full = 1;
        else if (strcmp(argv[i], "--out") == 0 && i + 1 < argc)
            out_dir = argv[++i];
        else if (strcmp(argv[i], "--repeats") == 0 && i + 1 < argc)
            repeats = atoi(argv[++i]);
        else if (strcmp(argv[i], "--case") == 0 && i + 1 < argc && n_only < 16)
            only[n_only++] = argv[++i];
        else {
            usage();
            return 2;
        }
    }
    if (repeats < 1) {
        fprintf(stderr, "gf-bench-accuracy: --repeats must be >= 1\n");
        return 2;
    }
    int n_cases;
    const bench_case *cases = bench_cases(&n_cases);
    for (int q = 0; q < n_only; ++q) {
        int known = 0;
        for (int c = 0; c < n_cases; ++c)
            known |= strcmp(only[q], cases[c].name) == 0;
        if (!known) {
            fprintf(stderr, "gf-bench-accuracy: --case %s: no such case; the cases:", only[q]);
            for (int c = 0; c < n_cases; ++c)
                fprintf(stderr, " %s", cases[c].name);
            fprintf(stderr, "\n");
            return 2;
        }
    }
    bench_point *pts = calloc(1024, sizeof *pts);
    if (!pts) {
        fprintf(stderr, "gf-bench-accuracy: out of memory\n");
        return 1;
    }
    int n = 0, n_failed = 0;
    printf("gf-bench-accuracy (%s, best of %d, 1 thread)\n", full ? "--full" : "--quick", repeats);
    printf("%-17s %-28s %14s %14s %10s %10s %10s\n", "case", "setting", "observable", "reference", "error", "cpu (s)",
           "wall (s)");
    for (int c = 0; c < n_cases; ++c) {
        const bench_case *bc = &cases[c];
        int wanted = n_only == 0;
        for (int q = 0; q < n_only; ++q)
            wanted |= strcmp(only[q], bc->name) == 0;
        if (!wanted)
            continue;
        const char *why = "";
        if (bc->full_only && !full) {
            printf("%-17s skipped: --full only\n", bc->name);
            continue;
        }
        if (!bc->available(&why)) {
            printf("%-17s skipped: %s\n", bc->name, why);
            continue;
        }
        bench_knobs ks[64];
        int m = settings_of(bc, full, ks, 64);
        for (int s = 0; s < m && n < 1024; ++s) {
            bench_point *p = &pts[n++];
            p->case_index = c;
            p->k = ks[s];
            label_of(bc, &ks[s], p->label, sizeof p->label);
            double best = INFINITY, best_wall = INFINITY;
            for (int r = 0; r < repeats; ++r) {
                gf_ctx ctx = {0};
                bench_result res;
                double w0 = gf_wtime();
                gf_status st = bc->measure(&ctx, &ks[s], full, &res);
                best_wall = fmin(best_wall, gf_wtime() - w0);
                if (st != GF_OK) {
                    p->status = st;
                    snprintf(p->message, sizeof p->message, "%s", ctx.last_msg);
                    break;
                }
                if (r == 0)
                    p->r = res;
                best = fmin(best, res.cpu_s);
                if (res.cpu_s > 5.0)
                    break; /* long runs: timer noise is negligible, one is enough */
            }
            if (p->status == GF_OK) {
                p->r.cpu_s = best;
                p->wall_s = best_wall;
                printf("%-17s %-28s %14.8g %14.8g %10.3g %10.4g %10.4g", bc->name, p->label, p->r.observable,
                       p->r.reference, p->r.error, p->r.cpu_s, p->wall_s);
                if (bc->aux)
                    printf("  (%s: %.4g)", bc->aux, p->r.aux);
                printf("\n");
            } else {
                n_failed++;
                printf("%-17s %-28s FAILED (%s): %s\n", bc->name, p->label, gf_status_str(p->status), p->message);
            }
            fflush(stdout);
        }
    }
    bench_analyse(pts, n, cases, n_cases);
    printf("\nPareto fronts and recommended defaults (cheapest within tolerance):\n");
    for (int c = 0; c < n_cases; ++c) {
        int any = 0;
        for (int i = 0; i < n; ++i)
            any |= pts[i].case_index == c;
        if (!any)
            continue;
        printf("  %-17s tol %-7g front:", cases[c].name, cases[c].tolerance);
        const bench_point *rec = NULL;
        for (int i = 0; i < n; ++i)
            if (pts[i].case_index == c && pts[i].on_front)
                printf(" [%s]", pts[i].label);
        for (int i = 0; i < n; ++i)
            if (pts[i].case_index == c && pts[i].recommended)
                rec = &pts[i];
        if (rec)
            printf("\n  %-17s recommended: %s (error %.3g, %.3g CPU s)\n", "", rec->label, rec->r.error, rec->r.cpu_s);
        else
            printf("\n  %-17s recommended: none within tolerance\n", "");
    }
    bench_print_orders(pts, n, cases, n_cases);
    bench_print_cell_orders(pts, n, cases, n_cases);
    gf_ctx ctx = {0};
    gf_status st = bench_write(&ctx, out_dir, pts, n, cases, n_cases, full);
    free(pts);
    if (st != GF_OK) {
        fprintf(stderr, "gf-bench-accuracy: %s\n", ctx.last_msg);
        return 1;
    }
    printf("\nwrote %s/bench_accuracy.csv, %s/bench_accuracy.nc, %s/pareto_<case>.svg\n", out_dir, out_dir, out_dir);
    return n_failed > 0 ? 1 : 0;
}
