/*
 * `grainflow check FILE.yaml`: validate a configuration and print every
 * resolved run: each value (defaults included, with its unit), the groups the
 * physical values realise (St, r, Ar, Re* = St/r) and the time scales
 * (T_v, T_i, T_ff, T_visq; gf_groups.h), and what each run and the campaign
 * will cost (grains, steps, CPU time, output size; gf_cost.h), with a warning
 * above an hour of CPU or a few GB. Several files: each is checked, the exit
 * status is 2 when any is invalid. Runs nothing.
 */
#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <string.h>

#include "campaign/gf_cost.h"
#include "campaign/gf_groups_map.h"
#include "campaign/gf_spec_schema.h"
#include "cli/gf_cli.h"
#include "scenes/gf_scene.h"
#include "schedule/gf_ledger.h"
#include "schedule/gf_sched.h"

#define MAX_FILES 256

static const char help[] =
    "usage: grainflow check FILE.yaml [FILE.yaml ...] [-o DIR] [--set key.path=value ...] [--brief]\n"
    "\n"
    "Validates each FILE.yaml (a run or a campaign) and prints every resolved\n"
    "run: all values with their units (defaults included), the realised St, r,\n"
    "Ar, Re* and the time scales T_v, T_i, T_ff, T_visq, and its cost: grains,\n"
    "steps, estimated CPU time and output size, per run and for the campaign\n"
    "(a warning above an hour of CPU or 4 GB). An error is one line\n"
    "file:line:column: message; every file is checked. Runs nothing; for runs\n"
    "already in DIR, warns when the packing they started from is further from\n"
    "the Phi_i asked than phi_tolerance.\n"
    "\n"
    "options:\n"
    "  -o, --output DIR     where the runs are, as for run and campaign (default: runs)\n"
    "      --set KEY=VALUE  override a value, as for run and campaign\n"
    "      --brief          one line per run (id, groups, realised St, r, T_ff)\n"
    "\n"
    "exit status: 0 every file valid, 2 any invalid\n";

static void print_field_line(const char *indent, const char *key, const char *value, const char *unit,
                             const char *doc)
{
    char left[160];
    snprintf(left, sizeof left, "%s%s: %s", indent, key, value);
    printf("%-44s # %s%s%s\n", left, unit && *unit && strcmp(unit, "1") ? unit : "", unit && *unit &&
           strcmp(unit, "1") ? ", " : "", doc ? doc : "");
}

static void print_run(const gf_campaign *c, const gf_campaign_run *r)
{
    const gf_run_spec *s = &r->spec;
    char what[200], value[64];
    gf_sched_describe(r, what, sizeof what);
    printf("# run %d of %d: %s  %s\n", r->index, c->n_runs, s->run_id, what);
    int nf;
    const gf_spec_field *f = gf_spec_fields(&nf);
    for (int i = 0; i < nf; ++i)
        if (!f[i].section[0]) {
            gf_spec_field_format(&f[i], s, value, sizeof value);
            if (f[i].type == GF_FIELD_DOUBLE)
                snprintf(value, sizeof value, "%.10g", *(const double *)((const char *)s + f[i].offset));
            print_field_line("", f[i].key, value, f[i].unit, f[i].doc);
        }
    const gf_scene_desc *scene = gf_scene_find(s->scene);
    printf("scene:\n  name: %s\n", s->scene);
    for (int i = 0; scene && i < scene->n_params; ++i) {
        snprintf(value, sizeof value, "%.10g", gf_run_spec_param(s, scene->params[i].key, NAN));
        print_field_line("  ", scene->params[i].key, value, scene->params[i].unit, scene->params[i].doc);
    }
    const char *sections[] = {"grains", "contact", "fluid", "output"};
    for (int k = 0; k < 4; ++k) {
        printf("%s:\n", sections[k]);
        for (int i = 0; i < nf; ++i)
            if (!strcmp(f[i].section, sections[k])) {
                gf_spec_field_format(&f[i], s, value, sizeof value);
                if (f[i].type == GF_FIELD_DOUBLE)
                    snprintf(value, sizeof value, "%.10g", *(const double *)((const char *)s + f[i].offset));
                print_field_line("  ", f[i].key, value, f[i].unit, f[i].doc);
            }
    }
    int any = 0;
    for (int g = 0; g < 4; ++g) {
        double x = *gf_spec_group((gf_run_spec *)s, g);
        if (!isnan(x))
            printf("%s  %s: %.10g\n", any++ ? "" : "groups:   # asked\n", gf_group_names[g], x);
    }
    const gf_scales *sc = &r->scales;
    printf("# realised: St = %.4g  r = %.4g  Ar = %.4g  Re* = St/r = %.4g  rho_p/rho_f = %.4g\n", sc->stokes_St,
           sc->density_ratio_r, sc->archimedes_Ar, sc->reynolds_Re, sc->rho_ratio);
    printf("# time scales: T_v = %.4g s  T_i = %.4g s  T_ff = %.4g s  T_visq = %.4g s  sqrt(D/g) = %.4g s\n",
           sc->t_viscous_s, sc->t_inertial_s, sc->t_freefall_s, sc->t_visq_s, sc->t_grain_s);
    printf("# contact: t_c = %.4g s  dt = %.4g s", gf_run_spec_t_contact_s(s), gf_run_spec_dt_s(s));
    if (s->end_time_nd > 0)
        printf("  end = %.4g s = %.3g steps", s->end_time_nd * sc->t_grain_s,
               s->end_time_nd * sc->t_grain_s / gf_run_spec_dt_s(s));
    printf("\n");
}

/* "%.*g" of x, or "?" when the scene gives no estimate (NaN). */
static const char *count_text(double x, int digits, char *buf, size_t n)
{
    if (isnan(x))
        snprintf(buf, n, "?");
    else
        snprintf(buf, n, "%.*g", digits, x);
    return buf;
}

/* "404 grains, 1e+05 steps, CPU 0:05, output 1.2 MB" (figures "?" when the scene gives no estimate); a
 * prelude's steps before t = 0 and a grid tier's cells and fluid steps when there are. */
static void cost_text(const gf_run_cost *k, char *buf, size_t n)
{
    char cpu[32], out[32], grains[32], steps[32], extra[96] = "", fluid[96] = "";
    gf_cost_format_time(k->cpu_s, cpu, sizeof cpu);
    gf_cost_format_bytes(k->output_bytes, out, sizeof out);
    if (!isnan(k->n_cells)) { /* method: continuum */
        snprintf(buf, n, "%s cells, %s steps, CPU %s (continuum), output %s", count_text(k->n_cells, 9, grains, sizeof grains),
                 count_text(k->steps, 3, steps, sizeof steps), cpu, out);
        return;
    }
    if (k->prelude_steps > 0)
        snprintf(extra, sizeof extra, " (and %.3g before t = 0)", k->prelude_steps);
    if (isfinite(k->fluid_steps) && isfinite(k->fluid_cells))
        snprintf(fluid, sizeof fluid, ", %.3g fluid cells x %.3g fluid steps", k->fluid_cells, k->fluid_steps);
    snprintf(buf, n, "%s grains, %s steps%s%s, CPU %s%s%s, output %s%s", count_text(round(k->n_grains), 9, grains, sizeof grains),
             count_text(k->steps, 3, steps, sizeof steps), extra, fluid, k->cpu_at_least ? "at least " : "", cpu,
             k->immersed ? " (DEM + fluid)" : "", out, k->may_stop_early ? " (at most: stops at rest)" : "");
}

/* The warnings a run's cost calls for, on stderr, naming the run. */
static void warn_cost(const char *file, const gf_campaign_run *r, const gf_run_cost *k)
{
    char text[64];
    const char *id = r->spec.run_id;
    if (k->cpu_s > GF_COST_WARN_CPU_S) {
        gf_cost_format_time(k->cpu_s, text, sizeof text);
        fprintf(stderr, "%s: warning: run %d (%s) needs about %s of CPU (%.3g steps of %.0f %s)\n", file, r->index,
                id, text, k->steps, isnan(k->n_cells) ? k->n_grains : k->n_cells, isnan(k->n_cells) ? "grains" : "cells");
    }
    if (k->output_bytes > GF_COST_WARN_BYTES) {
        gf_cost_format_bytes(k->output_bytes, text, sizeof text);
        fprintf(stderr, "%s: warning: run %d (%s) writes about %s (output.interval_nd = %g)\n", file, r->index, id,
                text, r->spec.output.interval_nd);
    }
    const double interval_steps = r->spec.output.interval_nd * r->scales.t_grain_s / gf_run_spec_dt_s(&r->spec);
    if (interval_steps < 10.0)
        fprintf(stderr, "%s: warning: run %d (%s) writes a record every %.3g steps (output.interval_nd = %g)\n",
                file, r->index, id, interval_steps, r->spec.output.interval_nd);
}

/* A global attribute of the first of the run's files that has it; NaN when none. */
static double run_attribute(const char *run_dir, const char *name)
{
    static const char *const files[] = {"diagnostics.nc", "particles.nc"};
    for (size_t k = 0; k < sizeof files / sizeof *files; ++k) {
        char path[4400];
        int ncid;
        double v;
        snprintf(path, sizeof path, "%s/%s", run_dir, files[k]);
        if (nc_open(path, NC_NOWRITE, &ncid) != NC_NOERR)
            continue;
        int rc = nc_get_att_double(ncid, NC_GLOBAL, name, &v);
        nc_close(ncid);
        if (rc == NC_NOERR)
            return v;
    }
    return NAN;
}

/* A run already in out_dir that started further from the Phi_i asked than the
 * scene's phi_tolerance (the same test as the run's own warning, gf_run.c). */
static void warn_realised_packing(const char *file, const char *out_dir, const gf_campaign *c,
                                  const gf_campaign_run *r)
{
    const gf_run_spec *s = &r->spec;
    const double asked = isnan(s->phi_initial) ? gf_run_spec_param(s, "phi_target", NAN) : s->phi_initial;
    const double tol = gf_run_spec_param(s, "phi_tolerance", NAN);
    if (isnan(asked) || isnan(tol))
        return;
    char dir[4200];
    gf_ledger_run_dir(out_dir, c->name, s->run_id, dir, sizeof dir);
    const double realised = run_attribute(dir, "phi_initial_local");
    if (!isnan(realised) && fabs(realised - asked) > tol)
        fprintf(stderr,
                "%s: warning: run %d (%s) started at Phi_i = %.4f (interior, at t = 0; %s), %.4f from the %.4g "
                "asked: more than phi_tolerance = %.4g\n",
                file, r->index, s->run_id, realised, dir, realised - asked, asked, tol);
}

/* The campaign's sums, and a warning when they pass the thresholds. */
static void print_campaign_cost(const char *file, const gf_campaign *c, const gf_run_cost *total, int may_stop_early)
{
    char cpu[32], out[32], grains[32], steps[32];
    gf_cost_format_time(total->cpu_s, cpu, sizeof cpu);
    gf_cost_format_bytes(total->output_bytes, out, sizeof out);
    printf("# cost of campaign %s: %d runs, %s grains, %s steps in all; CPU %s%s on one core%s, output %s\n", c->name,
           c->n_runs, count_text(round(total->n_grains), 9, grains, sizeof grains),
           count_text(total->steps, 3, steps, sizeof steps), total->cpu_at_least ? "at least " : "", cpu,
           may_stop_early ? " (at most: runs stop at rest)" : "", out);
    if (total->cpu_s > GF_COST_WARN_CPU_S)
        fprintf(stderr, "%s: warning: campaign %s needs about %s of CPU (%.3g h; --jobs N divides the wall time)\n",
                file, c->name, cpu, total->cpu_s / 3600.0);
    if (total->output_bytes > GF_COST_WARN_BYTES)
        fprintf(stderr, "%s: warning: campaign %s writes about %s\n", file, c->name, out);
}

/* Checks one file: 0 valid, GF_EXIT_USAGE invalid (the error printed). */
static int check_file(const char *file, const char *out_dir, const char *const *sets, int n_sets, int brief)
{
    gf_ctx ctx = {.log_level = GF_LOG_WARN};
    gf_campaign *c = NULL;
    if (gf_campaign_load_file(&ctx, file, sets, n_sets, &c) != GF_OK) {
        gf_cli_print_error(&ctx);
        return GF_EXIT_USAGE;
    }
    printf("# %s: campaign %s, scene %s, %d runs (%d grid points x %d variants)\n\n", file, c->name,
           c->runs[0].spec.scene, c->n_runs, c->n_points, c->n_variants);
    gf_run_cost total = {0};
    int may_stop_early = 0;
    for (int i = 0; i < c->n_runs; ++i) {
        const gf_campaign_run *r = &c->runs[i];
        gf_run_cost k;
        char cost[320];
        gf_cost_estimate(&r->spec, &k);
        cost_text(&k, cost, sizeof cost);
        if (brief) {
            char what[200];
            gf_sched_describe(r, what, sizeof what);
            printf("%4d  %s  %-40s St=%-9.4g r=%-9.4g T_ff=%.4g s\n      %s\n", i, r->spec.run_id, what,
                   r->scales.stokes_St, r->scales.density_ratio_r, r->scales.t_freefall_s, cost);
        } else {
            print_run(c, r);
            printf("# cost: %s\n\n", cost);
        }
        warn_cost(file, r, &k);
        warn_realised_packing(file, out_dir, c, r);
        total.n_grains += isnan(k.n_cells) ? k.n_grains : 0.0; /* continuum runs have cells, not grains */
        total.steps += k.steps;
        total.cpu_s += k.cpu_s;
        total.output_bytes += k.output_bytes;
        may_stop_early |= k.may_stop_early;
        total.cpu_at_least |= k.cpu_at_least;
    }
    print_campaign_cost(file, c, &total, may_stop_early);
    gf_campaign_destroy(&c);
    return GF_EXIT_OK;
}

int gf_cmd_check(int argc, char **argv)
{
    const char *files[MAX_FILES], *sets[GF_CLI_MAX_SETS], *out_dir = "runs";
    int n_files = 0, n_sets = 0, brief = 0;
    const gf_cli_shared shared = {"check", help, &out_dir, sets, &n_sets};
    for (int i = 1; i < argc; ++i) {
        int r = gf_cli_shared_option(&shared, argc, argv, &i);
        if (r != GF_CLI_OTHER) {
            if (r != GF_CLI_NEXT)
                return r;
        } else if (!strcmp(argv[i], "--brief")) {
            brief = 1;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            return gf_cli_usage_error("check", "unknown option '%s'", argv[i]);
        } else if (n_files < MAX_FILES) {
            files[n_files++] = argv[i];
        } else {
            return gf_cli_usage_error("check", "more than %d files", MAX_FILES);
        }
    }
    if (!n_files)
        return gf_cli_usage_error("check", "missing FILE.yaml");
    int code = GF_EXIT_OK, n_bad = 0;
    for (int k = 0; k < n_files; ++k) {
        if (k)
            printf("\n");
        if (check_file(files[k], out_dir, sets, n_sets, brief) != GF_EXIT_OK)
            code = GF_EXIT_USAGE, ++n_bad;
    }
    if (n_files > 1)
        printf("# %d files checked, %d invalid\n", n_files, n_bad);
    return code;
}
