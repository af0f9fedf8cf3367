/*
 * The fluid step's per-grain loops on several threads (gf_coupling_set_threads)
 * give the same held state and forces as on one, bit for bit: a suspension
 * of 2000 grains (above the 1000 from which the loops are split) at random
 * positions and velocities in a periodic box, three fluid steps each for a
 * coupling on 1 thread and one on 2, then for every grain the drag
 * coefficient K, the fluid velocity and fraction at the grain, and the
 * force gf_coupling_add_forces adds (drag, pressure gradient and buoyancy)
 * compared with memcmp. The drag's spreading to the cells, a sum over
 * grains, stays in grain order on one thread, so the fluid fields agree too.
 */
#include <stdio.h>
#include <string.h>

#include "coupling/gf_coupling_diag.h"
#include "fluid_test_util.h"
#include "gf_test.h"

enum { N_GRAINS = 2000 };

static double uniform(unsigned *state)
{
    *state = *state * 1664525u + 1013904223u;
    return (*state >> 8) / 16777216.0;
}

/* Forces the coupling adds to zeroed accumulators, into f (3 per grain). */
static void added_forces(gf_coupling *c, gf_particles *p, double *f)
{
    memset(p->fx_N, 0, p->n_local * sizeof(double));
    memset(p->fy_N, 0, p->n_local * sizeof(double));
    memset(p->fz_N, 0, p->n_local * sizeof(double));
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_coupling_add_forces(c, p), &ctx);
    for (size_t i = 0; i < p->n_local; ++i)
        f[3 * i] = p->fx_N[i], f[3 * i + 1] = p->fy_N[i], f[3 * i + 2] = p->fz_N[i];
}

int main(void)
{
    const double D = 1e-3, side = 16 * D;
    gf_ctx ctx = {0};
    gf_run_spec spec;
    spec_fluid(&spec, D, 2500.0, 1000.0, 1e-3, "di_felice", 2.0);
    gf_coupling_setup su = {.gravity_m_s2 = {0, 0, -9.81}};
    for (int d = 0; d < 3; ++d) {
        su.hi_m[d] = side;
        su.bc[d][0] = su.bc[d][1] = GF_BC_PERIODIC;
    }
    gf_particles *p = NULL;
    GF_CHECK_OK(gf_particles_create(&ctx, N_GRAINS, &p), &ctx);
    unsigned rng = 2024u;
    for (int k = 0; k < N_GRAINS; ++k) {
        size_t i;
        GF_CHECK_OK(gf_particles_add(&ctx, p, side * uniform(&rng), side * uniform(&rng), side * uniform(&rng),
                                     0.5 * D, 2500.0, 0, &i),
                    &ctx);
        p->vx_m_s[i] = 0.01 * (uniform(&rng) - 0.5), p->vy_m_s[i] = 0.01 * (uniform(&rng) - 0.5);
        p->vz_m_s[i] = -0.02 * uniform(&rng);
    }
    gf_coupling *c[2] = {NULL, NULL};
    for (int t = 0; t < 2; ++t) {
        GF_CHECK_OK(gf_coupling_create(&ctx, &spec, &su, &c[t]), &ctx);
        if (!c[t])
            return gf_test_finish();
        gf_coupling_set_threads(c[t], t + 1);
        const double dt = 0.5 * gf_coupling_dt_max_s(c[t], p);
        for (int step = 0; step < 3; ++step)
            GF_CHECK_OK(gf_coupling_fluid_step(c[t], p, dt), &ctx);
    }
    size_t same_state = 0, same_force = 0;
    static double f1[3 * N_GRAINS], f2[3 * N_GRAINS];
    added_forces(c[0], p, f1);
    added_forces(c[1], p, f2);
    for (size_t i = 0; i < p->n_local; ++i) {
        double s[2][5];
        for (int t = 0; t < 2; ++t)
            gf_coupling_grain_state(c[t], i, &s[t][0], &s[t][1], &s[t][4]);
        same_state += memcmp(s[0], s[1], sizeof s[0]) == 0;
        same_force += memcmp(&f1[3 * i], &f2[3 * i], 3 * sizeof(double)) == 0;
    }
    printf("%zu grains: held state bitwise equal for %zu, added force for %zu (1 against 2 threads)\n", p->n_local,
           same_state, same_force);
    GF_CHECK(same_state == p->n_local && same_force == p->n_local);
    double K = 0.0, uf[3], eps = 0.0;
    gf_coupling_grain_state(c[0], 0, &K, uf, &eps);
    GF_CHECK(K > 0.0 && eps > 0.3 && eps < 1.0); /* a live state: drag on, grains in the fluid */
    for (int t = 0; t < 2; ++t)
        gf_coupling_destroy(&c[t]);
    gf_particles_destroy(&p);
    return gf_test_finish();
}
