/* `grainflow run SCENE.yaml`: one run, in this process, with a progress line.
 * On a campaign file it runs the one run named by --index or --only, or the
 * one left when --set grid.KEY=VALUE pins the grid to a point. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/gf_cli.h"
#include "core/gf_timer.h"
#include "schedule/gf_ledger.h"
#include "schedule/gf_run_exec.h"
#include "schedule/gf_sched.h"


static const char help[] =
    "usage: grainflow run SCENE.yaml [-o DIR] [--set key.path=value ...] [--index K | --only RUN_ID] [--resume]\n"
    "\n"
    "Runs the one run SCENE.yaml describes into DIR/<name>/<run-id>/ (run.yaml,\n"
    "particles.nc, diagnostics.nc, probes.nc, fields.nc, status). A run.yaml\n"
    "written by an earlier run reproduces it exactly (same run id). A run directory\n"
    "that another process is writing (its .lock is held) is left alone, naming the\n"
    "holder; `done` is written after the run's files are reopened and listed with\n"
    "their sizes and CRC-32 in its manifest (docs/integrity.md).\n"
    "\n"
    "A file with a grid or variants is a campaign: run one of its runs with\n"
    "--index K or --only RUN_ID (grainflow check FILE --brief lists them), or\n"
    "pin the grid to one point with --set grid.a=2 (one --set per grid key);\n"
    "grainflow campaign runs them all. The run goes to the campaign's folder,\n"
    "where grainflow campaign would put it.\n"
    "\n"
    "options:\n"
    "  -o, --output DIR     output directory (default: runs)\n"
    "      --set KEY=VALUE  override a value, e.g. --set scene.aspect_ratio=2 --set fluid.model=none\n"
    "      --index K        run K (0-based, campaign order) of a campaign file\n"
    "      --only RUN_ID    the run of a campaign file with this id\n"
    "      --resume         continue an interrupted run from its checkpoint (Ctrl-C or SIGTERM\n"
    "                       wrote it), with the build that started it; a run already done is\n"
    "                       left as it is (exit 0)\n"
    "  -q, --quiet          no progress line\n"
    "\n"
    "exit status: 0 done, 1 the run failed or its directory is held by another process,\n"
    "2 usage/configuration error\n";

typedef struct progress_state {
    int tty;
    const char *run_id;
    gf_progress progress;
} progress_state;

static void on_progress(void *user, double t_s, double t_end_s, double steps_per_s)
{
    progress_state *p = user;
    gf_progress_update(&p->progress, t_s, t_end_s, steps_per_s);
    if (!p->tty)
        return;
    char text[160];
    gf_sched_progress_text(&p->progress, text, sizeof text);
    printf("\r  %s  %s\033[K", p->run_id, text);
    fflush(stdout);
}

/* The run to execute: the only one, or the one --index / --only names; -1 (said why) otherwise. */
static int pick_run(const char *file, const gf_campaign *c, int index, const char *only)
{
    if (index >= 0 && only)
        return gf_cli_usage_error("run", "--index and --only name the same thing: give one"), -1;
    if (only) {
        int k = gf_campaign_find(c, only);
        if (k < 0)
            gf_cli_usage_error("run", "--only %s: no run with this id in %s (grainflow check %s --brief lists them)",
                               only, file, file);
        return k;
    }
    if (index >= c->n_runs) {
        gf_cli_usage_error("run", "--index %d: %s has runs 0..%d", index, file, c->n_runs - 1);
        return -1;
    }
    if (index >= 0)
        return index;
    if (c->n_runs == 1)
        return 0;
    fprintf(stderr,
            "%s: a campaign of %d runs (%d grid points x %d variants): run one with --index K (0..%d) or --only "
            "RUN_ID (grainflow check %s --brief lists them), pin the grid with --set grid.KEY=VALUE, or run them all "
            "with grainflow campaign %s\n",
            file, c->n_runs, c->n_points, c->n_variants, c->n_runs - 1, file, file);
    return -1;
}

int gf_cmd_run(int argc, char **argv)
{
    const char *file = NULL, *out_dir = "runs", *v, *sets[GF_CLI_MAX_SETS], *only = NULL;
    int n_sets = 0, quiet = 0, index = -1, resume = 0;
    const gf_cli_shared shared = {"run", help, &out_dir, sets, &n_sets};
    for (int i = 1; i < argc; ++i) {
        int m, r = gf_cli_shared_option(&shared, argc, argv, &i);
        if (r != GF_CLI_OTHER) {
            if (r != GF_CLI_NEXT)
                return r;
        } else if ((m = gf_cli_opt_value(argc, argv, &i, NULL, "--only", &only))) {
            if (m < 0)
                return gf_cli_usage_error("run", "--only needs a run id");
        } else if ((m = gf_cli_opt_value(argc, argv, &i, NULL, "--index", &v))) {
            char *end = NULL;
            long k = m > 0 ? strtol(v, &end, 10) : -1;
            if (m < 0 || !*v || *end || k < 0 || k > INT_MAX)
                return gf_cli_usage_error("run", "--index needs a run number >= 0");
            index = (int)k;
        } else if (!strcmp(argv[i], "-q") || !strcmp(argv[i], "--quiet")) {
            quiet = 1;
        } else if (!strcmp(argv[i], "--resume")) {
            resume = 1;
        } else if ((r = gf_cli_operand("run", argv[i], &file)) != GF_CLI_NEXT) {
            return r;
        }
    }
    gf_ctx ctx = {.log_level = GF_LOG_WARN};
    gf_campaign *c = NULL;
    int loaded = gf_cli_load_campaign(&ctx, "run", file, "SCENE.yaml", sets, n_sets, &c);
    if (loaded != GF_EXIT_OK)
        return loaded;
    const int k = pick_run(file, c, index, only);
    if (k < 0) {
        gf_campaign_destroy(&c);
        return GF_EXIT_USAGE;
    }
    const gf_run_spec *spec = &c->runs[k].spec;
    char dir[4200];
    gf_ledger_run_dir(out_dir, c->name, spec->run_id, dir, sizeof dir);
    char reason[600];
    if (resume && gf_ledger_verified_state(dir, reason, sizeof reason) == GF_RUN_DONE) {
        if (!quiet)
            printf("run %s already done: %s\n", spec->run_id, dir);
        gf_campaign_destroy(&c);
        return GF_EXIT_OK;
    }
    progress_state ps = {.tty = gf_cli_is_tty() && !quiet, .run_id = spec->run_id,
                         .progress = {.started_s = gf_wtime(), .dt_s = gf_run_spec_dt_s(spec)}};
    gf_run_exec_opts eo = {.run_dir = dir,
                           .campaign = c->name,
                           .progress = on_progress,
                           .progress_user = &ps,
                           .interrupt = gf_cli_catch_signals(),
                           .resume = resume,
                           .lock_what = "run"};
    gf_run_result res;
    gf_status st = gf_run_execute(&ctx, spec, &eo, &res);
    if (ps.tty)
        printf("\r\033[K");
    int code = GF_EXIT_OK;
    if (st != GF_OK) {
        gf_cli_print_error(&ctx);
        code = GF_EXIT_RUN_FAILED;
    } else if (res.held) {
        fprintf(stderr, "run %s not started: %s\n", spec->run_id, res.message);
        code = GF_EXIT_RUN_FAILED;
    } else if (res.status != GF_OK) {
        fprintf(stderr, "run %s failed: %s\n", spec->run_id, res.message);
        code = GF_EXIT_RUN_FAILED;
    } else if (!quiet) {
        char from[80] = "";
        if (res.continued_from_s > 0.0)
            snprintf(from, sizeof from, " (continued from t = %.4g s)", res.continued_from_s);
        printf("run %s done: %ld grains, %ld steps, t = %.4g s%s in %.1f s wall -> %s\n", spec->run_id,
               res.n_particles, res.steps, res.sim_time_s, from, res.wall_s, dir);
    }
    gf_campaign_destroy(&c);
    return code;
}
