/*
 * `grainflow campaign FILE.yaml`: expand, run (worker pool or MPI task farm),
 * post-process. The body is shared with `grainflow demo`, which feeds it the
 * embedded default campaign instead of a file.
 */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/gf_cli.h"
#include "cli/gf_cli_verdict.h"
#include "gf_post.h"
#include "schedule/gf_comm.h"
#include "schedule/gf_ledger.h"
#include "schedule/gf_sched.h"
#include "schedule/gf_slurm.h"
#include "core/gf_timer.h"

#define MAX_SETS 64
#define MAX_SELECT 1024

static const char campaign_help[] =
    "usage: grainflow campaign CAMPAIGN.yaml [options]\n"
    "\n"
    "Expands the grid over (St, r, a, Phi_i) and the variants into runs and runs\n"
    "them into DIR/<campaign>/<run-id>/ (run.yaml, *.nc, status); a failed run is\n"
    "recorded and the campaign goes on. Under `mpirun -n K` the runs are spread\n"
    "over the ranks. Then post-processes the campaign (summary.csv, summary.nc).\n"
    "\n"
    "options:\n"
    "  -o, --output DIR     output directory (default: runs)\n"
    "  -j, --jobs N         runs at once on this machine (default: 1)\n"
    "      --resume         skip runs whose status is done, continue interrupted ones from their checkpoint\n"
    "      --dry-run        list the runs and their state; run nothing\n"
    "      --emit slurm     write a Slurm job-array script (one array task per run); run nothing\n"
    "      --no-post        skip post-processing\n"
    "      --only RUN_ID    run only this run (repeatable)\n"
    "      --index K        run only run K, 0-based, in campaign order (repeatable; Slurm arrays)\n"
    "      --set KEY=VALUE  override a configuration value in every run, e.g. --set end_time=5\n"
    "  -q, --quiet          no per-run lines\n"
    "\n"
    "Each run directory has one writer at a time (a lock file): a run another\n"
    "process holds is skipped with its holder named. Done runs are checked against\n"
    "their manifest (sizes, CRC-32) by --resume, --dry-run and post; one that fails\n"
    "is run again under --resume (docs/integrity.md).\n"
    "\n"
    "exit status: 0 all runs done, 1 a run failed, was left to another process or\n"
    "the campaign was interrupted, or post-processing marked a run; 2 usage/configuration error\n";

static const char demo_help[] =
    "usage: grainflow demo [options]\n"
    "\n"
    "Runs the embedded default campaign (configs/demo.yaml): a small dry column\n"
    "collapse over the aspect ratio a and the initial packing Phi_i, and an\n"
    "immersed variant (fluid: unresolved), into DIR/demo/, then post-processes it.\n"
    "A few minutes on 2 cores.\n"
    "\n"
    "options:\n"
    "  -o, --output DIR     output directory (default: runs)\n"
    "  -j, --jobs N         runs at once (default: 2)\n"
    "      --resume, --dry-run, --no-post, --set KEY=VALUE, -q   as for campaign\n"
    "      --print          print the embedded YAML and exit\n";

static int select_runs(const char *cmd, const gf_campaign *c, const char *const *only, int n_only,
                       const int *index, int n_index, int *selected, int *n_selected)
{
    *n_selected = 0;
    for (int i = 0; i < n_only; ++i) {
        int k = gf_campaign_find(c, only[i]);
        if (k < 0)
            return gf_cli_usage_error(cmd, "--only %s: no run with this id in campaign %s", only[i], c->name);
        selected[(*n_selected)++] = k;
    }
    for (int i = 0; i < n_index; ++i) {
        if (index[i] < 0 || index[i] >= c->n_runs)
            return gf_cli_usage_error(cmd, "--index %d: campaign %s has runs 0..%d", index[i], c->name,
                                      c->n_runs - 1);
        selected[(*n_selected)++] = index[i];
    }
    return GF_EXIT_OK;
}

static void dry_run(const gf_campaign *c, const char *out_dir)
{
    printf("campaign %s: %d runs (%d grid points x %d variants) into %s/%s/\n", c->name, c->n_runs, c->n_points,
           c->n_variants, out_dir, c->name);
    for (int i = 0; i < c->n_runs; ++i) {
        char dir[4200], what[200], reason[520];
        gf_ledger_run_dir(out_dir, c->name, c->runs[i].spec.run_id, dir, sizeof dir);
        gf_run_state st = gf_ledger_verified_state(dir, reason, sizeof reason);
        gf_sched_describe(&c->runs[i], what, sizeof what);
        const int why = st == GF_RUN_FAILED || st == GF_RUN_CORRUPT;
        printf("%4d  %s  %-7s %s%s%s\n", i, c->runs[i].spec.run_id,
               st == GF_RUN_DONE      ? "done"
               : st == GF_RUN_FAILED  ? "failed"
               : st == GF_RUN_CORRUPT ? "corrupt"
                                      : "new",
               what, why ? "  -- " : "", why ? reason : "");
    }
}

int gf_cli_campaign_common(const char *cmd, int argc, char **argv, const char *embedded_text,
                           const char *embedded_name)
{
    const char *file = NULL, *out_dir = "runs", *emit = NULL, *v;
    const char *sets[MAX_SETS], *only[MAX_SELECT];
    int index[MAX_SELECT];
    int n_sets = 0, n_only = 0, n_index = 0, n_jobs = embedded_text ? 2 : 1;
    int resume = 0, dry = 0, no_post = 0, quiet = 0, print = 0;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        int m;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(embedded_text ? demo_help : campaign_help, stdout);
            return GF_EXIT_OK;
        } else if ((m = gf_cli_opt_value(argc, argv, &i, "-o", "--output", &out_dir))) {
            if (m < 0)
                return gf_cli_usage_error(cmd, "%s needs a directory", a);
        } else if ((m = gf_cli_opt_value(argc, argv, &i, "-j", "--jobs", &v))) {
            if (m < 0 || (n_jobs = gf_cli_parse_count(cmd, "--jobs", v, 4096)) < 0)
                return m < 0 ? gf_cli_usage_error(cmd, "--jobs needs a number") : GF_EXIT_USAGE;
        } else if ((m = gf_cli_opt_value(argc, argv, &i, NULL, "--set", &v))) {
            if (m < 0 || n_sets == MAX_SETS)
                return gf_cli_usage_error(cmd, "--set needs KEY=VALUE (at most %d)", MAX_SETS);
            sets[n_sets++] = v;
        } else if (!embedded_text && (m = gf_cli_opt_value(argc, argv, &i, NULL, "--emit", &emit))) {
            if (m < 0 || strcmp(emit, "slurm") != 0)
                return gf_cli_usage_error(cmd, "--emit: only 'slurm' is supported");
        } else if (!embedded_text && (m = gf_cli_opt_value(argc, argv, &i, NULL, "--only", &v))) {
            if (m < 0 || n_only == MAX_SELECT)
                return gf_cli_usage_error(cmd, "--only needs a run id");
            only[n_only++] = v;
        } else if (!embedded_text && (m = gf_cli_opt_value(argc, argv, &i, NULL, "--index", &v))) {
            char *end;
            long k = m > 0 ? strtol(v, &end, 10) : -1;
            if (m < 0 || n_index == MAX_SELECT || !*v || *end || k < 0 || k > INT_MAX)
                return gf_cli_usage_error(cmd, "--index needs a run number >= 0");
            index[n_index++] = (int)k;
        } else if (!strcmp(a, "--resume")) {
            resume = 1;
        } else if (!strcmp(a, "--dry-run")) {
            dry = 1;
        } else if (!strcmp(a, "--no-post")) {
            no_post = 1;
        } else if (!strcmp(a, "--quiet") || !strcmp(a, "-q")) {
            quiet = 1;
        } else if (embedded_text && !strcmp(a, "--print")) {
            print = 1;
        } else if (a[0] == '-' && a[1]) {
            return gf_cli_usage_error(cmd, "unknown option '%s'", a);
        } else if (!file && !embedded_text) {
            file = a;
        } else {
            return gf_cli_usage_error(cmd, "unexpected argument '%s'", a);
        }
    }
    if (print) {
        fputs(embedded_text, stdout);
        return GF_EXIT_OK;
    }
    if (!file && !embedded_text)
        return gf_cli_usage_error(cmd, "missing CAMPAIGN.yaml");

    gf_ctx ctx = {.log_level = GF_LOG_WARN};
    gf_campaign *c = NULL;
    gf_status st = embedded_text ? gf_campaign_load_string(&ctx, embedded_name, embedded_text, strlen(embedded_text),
                                                           sets, n_sets, &c)
                                 : gf_campaign_load_file(&ctx, file, sets, n_sets, &c);
    if (st != GF_OK) {
        gf_cli_print_error(&ctx);
        return GF_EXIT_USAGE;
    }
    int selected[2 * MAX_SELECT], n_selected = 0;
    int code = select_runs(cmd, c, only, n_only, index, n_index, selected, &n_selected);
    if (code != GF_EXIT_OK) {
        gf_campaign_destroy(&c);
        return code;
    }
    if (dry) {
        if (gf_comm_rank() == 0)
            dry_run(c, out_dir);
        gf_campaign_destroy(&c);
        return GF_EXIT_OK;
    }
    if (emit) {
        char exe[PATH_MAX], cfg[PATH_MAX], out_abs[PATH_MAX], path[4200];
        gf_cli_self_path(argv[0], exe, sizeof exe);
        if (!realpath(file, cfg))
            snprintf(cfg, sizeof cfg, "%s", file);
        gf_ledger_mkdirs(&ctx, out_dir);
        if (!realpath(out_dir, out_abs))
            snprintf(out_abs, sizeof out_abs, "%s", out_dir);
        gf_slurm_opts so = {.config_path = cfg, .out_dir = out_abs, .executable = exe, .cpus_per_task = 1,
                            .sets = sets, .n_sets = n_sets};
        st = gf_slurm_emit(&ctx, c, &so, path, sizeof path);
        if (st != GF_OK) {
            gf_cli_print_error(&ctx);
            gf_campaign_destroy(&c);
            return GF_EXIT_RUN_FAILED;
        }
        printf("%s\n", path);
        gf_campaign_destroy(&c);
        return GF_EXIT_OK;
    }

    volatile int *interrupt = gf_cli_catch_signals();
    gf_sched_opts so = {.out_dir = out_dir,
                        .n_jobs = n_jobs,
                        .resume = resume,
                        .selected = n_selected ? selected : NULL,
                        .n_selected = n_selected,
                        .tty = gf_cli_is_tty(),
                        .quiet = quiet,
                        .interrupt = interrupt};
    gf_sched_counts counts;
    const double t0 = gf_wtime();
    if (gf_comm_rank() == 0 && !quiet) {
        printf("campaign %s: %d runs into %s/%s/ (%d at a time%s)\n", c->name, n_selected ? n_selected : c->n_runs,
               out_dir, c->name, gf_comm_size() > 1 ? gf_comm_size() : n_jobs,
               gf_comm_size() > 1 ? ", MPI ranks" : "");
        fflush(stdout);
    }
    st = gf_sched_run(&ctx, c, &so, &counts);
    code = GF_EXIT_OK;
    if (st != GF_OK) {
        gf_cli_print_error(&ctx);
        code = GF_EXIT_RUN_FAILED;
    }
    if (counts.n_failed > 0 || counts.n_held > 0)
        code = GF_EXIT_RUN_FAILED;
    if (gf_comm_rank() == 0) {
        printf("campaign %s: %d done, %d failed, %d skipped (already done) in %.1f s\n", c->name, counts.n_done,
               counts.n_failed, counts.n_skipped, gf_wtime() - t0);
        if (counts.n_rerun > 0)
            printf("campaign %s: %d run(s) marked done failed their manifest check and were run again\n", c->name,
                   counts.n_rerun);
        if (counts.n_held > 0)
            printf("campaign %s: %d run(s) left to another process that holds them (above); `--resume` after it "
                   "ends completes the campaign\n",
                   c->name, counts.n_held);
    }
    gf_comm_barrier();
    if (!no_post && st != GF_ERR_INTERRUPTED && gf_comm_rank() == 0) {
        char dir[4200];
        snprintf(dir, sizeof dir, "%s/%s", out_dir, c->name);
        gf_post_options po = {.stage = NULL, .n_jobs = n_jobs, .figures = 1, .quiet = quiet};
        gf_post_report rep;
        gf_ctx pctx = {.log_level = GF_LOG_WARN};
        fflush(stdout);
        if (gf_post_campaign_report(&pctx, dir, &po, &rep) != GF_OK) {
            fprintf(stderr, "grainflow %s: post-processing failed: %s\n", cmd, pctx.last_msg);
            code = GF_EXIT_RUN_FAILED;
        } else {
            if (gf_cli_post_verdict(cmd, &rep))
                code = GF_EXIT_RUN_FAILED;
            if (!quiet)
                printf("summary: %s/summary.csv, %s/summary.nc\n", dir, dir);
        }
    }
    gf_campaign_destroy(&c);
    return code;
}

int gf_cmd_campaign(int argc, char **argv)
{
    return gf_cli_campaign_common("campaign", argc, argv, NULL, NULL);
}

int gf_cmd_demo(int argc, char **argv)
{
    return gf_cli_campaign_common("demo", argc, argv, gf_demo_yaml, "demo.yaml (embedded)");
}
