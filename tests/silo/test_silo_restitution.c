/*
 * Row 11 of Djouwe Meffeja (2012) §3.4.4 (Figs. 3.11-3.12), slow: the
 * discharge rate Q and the packing over the orifice phi_out both fall as the
 * normal restitution e_n rises, and Q is linear in phi_out (R^2 > 0.9).
 *
 * The effect is small (Q falls 8 % from e_n = 0.1 to 0.95, phi_out by
 * 0.009) and phi_out's own noise over a window of 600 sqrt(d/g) is 0.0012,
 * so the study is run as docs/silo.md gives it: the campaign
 * configs/silo_restitution.yaml (read from GF_SOURCE_DIR) in the 15 d silo (6 d orifice, whose Q is the
 * thesis silo's), 600 sqrt(d/g) of discharge a run, drawn with seeds 1, 2
 * and 3 (18 runs, about 4.2 CPU-h), through the scheduler and
 * `grainflow post`, whose fits go through one point per e_n, the mean of
 * its three seeds (gf_post_replicates.h). Checks on those points: Q and
 * phi_out decrease at every step of e_n; the summary's Q_phi_R2 > 0.9; each
 * point pools three runs.
 *
 * GF_TEST_RUNS=DIR keeps the runs in DIR (and reuses those already done
 * there, as `grainflow campaign --resume` does); GF_TEST_JOBS=N runs N at a
 * time (default 2). Without GF_TEST_RUNS the runs go to a temporary
 * directory, removed when every check passes.
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

/* docs/silo.md's command: configs/silo_restitution.yaml in the 15 d silo over 600 sqrt(d/g), once per seed */
static const char *const docs_sets[] = {"scene.width_x_over_d=15",        "scene.width_z_over_d=15",
                                        "scene.height_over_d=30",         "scene.fill_height_over_d=15",
                                        "scene.reinject_height_over_d=25", "end_time=600",
                                        NULL /* seed=N */};
enum { N_SETS = sizeof docs_sets / sizeof docs_sets[0] };

enum { N_EN = 6, N_SEEDS = 3 };
static const double e_n[N_EN] = {0.1, 0.3, 0.5, 0.7, 0.885, 0.95};

static int e_index(double e)
{
    for (int k = 0; k < N_EN; ++k)
        if (fabs(e - e_n[k]) < 1e-9)
            return k;
    return -1;
}

/* Adds each run's Q and phi_out over N_SEEDS to its e_n's point, from the summary's rows. */
static void add_points(const gf_campaign *c, const gf_post_row *rows, int n_rows, double *Q, double *phi, int *count)
{
    for (int r = 0; r < c->n_runs; ++r) {
        const gf_run_spec *s = &c->runs[r].spec;
        const int k = e_index(s->contact.restitution);
        const gf_post_row *row = gf_summary_find(rows, n_rows, s->run_id);
        GF_CHECK(k >= 0 && row != NULL);
        if (k < 0 || !row)
            continue;
        Q[k] += gf_post_row_get(row, "silo_Q") / N_SEEDS;
        phi[k] += gf_post_row_get(row, "silo_phi_out") / N_SEEDS;
        ++count[k];
        GF_CHECK_ABS(gf_post_row_get(row, "silo_replicates"), N_SEEDS, 0.0);
    }
}

/* The study with seed `seed`, as `grainflow campaign ... --set seed=N --resume` runs it; NULL when refused. */
static gf_campaign *study(gf_ctx *ctx, const char *src, int seed)
{
    char path[1100], seed_set[32];
    const char *sets[N_SETS];
    snprintf(path, sizeof path, "%s/configs/silo_restitution.yaml", src);
    snprintf(seed_set, sizeof seed_set, "seed=%d", seed);
    for (int k = 0; k + 1 < N_SETS; ++k)
        sets[k] = docs_sets[k];
    sets[N_SETS - 1] = seed_set;
    gf_campaign *c = NULL;
    GF_CHECK_OK(gf_campaign_load_file(ctx, path, sets, N_SETS, &c), ctx);
    return c;
}

int main(void)
{
    gf_ctx ctx = {0};
    const char *src = getenv("GF_SOURCE_DIR");
    gf_campaign *c[N_SEEDS] = {NULL};
    for (int k = 0; k < N_SEEDS; ++k)
        if (!(c[k] = study(&ctx, src ? src : ".", k + 1)))
            return gf_test_finish();
    char tmp[] = "/tmp/gf_silo_restitution_XXXXXX";
    const char *out = gf_test_runs_dir(tmp);
    for (int k = 0; k < N_SEEDS; ++k)
        gf_test_run_campaign(&ctx, c[k], out);
    gf_post_row *rows;
    int n_rows;
    gf_test_post_summary(&ctx, out, c[0]->name, 0, &rows, &n_rows);
    double Q[N_EN] = {0}, phi[N_EN] = {0};
    int count[N_EN] = {0};
    for (int k = 0; rows && k < N_SEEDS; ++k)
        add_points(c[k], rows, n_rows, Q, phi, count);
    int q_down = 1, phi_down = 1;
    for (int k = 0; k < N_EN; ++k) {
        printf("e_n %.3f: Q %.1f grains/s, phi_out %.4f (mean of %d seeds)\n", e_n[k], Q[k], phi[k], count[k]);
        GF_CHECK(count[k] == N_SEEDS);
        if (k > 0)
            q_down &= Q[k] < Q[k - 1], phi_down &= phi[k] < phi[k - 1];
    }
    const double R2 = rows && n_rows > 0 ? gf_post_row_get(&rows[0], "Q_phi_R2") : NAN;
    printf("Q decreasing %s, phi_out decreasing %s; line Q sqrt(d/g) against phi_out: slope %.1f, R^2 %.4f "
           "(row 11: > 0.9)\n",
           q_down ? "yes" : "no", phi_down ? "yes" : "no", rows ? gf_post_row_get(&rows[0], "Q_phi_slope") : NAN, R2);
    GF_CHECK(q_down);
    GF_CHECK(phi_down);
    GF_CHECK(R2 > 0.9);
    free(rows);
    for (int k = 0; k < N_SEEDS; ++k)
        gf_campaign_destroy(&c[k]);
    return out == tmp ? gf_test_finish_removing(tmp) : gf_test_finish();
}
