/*
 * Skips decided from the spec and the scene (issue #6, engine/sim/gf_skips.c).
 *
 * Claims:
 *   1. mu_c = 0 on grains and walls: GF_SKIP_TANGENTIAL is set and named in
 *      the record; a dissipative frictionless settled bed (300 grains, 2000
 *      steps after settling) ends with positions and velocities bitwise equal
 *      (difference exactly 0) to the same run with every skip off
 *      (keep_all_work): the skip is exact, not a tolerance;
 *   2. mu_c = 0 between grains but a frictional wall, or mu_c > 0: no skip;
 *   3. glass in air with lubrication asked for and `fluid: auto` (which
 *      chooses the dry tier at St, r >= 10): GF_SKIP_LUBRICATION is set and
 *      named; with keep_all_work it is not;
 *   4. gf_sim_run with frequent output instants (a record every
 *      0.01 sqrt(D/g)) reaches its end time (it used to stop advancing when
 *      its step chunk overflowed).
 */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "stress_util.h"

static gf_run_spec bed(gf_ctx *ctx, double mu, double mu_wall)
{
    gf_run_spec s = gf_test_spec("settled_bed");
    s.grains.polydispersity = 0.1;
    s.contact.restitution = 0.5;
    s.contact.friction = mu;
    s.contact.wall_friction = mu_wall;
    gf_run_spec_set_param(ctx, &s, "n_grains", 300);
    gf_run_spec_set_param(ctx, &s, "settle_time_nd", 1.0);
    return s;
}

static gf_sim *make(gf_ctx *ctx, const gf_run_spec *s, int keep_all)
{
    gf_sim_options o = {.n_threads = 1, .tuning.keep_all_work = keep_all};
    gf_sim *sim = NULL;
    GF_CHECK_OK(gf_sim_create(ctx, s, &o, &sim), ctx);
    return sim;
}

static void frictionless_exact(gf_ctx *ctx)
{
    gf_run_spec s = bed(ctx, 0.0, 0.0);
    gf_sim *on = make(ctx, &s, 0), *off = make(ctx, &s, 1);
    if (!on || !off)
        return;
    char text[128];
    GF_CHECK(gf_sim_skips(on, text, sizeof text) == GF_SKIP_TANGENTIAL);
    GF_CHECK(strstr(text, "tangential") != NULL);
    GF_CHECK(gf_sim_skips(off, NULL, 0) == 0);
    GF_CHECK_OK(gf_sim_advance(on, 2000), ctx);
    GF_CHECK_OK(gf_sim_advance(off, 2000), ctx);
    const gf_particles *a = gf_sim_particles(on), *b = gf_sim_particles(off);
    double dx = 0.0, dv = 0.0, v = 0.0;
    for (size_t i = 0; i < a->n_local; ++i) {
        dx = fmax(dx, fabs(a->x_m[i] - b->x_m[i]) + fabs(a->y_m[i] - b->y_m[i]) + fabs(a->z_m[i] - b->z_m[i]));
        dv = fmax(dv, fabs(a->vx_m_s[i] - b->vx_m_s[i]) + fabs(a->vy_m_s[i] - b->vy_m_s[i]) +
                          fabs(a->vz_m_s[i] - b->vz_m_s[i]));
        v = fmax(v, fabs(a->vy_m_s[i]));
    }
    printf("frictionless bed, skip on vs off: max |dx| = %g m, max |dv| = %g m/s (max |v_y| %g m/s)\n", dx, dv, v);
    GF_CHECK(dx == 0.0); /* bitwise the same trajectories */
    GF_CHECK(dv == 0.0);
    GF_CHECK(a->n_local == 300);
    gf_sim_destroy(&on);
    gf_sim_destroy(&off);
}

static void no_skip_with_friction(gf_ctx *ctx)
{
    gf_run_spec s = bed(ctx, 0.0, 0.3); /* a frictional floor makes torques */
    gf_sim *sim = make(ctx, &s, 0);
    if (sim)
        GF_CHECK((gf_sim_skips(sim, NULL, 0) & GF_SKIP_TANGENTIAL) == 0);
    gf_sim_destroy(&sim);
    s = bed(ctx, 0.3, 0.0);
    sim = make(ctx, &s, 0);
    if (sim)
        GF_CHECK((gf_sim_skips(sim, NULL, 0) & GF_SKIP_TANGENTIAL) == 0);
    gf_sim_destroy(&sim);
}

static void dry_tier_lubrication(gf_ctx *ctx)
{
    gf_run_spec s = gf_test_spec("settling");
    snprintf(s.fluid.model, sizeof s.fluid.model, "auto");
    s.grains.density_kg_m3 = 2500.0;
    s.fluid.density_kg_m3 = 1.2, s.fluid.viscosity_Pa_s = 1.8e-5, s.fluid.lubrication = 1;
    for (int keep = 0; keep < 2; ++keep) {
        gf_sim *sim = make(ctx, &s, keep);
        if (!sim)
            return;
        char text[128];
        unsigned bits = gf_sim_skips(sim, text, sizeof text);
        printf("glass in air, fluid: auto, keep_all_work %d: skipped \"%s\"\n", keep, text);
        GF_CHECK(((bits & GF_SKIP_LUBRICATION) != 0) == !keep);
        if (!keep)
            GF_CHECK(strstr(text, "lubrication") != NULL);
        gf_sim_destroy(&sim);
    }
}

static void frequent_output(gf_ctx *ctx)
{
    char dir[] = "/tmp/gf_test_skips_XXXXXX";
    if (!mkdtemp(dir)) {
        GF_CHECK(0);
        return;
    }
    gf_run_spec s = gf_test_spec("elastic_gas");
    s.end_time_nd = 3.0;
    s.output.interval_nd = 0.01;
    s.output.particles = 0;
    gf_sim_options o = {.n_threads = 1, .output_dir = dir};
    gf_sim *sim = NULL;
    GF_CHECK_OK(gf_sim_create(ctx, &s, &o, &sim), ctx);
    if (sim) {
        GF_CHECK_OK(gf_sim_run(sim), ctx);
        printf("frequent output: t = %g of %g s\n", gf_sim_time_s(sim), gf_sim_end_time_s(sim));
        GF_CHECK(gf_sim_time_s(sim) >= gf_sim_end_time_s(sim) - gf_sim_dt_s(sim));
    }
    gf_sim_destroy(&sim);
    GF_CHECK(gf_test_remove_tree(dir));
}

int main(void)
{
    gf_ctx ctx = {0};
    frictionless_exact(&ctx);
    no_skip_with_friction(&ctx);
    dry_tier_lubrication(&ctx);
    frequent_output(&ctx);
    return gf_test_finish();
}
