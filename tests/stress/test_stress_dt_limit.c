/*
 * dt swept past the stability limit of the contact spring.
 *
 * Velocity Verlet on one linear spring is stable for omega dt < 2, i.e.
 * dt < (2/pi) t_c = 0.64 t_c for the mean pair; in a dense pack the stiffest
 * mode of the contact network is up to ~2.4x faster, so gf_sim refuses
 * dt > t_c/5 (gf_sim.c). The claim tested here: for every dt, either
 *   (a) gf_sim_create refuses with GF_ERR_NUMERIC, no sim, and one line
 *       naming the limit ("stability limit", "t_c/5"), or
 *   (b) the run ends GF_OK with a physically sane state, or
 *   (c) the run stops with a non-OK status and a message;
 * never a NaN with status OK, never status OK with garbage. "Garbage" is
 * checked against physics that cannot fail in a sane run:
 *   - a dissipative collision (eps_max 0.5) cannot rebound faster than it
 *     came in: 0 <= e <= 1;
 *   - an elastic frictionless gas keeps its energy within 5 % even at the
 *     limit (Verlet's shadow-energy error is O((omega dt)^2) ~ 0.4 at
 *     dt = t_c/5 during a contact, averaged over the few grains in contact
 *     at once; measured well below 5 %);
 *   - a settled frictional bed (settled_bed: quenched, so it starts with zero
 *     velocities but small residual force imbalances) run for 2 sqrt(D/g)
 *     stays a bed at every accepted dt: no grain faster than sqrt(gD)
 *     (nothing ejected), its kinetic energy at the end below half its peak
 *     (the release jolt decays), overlaps below 5 % of D.
 * Sweep: dt/t_c = 0.02, 0.05, 0.1, 0.2 (accepted), 0.2001, 0.3, 0.5, 0.64,
 * 1, 2, 10 (refused).
 * Mode "impact" (a separate ctest entry): fast head-on impacts, V = 10, 30,
 * 100, 1000 sqrt(gD), linear and Hertz laws, dt = t_c/50 and t_c/5. The
 * Hertz stiffness grows as delta^(1/2), so a fast impact shortens the
 * contact below t_c (as (V/sqrt(gD))^(-1/5)) and dt = t_c/5 passes the pair
 * bound for that collision; at V = 1000 sqrt(gD) a linear contact of
 * t_c = 1e-2 sqrt(D/g) would need an overlap of ~3 D, and at dt = t_c/5
 * the grains move 2 D per step. Each run must either stop with a message or
 * end sane: 0 <= e <= 1 (no energy from nowhere, no grains passing through
 * each other) and overlaps below D/2.
 */
#include "stress_util.h"

static const double sweep[] = {0.02, 0.05, 0.1, 0.2, 0.2001, 0.3, 0.5, 0.64, 1.0, 2.0, 10.0};
#define N_SWEEP ((int)(sizeof sweep / sizeof sweep[0]))
#define DT_LIMIT 0.2

/* Refused at create: the status, no sim, and the limit named. */
static void check_refused(const char *what, double dt_over_tc, gf_status st, const gf_sim *sim, const gf_ctx *ctx)
{
    printf("  %-16s dt = %-6g t_c: refused (%s): %s\n", what, dt_over_tc, gf_status_str(st), ctx->last_msg);
    GF_CHECK(st == GF_ERR_NUMERIC);
    GF_CHECK(sim == NULL);
    GF_CHECK(strstr(ctx->last_msg, "stability limit") != NULL);
    GF_CHECK(strstr(ctx->last_msg, "t_c/5") != NULL);
}

/* The sim of spec s (dt = dt_over_tc t_c); NULL when refused (the refusal
 * checked where dt passes the limit, what: the printed line's label) or when
 * it could not be made (checked). Owner: the caller (gf_sim_destroy). */
static gf_sim *accepted_sim(gf_ctx *ctx, const gf_run_spec *s, const char *what, double dt_over_tc)
{
    gf_sim *sim = NULL;
    gf_status st = gf_test_sim(ctx, s, 1, &sim);
    if (dt_over_tc > DT_LIMIT) {
        check_refused(what, dt_over_tc, st, sim, ctx);
        gf_sim_destroy(&sim);
        return NULL;
    }
    GF_CHECK_OK(st, ctx);
    return sim;
}

/* A run that stopped with status st: a message says why. */
static void check_stopped(const char *what, double dt_over_tc, gf_status st, const gf_ctx *ctx)
{
    printf("  %-16s dt = %-6g t_c: stopped (%s): %s\n", what, dt_over_tc, gf_status_str(st), ctx->last_msg);
    GF_CHECK(strlen(ctx->last_msg) > 0);
}

/* Head-on collision; returns the restitution, NAN when the run stopped (message checked). */
static double collision(const char *law, double eps, double dt_over_tc, double speed_nd)
{
    gf_ctx ctx = {0};
    gf_run_spec s = gf_test_spec("binary_collision");
    snprintf(s.contact.law, sizeof s.contact.law, "%s", law);
    s.contact.restitution = eps;
    s.contact.friction = 0.0;
    s.contact.dt_over_tc = dt_over_tc;
    gf_run_spec_set_param(&ctx, &s, "impact_speed_nd", speed_nd);
    gf_run_spec_set_param(&ctx, &s, "gap_over_D", 0.001);
    gf_sim *sim = accepted_sim(&ctx, &s, law, dt_over_tc);
    if (!sim)
        return NAN;
    gf_status st = GF_OK;
    double V = speed_nd * sqrt(s.gravity_m_s2 * s.grains.diameter_m), ov_max = 0.0;
    long n = (long)ceil(gf_sim_end_time_s(sim) / gf_sim_dt_s(sim));
    for (long k = 0; k < n && st == GF_OK; ++k) {
        st = gf_sim_advance(sim, 1);
        double ov;
        gf_sim_contact_stats(sim, NULL, &ov);
        ov_max = fmax(ov_max, ov);
    }
    gf_particles *p = gf_sim_particles(sim);
    double e = (p->vx_m_s[1] - p->vx_m_s[0]) / V;
    if (st != GF_OK) {
        printf("  %-8s dt = %-6g t_c, V = %-4g sqrt(gD): stopped (%s): %s\n", law, dt_over_tc, speed_nd,
               gf_status_str(st), ctx.last_msg);
        GF_CHECK(strlen(ctx.last_msg) > 0);
        e = NAN;
    } else {
        printf("  %-8s dt = %-6g t_c, V = %-4g sqrt(gD): ok, restitution %.4f, max overlap %.3g D\n", law,
               dt_over_tc, speed_nd, e, ov_max);
        GF_CHECK(isfinite(e));
        GF_CHECK(e >= 0.0 && e <= 1.0); /* no energy from nowhere, no grains passing through each other */
        GF_CHECK(ov_max < 0.5);         /* centres closer than R: the pair geometry is meaningless */
    }
    gf_sim_destroy(&sim);
    return e;
}

/* Elastic frictionless gas at solid fraction ~0.4 for 200 t_c: energy drift. */
static void elastic_gas(double dt_over_tc)
{
    gf_ctx ctx = {0};
    gf_run_spec s = gf_test_elastic_gas_spec(&ctx, 125, 5.5, dt_over_tc);
    gf_sim *sim = accepted_sim(&ctx, &s, "elastic_gas", dt_over_tc);
    if (!sim)
        return;
    gf_status st = GF_OK;
    gf_particles *p = gf_sim_particles(sim);
    double e0 = gf_particles_kinetic_energy(p) + gf_test_spring_energy(sim), worst = 0.0;
    long n = (long)ceil(200.0 / dt_over_tc);
    for (int k = 0; k < 20 && st == GF_OK; ++k) {
        st = gf_sim_advance(sim, n / 20);
        if (st == GF_OK)
            worst = fmax(worst, fabs((gf_particles_kinetic_energy(p) + gf_test_spring_energy(sim)) / e0 - 1.0));
    }
    if (st != GF_OK) {
        check_stopped("elastic_gas", dt_over_tc, st, &ctx);
    } else {
        printf("  %-16s dt = %-6g t_c: ok, max |dE/E| over 200 t_c = %.3g\n", "elastic_gas", dt_over_tc, worst);
        GF_CHECK(worst < 0.05);
    }
    gf_sim_destroy(&sim);
}

/* Settled frictional bed (500 grains, mu 0.5, eps 0.5) run for 2 sqrt(D/g). */
static void settled_bed(double dt_over_tc)
{
    gf_ctx ctx = {0};
    gf_run_spec s = gf_test_bed_spec(&ctx, 500, 4.0);
    s.contact.restitution = 0.5;
    s.contact.wall_friction = 0.5;
    s.contact.dt_over_tc = dt_over_tc;
    gf_sim *sim = accepted_sim(&ctx, &s, "settled_bed", dt_over_tc);
    if (!sim)
        return;
    gf_status st = GF_OK;
    gf_particles *p = gf_sim_particles(sim);
    double vref = sqrt(s.gravity_m_s2 * s.grains.diameter_m);
    double m = s.grains.density_kg_m3 * M_PI * pow(s.grains.diameter_m, 3) / 6.0;
    double ek0 = gf_particles_kinetic_energy(p), ek_max = ek0, vmax = 0.0, ek_end = 0.0, ov = 0.0;
    long n = (long)ceil(200.0 / dt_over_tc);
    for (int k = 0; k < 20 && st == GF_OK; ++k) {
        st = gf_sim_advance(sim, n / 20);
        ek_end = gf_particles_kinetic_energy(p);
        ek_max = fmax(ek_max, ek_end);
        vmax = fmax(vmax, stress_max_speed(p));
        double o;
        gf_sim_contact_stats(sim, NULL, &o);
        ov = fmax(ov, o);
    }
    if (st != GF_OK) {
        check_stopped("settled_bed", dt_over_tc, st, &ctx);
    } else {
        double mgd = p->n_local * m * s.gravity_m_s2 * s.grains.diameter_m;
        printf("  %-16s dt = %-6g t_c: ok, max speed %.3g sqrt(gD), E_k max %.3g -> end %.3g m g D per grain, max "
               "overlap %.3g D\n",
               "settled_bed", dt_over_tc, vmax / vref, ek_max / mgd, ek_end / mgd, ov);
        GF_CHECK(vmax < vref);         /* nothing ejected */
        GF_CHECK(ek_end < 0.5 * ek_max); /* the jolt of release decays: energy is not pumped in */
        GF_CHECK(ov < 0.05);
    }
    gf_sim_destroy(&sim);
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "impact") == 0) {
        const double speeds[] = {10.0, 30.0, 100.0, 1000.0}, dts[] = {0.02, DT_LIMIT};
        const char *laws[] = {"linear", "hertz"};
        printf("fast impacts, eps 0.5:\n");
        for (int l = 0; l < 2; ++l)
            for (int d = 0; d < 2; ++d)
                for (int i = 0; i < 4; ++i)
                    collision(laws[l], 0.5, dts[d], speeds[i]);
        return gf_test_finish();
    }
    printf("linear law, eps_max 0.5, V = sqrt(gD):\n");
    for (int i = 0; i < N_SWEEP; ++i)
        collision("linear", 0.5, sweep[i], 1.0);
    printf("Hertz law, eps 0.5, V = sqrt(gD):\n");
    for (int i = 0; i < N_SWEEP; ++i)
        collision("hertz", 0.5, sweep[i], 1.0);
    printf("dense elastic gas (phi 0.39), eps 1, mu 0:\n");
    for (int i = 0; i < N_SWEEP; ++i)
        elastic_gas(sweep[i]);
    printf("settled frictional bed, 500 grains:\n");
    const double bed_sweep[] = {0.02, 0.1, 0.2, 0.3, 1.0};
    for (int i = 0; i < 5; ++i)
        settled_bed(bed_sweep[i]);
    return gf_test_finish();
}
