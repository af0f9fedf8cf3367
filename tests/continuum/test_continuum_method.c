/*
 * method: dem | continuum. One campaign file runs the column collapse with
 * grains or with the continuum mu(I) solver (engine/continuum/
 * gf_continuum_collapse.h). Checks: the continuum's bad input is refused at
 * load with file:line:column (mu_2 <= mu_s, I0 <= 0, a scene with no continuum
 * form); `method: dem` leaves the run id of a file without the key unchanged;
 * a small continuum collapse (R0 = 16 D, a = 0.5, cell D, 25 sqrt(D/g)) runs
 * through gf_run_execute, writes diagnostics.nc, conserves the column's
 * volume to 1e-3 and spreads: the front advances past R0 while the height at
 * the back wall stays at H0 within one cell (a = 0.5 leaves a trapezoid,
 * Lajeunesse et al. 2005). The avalanche scene by the continuum (bed 12 D at
 * 25 deg, cell D/2, 300 sqrt(D/g)) writes the DEM scene's grain_flow_rate, whose
 * last sample is W phi times the Bagnold flux within 1 % (the grid's error is 0.5 %,
 * test_continuum_avalanche).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "campaign/gf_campaign.h"
#include "continuum/gf_continuum_collapse.h"
#include "continuum/gf_mui_oracles.h"
#include "gf_ncread.h"
#include "gf_test.h"
#include "gf_test_campaign.h"
#include "schedule/gf_run_exec.h"

static void refused(const char *text, const char *want)
{
    gf_ctx ctx = {0};
    gf_campaign *c = NULL;
    gf_status st = gf_campaign_load_string(&ctx, "t.yaml", text, strlen(text), NULL, 0, &c);
    gf_test_check(st == GF_ERR_CONFIG, __FILE__, __LINE__, "status %s (%s)", gf_status_str(st), ctx.last_msg);
    gf_test_check(strncmp(ctx.last_msg, want, strlen(want)) == 0, __FILE__, __LINE__, "got:  %s\nwant: %s...",
                  ctx.last_msg, want);
    gf_campaign_destroy(&c);
}

static void refusals(void)
{
    refused("method: continuum\nscene: {name: column_collapse}\ncontinuum:\n  mu_s: 0.5\n  mu_2: 0.4\n",
            "t.yaml:5:9: continuum: mu_2 must be > mu_s (got mu_2 = 0.4, mu_s = 0.5)");
    refused("method: continuum\nscene: {name: column_collapse}\ncontinuum: {I0: 0}\n",
            "t.yaml:3:17: I0 = 0 is out of range: must be > 0");
    refused("method: continuum\nscene: {name: binary_collision}\n",
            "t.yaml:1:9: method: continuum runs the scenes column_collapse and avalanche only (got binary_collision)");
}

static void run_id_unchanged(void)
{
    const char *a = "scene: {name: column_collapse}\n", *b = "method: dem\nscene: {name: column_collapse}\n",
               *c = "method: continuum\nscene: {name: column_collapse}\n";
    gf_ctx ctx = {0};
    gf_campaign *ca = gf_test_campaign(&ctx, "a.yaml", a), *cb = gf_test_campaign(&ctx, "b.yaml", b),
                *cc = gf_test_campaign(&ctx, "c.yaml", c);
    if (ca && cb && cc) {
        GF_CHECK(strcmp(ca->runs[0].spec.run_id, cb->runs[0].spec.run_id) == 0);
        GF_CHECK(strcmp(ca->runs[0].spec.run_id, cc->runs[0].spec.run_id) != 0);
    }
    gf_campaign_destroy(&ca), gf_campaign_destroy(&cb), gf_campaign_destroy(&cc);
}

/* Loads the one-run campaign text and runs it through the campaign path into
 * a fresh temporary folder (m->dir, removed by run_done); 0 when the text does not load. */
typedef struct method_run {
    gf_campaign *campaign;
    char dir[64], run_dir[256];
    gf_run_result res;
} method_run;

static int run_text(gf_ctx *ctx, const char *name, const char *text, method_run *m)
{
    m->campaign = gf_test_campaign(ctx, name, text);
    if (!m->campaign)
        return 0;
    snprintf(m->dir, sizeof m->dir, "/tmp/gf_continuum_method_XXXXXX");
    GF_CHECK(mkdtemp(m->dir) != NULL);
    snprintf(m->run_dir, sizeof m->run_dir, "%s/run", m->dir);
    gf_run_exec_opts opt = {.run_dir = m->run_dir, .campaign = name};
    GF_CHECK_OK(gf_run_execute(ctx, &m->campaign->runs[0].spec, &opt, &m->res), ctx);
    GF_CHECK(m->res.status == GF_OK);
    return 1;
}

static void run_done(method_run *m)
{
    GF_CHECK(gf_test_remove_tree(m->dir));
    gf_campaign_destroy(&m->campaign);
}

/* R0 = 16 D, a = 0.5, cell D, 25 sqrt(D/g): the volume kept, the front past R0, the back wall's height H0. */
static const char *const small_collapse_text =
    "method: continuum\nend_time: 25\n"
    "scene: {name: column_collapse, column_length_over_D: 16, aspect_ratio: 0.5}\n"
    "grains: {diameter_m: 0.01, density_kg_m3: 2500}\ncontinuum: {cell_over_D: 1.0}\n";

static void small_collapse(gf_ctx *ctx, const method_run *m)
{
    char path[300];
    snprintf(path, sizeof path, "%s/diagnostics.nc", m->run_dir);
    GF_CHECK(access(path, R_OK) == 0);
    gf_continuum_collapse_result r;
    GF_CHECK_OK(gf_continuum_collapse_run(ctx, &m->campaign->runs[0].spec, NULL, NULL, NULL, &r), ctx);
    double D = 0.01, R0 = r.column_length_m, H0 = r.column_height_m;
    printf("continuum collapse R0 = 16 D, a = 0.5, cell D: (R - R0)/R0 = %.3f, H(back wall)/H0 = %.3f, volume drift "
           "%.2e, %ld steps to t = %.2f s\n",
           (r.front_m - R0) / R0, r.height_m / H0, r.mass_drift, r.steps, r.time_s);
    GF_CHECK(fabs(r.mass_drift) < 1e-3);
    GF_CHECK(r.front_m > R0 + D);
    GF_CHECK_ABS(r.height_m, H0, D);
    /* the extents the DEM scene writes too: at t = 0 the step of the column read between the centres of
     * its last cell and the next, R0 + D/2 - D depth/H0 (cell D); at the end, deeper is shorter */
    gf_ncr f;
    double *e1 = NULL, *e2 = NULL, *xf = NULL;
    size_t n1 = 0, n2 = 0, nf = 0;
    GF_CHECK_OK(gf_ncr_open(ctx, path, &f), ctx);
    GF_CHECK_OK(gf_ncr_var_1d(ctx, &f, "deposit_extent_1D", &e1, &n1), ctx);
    GF_CHECK_OK(gf_ncr_var_1d(ctx, &f, "deposit_extent_2D", &e2, &n2), ctx);
    GF_CHECK_OK(gf_ncr_var_1d(ctx, &f, "front_position", &xf, &nf), ctx);
    gf_ncr_close(&f);
    if (n1 > 1 && n1 == n2 && n1 == nf) {
        GF_CHECK_ABS(e1[0], R0 + 0.5 * D - D * D / H0, 1e-9 * D);
        GF_CHECK_ABS(e2[0], R0 + 0.5 * D - 2.0 * D * D / H0, 1e-9 * D);
        printf("extents at the end: (x - R0)/R0 = %.3f (1 D deep), %.3f (2 D), front %.3f\n", (e1[n1 - 1] - R0) / R0,
               (e2[n1 - 1] - R0) / R0, (xf[n1 - 1] - R0) / R0);
        GF_CHECK(e2[n1 - 1] < e1[n1 - 1] && e1[n1 - 1] < xf[n1 - 1] && e1[n1 - 1] > R0);
    } else {
        GF_CHECK(!"deposit_extent_1D, _2D and front_position: same length, two records at least");
    }
    free(e1), free(e2), free(xf);
}

static double last_flow_rate(gf_ctx *ctx, const char *run_dir)
{
    char path[300];
    snprintf(path, sizeof path, "%s/diagnostics.nc", run_dir);
    gf_ncr f;
    double *q = NULL, last = NAN;
    size_t n = 0;
    GF_CHECK_OK(gf_ncr_open(ctx, path, &f), ctx);
    GF_CHECK_OK(gf_ncr_var_1d(ctx, &f, "grain_flow_rate", &q, &n), ctx);
    if (q && n > 0)
        last = q[n - 1];
    free(q);
    gf_ncr_close(&f);
    return last;
}

/* Bed 12 D at 25 deg, cell D/2, 300 sqrt(D/g): the last flow rate is W phi times the Bagnold flux. */
static const char *const small_avalanche_text =
    "method: continuum\nend_time: 300\n"
    "scene: {name: avalanche, incline_deg: 25, bed_height_over_D: 12, width_over_D: 6}\n"
    "grains: {diameter_m: 0.005, density_kg_m3: 2500}\n"
    "continuum: {mu_s: 0.280, mu_2: 0.703, I0: 0.3, phi: 0.6, cell_over_D: 0.5}\n";

static void small_avalanche(gf_ctx *ctx, const method_run *m)
{
    double D = 0.005, g = m->campaign->runs[0].spec.gravity_m_s2, W = 6.0 * D, phi = 0.6;
    gf_bagnold b = {.law = {.mu_s = 0.280, .mu_2 = 0.703, .I0 = 0.3}, .theta_rad = 25.0 * M_PI / 180.0, .phi = phi,
                    .g_m_s2 = g, .d_m = D, .h_m = 12.0 * D};
    double q = last_flow_rate(ctx, m->run_dir), q_exact = W * phi * gf_bagnold_flux(&b);
    printf("continuum avalanche 25 deg, h = 12 D, cell D/2: Q_g = %.5e m3/s at t = 300 sqrt(D/g), Bagnold %.5e "
           "(%+.2f %%), %ld steps\n",
           q, q_exact, 100.0 * (q / q_exact - 1.0), m->res.steps);
    GF_CHECK_REL(q, q_exact, 1e-2);
}

/* The campaign text run through the campaign path (run_text), checked by check, its folder removed. */
static void run_and_check(const char *name, const char *text, void (*check)(gf_ctx *ctx, const method_run *m))
{
    gf_ctx ctx = {0};
    method_run m;
    if (!run_text(&ctx, name, text, &m))
        return;
    check(&ctx, &m);
    run_done(&m);
}

int main(void)
{
    refusals();
    run_id_unchanged();
    run_and_check("s", small_collapse_text, small_collapse);
    run_and_check("v", small_avalanche_text, small_avalanche);
    return gf_test_finish();
}
