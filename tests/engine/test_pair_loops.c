/*
 * The blocked, vectorised pair loop of the dry linear law (engine/
 * gf_pairs_blocked.c: scan, force pass in an AVX-512 clone where the machine has
 * it, scatter in list order) gives the bits of the scalar loop
 * (engine/sim/gf_forces.c) it replaces: same expressions, same sums.
 *
 * Claim: from the same start, the two loops (gf_sim_tuning.generic_pair_loop
 * 0 and 1) leave bitwise identical positions, velocities and spins
 *   - in a frictional settled bed of 1200 grains, 1 and 2 threads, 2000 steps
 *     from an unsettled stack (contacts made and broken, Coulomb slip);
 *   - in a column collapse on a rough base of glued grains (the scan's
 *     flagged path), 3000 steps after its pre-run settle;
 *   - in the same collapse immersed (unresolved fluid, Brenner lubrication
 *     of every pair closer than R/2: the candidates then include near pairs
 *     that do not touch), 1 and 2 threads;
 *   - in a bed of 26 000 grains, above the store size from which the scan
 *     prefetches the partners' lines (GF_PAIR_PREFETCH_MIN_GRAINS), 100 steps.
 */
#include <stdio.h>
#include <string.h>

#include "gf_test.h"
#include "gf_test_sim.h"

static gf_sim *make(gf_ctx *ctx, const gf_run_spec *spec, int threads, int generic)
{
    gf_sim *s = NULL;
    GF_CHECK_OK(gf_sim_create(ctx, spec, &(gf_sim_options){.n_threads = threads, .tuning.generic_pair_loop = generic}, &s), ctx);
    return s;
}

static void compare(gf_ctx *ctx, const char *what, const gf_run_spec *spec, int threads, long steps)
{
    gf_sim *blocked = make(ctx, spec, threads, 0), *generic = make(ctx, spec, threads, 1);
    if (!blocked || !generic) {
        gf_sim_destroy(&blocked);
        gf_sim_destroy(&generic);
        return;
    }
    GF_CHECK_OK(gf_sim_advance(blocked, steps), ctx);
    GF_CHECK_OK(gf_sim_advance(generic, steps), ctx);
    int same = gf_test_same_motion(gf_sim_particles(blocked), gf_sim_particles(generic));
    gf_test_check(same, __FILE__, __LINE__, "%s, %d thread(s), %ld steps, %zu grains: blocked loop bitwise the scalar one",
                  what, threads, steps, gf_sim_particles(blocked)->n_local);
    gf_sim_destroy(&blocked);
    gf_sim_destroy(&generic);
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_test_pair_loop_scenes(&ctx, compare);
    gf_run_spec big = gf_test_bed_spec(&ctx, 26000, 0.0);
    compare(&ctx, "large settling bed (prefetching scan)", &big, 1, 100);
    return gf_test_finish();
}
