/*
 * A run's files do not depend on how gf_sim_run cut it into chunks.
 *
 * gf_sim_run advances in chunks sized by the wall clock (about 0.1 s each,
 * for progress lines and interrupts). The output instants, checkpoints and
 * the done() test of a scene that ends itself must fall on steps of the
 * clock, not on chunk ends: otherwise a record, or the last step, moves by a
 * step with the machine's load (seen on the demo: one record of a dry
 * collapse one step late when two runs shared the machine).
 *
 * Claim: a small dry column collapse that ends by done() (outputs every
 * 0.05 sqrt(D/g), instants whose accumulated time falls between steps) writes
 * bitwise the same diagnostics.nc and particles.nc with chunks of 1, 7 and 64
 * steps and with the adaptive chunks.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "gf_sim.h"
#include "gf_test.h"
#include "gf_test_files.h"

static const char *const diag_vars[] = {"time", "kinetic_energy", "front_position", "deposit_height", "n_contacts"};
static const char *const part_vars[] = {"time", "x", "y", "z", "u", "v", "w"};

static void run_into(const char *dir, int chunk_steps, long *steps)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    gf_run_spec_defaults(&spec);
    snprintf(spec.scene, sizeof spec.scene, "column_collapse");
    snprintf(spec.fluid.model, sizeof spec.fluid.model, "none");
    spec.grains.diameter_m = 0.01;
    spec.grains.polydispersity = 0.10;
    spec.grains.density_kg_m3 = 2500.0;
    spec.contact.t_contact_nd = 0.02;
    spec.contact.restitution = 0.5;
    spec.contact.friction = spec.contact.wall_friction = 0.5;
    spec.end_time_nd = 30.0; /* done() ends it first */
    spec.output.interval_nd = 0.05;
    spec.output.particles = spec.output.diagnostics = 1;
    spec.output.fields = spec.output.probes = 0;
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "column_length_over_D", 6.0), &ctx);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "aspect_ratio", 1.0), &ctx);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "settle_time_nd", 1.0), &ctx);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "rest_energy", 1e-3), &ctx);
    gf_sim_options opt = {.output_dir = dir, .n_threads = 1, .tuning.chunk_steps = chunk_steps};
    gf_sim *sim = NULL;
    GF_CHECK_OK(gf_sim_create(&ctx, &spec, &opt, &sim), &ctx);
    if (sim) {
        GF_CHECK_OK(gf_sim_run(sim), &ctx);
        *steps = gf_sim_step_count(sim);
    }
    gf_sim_destroy(&sim);
}

static void same_file(const char *ref_dir, const char *dir, const char *file, const char *const *vars, int n_vars,
                      int chunk_steps)
{
    char a[700], b[700];
    snprintf(a, sizeof a, "%s/%s", ref_dir, file);
    snprintf(b, sizeof b, "%s/%s", dir, file);
    for (int k = 0; k < n_vars; ++k) {
        size_t na = 0, nb = 0;
        double *x = gf_test_nc_read(a, vars[k], &na), *y = gf_test_nc_read(b, vars[k], &nb);
        int same = x && y && na == nb && memcmp(x, y, na * sizeof *x) == 0;
        gf_test_check(same, __FILE__, __LINE__, "%s %s: %zu / %zu values, chunks of %d steps against 1", file,
                      vars[k], na, nb, chunk_steps);
        free(x), free(y);
    }
}

int main(void)
{
    char root[] = "/tmp/gf_chunking_XXXXXX";
    GF_CHECK(mkdtemp(root) != NULL);
    const int chunks[] = {1, 7, 64, 0};
    char ref[600];
    long ref_steps = 0;
    for (size_t c = 0; c < sizeof chunks / sizeof chunks[0]; ++c) {
        char dir[600];
        snprintf(dir, sizeof dir, "%s/chunk%d", root, chunks[c]);
        long steps = 0;
        GF_CHECK(mkdir(dir, 0777) == 0);
        run_into(dir, chunks[c], &steps);
        printf("chunks of %d steps (0: adaptive): %ld steps\n", chunks[c], steps);
        GF_CHECK(steps > 0 && steps < 75000); /* ended by done(), before end_time */
        if (c == 0) {
            snprintf(ref, sizeof ref, "%s", dir);
            ref_steps = steps;
            continue;
        }
        GF_CHECK(steps == ref_steps);
        same_file(ref, dir, "diagnostics.nc", diag_vars, 5, chunks[c]);
        same_file(ref, dir, "particles.nc", part_vars, 7, chunks[c]);
    }
    GF_CHECK(gf_test_remove_tree(root));
    return gf_test_finish();
}
