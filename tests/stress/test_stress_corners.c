/*
 * Extreme inputs actually run (issue #6, "numerical stability under stress"):
 * each either runs stably or is refused before it starts, with the reason.
 *
 * 1. Very polydisperse beds. The schema's widest size distribution,
 *    radii uniform in R(1 -+ 0.5), on the settled_bed scene (320 grains,
 *    eps 0.5, mu 0.5). k_n is the mean pair's, so the smallest pair's
 *    contact lasts (1 - p)^(3/2) t_c = 0.35 t_c and the accepted step
 *    shrinks to t_c/5 ((1 - p)/0.9)^(3/2) = 0.083 t_c
 *    (gf_run_spec_dt_limit_over_tc). Claims: at dt = t_c/50 and at 0.95 of
 *    the limit the bed settles (12 sqrt(D/g) of preparation) and stays a bed for 2 sqrt(D/g) after its
 *    preparation (no grain faster than sqrt(gD), overlaps below 5 % of D,
 *    finite state); just above the limit gf_sim_create refuses with
 *    GF_ERR_NUMERIC and a message naming the polydispersity.
 * 2. The corners of the (St, r) plane, St 0.01 and 1000, r 1.3 and 100
 *    (grains barely denser than the fluid to grains in air; r <= sqrt(5/3) is
 *    refused, test_stress_groups_tier), at the seeds' grains (D = 7.6 mm,
 *    rho_p 2500 kg/m3), on the settling scene (homogeneous suspension, phi
 *    0.2, periodic 8 D cube, unresolved tier forced: `auto` would drop the
 *    fluid at (1000, 100)). Each runs 5 sqrt(D/g) (a tenth of that at
 *    St = 0.01, where the fluid step is short): status OK, finite state,
 *    and no grain faster than the isolated sphere's terminal velocity
 *    (Schiller–Naumann, iterated) bounded by free fall over the run,
 *    min(u_T, (1 - 1/rho_ratio) g t) x 1.5 plus the initial jitter.
 */
#include <stdlib.h>

#include "core/gf_groups.h"
#include "stress_util.h"

/* Settled bed of the widest distribution at dt = ratio t_c. */
static void polydisperse_bed(double dt_over_tc, int expect_refused)
{
    gf_ctx ctx = {0};
    gf_run_spec s = gf_test_spec("settled_bed");
    s.grains.polydispersity = 0.5;
    s.contact.restitution = 0.5;
    s.contact.friction = s.contact.wall_friction = 0.5;
    s.contact.dt_over_tc = dt_over_tc;
    gf_run_spec_set_param(&ctx, &s, "n_grains", 320);
    gf_run_spec_set_param(&ctx, &s, "width_over_D", 6.0);
    /* the body-centred stack of so wide a distribution has holes: settle longer than the default 4 */
    gf_run_spec_set_param(&ctx, &s, "settle_time_nd", 12.0);
    gf_sim *sim = NULL;
    gf_status st = gf_test_sim(&ctx, &s, 1, &sim);
    if (expect_refused) {
        printf("  p = 0.5, dt = %.4g t_c: refused (%s): %s\n", dt_over_tc, gf_status_str(st), ctx.last_msg);
        GF_CHECK(st == GF_ERR_NUMERIC && sim == NULL);
        GF_CHECK(strstr(ctx.last_msg, "polydispersity") != NULL);
        gf_sim_destroy(&sim);
        return;
    }
    GF_CHECK_OK(st, &ctx);
    if (!sim)
        return;
    gf_particles *p = gf_sim_particles(sim);
    const double D = s.grains.diameter_m, vref = sqrt(s.gravity_m_s2 * D);
    long n = (long)ceil(2.0 * sqrt(D / s.gravity_m_s2) / gf_sim_dt_s(sim));
    double vmax = 0.0, ov_max = 0.0, ov;
    for (long done = 0; done < n && st == GF_OK; done += n / 20) {
        st = gf_sim_advance(sim, n / 20);
        vmax = fmax(vmax, stress_max_speed(p));
        gf_sim_contact_stats(sim, NULL, &ov);
        ov_max = fmax(ov_max, ov);
    }
    GF_CHECK_OK(st, &ctx);
    printf("  p = 0.5, dt = %.4g t_c: ran %ld steps, max speed %.3g sqrt(gD), max overlap %.4f D\n", dt_over_tc, n,
           vmax / vref, ov_max);
    GF_CHECK(isfinite(vmax) && vmax < vref);
    GF_CHECK(ov_max < 0.05);
    gf_sim_destroy(&sim);
}

/* Isolated-sphere terminal velocity, Schiller–Naumann drag, fixed point. */
static double terminal_velocity(double D, double rho_p, double rho_f, double eta, double g)
{
    double u = (rho_p - rho_f) * g * D * D / (18.0 * eta);
    for (int k = 0; k < 200; ++k) {
        double re = rho_f * u * D / eta;
        u = (rho_p - rho_f) * g * D * D / (18.0 * eta * (1.0 + 0.15 * pow(re, 0.687)));
    }
    return u;
}

static void corner(double St, double r)
{
    gf_ctx ctx = {0};
    const double D = 7.6e-3, rho_p = 2500.0, g = 9.81;
    double rho_f, eta;
    GF_CHECK_OK(gf_groups_invert(&ctx, St, r, D, rho_p, g, &rho_f, &eta), &ctx);
    gf_run_spec s;
    gf_run_spec_defaults(&s);
    snprintf(s.scene, sizeof s.scene, "settling");
    s.grains.diameter_m = D;
    s.grains.density_kg_m3 = rho_p;
    s.grains.polydispersity = 0.0;
    snprintf(s.fluid.model, sizeof s.fluid.model, "unresolved");
    s.fluid.density_kg_m3 = rho_f;
    s.fluid.viscosity_Pa_s = eta;
    gf_run_spec_set_param(&ctx, &s, "box_over_D", 8.0);
    gf_sim *sim = NULL;
    gf_status st = gf_test_sim(&ctx, &s, 1, &sim);
    GF_CHECK_OK(st, &ctx);
    if (!sim)
        return;
    gf_particles *p = gf_sim_particles(sim);
    double t_run = 5.0 * sqrt(D / g);
    long n = (long)ceil(t_run / gf_sim_dt_s(sim));
    if (St < 0.1)
        n /= 10, t_run /= 10.0;
    double wall = gf_wtime();
    st = gf_sim_advance(sim, n);
    wall = gf_wtime() - wall;
    double ut = terminal_velocity(D, rho_p, rho_f, eta, g);
    double bound = 1.5 * fmin(ut, (1.0 - rho_f / rho_p) * g * t_run) + 0.01 * sqrt(g * D);
    double vmax = stress_max_speed(p);
    printf("  St %-6g r %-4g (rho_f %.4g kg/m3, eta %.3g Pa s, u_T %.3g m/s, Re_T %.3g): %s, %ld steps in %.1f s, "
           "max grain speed %.3g m/s (bound %.3g)\n",
           St, r, rho_f, eta, ut, rho_f * ut * D / eta, st == GF_OK ? "ran" : ctx.last_msg, n, wall, vmax, bound);
    GF_CHECK_OK(st, &ctx);
    GF_CHECK(isfinite(vmax) && vmax <= bound);
    gf_sim_destroy(&sim);
}

int main(void)
{
    gf_run_spec probe;
    gf_run_spec_defaults(&probe);
    probe.grains.polydispersity = 0.5;
    const double limit = gf_run_spec_dt_limit_over_tc(&probe);
    printf("polydisperse bed, radii R(1 -+ 0.5): dt limit %.4g t_c\n", limit);
    polydisperse_bed(0.02, 0);
    polydisperse_bed(0.95 * limit, 0);
    polydisperse_bed(1.01 * limit, 1);
    printf("(St, r) corners, settling suspension phi 0.2:\n");
    const double corners[4][2] = {{0.01, 1.3}, {0.01, 100.0}, {1000.0, 1.3}, {1000.0, 100.0}};
    for (int k = 0; k < 4; ++k)
        corner(corners[k][0], corners[k][1]);
    return gf_test_finish();
}
