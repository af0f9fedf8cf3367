/*
 * `grainflow bench FILE.yaml`: every run of a (benchmark) campaign, in this
 * process, output off, timed. Reports particle-timesteps per second (grains x
 * DEM steps / wall second: the throughput measure that is comparable across
 * system sizes), the wall time and the split of gf_sim_timers, into bench.csv.
 */
#include <stdio.h>
#include <string.h>

#include "campaign/gf_spec_schema.h"
#include "cli/gf_cli.h"
#include "core/gf_timer.h"
#include "schedule/gf_ledger.h"
#include "schedule/gf_run_exec.h"
#include "schedule/gf_sched.h"


static const char help[] =
    "usage: grainflow bench FILE.yaml [-o DIR] [--set key.path=value ...]\n"
    "\n"
    "Runs every run of FILE.yaml one after the other with all output off and\n"
    "reports, per run, grains, steps, wall time, particle-timesteps per second\n"
    "and the time split (neighbour, force, integrate, fluid, coupling, output).\n"
    "Writes DIR/bench.csv (default DIR: .).\n"
    "\n"
    "exit status: 0 all runs completed, 1 a run failed, 2 usage/configuration error\n";

int gf_cmd_bench(int argc, char **argv)
{
    const char *file = NULL, *out_dir = ".", *sets[GF_CLI_MAX_SETS];
    int n_sets = 0;
    const gf_cli_shared shared = {"bench", help, &out_dir, sets, &n_sets};
    for (int i = 1; i < argc; ++i) {
        int r = gf_cli_shared_option(&shared, argc, argv, &i);
        if (r == GF_CLI_OTHER)
            r = gf_cli_operand("bench", argv[i], &file);
        if (r != GF_CLI_NEXT)
            return r;
    }
    gf_ctx ctx = {.log_level = GF_LOG_WARN};
    gf_campaign *c = NULL;
    int code = gf_cli_load_campaign(&ctx, "bench", file, "FILE.yaml", sets, n_sets, &c);
    if (code != GF_EXIT_OK)
        return code;
    if (gf_ledger_mkdirs(&ctx, out_dir) != GF_OK) {
        gf_cli_print_error(&ctx);
        gf_campaign_destroy(&c);
        return GF_EXIT_USAGE;
    }
    char path[4200];
    snprintf(path, sizeof path, "%s/bench.csv", out_dir);
    char tmp[4300];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    FILE *csv = fopen(tmp, "w");
    if (!csv) {
        fprintf(stderr, "grainflow bench: cannot write %s\n", tmp);
        gf_campaign_destroy(&c);
        return GF_EXIT_USAGE;
    }
    fprintf(csv, "run_id,scene,label,St,r,a,Phi_i,status,n_particles,steps,sim_time_s,wall_s,particle_steps_per_s");
    for (int t = 0; t < GF_TIMER_COUNT; ++t)
        fprintf(csv, ",%s_s", gf_timer_name((gf_timer_id)t));
    fprintf(csv, "\n");
    printf("%-12s %-28s %9s %9s %9s %12s  split (neighbour/force/integrate/fluid/coupling)\n", "run", "groups",
           "grains", "steps", "wall s", "p-steps/s");
    volatile int *interrupt = gf_cli_catch_signals();
    int n_failed = 0;
    for (int i = 0; i < c->n_runs && !*interrupt; ++i) {
        const gf_campaign_run *r = &c->runs[i];
        gf_run_exec_opts eo = {.run_dir = NULL, .campaign = c->name, .interrupt = interrupt};
        gf_run_result res;
        gf_run_execute(&ctx, &r->spec, &eo, &res);
        const double rate = res.wall_s > 0 ? (double)res.n_particles * (double)res.steps / res.wall_s : 0.0;
        char what[200];
        gf_sched_describe(r, what, sizeof what);
        n_failed += res.status != GF_OK;
        fprintf(csv, "%s,%s,%s", r->spec.run_id, r->spec.scene, r->label);
        for (int g = 0; g < 4; ++g)
            fprintf(csv, ",%.10g", *gf_spec_group((gf_run_spec *)&r->spec, g));
        fprintf(csv, ",%s,%ld,%ld,%.6g,%.6g,%.6g", res.status == GF_OK ? "done" : "failed", res.n_particles, res.steps,
                res.sim_time_s, res.wall_s, rate);
        for (int t = 0; t < GF_TIMER_COUNT; ++t)
            fprintf(csv, ",%.6g", res.timers_s[t]);
        fprintf(csv, "\n");
        const double tot = res.timers_s[GF_T_TOTAL] > 0 ? res.timers_s[GF_T_TOTAL] : 1.0;
        if (res.status == GF_OK)
            printf("%-12s %-28.28s %9ld %9ld %9.2f %12.4g  %.0f/%.0f/%.0f/%.0f/%.0f %%\n", r->spec.run_id, what,
                   res.n_particles, res.steps, res.wall_s, rate, 100 * res.timers_s[GF_T_NEIGHBOUR] / tot,
                   100 * res.timers_s[GF_T_FORCE] / tot, 100 * res.timers_s[GF_T_INTEGRATE] / tot,
                   100 * res.timers_s[GF_T_FLUID] / tot, 100 * res.timers_s[GF_T_COUPLING] / tot);
        else
            printf("%-12s %-28.28s failed: %s\n", r->spec.run_id, what, res.message);
        fflush(stdout);
    }
    fclose(csv);
    rename(tmp, path);
    printf("bench: %s\n", path);
    gf_campaign_destroy(&c);
    return n_failed || *interrupt ? GF_EXIT_RUN_FAILED : GF_EXIT_OK;
}
