/*
 * Campaign-scale tests (the slow validations that run a repository campaign
 * through the scheduler, then `grainflow post`): where the runs go and how
 * they are run.
 *   GF_TEST_RUNS=DIR keeps the runs in DIR and reuses those already done there
 *   (`grainflow campaign --resume`); without it they go to a temporary
 *   directory that the test removes when every check passes.
 *   GF_TEST_JOBS=N runs N at a time (default 2).
 *   GF_TEST_NO_RUN=1 runs nothing: the test scores the runs already done in
 *   GF_TEST_RUNS (a multi-hour campaign scored while its last run is going).
 */
#ifndef GF_TEST_RUNS_H
#define GF_TEST_RUNS_H

#include <stdio.h>
#include <stdlib.h>

#include "campaign/gf_campaign.h"
#include "gf_post.h"
#include "gf_summary.h"
#include "gf_test.h"
#include "schedule/gf_sched.h"

/* $GF_TEST_RUNS, else tmp (a mkdtemp template ending in XXXXXX) made. */
static inline const char *gf_test_runs_dir(char *tmp)
{
    const char *out = getenv("GF_TEST_RUNS");
    if (out)
        return out;
    GF_CHECK(mkdtemp(tmp) != NULL);
    return tmp;
}

/* Runs c into out as `grainflow campaign --resume --jobs N` would; checks that no run failed. */
static inline void gf_test_run_campaign(gf_ctx *ctx, const gf_campaign *c, const char *out)
{
    const char *no_run = getenv("GF_TEST_NO_RUN");
    if (no_run && *no_run && *no_run != '0')
        return;
    const int jobs = getenv("GF_TEST_JOBS") ? atoi(getenv("GF_TEST_JOBS")) : 2;
    gf_sched_opts so = {.out_dir = out, .n_jobs = jobs, .resume = 1};
    gf_sched_counts counts;
    GF_CHECK_OK(gf_sched_run(ctx, c, &so, &counts), ctx);
    GF_CHECK(counts.n_failed == 0);
}

/* `grainflow post` on out/<campaign>, then its summary.nc read into *rows (free() them); figures: write figures/. */
static inline void gf_test_post_summary(gf_ctx *ctx, const char *out, const char *campaign, int figures,
                                        gf_post_row **rows, int *n_rows)
{
    char campaign_dir[1200], summary[1300];
    snprintf(campaign_dir, sizeof campaign_dir, "%s/%s", out, campaign);
    gf_post_options po = {.stage = NULL, .n_jobs = 1, .figures = figures, .quiet = 1};
    GF_CHECK_OK(gf_post_campaign(ctx, campaign_dir, &po), ctx);
    snprintf(summary, sizeof summary, "%s/summary.nc", campaign_dir);
    *rows = NULL, *n_rows = 0;
    GF_CHECK_OK(gf_summary_read(ctx, summary, rows, n_rows), ctx);
}

#endif
