/*
 * Lab notebook — post-processing of one tiny real run made by the engine
 * (label slow: about 3 minutes on one core).
 *
 * `grainflow campaign` runs one dry column collapse: glass beads D = 7.6 mm,
 * R0 = 6 D, a = H0/R0 = 1, Phi_i = 0.60, width 3 D periodic, 20 sqrt(D/g).
 * gf_post_campaign then runs every stage on its netCDF files. Checks against
 * physics that does not depend on this code:
 *   - normalised runout (R_inf − R0)/R0 inside the band of the dry planar
 *     laws for a < 1.8: Lube et al. 2005, 1.2 a, to Lajeunesse et al. 2005,
 *     1.8 a, widened by their ~15 % scatter: [1.02, 2.07] at a = 1;
 *   - the heap is no higher than the column: H_inf <= H0 + D/2, and at
 *     a = 1 most of the height is kept (H_inf > H0/2);
 *   - the front-from-grains end position agrees with the engine's
 *     diagnostics front_position within 1.5 D (two definitions of the toe:
 *     the stage follows the chain of grains from the wall, gaps < D/2; the
 *     engine counts D-bins holding at least D/4 of solid height, so a trail
 *     of single grains ahead of the heap counts for the stage only). Run on
 *     one thread (ctest sets OMP_NUM_THREADS=1): the collapse is chaotic and
 *     its 162 grains leave a trail whose length changes with the summation
 *     order; measured, engine / stage: 13.00 / 14.35 D on one thread, 12.00 /
 *     15.35 D on two (three single grains strung over 3 D).
 *   - a dry run is labelled free fall (T_v = T_i = 0);
 *   - the peak of E_cx comes before the front stops.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_ncread.h"
#include "gf_post.h"
#include "gf_post_synth.h"
#include "gf_summary.h"
#include "gf_test.h"

int main(void)
{
    const char *bin = getenv("GF_BINARY_DIR");
    char dir[1024], yaml[1100], cmd[3000];
    synth_scratch(dir, sizeof dir, "real_run");
    snprintf(yaml, sizeof yaml, "%s/tiny.yaml", dir);
    FILE *f = fopen(yaml, "w");
    GF_CHECK(f != NULL);
    if (!f)
        return gf_test_finish();
    fputs("name: tiny\nseed: 1\nend_time: 20\nscene:\n  name: column_collapse\n  column_length_over_D: 6\n"
          "  width_over_D: 3\ngrains:\n  diameter_m: 7.6e-3\n  polydispersity: 0.05\n  density_kg_m3: 2500\n"
          "output:\n  interval_nd: 1.0\ngrid:\n  a: [1.0]\n  Phi_i: [0.60]\n  combine: product\n",
          f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "nice %s/grainflow campaign %s -o %s --jobs 1 --no-post", bin ? bin : ".", yaml, dir);
    const int rc = system(cmd);
    gf_test_check(rc == 0, __FILE__, __LINE__, "%s -> %d", cmd, rc);
    char camp[1200];
    snprintf(camp, sizeof camp, "%s/tiny", dir);
    gf_ctx ctx = {0};
    gf_post_options opt = {NULL, 1, 1, 0};
    GF_CHECK_OK(gf_post_campaign(&ctx, camp, &opt), &ctx);
    char p[1300];
    snprintf(p, sizeof p, "%s/summary.nc", camp);
    gf_post_row *rows = NULL;
    int n = 0;
    GF_CHECK_OK(gf_summary_read(&ctx, p, &rows, &n), &ctx);
    GF_CHECK(n == 1);
    if (n >= 1) {
        const gf_post_row *r = &rows[0];
        const double D = 7.6e-3, R0 = 6 * D, H0 = R0;
        const double ro = gf_post_row_get(r, "runout_norm"), H = gf_post_row_get(r, "H_inf_m");
        const double Rinf = gf_post_row_get(r, "R_inf_m");
        printf("run %s: status %s; R_inf = %.2f D, (R_inf-R0)/R0 = %.3f (dry laws 1.2-1.8), H_inf/H0 = %.3f, "
               "shape %s, flank %.1f deg, t_rest = %.3f s, Ecx_max/(mgD) = %.3f at %.3f s, regime %s\n",
               r->run_id, r->status, Rinf / D, ro, H / H0, gf_post_row_get_text(r, "deposit_shape"),
               gf_post_row_get(r, "flank_angle_deg"), gf_post_row_get(r, "t_rest_s"),
               gf_post_row_get(r, "Ecx_max_over_mgD"), gf_post_row_get(r, "t_Ecx_max_s"),
               gf_post_row_get_text(r, "regime"));
        GF_CHECK(strcmp(r->status, "ok") == 0);
        GF_CHECK(ro >= 1.2 * 0.85 && ro <= 1.8 * 1.15);
        GF_CHECK(H <= H0 + 0.5 * D && H > 0.5 * H0);
        GF_CHECK(gf_post_row_get(r, "t_Ecx_max_s") < gf_post_row_get(r, "t_rest_s"));
        const char *reg = gf_post_row_get_text(r, "regime");
        GF_CHECK(reg && strcmp(reg, "free-fall") == 0);
        /* the engine's own front at the last record */
        char dp[1400];
        snprintf(dp, sizeof dp, "%s/diagnostics.nc", r->run_dir);
        gf_ncr nc;
        double *xf = NULL;
        size_t m = 0;
        if (gf_ncr_open(&ctx, dp, &nc) == GF_OK) {
            if (gf_ncr_var_1d(&ctx, &nc, "front_position", &xf, &m) == GF_OK && m > 0) {
                printf("engine front_position at the end %.2f D, stage deposit %.2f D\n", xf[m - 1] / D, Rinf / D);
                GF_CHECK_ABS(xf[m - 1], Rinf, 1.5 * D);
            }
            gf_ncr_close(&nc);
        }
        GF_CHECK(m > 0);
        free(xf);
    }
    free(rows);
    return gf_test_finish();
}
