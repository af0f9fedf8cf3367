/*
 * The near list (engine/sim/gf_near_list.c): the blocked pair loop scans only the
 * neighbour pairs within a thinner skin, rebuilt when a grain has moved
 * half of it. A pair it leaves out cannot reach the contact (or
 * lubrication) range before the next near build, so the run must be
 * bitwise the one that scans the whole list.
 *
 * Claim: from the same start, near skin off (gf_sim_tuning.near_skin < 0),
 * the default (a quarter of the skin) and a thin one (2 % of the skin:
 * a near build every few steps of a flow) leave bitwise identical
 * positions, velocities and spins, and the near list was used (near builds
 * counted, fewer near pairs than list pairs):
 *   - a frictional bed settling from a stack, 1 and 2 threads;
 *   - a column collapse on a glued rough base (the scan's flagged path);
 *   - the same collapse immersed, with Brenner lubrication (candidates
 *     within the lubrication range that do not touch), 1 and 2 threads;
 *   - the dry collapse with sleeping grains (contact.sleep_speed_nd: pairs of
 *     frozen grains keep their history whatever their distance).
 */
#include <stdio.h>
#include <string.h>

#include "gf_test.h"
#include "gf_test_sim.h"

static gf_sim *make(gf_ctx *ctx, const gf_run_spec *spec, int threads, double near_skin)
{
    gf_sim *s = NULL;
    GF_CHECK_OK(gf_sim_create(ctx, spec, &(gf_sim_options){.n_threads = threads, .tuning.near_skin = near_skin}, &s), ctx);
    return s;
}

static void compare(gf_ctx *ctx, const char *what, const gf_run_spec *spec, int threads, long steps)
{
    const double skins[3] = {-1.0, 0.0, 0.02};
    gf_sim *s[3] = {NULL, NULL, NULL};
    for (int q = 0; q < 3; ++q) {
        s[q] = make(ctx, spec, threads, skins[q]);
        if (!s[q] || gf_sim_advance(s[q], steps) != GF_OK) {
            gf_test_check(0, __FILE__, __LINE__, "%s: %s", what, ctx->last_msg);
            for (int u = 0; u <= q; ++u)
                gf_sim_destroy(&s[u]);
            return;
        }
    }
    const size_t n = gf_sim_particles(s[0])->n_local;
    for (int q = 1; q < 3; ++q) {
        gf_sim_list_stats st = gf_sim_list_counters(s[q]);
        printf("%s, %d thread(s), near skin %g of the skin: %ld list builds, %ld near builds, %.2f pairs per grain, "
               "%.2f near\n", what, threads, q == 1 ? GF_SIM_NEAR_SKIN_DEFAULT : skins[q], st.builds, st.near_builds,
               (double)st.pairs / n, (double)st.near_pairs / n);
        gf_test_check(st.near_builds > 0 && st.near_pairs < st.pairs, __FILE__, __LINE__,
                      "%s: the near list is used (%ld builds, %zu of %zu pairs)", what, st.near_builds, st.near_pairs,
                      st.pairs);
        gf_test_check(gf_test_same_motion(gf_sim_particles(s[0]), gf_sim_particles(s[q])), __FILE__, __LINE__,
                      "%s, %d thread(s), %ld steps, %zu grains, near skin %g: bitwise the run over the whole list",
                      what, threads, steps, n, skins[q]);
    }
    gf_test_check(gf_sim_list_counters(s[0]).near_builds == 0, __FILE__, __LINE__, "%s: near skin < 0 builds none",
                  what);
    for (int q = 0; q < 3; ++q)
        gf_sim_destroy(&s[q]);
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_test_pair_loop_scenes(&ctx, compare);
    gf_run_spec sleepy = gf_test_small_collapse_spec(&ctx);
    sleepy.contact.sleep_speed_nd = 0.01;
    compare(&ctx, "column collapse with sleeping grains", &sleepy, 1, 6000);
    return gf_test_finish();
}
