/*
 * gf-bench-accuracy: run time against error for the validation scenes that
 * have a reference (bench_cases.c), the Pareto front of each, the
 * recommended default (cheapest setting within the scene's tolerance) and the
 * measured convergence order in dt.
 *
 *   gf-bench-accuracy [--quick | --full] [--out DIR] [--repeats N] [--case NAME]...
 *
 * Knobs swept (each case sweeps those that change its error or its cost):
 *   dt/t_c        in {1/10, 1/20, 1/50, 1/100, 1/200}
 *   skin/D        in {0.05, 0.1, 0.2, 0.4}   (cost only: the Verlet list)
 *   t_c sqrt(g/D) in {1e-2, 5e-3}            (where the physics sees it)
 *   fluid cell/D  in {1.5, 2, 3, 4}          (where the fluid works)
 * --quick (default): the dt sweep with the other knobs at default, plus the
 *   sweep of each other knob at the default dt (t_c/50); a minute or two on
 *   one core.
 * --full: every combination, longer runs, more onset phases, and the cases
 *   marked full_only (the dry collapse).
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

static void label_of(const bench_case *c, const bench_knobs *k, char *buf, size_t len)
{
    int n = snprintf(buf, len, "dt=tc/%.0f", 1.0 / k->dt_over_tc);
    if (c->knobs & BENCH_KNOB_SKIN)
        n += snprintf(buf + n, len - (size_t)n, " skin=%g", k->skin_over_D);
    if (c->knobs & BENCH_KNOB_TC)
        n += snprintf(buf + n, len - (size_t)n, " tc=%g", k->t_contact_nd);
    if (c->knobs & BENCH_KNOB_CELL)
        snprintf(buf + n, len - (size_t)n, " cell=%gD", k->cell_over_D);
}

/* Settings of case c: appends to ks (capacity cap), returns the count. */
static int settings_of(const bench_case *c, int full, bench_knobs *ks, int cap)
{
    const bench_knobs def = {BENCH_DEFAULT_DT_OVER_TC, BENCH_DEFAULT_SKIN_OVER_D, BENCH_DEFAULT_TC_ND,
                             BENCH_DEFAULT_CELL_OVER_D};
    int n = 0;
    int n_skin = (c->knobs & BENCH_KNOB_SKIN) ? 4 : 1, n_tc = (c->knobs & BENCH_KNOB_TC) ? 2 : 1;
    int n_cell = (c->knobs & BENCH_KNOB_CELL) ? 4 : 1;
    if (full) {
        for (int a = 0; a < 5; ++a)
            for (int b = 0; b < n_skin; ++b)
                for (int t = 0; t < n_tc; ++t)
                    for (int q = 0; q < n_cell && n < cap; ++q) {
                        bench_knobs k = def;
                        k.dt_over_tc = dt_sweep[a];
                        if (c->knobs & BENCH_KNOB_SKIN)
                            k.skin_over_D = skin_sweep[b];
                        if (c->knobs & BENCH_KNOB_TC)
                            k.t_contact_nd = tc_sweep[t];
                        if (c->knobs & BENCH_KNOB_CELL)
                            k.cell_over_D = cell_sweep[q];
                        ks[n++] = k;
                    }
        return n;
    }
    for (int a = 0; a < 5 && n < cap; ++a) {
        ks[n] = def;
        ks[n++].dt_over_tc = dt_sweep[a];
    }
    if (c->knobs & BENCH_KNOB_SKIN)
        for (int b = 0; b < 4 && n < cap; ++b)
            if (fabs(skin_sweep[b] - def.skin_over_D) > 1e-12) {
                ks[n] = def;
                ks[n++].skin_over_D = skin_sweep[b];
            }
    if (c->knobs & BENCH_KNOB_TC)
        for (int t = 0; t < 2 && n < cap; ++t)
            if (fabs(tc_sweep[t] - def.t_contact_nd) > 1e-15) {
                ks[n] = def;
                ks[n++].t_contact_nd = tc_sweep[t];
            }
    if (c->knobs & BENCH_KNOB_CELL)
        for (int q = 0; q < 4 && n < cap; ++q)
            if (fabs(cell_sweep[q] - def.cell_over_D) > 1e-12) {
                ks[n] = def;
                ks[n++].cell_over_D = cell_sweep[q];
            }
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
                printf("%-17s %-28s %14.8g %14.8g %10.3g %10.4g %10.4g\n", bc->name, p->label, p->r.observable,
                       p->r.reference, p->r.error, p->r.cpu_s, p->wall_s);
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
