/*
 * The spatial sort of the store, with two threads, makes the cut between the
 * two threads' chunks a plane (engine/sim/gf_sort.c): layers of cells across
 * the axis of smallest cross-section, Morton order within a layer.
 *
 * What matters for speed on two cores is how many grains of the second chunk
 * the first chunk's rows read (they are written by the other core at every
 * step) and how many cache lines they span. Claims, on settled beds of 2000
 * grains, one tall and narrow (footprint 6 D: the cut goes across the
 * height, one plane) and one wide and flat (footprint 24 D: across a
 * periodic horizontal axis, two planes):
 *   - the grains of chunk 1 reached from chunk 0 are no more than those
 *     reached across the same split of the single-thread (3-D Morton) order
 *     (measured: 34 against 47 for the tall bed, 114 against 179 for the
 *     flat one);
 *   - they lie together: in each per-grain array of doubles they occupy at
 *     most 0.6 times the 64-byte cache lines they occupy in Morton order
 *     (measured: 7 against 13 lines, 30 against 86);
 *   - the sort reorders without losing a grain (ids a permutation).
 * Measured figures on the 1e4 benchmark bed: docs/notes/benchmarks.md, "Two cores:
 * the cut between the chunks".
 *
 * A store sorted on one thread and continued from its checkpoint on two is
 * sorted into the two-thread order at once (gf_sim_checkpoint.c,
 * resort_for_threads): the same bound on the cache lines across the cut
 * holds right after the restart (and fails when sorting is off, the store
 * kept in Morton order), and the continuation follows the one-thread run
 * grain by grain to round-off (contact history carried over by ids), dry
 * and immersed (the held fluid forces are keyed by ids too).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "contact/gf_nlist.h"
#include "gf_test.h"
#include "gf_test_sim.h"

typedef struct cut_reach {
    size_t split;      /* first row of chunk 1 */
    size_t grains;     /* distinct grains >= split that rows < split pair with */
    size_t lines;      /* cache lines those grains occupy in one per-grain array of doubles */
} cut_reach;

static cut_reach reach_across(const gf_sim *s, size_t split)
{
    const gf_nlist *nl = gf_sim_neighbour_list(s);
    cut_reach r = {split, 0, 0};
    char *seen = calloc(nl->n, 1), *line = calloc(nl->n / 8 + 1, 1); /* 8 doubles a 64-byte line */
    for (size_t k = 0; k < nl->row_start[split]; ++k) {
        size_t j = (size_t)nl->j[k];
        if (j < split || seen[j])
            continue;
        seen[j] = 1, r.grains++;
        r.lines += !line[j / 8];
        line[j / 8] = 1;
    }
    free(seen), free(line);
    return r;
}

static int ids_are_permutation(const gf_particles *p)
{
    size_t n = p->n_local;
    char *seen = calloc(n, 1);
    int ok = 1;
    for (size_t i = 0; i < n && ok; ++i) {
        int64_t id = p->id[i];
        ok = id >= 0 && (size_t)id < n && !seen[id];
        if (ok)
            seen[id] = 1;
    }
    free(seen);
    return ok;
}

static gf_sim *sorted_bed(gf_ctx *ctx, const gf_run_spec *spec, int threads)
{
    gf_sim *s = NULL;
    GF_CHECK_OK(gf_test_sim(ctx, spec, threads, &s), ctx);
    if (s)
        GF_CHECK_OK(gf_sim_sort(s), ctx);
    return s;
}

static void check_bed(gf_ctx *ctx, const char *what, double width_over_D)
{
    gf_run_spec bed = gf_test_bed_spec(ctx, 2000, 1.0);
    gf_run_spec_set_param(ctx, &bed, "width_over_D", width_over_D);
    gf_sim *morton = sorted_bed(ctx, &bed, 1), *slab = sorted_bed(ctx, &bed, 2);
    if (!morton || !slab) {
        gf_sim_destroy(&morton), gf_sim_destroy(&slab);
        return;
    }
    /* the same split for both orders: the two-thread list's chunk boundary */
    size_t split = gf_sim_neighbour_list(slab)->chunk_row[1];
    cut_reach m = reach_across(morton, split), c = reach_across(slab, split);
    printf("%s: split at %zu of %zu; chunk 1 grains read from chunk 0: Morton %zu on %zu lines, layers %zu on %zu "
           "lines\n", what, split, gf_sim_neighbour_list(slab)->n, m.grains, m.lines, c.grains, c.lines);
    gf_test_check(c.grains > 0 && c.grains <= m.grains, __FILE__, __LINE__,
                  "%s: grains across the cut %zu <= Morton's %zu", what, c.grains, m.grains);
    gf_test_check((double)c.lines <= 0.6 * (double)m.lines, __FILE__, __LINE__,
                  "%s: cache lines of the grains across the cut %zu <= 0.6 x Morton's %zu", what, c.lines, m.lines);
    gf_test_check(ids_are_permutation(gf_sim_particles(slab)) && ids_are_permutation(gf_sim_particles(morton)), __FILE__, __LINE__,
                  "%s: the sorted stores hold every grain once", what);
    gf_sim_destroy(&morton), gf_sim_destroy(&slab);
}

static gf_sim *sim_with(gf_ctx *ctx, const gf_run_spec *spec, int threads, int sort_every, const char *restart)
{
    gf_sim *s = NULL;
    GF_CHECK_OK(gf_test_sim_sorted(ctx, spec, threads, sort_every, restart, &s), ctx);
    return s;
}

/* Largest |a - b| of positions over grains of the same id, in D. */
static double largest_offset(const gf_particles *a, const gf_particles *b, double D)
{
    size_t n = a->n_local;
    double *at = malloc(3 * n * sizeof *at), d = 0.0;
    for (size_t i = 0; at && i < n; ++i) {
        size_t k = (size_t)b->id[i];
        at[3 * k] = b->x_m[i], at[3 * k + 1] = b->y_m[i], at[3 * k + 2] = b->z_m[i];
    }
    for (size_t i = 0; at && i < n; ++i) {
        size_t k = (size_t)a->id[i];
        d = fmax(d, fmax(fabs(a->x_m[i] - at[3 * k]), fmax(fabs(a->y_m[i] - at[3 * k + 1]), fabs(a->z_m[i] - at[3 * k + 2]))));
    }
    free(at);
    return at ? d / D : INFINITY;
}

static void check_restart_on_two_threads(gf_ctx *ctx, int immersed)
{
    gf_run_spec bed = gf_test_bed_spec(ctx, 2000, 1.0);
    gf_run_spec_set_param(ctx, &bed, "width_over_D", 24.0);
    if (immersed)
        gf_test_immerse(&bed);
    char path[512];
    snprintf(path, sizeof path, "%s/sort_cut_%d.h5", getenv("GF_BINARY_DIR") ? getenv("GF_BINARY_DIR") : "/tmp",
             (int)getpid());
    gf_sim *one = sim_with(ctx, &bed, 1, 20, NULL); /* sorted at its first rebuild: Morton order */
    if (!one)
        return;
    if (immersed) /* fluid steps before the checkpoint: held fluid forces cross the restart */
        GF_CHECK_OK(gf_sim_advance(one, 100), ctx);
    GF_CHECK_OK(gf_sim_checkpoint(one, path), ctx);
    gf_run_spec_set_param(ctx, &bed, "settle_time_nd", 0.0); /* the checkpoint overwrites the bed */
    gf_sim *two = sim_with(ctx, &bed, 2, 20, path), *kept = sim_with(ctx, &bed, 2, -1, path);
    if (two && kept) {
        size_t split = gf_sim_neighbour_list(two)->chunk_row[1];
        cut_reach m = reach_across(one, split), c = reach_across(two, split), k = reach_across(kept, split);
        printf("%s restart on 2 threads: lines across the cut at %zu: Morton %zu, re-sorted %zu, sorting off %zu\n",
               immersed ? "immersed" : "dry", split, m.lines, c.lines, k.lines);
        gf_test_check(c.grains > 0 && (double)c.lines <= 0.6 * (double)m.lines, __FILE__, __LINE__,
                      "restart on 2 threads: cache lines across the cut %zu <= 0.6 x Morton's %zu", c.lines, m.lines);
        gf_test_check((double)k.lines > 0.6 * (double)m.lines, __FILE__, __LINE__,
                      "restart with sorting off keeps the Morton order (%zu lines against %zu)", k.lines, m.lines);
        gf_test_check(ids_are_permutation(gf_sim_particles(two)), __FILE__, __LINE__, "re-sorted store holds every grain once");
        GF_CHECK_OK(gf_sim_advance(one, 300), ctx);
        GF_CHECK_OK(gf_sim_advance(two, 300), ctx);
        double d = largest_offset(gf_sim_particles(one), gf_sim_particles(two), bed.grains.diameter_m);
        printf("  300 steps on: largest offset from the one-thread run %.3g D\n", d);
        gf_test_check(d < 1e-9, __FILE__, __LINE__, "re-sorted restart follows the run (offset %.3g D < 1e-9 D)", d);
    }
    gf_sim_destroy(&one), gf_sim_destroy(&two), gf_sim_destroy(&kept);
    remove(path);
}

int main(void)
{
    gf_ctx ctx = {0};
    check_bed(&ctx, "tall bed (6 D wide)", 6.0);
    check_bed(&ctx, "flat bed (24 D wide)", 24.0);
    check_restart_on_two_threads(&ctx, 0);
    check_restart_on_two_threads(&ctx, 1);
    return gf_test_finish();
}
