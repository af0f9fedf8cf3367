/*
 * Invariants under stress: dense, polydisperse granular gases in a fully
 * periodic box (elastic_gas scene, no gravity, no walls), solid fraction
 * 0.38 (343 grains, 10 % polydispersity, rms speed 2 sqrt(gD)).
 *
 *  1. Frictional and dissipative (eps 0.5, mu 0.5, kt/kn 0.2): every pair
 *     force is equal and opposite (tangential included) and periodic images
 *     carry the same force, so the total linear momentum is conserved to
 *     round-off: |P(t) - P(0)| <= 1e-12 sum m|v(0)| over 2e4 steps (the sum
 *     of N ~ 1e3 forces per step in double precision loses ~1e-16 each). The
 *     grain count is unchanged (no grain lost through a periodic face), and
 *     the gas cools (kinetic energy at the end below its start: it cannot
 *     gain energy; Haff's law is not asserted here).
 *  2. Elastic and frictionless (eps 1, mu 0): total energy kinetic +
 *     (1/2) k_n delta^2 (one k_n for every pair, gf_contact.h) is conserved by
 *     the ODE and by velocity Verlet up to the O((omega dt)^2) shadow-energy
 *     oscillation during contacts: |E(t)/E(0) - 1| <= 2e-3 at dt = t_c/50
 *     over 2e4 steps at phi 0.38, where ~10 % of the grains are in contact at
 *     any time (the dilute-gas bound of test_dem_elastic_gas is 1e-4 at
 *     t_c/100; accuracy benchmark: 1.5e-4 at t_c/50, phi 0.27).
 */
#include "stress_util.h"

static gf_run_spec dense_gas(gf_ctx *ctx, double eps, double mu)
{
    gf_run_spec s = gf_test_spec("elastic_gas");
    s.grains.polydispersity = 0.1;
    s.contact.restitution = eps;
    s.contact.friction = mu;
    s.contact.wall_friction = mu;
    gf_run_spec_set_param(ctx, &s, "n_grains", 343);
    /* phi = 343 (pi/6) <D^3> / L^3 = 0.38 with <D^3> = D^3 (1 + p^2) for radii uniform in R(1 +- p) */
    double L = cbrt(343.0 * M_PI / 6.0 * (1.0 + 0.01) / 0.38);
    gf_run_spec_set_param(ctx, &s, "box_over_D", L);
    gf_run_spec_set_param(ctx, &s, "speed_nd", 2.0);
    return s;
}

int main(void)
{
    gf_ctx ctx = {0};
    /* 1. frictional dissipative gas */
    gf_run_spec s = dense_gas(&ctx, 0.5, 0.5);
    gf_sim *sim = NULL;
    GF_CHECK_OK(gf_test_sim(&ctx, &s, 1, &sim), &ctx);
    if (sim) {
        gf_particles *p = gf_sim_particles(sim);
        size_t n0 = p->n_local;
        double P0[3], scale = 0.0, ek0 = gf_particles_kinetic_energy(p), worst = 0.0;
        gf_particles_momentum(p, P0);
        for (size_t i = 0; i < p->n_local; ++i)
            scale += p->mass_kg[i] * sqrt(p->vx_m_s[i] * p->vx_m_s[i] + p->vy_m_s[i] * p->vy_m_s[i] +
                                          p->vz_m_s[i] * p->vz_m_s[i]);
        long contacts = 0;
        for (int k = 0; k < 20; ++k) {
            GF_CHECK_OK(gf_sim_advance(sim, 1000), &ctx);
            double P[3];
            gf_particles_momentum(p, P);
            for (int a = 0; a < 3; ++a)
                worst = fmax(worst, fabs(P[a] - P0[a]) / scale);
            size_t nc;
            gf_sim_contact_stats(sim, &nc, NULL);
            contacts += (long)nc;
            GF_CHECK(p->n_local == n0);
        }
        double ek = gf_particles_kinetic_energy(p);
        printf("frictional gas, phi 0.38, 343 grains, 2e4 steps: max |dP|/sum m|v| = %.3g, grains %zu -> %zu, "
               "E_k/E_k0 = %.3g, mean contacts at samples %.1f\n",
               worst, n0, p->n_local, ek / ek0, contacts / 20.0);
        GF_CHECK(worst <= 1e-12);
        GF_CHECK(ek < ek0);
        GF_CHECK(contacts > 0);
        gf_sim_destroy(&sim);
    }

    /* 2. elastic frictionless gas */
    s = dense_gas(&ctx, 1.0, 0.0);
    GF_CHECK_OK(gf_test_sim(&ctx, &s, 1, &sim), &ctx);
    if (sim) {
        gf_particles *p = gf_sim_particles(sim);
        double e0 = gf_particles_kinetic_energy(p) + gf_test_spring_energy(sim), worst = 0.0;
        for (int k = 0; k < 40; ++k) {
            GF_CHECK_OK(gf_sim_advance(sim, 500), &ctx);
            worst = fmax(worst, fabs((gf_particles_kinetic_energy(p) + gf_test_spring_energy(sim)) / e0 - 1.0));
        }
        printf("elastic gas, phi 0.38, dt = t_c/50, 2e4 steps: max |E/E0 - 1| = %.3g\n", worst);
        GF_CHECK(worst <= 2e-3);
        gf_sim_destroy(&sim);
    }
    return gf_test_finish();
}
