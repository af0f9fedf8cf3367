/*
 * The dry column collapse by both methods on the same columns (the campaign
 * configs/column_collapse_methods.yaml: R0 = 16 D, a = 0.5 and 1, mu_c 0.25;
 * the continuum at cell D/2 with this DEM's steady-chute law mu_s 0.280,
 * mu_2 0.703, I0 0.279). The DEM runs through gf_run_execute and the post
 * stage deposit, on five packing seeds: one column is one realisation, and
 * its run-out scatters by 0.06 R0 (a = 0.5) and 0.10 R0 (a = 1) from seed to
 * seed, more than the criterion; the continuum runs once, through
 * gf_continuum_collapse_run. Lagree, Staron & Popinet (JFM 686, 2011, §4)
 * reach a few per cent between their mu(I) continuum and contact dynamics;
 * the criterion here is 5 % against the DEM's five-seed mean on
 *   - the run-out (R_inf - R0)/R0, the front where the solid height falls to
 *     D/4 (the DEM scene's front_position, both methods): measured +3.0 %
 *     (a = 0.5) and -15.5 % (a = 1): NOT met at a = 1 (label open). The tip
 *     of the continuum's deposit is a layer under two cells thick whose
 *     extent falls as the cell shrinks, and at a = 1 the DEM ends in a layer
 *     one grain thick that the continuum does not carry;
 *   - the body of the deposit, (x_2D - R0)/R0 with x_2D the farthest x where
 *     the deposit is 2 D deep, so past any layer one grain thick (DEM: the
 *     deposit stage's surface profile, grain tops, bins of D; continuum:
 *     sum_j c h_y): -2.1 % (a = 0.5), -6.4 % (a = 1).
 * docs/continuum.md, "Column collapse", for the figures. About 6 min of CPU (slow).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "campaign/gf_campaign.h"
#include "continuum/gf_continuum_collapse.h"
#include "gf_ncread.h"
#include "gf_post.h"
#include "gf_test.h"
#include "gf_test_campaign.h"
#include "schedule/gf_run_exec.h"

static const char *campaign_text =
    "name: collapse_both\nseed: 1\nend_time: 40\n"
    "scene: {name: column_collapse, column_length_over_D: 16}\n"
    "grains: {diameter_m: 7.6e-3, polydispersity: 0.05, density_kg_m3: 2500}\n"
    "contact: {restitution: 0.87, friction: 0.25}\nfluid: {model: none}\n"
    "continuum: {mu_s: 0.280, mu_2: 0.703, I0: 0.279, cell_over_D: 0.5}\n"
    "output: {interval_nd: 1.0}\n"
    "grid: {a: [0.5, 1.0], Phi_i: [0.60]}\n"
    "variants:\n  - {label: dem1, method: dem, seed: 1}\n  - {label: dem2, method: dem, seed: 2}\n"
    "  - {label: dem3, method: dem, seed: 3}\n  - {label: dem4, method: dem, seed: 4}\n"
    "  - {label: dem5, method: dem, seed: 5}\n  - {label: continuum, method: continuum}\n";

enum { N_SEEDS = 5 };

/* Last value of a run file's 1-D variable; the whole variable in *all (owned) when all is not NULL. */
static double read_last(gf_ctx *ctx, const char *run_dir, const char *file, const char *var, double **all,
                        size_t *n)
{
    char path[400];
    snprintf(path, sizeof path, "%s/%s", run_dir, file);
    gf_ncr f;
    double *x = NULL, last = NAN;
    size_t nx = 0;
    if (gf_ncr_open(ctx, path, &f) != GF_OK) {
        GF_CHECK_OK(GF_ERR_IO, ctx);
        return NAN;
    }
    GF_CHECK_OK(gf_ncr_var_1d(ctx, &f, var, &x, &nx), ctx);
    if (x && nx > 0)
        last = x[nx - 1];
    gf_ncr_close(&f);
    if (all)
        *all = x, *n = nx;
    else
        free(x);
    return last;
}

/* Farthest x, contiguous from the back wall, where the DEM deposit's surface is at least depth high. */
static double dem_extent(gf_ctx *ctx, const char *run_dir, double depth)
{
    double *xb = NULL, *hb = NULL, x = NAN;
    size_t nb = 0, nh = 0;
    read_last(ctx, run_dir, "post_deposit.nc", "x_bin", &xb, &nb);
    read_last(ctx, run_dir, "post_deposit.nc", "deposit_height", &hb, &nh);
    if (xb && hb && nb == nh && nb > 1) {
        x = xb[nb - 1];
        for (size_t i = 1; i < nb; ++i)
            if (hb[i] < depth) {
                x = hb[i - 1] < depth ? xb[i - 1] : xb[i - 1] + (xb[i] - xb[i - 1]) * (hb[i - 1] - depth) / (hb[i - 1] - hb[i]);
                break;
            }
    }
    free(xb), free(hb);
    return x;
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_campaign *c = gf_test_campaign(&ctx, "collapse_both.yaml", campaign_text);
    if (!c)
        return gf_test_finish();
    char dir[] = "/tmp/gf_collapse_dem_XXXXXX";
    GF_CHECK(mkdtemp(dir) != NULL);
    /* [a][dem mean over the seeds, continuum] */
    double runout[2][2] = {{0.0, NAN}, {0.0, NAN}}, body[2][2] = {{0.0, NAN}, {0.0, NAN}};
    char dem_dir[2][N_SEEDS][400];
    int n_dem[2] = {0, 0};
    for (int r = 0; r < c->n_runs; ++r) {
        const gf_run_spec *spec = &c->runs[r].spec;
        double D = spec->grains.diameter_m, R0 = gf_run_spec_param(spec, "column_length_over_D", 16.0) * D;
        int ia = spec->aspect_ratio_a > 0.75;
        if (strcmp(spec->method, "continuum") == 0) {
            gf_continuum_collapse_result cr;
            GF_CHECK_OK(gf_continuum_collapse_run(&ctx, spec, NULL, NULL, NULL, &cr), &ctx);
            runout[ia][1] = (cr.front_m - R0) / R0;
            body[ia][1] = (cr.body_front_m - R0) / R0;
            continue;
        }
        GF_CHECK(n_dem[ia] < N_SEEDS);
        char *run_dir = dem_dir[ia][n_dem[ia]++];
        snprintf(run_dir, sizeof dem_dir[ia][0], "%s/collapse_both/%s", dir, spec->run_id);
        gf_run_exec_opts opt = {.run_dir = run_dir, .campaign = "collapse_both", .n_threads = 1};
        gf_run_result res;
        GF_CHECK_OK(gf_run_execute(&ctx, spec, &opt, &res), &ctx);
        GF_CHECK(res.status == GF_OK);
        double x = (read_last(&ctx, run_dir, "diagnostics.nc", "front_position", NULL, NULL) - R0) / R0;
        printf("DEM a = %.1f, seed %u: run-out %.3f\n", spec->aspect_ratio_a, (unsigned)spec->seed, x);
        runout[ia][0] += x / N_SEEDS;
    }
    char campaign_dir[300];
    snprintf(campaign_dir, sizeof campaign_dir, "%s/collapse_both", dir);
    gf_post_options po = {.stage = "deposit", .quiet = 1};
    GF_CHECK_OK(gf_post_campaign(&ctx, campaign_dir, &po), &ctx);
    for (int ia = 0; ia < 2; ++ia) {
        const gf_run_spec *spec = &c->runs[0].spec;
        double D = spec->grains.diameter_m, R0 = 16.0 * D;
        GF_CHECK(n_dem[ia] == N_SEEDS);
        for (int k = 0; k < n_dem[ia]; ++k)
            body[ia][0] += (dem_extent(&ctx, dem_dir[ia][k], 2.0 * D) - R0) / R0 / N_SEEDS;
        printf("a = %.1f: run-out continuum %.3f against the DEM's %d-seed mean %.3f (%+.1f %%); body (x_2D - R0)/R0 "
               "continuum %.3f against DEM %.3f (%+.1f %%); criterion 5 %%\n",
               ia ? 1.0 : 0.5, runout[ia][1], N_SEEDS, runout[ia][0], 100.0 * (runout[ia][1] / runout[ia][0] - 1.0),
               body[ia][1], body[ia][0], 100.0 * (body[ia][1] / body[ia][0] - 1.0));
        GF_CHECK_REL(body[ia][1], body[ia][0], 0.05);
        GF_CHECK_REL(runout[ia][1], runout[ia][0], 0.05);
    }
    GF_CHECK(gf_test_remove_tree(dir));
    gf_campaign_destroy(&c);
    return gf_test_finish();
}
