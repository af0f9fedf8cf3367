/*
 * The grain-resolved immersed avalanche at one point of each regime of
 * Izard (2014) Table 4.2, in the thesis' steady window: slow and long
 * (configs/avalanche_resolved_points.yaml, read from GF_SOURCE_DIR: three
 * resolved runs at D/dx 8 to 400 sqrt(D/g), ~2-3 CPU-h each).
 *
 * The grain flow rate of the thesis is steady from t_sg ~ 250 sqrt(D/g)
 * (Izard 2014 §4.1.4.1, Fig. 4.5); `grainflow post` takes Q_g over the
 * MSER-5 window, and T = V_g / Q_g (4.12). Checks, for each point (the
 * issue's tolerance, docs/resolved.md):
 *   - the label the classifier gives (stages/gf_regime.h) is the one the
 *     thesis' boundaries give (§4.1.4.2; tests/post/table42.h);
 *   - T / T_x within a factor 2 of 1, T_x the scale of that regime
 *     (T_v, T_i or T_ff, eq. (4.1)).
 * The thesis' own T for the point is printed beside (Table 4.2).
 *
 * GF_TEST_RUNS=DIR keeps the runs in DIR and continues or reuses those there
 * (a long run is resumed with the build that started it: docs/campaigns.md);
 * GF_TEST_NO_RUN=1 scores only the runs already done (the others fail).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "campaign/gf_campaign.h"
#include "gf_post.h"
#include "gf_summary.h"
#include "gf_test.h"
#include "gf_test_runs.h"
#include "../post/table42.h"

/* The summary column of T over the regime's own time scale. */
static const char *scale_column(gf_regime_label label)
{
    switch (label) {
    case GF_REGIME_VISCOUS:
        return "T_over_Tv";
    case GF_REGIME_INERTIAL:
        return "T_over_Ti";
    default:
        return "T_over_Tff";
    }
}

/* Table 4.2's T (ms) at the run's (St, r), NAN if the table has no such point. */
static double thesis_T_ms(double St, double r)
{
    for (int k = 0; k < TABLE42_N; ++k)
        if (table42_is(&table42[k], St, r))
            return table42[k].T_ms;
    return NAN;
}

static void check_point(const gf_campaign_run *run, const gf_post_row *rows, int n_rows)
{
    const gf_run_spec *s = &run->spec;
    const gf_regime_label want = table42_expected(s->stokes_St, s->density_ratio_r);
    const gf_post_row *row = gf_summary_find(rows, n_rows, s->run_id);
    GF_CHECK(row != NULL);
    if (!row) {
        printf("St %6.2f r %5.2f  thesis %-10s no run done\n", s->stokes_St, s->density_ratio_r,
               gf_regime_name(want));
        return;
    }
    const char *got = gf_post_row_get_text(row, "regime");
    const double x = gf_post_row_get(row, scale_column(want));
    const double T_ms = 1e3 * gf_post_row_get(row, "T_over_Tv") * run->scales.t_viscous_s;
    printf("St %6.2f r %5.2f  thesis %-10s run %-12s %s %.3f  T %.1f ms (thesis %.0f)\n", s->stokes_St,
           s->density_ratio_r, gf_regime_name(want), got ? got : "-", scale_column(want), x, T_ms,
           thesis_T_ms(s->stokes_St, s->density_ratio_r));
    GF_CHECK(got && strcmp(got, gf_regime_name(want)) == 0);
    GF_CHECK(x >= 0.5 && x <= 2.0);
}

int main(void)
{
    gf_ctx ctx = {0};
    const char *src = getenv("GF_SOURCE_DIR");
    char path[1100], tmp[] = "/tmp/gf_resolved_points_XXXXXX";
    snprintf(path, sizeof path, "%s/configs/avalanche_resolved_points.yaml", src ? src : ".");
    gf_campaign *c = NULL;
    GF_CHECK_OK(gf_campaign_load_file(&ctx, path, NULL, 0, &c), &ctx);
    if (!c)
        return gf_test_finish();
    const char *out = gf_test_runs_dir(tmp);
    gf_test_run_campaign(&ctx, c, out);
    gf_post_row *rows;
    int n_rows;
    gf_test_post_summary(&ctx, out, c->name, 0, &rows, &n_rows);
    for (int i = 0; i < c->n_runs; ++i)
        check_point(&c->runs[i], rows, n_rows);
    free(rows);
    gf_campaign_destroy(&c);
    return out == tmp ? gf_test_finish_removing(tmp) : gf_test_finish();
}
