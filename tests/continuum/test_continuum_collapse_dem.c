/*
 * The dry column collapse by both methods on the same columns (the campaign
 * configs/column_collapse_methods.yaml: R0 = 16 D, a = 0.5 and 1, mu_c 0.25,
 * packing seed 1; the continuum at cell D/2 with this DEM's steady-chute law
 * mu_s 0.280, mu_2 0.703, I0 0.279), each run through gf_run_execute, the
 * run-out (R_inf - R0)/R0 read from the final front_position of each run's
 * diagnostics.nc (one definition: the contiguous deposit of solid height
 * >= D/4). Lagree, Staron & Popinet (JFM 686, 2011, §4) reach a few per cent
 * on the run-out between their mu(I) continuum and contact dynamics; the
 * criterion here is 5 %. Not met (label open): measured -12.8 % (a = 0.5) and
 * see docs/continuum.md, "Column collapse", for the figures and the reasons.
 * About 3 min of CPU (slow).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "campaign/gf_campaign.h"
#include "gf_ncread.h"
#include "gf_test.h"
#include "schedule/gf_run_exec.h"

static const char *campaign_text =
    "name: collapse_both\nseed: 1\nend_time: 40\n"
    "scene: {name: column_collapse, column_length_over_D: 16}\n"
    "grains: {diameter_m: 7.6e-3, polydispersity: 0.05, density_kg_m3: 2500}\n"
    "contact: {restitution: 0.87, friction: 0.25}\nfluid: {model: none}\n"
    "continuum: {mu_s: 0.280, mu_2: 0.703, I0: 0.279, cell_over_D: 0.5}\n"
    "output: {interval_nd: 1.0, particles: false}\n"
    "grid: {a: [0.5, 1.0], Phi_i: [0.60]}\n"
    "variants:\n  - {label: dem, method: dem}\n  - {label: continuum, method: continuum}\n";

static double final_front(gf_ctx *ctx, const char *run_dir)
{
    char path[400];
    snprintf(path, sizeof path, "%s/diagnostics.nc", run_dir);
    gf_ncr f;
    double *x = NULL, last = NAN;
    size_t n = 0;
    GF_CHECK_OK(gf_ncr_open(ctx, path, &f), ctx);
    GF_CHECK_OK(gf_ncr_var_1d(ctx, &f, "front_position", &x, &n), ctx);
    if (x && n > 0)
        last = x[n - 1];
    free(x);
    gf_ncr_close(&f);
    return last;
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_campaign *c = NULL;
    GF_CHECK_OK(gf_campaign_load_string(&ctx, "collapse_both.yaml", campaign_text, strlen(campaign_text), NULL, 0, &c),
                &ctx);
    if (!c)
        return gf_test_finish();
    char dir[] = "/tmp/gf_collapse_dem_XXXXXX";
    GF_CHECK(mkdtemp(dir) != NULL);
    double runout[2][2] = {{NAN, NAN}, {NAN, NAN}}; /* [a][dem, continuum] */
    for (int r = 0; r < c->n_runs; ++r) {
        const gf_run_spec *spec = &c->runs[r].spec;
        char run_dir[300];
        snprintf(run_dir, sizeof run_dir, "%s/%s", dir, spec->run_id);
        gf_run_exec_opts opt = {.run_dir = run_dir, .campaign = "collapse_both", .n_threads = 1};
        gf_run_result res;
        GF_CHECK_OK(gf_run_execute(&ctx, spec, &opt, &res), &ctx);
        GF_CHECK(res.status == GF_OK);
        double R0 = gf_run_spec_param(spec, "column_length_over_D", 16.0) * spec->grains.diameter_m;
        int ia = spec->aspect_ratio_a > 0.75, im = strcmp(spec->method, "continuum") == 0;
        runout[ia][im] = (final_front(&ctx, run_dir) - R0) / R0;
        printf("a = %.1f, %s: (R_inf - R0)/R0 = %.3f (%.0f s wall)\n", spec->aspect_ratio_a, spec->method,
               runout[ia][im], res.wall_s);
        fflush(stdout);
    }
    for (int ia = 0; ia < 2; ++ia) {
        printf("a = %.1f: continuum %.3f against DEM %.3f: %+.1f %% (criterion 5 %%)\n", ia ? 1.0 : 0.5,
               runout[ia][1], runout[ia][0], 100.0 * (runout[ia][1] / runout[ia][0] - 1.0));
        GF_CHECK_REL(runout[ia][1], runout[ia][0], 0.05);
    }
    char cmd[400];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    GF_CHECK(system(cmd) == 0);
    gf_campaign_destroy(&c);
    return gf_test_finish();
}
