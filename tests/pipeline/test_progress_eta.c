/*
 * The ETAs of the progress lines. A run's ETA after one report is its time
 * left at the reported speed (steps/s times dt), not "--:--"; the campaign
 * ETA is the estimated weight left at the pace measured so far, exact for a
 * campaign whose runs go at a constant pace.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "campaign/gf_campaign.h"
#include "core/gf_timer.h"
#include "gf_test.h"
#include "gf_test_campaign.h"
#include "schedule/gf_eta.h"
#include "schedule/gf_sched.h"

static const char yaml[] = "name: eta\n"
                           "end_time: 10\n"
                           "scene: {name: column_collapse, column_length_over_D: 10}\n"
                           "grains: {diameter_m: 7.6e-3}\n"
                           "grid: {a: [0.5, 1.0, 2.0]}\n";

/* "m:ss" of the text after "ETA ", in seconds; -1 for "--:--". */
static double eta_in(const char *text)
{
    const char *e = strstr(text, "ETA ");
    int m, s;
    return e && sscanf(e + 4, "%d:%d", &m, &s) == 2 ? 60.0 * m + s : -1.0;
}

static void run_eta_after_one_report(void)
{
    /* 60 % of 1 s simulated, 1e4 steps/s at dt = 1e-5 s: 0.1 simulated s per wall s, 4 s left */
    gf_progress p = {.started_s = gf_wtime() - 5.0, .dt_s = 1e-5};
    gf_progress_update(&p, 0.6, 1.0, 1e4);
    char text[160];
    gf_sched_progress_text(&p, text, sizeof text);
    printf("one report: %s\n", text);
    GF_CHECK_ABS(eta_in(text), 4.0, 1.0);
}

static void campaign_eta_constant_pace(void)
{
    gf_ctx ctx = {0};
    gf_campaign *c = gf_test_campaign(&ctx, "eta.yaml", yaml);
    if (!c)
        return;
    const int todo[3] = {0, 1, 2};
    gf_campaign_eta e;
    gf_campaign_eta_init(&e, c, todo, 3, 1);
    GF_CHECK(e.weight && e.total > 0);
    /* taller columns hold more grains: they weigh more */
    GF_CHECK(e.weight && e.weight[2] > e.weight[1] && e.weight[1] > e.weight[0]);
    /* before any run finished: the estimate itself on one worker */
    e.started_s = 100.0;
    GF_CHECK_REL(gf_campaign_eta_left_s(&e, 0.0, 100.0), e.total, 1e-12);
    /* run 0 done and run 1 half done in T wall seconds: the rest goes at the same pace */
    gf_campaign_eta_finished(&e, 0);
    const double part = gf_campaign_eta_part(&e, 1, 0.5), done = e.weight[0] + 0.5 * e.weight[1], T = 30.0;
    const double want = (e.total - done) * T / done;
    GF_CHECK_REL(gf_campaign_eta_left_s(&e, part, 100.0 + T), want, 1e-12);
    printf("campaign: weights %.3g %.3g %.3g s, left after %.0f s: %.1f s\n", e.weight[0], e.weight[1], e.weight[2], T,
           want);
    gf_campaign_eta_free(&e);
    gf_campaign_destroy(&c);
}

int main(void)
{
    run_eta_after_one_report();
    campaign_eta_constant_pace();
    return gf_test_finish();
}
