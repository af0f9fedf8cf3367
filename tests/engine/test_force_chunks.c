/*
 * The force evaluation split into chunks (engine/sim/gf_forces.c): each
 * chunk adds into the store the forces on its rows and on partners inside
 * it, and into a buffer of its own those on partners in later chunks; after
 * a barrier the owner of each grain adds the earlier chunks' buffers over the
 * list's reach runs (engine/contact/gf_nlist.c). A partner left out of the
 * runs, or a buffer added twice, loses or doubles a whole contact force.
 *
 * Claims, on one settled frictional bed of 1200 grains (checkpointed once,
 * every sim restarted from it: same positions, velocities and contact
 * history), forces evaluated at that state with 2, 3, 4, 7 and 16 chunks
 * (at 16 a chunk is thinner than the contact range and also reaches beyond
 * its neighbour):
 *   - every partner a chunk's rows reach beyond the chunk lies in a reach
 *     run (the list's own bookkeeping);
 *   - every chunk boundary, and every end of a reach run, is a multiple of 8
 *     rows (a cache line of doubles);
 *   - the force and torque on every grain (matched by id) equal those of one
 *     chunk to round-off: within 1e-12 of the largest force (torque) on any
 *     grain; one contact left out or counted twice would be ~1e-2 of it
 *     (measured: 1e-16 to 4e-16; adding only the previous chunk's buffer
 *     gives 3.5 at 16 chunks).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact/gf_nlist.h"
#include "gf_test.h"
#include "gf_test_sim.h"

static gf_sim *from_checkpoint(gf_ctx *ctx, const gf_run_spec *spec, int chunks, const char *path)
{
    gf_sim *s = NULL;
    GF_CHECK_OK(gf_test_sim_restart(ctx, spec, chunks, path, &s), ctx);
    if (s)
        GF_CHECK_OK(gf_sim_evaluate_forces(s), ctx);
    return s;
}

/* Partners beyond each chunk that no reach run covers. */
static size_t partners_outside_runs(const gf_nlist *nl)
{
    char *in_run = calloc(nl->n, 1);
    for (size_t r = 0; r < nl->n_reach_runs; ++r)
        memset(in_run + nl->reach_run[2 * r], 1, nl->reach_run[2 * r + 1] - nl->reach_run[2 * r]);
    size_t missing = 0;
    for (int c = 0; c + 1 < nl->n_chunks; ++c) {
        size_t end = nl->chunk_row[c + 1];
        for (size_t k = nl->row_start[nl->chunk_row[c]]; k < nl->row_start[end]; ++k)
            missing += (size_t)nl->j[k] >= end && !in_run[nl->j[k]];
    }
    free(in_run);
    return missing;
}

/* Chunk boundaries and reach runs on cache lines of doubles (the end of the
 * store excepted). */
static int boundaries_on_lines(const gf_nlist *nl)
{
    for (int c = 1; c < nl->n_chunks; ++c)
        if (nl->chunk_row[c] % 8 != 0)
            return 0;
    for (size_t r = 0; r < 2 * nl->n_reach_runs; ++r)
        if (nl->reach_run[r] % 8 != 0 && nl->reach_run[r] != nl->n)
            return 0;
    return 1;
}

/* Largest difference of force (q = 0) or torque (q = 1) between two stores,
 * grains matched by id, relative to the largest value in the reference. */
static double largest_difference(const gf_particles *ref, const gf_particles *p, int q)
{
    const size_t n = ref->n_local;
    const double *const a[3] = {q ? ref->tx_N_m : ref->fx_N, q ? ref->ty_N_m : ref->fy_N, q ? ref->tz_N_m : ref->fz_N};
    const double *const b[3] = {q ? p->tx_N_m : p->fx_N, q ? p->ty_N_m : p->fy_N, q ? p->tz_N_m : p->fz_N};
    size_t *at = malloc(n * sizeof *at);
    for (size_t i = 0; i < n; ++i)
        at[p->id[i]] = i;
    double scale = 0.0, diff = 0.0;
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            scale = fmax(scale, fabs(a[c][i]));
            diff = fmax(diff, fabs(a[c][i] - b[c][at[ref->id[i]]]));
        }
    free(at);
    return diff / scale;
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_run_spec bed = gf_test_bed_spec(&ctx, 1200, 3.0); /* above the serial threshold: two threads really run */
    char path[512];
    snprintf(path, sizeof path, "%s/force_chunks_bed.h5", getenv("GF_BINARY_DIR") ? getenv("GF_BINARY_DIR") : "/tmp");
    gf_sim *s0 = NULL;
    GF_CHECK_OK(gf_test_sim(&ctx, &bed, 1, &s0), &ctx);
    if (!s0)
        return gf_test_finish();
    GF_CHECK_OK(gf_sim_checkpoint(s0, path), &ctx);
    gf_sim_destroy(&s0);
    gf_run_spec_set_param(&ctx, &bed, "settle_time_nd", 0.0); /* the checkpoint replaces the bed */

    gf_sim *one = from_checkpoint(&ctx, &bed, 1, path);
    if (!one)
        return gf_test_finish();
    size_t one_contacts;
    gf_sim_contact_stats(one, &one_contacts, NULL);
    printf("1 chunk: %zu grains, %zu contacts\n", gf_sim_particles(one)->n_local, one_contacts);
    const int chunks[] = {2, 3, 4, 7, 16};
    for (size_t k = 0; k < sizeof chunks / sizeof *chunks; ++k) {
        gf_sim *s = from_checkpoint(&ctx, &bed, chunks[k], path);
        if (!s)
            continue;
        const gf_nlist *nl = gf_sim_neighbour_list(s);
        size_t n_contacts;
        gf_sim_contact_stats(s, &n_contacts, NULL);
        size_t missing = partners_outside_runs(nl), reached = 0;
        for (size_t r = 0; r < nl->n_reach_runs; ++r)
            reached += nl->reach_run[2 * r + 1] - nl->reach_run[2 * r];
        double df = largest_difference(gf_sim_particles(one), gf_sim_particles(s), 0),
               dt = largest_difference(gf_sim_particles(one), gf_sim_particles(s), 1);
        printf("%d chunks: boundary rows", chunks[k]);
        for (int c = 1; c < nl->n_chunks; ++c)
            printf(" %zu", nl->chunk_row[c]);
        printf("; %zu reach runs over %zu grains; %zu contacts; force difference %.2e, torque %.2e (of the largest)\n",
               nl->n_reach_runs, reached, n_contacts, df, dt);
        gf_test_check(missing == 0, __FILE__, __LINE__, "%d chunks: every partner beyond a chunk in a reach run (%zu not)",
                      chunks[k], missing);
        gf_test_check(boundaries_on_lines(nl), __FILE__, __LINE__, "%d chunks: boundaries and reach runs on multiples of 8 rows",
                      chunks[k]);
        gf_test_check(n_contacts == one_contacts, __FILE__, __LINE__, "%d chunks: %zu contacts, one chunk %zu",
                      chunks[k], n_contacts, one_contacts);
        gf_test_check(df < 1e-12 && dt < 1e-12, __FILE__, __LINE__,
                      "%d chunks: forces %.2e and torques %.2e of the largest from one chunk's (< 1e-12)", chunks[k], df,
                      dt);
        gf_sim_destroy(&s);
    }
    gf_sim_destroy(&one);
    remove(path);
    return gf_test_finish();
}
