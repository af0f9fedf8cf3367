/*
 * A campaign's runs share their packed columns (docs/campaigns.md, "Shared
 * preparations"), end to end through the scheduler.
 *
 * Three small dry collapses: two differ only in the restitution (same
 * column), the third asks for another Phi_i. The columns are 8 D x 8 D: at
 * a = 0.5 the preparation's interior control box would be half a grain tall,
 * too few grains for Phi_i within 0.005, and the runs would be refused. Run
 * in order by one worker:
 * - the campaign's preparations/ holds two deposits, not three;
 * - the second run, which read the first run's column back, writes the same
 *   particles.nc (positions and velocities at every output instant, bit for
 *   bit) as the same run alone in an empty directory, which built it.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "campaign/gf_campaign.h"
#include "gf_test.h"
#include "gf_test_campaign.h"
#include "gf_test_files.h"
#include "schedule/gf_ledger.h"
#include "schedule/gf_sched.h"

static const char campaign_text[] =
    "name: shared_prep\n"
    "end_time: 1\n"
    "scene: {name: column_collapse, aspect_ratio: 1, column_length_over_D: 8, phi_target: 0.58,\n"
    "        settle_time_nd: 1}\n"
    "grains: {diameter_m: 7.6e-3, density_kg_m3: 2500}\n"
    "output: {interval_nd: 0.5, fields: false, probes: false}\n"
    "variants:\n"
    "  - {label: bouncy, contact.restitution: 0.9}\n"
    "  - {label: dull, contact.restitution: 0.5}\n"
    "  - {label: looser, scene.phi_target: 0.56}\n";

/* Variable name of particles.nc in run directory dir, whole; NULL when unreadable. */
static double *read_var(const char *dir, const char *name, size_t *n)
{
    char path[4300];
    snprintf(path, sizeof path, "%s/particles.nc", dir);
    return gf_test_nc_read(path, name, n);
}

/* The campaign's runs (the n_selected of selected; NULL: all) scheduled into out, one worker (checked). */
static gf_sched_counts run_into(gf_ctx *ctx, const gf_campaign *c, const char *out, const int *selected, int n_selected)
{
    gf_sched_opts opt = {.out_dir = out, .n_jobs = 1, .quiet = 1, .selected = selected, .n_selected = n_selected};
    gf_sched_counts n = {0};
    GF_CHECK_OK(gf_sched_run(ctx, c, &opt, &n), ctx);
    return n;
}

int main(void)
{
    char shared[] = "/tmp/gf_shared_prep_XXXXXX", alone[] = "/tmp/gf_alone_prep_XXXXXX";
    GF_CHECK(mkdtemp(shared) != NULL && mkdtemp(alone) != NULL);
    gf_ctx ctx = {0};
    gf_campaign *c = gf_test_campaign(&ctx, "shared.yaml", campaign_text);
    if (!c)
        return gf_test_finish();
    gf_sched_counts n = run_into(&ctx, c, shared, NULL, 0);
    GF_CHECK(n.n_total == 3 && n.n_done == 3);
    char prep[4300];
    snprintf(prep, sizeof prep, "%s/%s/preparations", shared, c->name);
    char pattern[4400];
    snprintf(pattern, sizeof pattern, "%s/*.h5", prep);
    size_t n_files = gf_test_count_files(pattern);
    gf_test_check(n_files == 2, __FILE__, __LINE__, "%zu deposits kept for 3 runs over 2 columns", n_files);

    const int only_dull[] = {1};
    n = run_into(&ctx, c, alone, only_dull, 1);
    GF_CHECK(n.n_done == 1);

    char dir_shared[4200], dir_alone[4200];
    gf_ledger_run_dir(shared, c->name, c->runs[1].spec.run_id, dir_shared, sizeof dir_shared);
    gf_ledger_run_dir(alone, c->name, c->runs[1].spec.run_id, dir_alone, sizeof dir_alone);
    static const char *vars[] = {"x", "y", "z", "u", "v", "w", "radius"};
    for (size_t k = 0; k < sizeof vars / sizeof vars[0]; ++k) {
        size_t na = 0, nb = 0;
        double *a = read_var(dir_shared, vars[k], &na), *b = read_var(dir_alone, vars[k], &nb);
        int same = a && b && na == nb && na > 1 && memcmp(a, b, na * sizeof *a) == 0;
        gf_test_check(same, __FILE__, __LINE__, "particles.nc %s: %zu values, read-back column against built one",
                      vars[k], na);
        free(a), free(b);
    }
    gf_campaign_destroy(&c);
    GF_CHECK(gf_test_remove_tree(shared) && gf_test_remove_tree(alone));
    return gf_test_finish();
}
