/*
 * The run ledger and --resume, on a real (tiny) campaign: binary collisions
 * at three impact speeds, plus one impossible run (grains overlapping by
 * 0.4 D at t = 0, refused by the engine).
 *
 * - two workers run the four runs; the three good runs end "done", the bad
 *   one "failed: <engine message>", and the campaign goes on past it;
 * - every run directory holds run.yaml, which reloads to the same run id;
 * - resume skips the done runs (their status file is not rewritten: same
 *   modification time and inode) and retries only the failed one;
 * - a run whose status is missing (as after a kill) is run again.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "campaign/gf_campaign.h"
#include "gf_test.h"
#include "gf_test_campaign.h"
#include "schedule/gf_ledger.h"
#include "schedule/gf_sched.h"

static const char campaign_text[] =
    "name: resume_test\n"
    "scene: {name: binary_collision}\n"
    "grains: {diameter_m: 5e-3, density_kg_m3: 2500}\n"
    "output: {particles: false}\n"
    "variants:\n"
    "  - {label: slow, scene.impact_speed_nd: 0.5}\n"
    "  - {label: mid, scene.impact_speed_nd: 1.0}\n"
    "  - {label: fast, scene.impact_speed_nd: 2.0}\n"
    "  - {label: overlapping, scene.gap_over_D: -0.4}\n";

static int status_stat(const char *out, const gf_campaign *c, int i, struct stat *sb)
{
    char dir[4200], path[4300];
    gf_ledger_run_dir(out, c->name, c->runs[i].spec.run_id, dir, sizeof dir);
    snprintf(path, sizeof path, "%s/status", dir);
    return stat(path, sb);
}

int main(void)
{
    char out[] = "/tmp/gf_resume_XXXXXX";
    GF_CHECK(mkdtemp(out) != NULL);
    gf_ctx ctx = {0};
    gf_campaign *c = gf_test_campaign(&ctx, "resume.yaml", campaign_text);
    if (!c)
        return gf_test_finish();
    gf_sched_opts opt = {.out_dir = out, .n_jobs = 2, .quiet = 1};
    gf_sched_counts n;
    GF_CHECK_OK(gf_sched_run(&ctx, c, &opt, &n), &ctx);
    GF_CHECK(n.n_total == 4 && n.n_done == 3 && n.n_failed == 1 && n.n_skipped == 0);

    char dir[4200], reason[600];
    for (int i = 0; i < 4; ++i) {
        gf_ledger_run_dir(out, c->name, c->runs[i].spec.run_id, dir, sizeof dir);
        gf_run_state st = gf_ledger_state(dir, reason, sizeof reason);
        gf_test_check(st == (i < 3 ? GF_RUN_DONE : GF_RUN_FAILED), __FILE__, __LINE__, "run %d state %d (%s)", i, st,
                      reason);
        char yaml[4300];
        snprintf(yaml, sizeof yaml, "%s/run.yaml", dir);
        gf_campaign *r = NULL;
        GF_CHECK_OK(gf_campaign_load_file(&ctx, yaml, NULL, 0, &r), &ctx);
        if (r)
            GF_CHECK(strcmp(r->runs[0].spec.run_id, c->runs[i].spec.run_id) == 0 && strcmp(r->name, c->name) == 0);
        gf_campaign_destroy(&r);
    }
    gf_ledger_run_dir(out, c->name, c->runs[3].spec.run_id, dir, sizeof dir);
    gf_ledger_state(dir, reason, sizeof reason);
    gf_test_check(strstr(reason, "overlap") != NULL, __FILE__, __LINE__, "failure reason names the cause: %s", reason);

    /* resume: done runs untouched, the failed one retried */
    struct stat before[3], after;
    for (int i = 0; i < 3; ++i)
        GF_CHECK(status_stat(out, c, i, &before[i]) == 0);
    sleep(1); /* a rewrite would show in the mtime at 1 s resolution at worst */
    opt.resume = 1;
    GF_CHECK_OK(gf_sched_run(&ctx, c, &opt, &n), &ctx);
    GF_CHECK(n.n_skipped == 3 && n.n_done == 0 && n.n_failed == 1);
    for (int i = 0; i < 3; ++i) {
        GF_CHECK(status_stat(out, c, i, &after) == 0);
        GF_CHECK(after.st_ino == before[i].st_ino && after.st_mtime == before[i].st_mtime);
    }

    /* a run without status (killed) is not done: resume runs it again */
    char path[4300];
    gf_ledger_run_dir(out, c->name, c->runs[1].spec.run_id, dir, sizeof dir);
    snprintf(path, sizeof path, "%s/status", dir);
    GF_CHECK(remove(path) == 0);
    int only[] = {1};
    opt.selected = only;
    opt.n_selected = 1;
    GF_CHECK_OK(gf_sched_run(&ctx, c, &opt, &n), &ctx);
    GF_CHECK(n.n_done == 1 && n.n_skipped == 0 && n.n_total == 1);
    GF_CHECK(gf_ledger_state(dir, NULL, 0) == GF_RUN_DONE);

    gf_campaign_destroy(&c);
    if (!gf_test_remove_tree(out))
        fprintf(stderr, "could not remove %s\n", out);
    return gf_test_finish();
}
