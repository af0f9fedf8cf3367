/*
 * Sleeping grains (issue #6, engine/sim/gf_sleep.c), measured on the dry
 * column collapse a = 1, R0 = 16 D (the set-up of tests/scenes/
 * test_column_collapse.c: eps = 0.5, mu_c = 1, t_c = 0.02 sqrt(D/g)), run to
 * t = 40 sqrt(D/g), about 7 free-fall times T0 = sqrt(2 H0/g): the deposit
 * is at rest for most of the run.
 *
 * Claims:
 *   - sleep off and on (contact.sleep_speed_nd = 0.01) give the same mean
 *     run-out (R_inf - R0)/R0 within 5 % and the same H_inf/R0 within 5 % (the
 *     observable must not depend on skipping grains at rest; 5 % is below
 *     the 10 % scatter of the published laws);
 *   - at the end more than half of the mobile grains are asleep (grains at
 *     rest on the deposit's free surface, a slope below the friction angle,
 *     included);
 *   - a surface grain woken by hand and thrown into the deposit at
 *     1 sqrt(gD) wakes the sleeping grains it hits.
 * The wall time of both runs is printed (speed-up for docs/notes/benchmarks.md).
 */
#include <stdint.h>
#include <stdlib.h>

#include "../scenes/scene_runner.h"

#define GF_SLEEP_T_END_ND 40.0 /* ~7 T0: the deposit is at rest from ~3 T0 */

static size_t count_asleep(const gf_particles *p, size_t *n_mobile)
{
    size_t a = 0, m = 0;
    for (size_t i = 0; i < p->n_local; ++i) {
        if (p->flags[i] & GF_P_GLUED)
            continue;
        m++;
        a += (p->flags[i] & GF_P_SLEEPING) != 0;
    }
    *n_mobile = m;
    return a;
}

static double collapse(double sleep, double dt_over_tc, double *runout, double *h_over_r0, int hit)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    runner_dry_spec(&spec, "column_collapse");
    spec.contact.restitution = 0.5;
    spec.contact.friction = spec.contact.wall_friction = 1.0;
    spec.contact.t_contact_nd = 0.02;
    spec.contact.sleep_speed_nd = sleep;
    spec.contact.dt_over_tc = dt_over_tc;
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "aspect_ratio", 1.0), &ctx);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "column_length_over_D", 16.0), &ctx);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "phi_target", 0.60), &ctx);
    gf_sim *sim = NULL;
    gf_sim_options opt = {.n_threads = 1};
    GF_CHECK_OK(gf_sim_create(&ctx, &spec, &opt, &sim), &ctx);
    if (!sim)
        return NAN;
    const double D = spec.grains.diameter_m, tg = sqrt(D / spec.gravity_m_s2), R0 = 16 * D;
    long steps = (long)ceil(GF_SLEEP_T_END_ND * tg / gf_sim_dt_s(sim));
    double t0 = runner_now_s();
    GF_CHECK_OK(gf_sim_advance(sim, steps), &ctx);
    double wall = runner_now_s() - t0;
    const gf_scene_desc *d = gf_scene_find("column_collapse");
    double v[5]; /* the scene's diagnostics (gf_scene_column_collapse.c) */
    GF_CHECK_OK(d->diagnose(sim, v), &ctx);
    *runout = (v[0] - R0) / R0;
    *h_over_r0 = v[1] / R0;
    gf_particles *p = gf_sim_particles(sim);
    size_t n_mob, n_sleep = count_asleep(p, &n_mob);
    printf("sleep_speed_nd = %g: (R_inf - R0)/R0 = %.4f, H_inf/R0 = %.4f, %zu of %zu mobile grains asleep, "
           "dt/t_c = %g, %ld steps in %.2f s\n",
           sleep, *runout, *h_over_r0, n_sleep, n_mob, dt_over_tc, steps, wall);
    if (sleep > 0.0) {
        GF_CHECK(n_sleep > n_mob / 2); /* more than half of the mobile grains asleep at the end */
    }
    if (hit && sleep > 0.0) {
        /* the highest sleeping grain is woken by hand and thrown down into the deposit */
        size_t top = 0;
        double ytop = -1.0;
        for (size_t i = 0; i < p->n_local; ++i)
            if ((p->flags[i] & GF_P_SLEEPING) && p->y_m[i] > ytop)
                ytop = p->y_m[i], top = i;
        p->flags[top] &= (uint8_t)~GF_P_SLEEPING;
        p->vy_m_s[top] = -sqrt(spec.gravity_m_s2 * D);
        p->vx_m_s[top] = 0.3 * sqrt(spec.gravity_m_s2 * D);
        size_t before = n_sleep;
        /* a builder call marks the forces stale: the next advance rebuilds the
         * list, which reads the flags into the integrator factors */
        GF_CHECK_OK(gf_sim_set_wall_active(sim, 0, 1), &ctx);
        GF_CHECK_OK(gf_sim_advance(sim, 1000), &ctx);
        size_t after = count_asleep(p, &n_mob);
        printf("hit: grain %zu thrown into the deposit: asleep %zu -> %zu after %.2f sqrt(D/g)\n", top, before - 1,
               after, 1000 * gf_sim_dt_s(sim) / tg);
        GF_CHECK(after < before - 1); /* sleeping grains hit by a moving one wake */
    }
    gf_sim_destroy(&sim);
    return wall;
}

int main(void)
{
    double r, h;
    if (getenv("GF_TEST_SLEEP")) { /* exploration: one run at the given threshold */
        collapse(atof(getenv("GF_TEST_SLEEP")), 0.02, &r, &h, 0);
        return gf_test_finish();
    }
    /* The front of one collapse moves by +-1-2 bins of D (+-5-10 % of the
     * run-out) under any perturbation: with sleep off, dt/t_c = 0.019, 0.020,
     * 0.021 give (R_inf - R0)/R0 = 1.44, 1.31, 1.25. A single off/on pair
     * therefore cannot be held to 5 % (at dt/t_c = 0.020 it differs by two
     * bins, +9.5 %); the claim is on the mean of two runs bracketing the
     * default step, dt/t_c = 0.019 and 0.021, each with sleep off and on
     * (the mean over 0.019, 0.020, 0.021 differs by +3.1 %, docs/notes/benchmarks.md). */
    const double dts[2] = {0.019, 0.021};
    double r_off = 0, h_off = 0, r_on = 0, h_on = 0, w_off = 0, w_on = 0;
    for (int k = 0; k < 2; ++k) {
        w_off += collapse(0.0, dts[k], &r, &h, 0);
        r_off += r / 2, h_off += h / 2;
        w_on += collapse(0.01, dts[k], &r, &h, k == 1);
        r_on += r / 2, h_on += h / 2;
    }
    printf("mean of 2: sleep off (R_inf - R0)/R0 = %.4f, H_inf/R0 = %.4f; on %.4f, %.4f\n", r_off, h_off, r_on, h_on);
    printf("speed-up (2 runs each): %.2fx (off %.2f s, on %.2f s); run-out change %+.2f %%, H_inf change %+.2f %%\n",
           w_off / w_on, w_off, w_on, 100 * (r_on - r_off) / r_off, 100 * (h_on - h_off) / h_off);
    GF_CHECK_REL(r_on, r_off, 0.05); /* run-out with sleep within 5 % of without */
    GF_CHECK_REL(h_on, h_off, 0.05); /* H_inf/R0 with sleep within 5 % of without */
    return gf_test_finish();
}
