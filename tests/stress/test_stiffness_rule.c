/*
 * Contact stiffness from the scene's confining pressure
 * (contact.overlap_target_over_D, engine/gf_stiffness_rule.h), on the
 * settled columns of the dry collapse (the set-up of test_sleep.c:
 * eps = 0.5, mu_c = 1, R0 = 16 D, 10 % polydisperse), prepared by the scene
 * with the stiffness the rule chose.
 *
 * Claims:
 *   - the rule's t_c gives back its k_n through the law's own derivation
 *     (gf_contact_params_from_spec, Izard (3.17)) to 1e-12;
 *   - in the settled column (gate put back at t = 0, 1.5 sqrt(D/g) of rest)
 *     the largest overlap, grain-grain and grain-wall, stays below the target
 *     x D, for x = 0.01 and 0.02 and columns a = 1 and 2 (H0 = 16 D, 32 D).
 *     Smaller targets are not tested here: the scene prepares its packing
 *     with contacts of t_c = 0.02 sqrt(D/g) and friction locks up to
 *     ~0.006 D of those overlaps in, whatever the run's stiffness (measured:
 *     0.0058-0.0063 D at x = 0.005, docs/notes/benchmarks.md);
 *   - the time step the rule derives for x = 0.01 and a = 1 is larger than
 *     the default one (t_contact_nd = 1e-2): the rule lets a run take larger
 *     steps where its pressure allows.
 * The largest overlap / (p D / k_n) (the force-chain factor C_f the rule
 * assumes) is printed for docs/notes/benchmarks.md.
 */
#include <stdlib.h>

#include "../scenes/scene_runner.h"
#include "contact/gf_contact.h"
#include "gf_stiffness_rule.h"

#define GF_TEST_GATE_WALL 2 /* the gate's wall id in column_collapse (floor 0, back 1, gate 2) */
#define SETTLE_ND (getenv("GF_TEST_SETTLE") ? atof(getenv("GF_TEST_SETTLE")) : 1.5)

static void column_spec(gf_ctx *ctx, gf_run_spec *spec, double aspect, double target)
{
    runner_dry_spec(spec, "column_collapse");
    spec->contact.restitution = 0.5;
    spec->contact.friction = spec->contact.wall_friction = 1.0;
    spec->contact.t_contact_nd = 0.02;
    spec->contact.overlap_target_over_D = target;
    GF_CHECK_OK(gf_run_spec_set_param(ctx, spec, "aspect_ratio", aspect), ctx);
    GF_CHECK_OK(gf_run_spec_set_param(ctx, spec, "column_length_over_D", 16.0), ctx);
    GF_CHECK_OK(gf_run_spec_set_param(ctx, spec, "phi_target", 0.60), ctx);
}

/* Settled column under the rule: largest overlap / D at t = 0; *dt_s the step. */
static double settled_overlap(double aspect, double target, double *dt_s)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    column_spec(&ctx, &spec, aspect, target);
    gf_sim *sim = NULL;
    gf_sim_options opt = {.n_threads = 1};
    GF_CHECK_OK(gf_sim_create(&ctx, &spec, &opt, &sim), &ctx);
    if (!sim)
        return NAN;
    const gf_run_spec *used = gf_sim_spec(sim);
    const double D = spec.grains.diameter_m, H0 = aspect * 16.0 * D;
    const double k_n = gf_stiffness_k_n(&spec, gf_stiffness_column_pressure_Pa(&spec, 0.6, H0), target);
    const double unit = gf_stiffness_column_pressure_Pa(&spec, 0.6, H0) * D / k_n; /* p D / k_n, over D */
    /* the scene removes the gate at t = 0: put it back and let the column come
     * to rest with the run's contacts (1.5 sqrt(D/g)), then read the overlaps */
    GF_CHECK_OK(gf_sim_set_wall_active(sim, GF_TEST_GATE_WALL, 1), &ctx);
    size_t nc;
    double ov, tg = sqrt(D / spec.gravity_m_s2);
    GF_CHECK_OK(gf_sim_advance(sim, (long)ceil(SETTLE_ND * tg / gf_sim_dt_s(sim))), &ctx);
    gf_sim_contact_stats(sim, &nc, &ov);
    *dt_s = gf_sim_dt_s(sim);
    printf("a = %g, target %.3g D: t_c sqrt(g/D) = %.4g, dt = %.3g s, max overlap %.3g D (%.2f x p D/k_n), %zu "
           "contacts\n",
           aspect, target, used->contact.t_contact_nd, *dt_s, ov, ov / unit, nc);
    gf_sim_destroy(&sim);
    return ov;
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    column_spec(&ctx, &spec, 1.0, 0.005);
    /* round trip through the law's derivation */
    double k_n = gf_stiffness_k_n(&spec, 1234.0, 0.005);
    spec.contact.t_contact_nd = gf_stiffness_t_contact_nd(&spec, k_n);
    gf_contact_params cp;
    GF_CHECK_OK(gf_contact_params_from_spec(&ctx, &spec, &cp), &ctx);
    GF_CHECK_REL(cp.k_n_N_m, k_n, 1e-12);

    double dt;
    if (getenv("GF_TEST_TARGET")) { /* exploration */
        settled_overlap(getenv("GF_TEST_ASPECT") ? atof(getenv("GF_TEST_ASPECT")) : 1.0, atof(getenv("GF_TEST_TARGET")),
                        &dt);
        return gf_test_finish();
    }
    const double targets[2] = {0.02, 0.01}, aspects[2] = {2.0, 1.0};
    for (int t = 0; t < 2; ++t)
        for (int a = 0; a < 2; ++a)
            GF_CHECK(settled_overlap(aspects[a], targets[t], &dt) < targets[t]); /* static overlaps below x D */
    /* dt: the last run, x = 0.01 at a = 1 */
    gf_run_spec def;
    gf_run_spec_defaults(&def);
    def.grains = spec.grains;
    printf("dt with the rule (x = 0.01) %.3g s, default (t_contact_nd = %g) %.3g s: %.2fx\n", dt,
           def.contact.t_contact_nd, gf_run_spec_dt_s(&def), dt / gf_run_spec_dt_s(&def));
    GF_CHECK(dt > gf_run_spec_dt_s(&def)); /* larger step than the default where the pressure allows */
    return gf_test_finish();
}
