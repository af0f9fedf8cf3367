/*
 * The fused step against the reference step (engine/sim/gf_step.c): the
 * velocity-Verlet method written as its five operations (kick, drift,
 * neighbour upkeep, forces over the whole list, kick) and the default step,
 * which defers the closing half-kick into the next opening one, runs the
 * next kick and drift inside the force region when steps follow one another
 * and scans the near list. Each grain sees the same operations in the same
 * order (two half-kicks stay two additions), so the claim is bitwise:
 * positions, velocities, spins (memcmp) and every contact's tangential
 * history, on
 *   - a frictional, polydisperse bed settling from its stack (1200 grains:
 *     the threads really run), 1 and 2 threads, sorted at every rebuild;
 *   - the same bed settling through a viscous fluid (unresolved tier, fluid
 *     steps every few DEM steps, Brenner lubrication), 1 and 2 threads;
 *   - the same bed with sleeping grains (sleep updates between steps);
 *   - a frictionless elastic gas (the normal-only pair loop, no rotation);
 *   - two grains colliding obliquely under the Hertz law (the table kernel).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_test.h"
#include "gf_test_sim.h"

typedef struct history_copy {
    double *h;
    size_t n, cap;
} history_copy;

static int copy_history(void *user, const gf_sim_contact *c)
{
    history_copy *hc = user;
    if (hc->n + 3 > hc->cap) {
        size_t cap = 2 * hc->cap + 300;
        double *h = realloc(hc->h, cap * sizeof *h);
        if (!h)
            return 1;
        hc->h = h, hc->cap = cap;
    }
    memcpy(hc->h + hc->n, c->history, 3 * sizeof(double));
    hc->n += 3;
    return 0;
}

static int same_history(gf_ctx *ctx, gf_sim *a, gf_sim *b)
{
    history_copy ha = {0}, hb = {0};
    GF_CHECK_OK(gf_sim_foreach_contact(a, copy_history, &ha), ctx);
    GF_CHECK_OK(gf_sim_foreach_contact(b, copy_history, &hb), ctx);
    const int same = ha.n == hb.n && (ha.n == 0 || memcmp(ha.h, hb.h, ha.n * sizeof(double)) == 0);
    free(ha.h), free(hb.h);
    return same;
}

static void compare(gf_ctx *ctx, const char *what, const gf_run_spec *spec, int threads, int sort_every, long steps,
                    long per_call)
{
    gf_sim *sim[2] = {NULL, NULL};
    for (int r = 0; r < 2; ++r) {
        gf_sim_options opt;
        memset(&opt, 0, sizeof opt);
        opt.n_threads = threads, opt.tuning.sort_every = sort_every, opt.tuning.reference_step = r;
        GF_CHECK_OK(gf_sim_create(ctx, spec, &opt, &sim[r]), ctx);
        for (long done = 0; sim[r] && done < steps; done += per_call)
            GF_CHECK_OK(gf_sim_advance(sim[r], per_call), ctx);
    }
    if (sim[0] && sim[1]) {
        const int motion = gf_test_same_motion(gf_sim_particles(sim[0]), gf_sim_particles(sim[1]));
        const int history = same_history(ctx, sim[0], sim[1]);
        size_t n_contacts;
        gf_sim_contact_stats(sim[0], &n_contacts, NULL);
        printf("%s, %d thread(s): %zu grains, %ld steps, %zu contacts: motion %s, history %s\n", what, threads,
               gf_sim_particles(sim[0])->n_local, steps, n_contacts, motion ? "bitwise" : "DIFFERS",
               history ? "bitwise" : "DIFFERS");
        gf_test_check(motion && history, __FILE__, __LINE__, "%s, %d thread(s): fused step bitwise the reference",
                      what, threads);
    }
    gf_sim_destroy(&sim[0]), gf_sim_destroy(&sim[1]);
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_run_spec bed = gf_test_bed_spec(&ctx, 1200, 0.0);
    compare(&ctx, "settling bed", &bed, 1, 1, 800, 100);
    compare(&ctx, "settling bed", &bed, 2, 1, 800, 100);
    gf_run_spec wet = bed;
    gf_test_immerse(&wet);
    compare(&ctx, "immersed settling bed", &wet, 1, 0, 400, 50);
    compare(&ctx, "immersed settling bed", &wet, 2, 0, 400, 50);
    gf_run_spec sleepy = gf_test_bed_spec(&ctx, 400, 0.0);
    sleepy.contact.sleep_speed_nd = 0.05;
    compare(&ctx, "bed with sleeping grains", &sleepy, 1, 0, 1500, 100);
    gf_run_spec gas = gf_test_spec("elastic_gas");
    gas.contact.friction = 0.0, gas.contact.restitution = 0.8;
    gf_run_spec_set_param(&ctx, &gas, "n_grains", 125);
    gf_run_spec_set_param(&ctx, &gas, "box_over_D", 6.0);
    compare(&ctx, "frictionless gas", &gas, 1, 0, 2000, 100);
    gf_run_spec pair = gf_test_spec("binary_collision");
    snprintf(pair.contact.law, sizeof pair.contact.law, "hertz");
    pair.contact.friction = 0.4;
    gf_run_spec_set_param(&ctx, &pair, "psi1", 2.0);
    compare(&ctx, "oblique Hertz collision", &pair, 1, 0, 60, 10);
    return gf_test_finish();
}
