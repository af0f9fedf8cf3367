/*
 * Long run of a static bed: no drift, no creep, no energy from nowhere.
 *
 * A settled frictional bed (settled_bed scene: 320 grains, 10 %
 * polydispersity, eps 0.5, mu 0.5, floor at y = 0, periodic x and z 5.15 D
 * wide, ~20 layers) is held under gravity for many steps at dt = t_c/50.
 * Nothing drives it, so the exact solution is rest: any motion is numerical
 * (round-off in the force sums, the tangential springs, neighbour rebuilds).
 * The scene's settling ends on a velocity quench; 10 sqrt(D/g) of relaxation
 * come first (not part of the claims: the quenched state is not an exact
 * equilibrium, its release peaks at 0.05 sqrt(gD)). Claims, sampled every
 * 2000 steps (at most 4000 samples) over the watched run:
 *  - every grain stays slower than 1e-2 sqrt(gD) (a grain at that speed
 *    would cross its own diameter in 100 sqrt(D/g); measured peaks
 *    0.4e-3 to 1.6e-3 sqrt(gD), the last creep of the quenched pack), and the
 *    fastest grain of the second half is slower than that of the first;
 *  - the kinetic energy does not grow: its largest value in the second half
 *    of the run is below its largest value in the first half (the
 *    dissipative contacts can only remove energy from a bed at rest);
 *  - no creep: the bed's centre of mass moves by less than 1e-4 D, and the
 *    grain count and the largest overlap (below 1 % of D: the weight of 20
 *    layers on the stiffness of t_c = 1e-2 sqrt(D/g)) do not change.
 * Usage: test_stress_static_bed [BUDGET_S [MAX_STEPS]]: runs until MAX_STEPS
 * (default 1e7) or BUDGET_S seconds of wall time (0: no limit). The default
 * suite runs 25 s; the `slow` run does the full 1e7 steps.
 */
#include <stdlib.h>

#include "core/gf_timer.h"
#include "stress_util.h"

int main(int argc, char **argv)
{
    double budget_s = argc > 1 ? atof(argv[1]) : 25.0;
    long max_steps = argc > 2 ? atol(argv[2]) : 10000000L;
    gf_ctx ctx = {0};
    gf_run_spec s = gf_test_spec("settled_bed");
    s.grains.polydispersity = 0.1;
    s.contact.restitution = 0.5;
    s.contact.friction = 0.5;
    s.contact.wall_friction = 0.5;
    gf_run_spec_set_param(&ctx, &s, "n_grains", 320);
    /* 4 x 4 grains per layer at spacing 1.17 D_max (the scene's stack spacing 1.16 D_max) */
    gf_run_spec_set_param(&ctx, &s, "width_over_D", 5.15);
    gf_run_spec_set_param(&ctx, &s, "settle_time_nd", 8.0);
    gf_sim *sim = NULL;
    GF_CHECK_OK(gf_test_sim(&ctx, &s, 1, &sim), &ctx);
    if (!sim)
        return gf_test_finish();
    gf_particles *p = gf_sim_particles(sim);
    const double D = s.grains.diameter_m, vref = sqrt(s.gravity_m_s2 * D);
    /* the scene's settling ends on a velocity quench, which leaves the last
     * small force imbalances: let them relax for 10 sqrt(D/g) (measured peak
     * 0.05 sqrt(gD) just after the quench), then watch */
    long n_relax = (long)ceil(10.0 * sqrt(D / s.gravity_m_s2) / gf_sim_dt_s(sim));
    GF_CHECK_OK(gf_sim_advance(sim, n_relax), &ctx);
    double v_relaxed = stress_max_speed(p);
    const size_t n0 = p->n_local;
    double ycm0 = 0.0, mass = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        ycm0 += p->mass_kg[i] * p->y_m[i], mass += p->mass_kg[i];
    ycm0 /= mass;
    double ov0;
    gf_sim_contact_stats(sim, NULL, &ov0);

    /* samples every 2000 steps (20 t_c), at most 4096 of them over the run */
    long chunk = max_steps / 4000 > 2000 ? max_steps / 4000 : 2000;
    double t_start = gf_wtime(), ek_first = 0.0, ek_second = 0.0, vmax = 0.0, dy_max = 0.0, ov_max = ov0;
    long done = 0;
    int n_samples = 0;
    static double ek[4096], vs[4096];
    double v_first = 0.0, v_second = 0.0;
    gf_status st = GF_OK;
    while (done < max_steps && st == GF_OK) {
        long n = chunk < max_steps - done ? chunk : max_steps - done;
        st = gf_sim_advance(sim, n);
        done += n;
        double ycm = 0.0, ov;
        for (size_t i = 0; i < p->n_local; ++i)
            ycm += p->mass_kg[i] * p->y_m[i];
        dy_max = fmax(dy_max, fabs(ycm / mass - ycm0));
        vmax = fmax(vmax, stress_max_speed(p));
        if (n_samples < 4096)
            vs[n_samples] = stress_max_speed(p);
        gf_sim_contact_stats(sim, NULL, &ov);
        ov_max = fmax(ov_max, ov);
        if (n_samples < 4096)
            ek[n_samples++] = gf_particles_kinetic_energy(p);
        GF_CHECK(p->n_local == n0);
        if (budget_s > 0.0 && gf_wtime() - t_start > budget_s)
            break;
    }
    GF_CHECK_OK(st, &ctx);
    for (int k = 0; k < n_samples; ++k) {
        if (k < n_samples / 2)
            ek_first = fmax(ek_first, ek[k]), v_first = fmax(v_first, vs[k]);
        else
            ek_second = fmax(ek_second, ek[k]), v_second = fmax(v_second, vs[k]);
    }
    double mgd = mass / n0 * s.gravity_m_s2 * D;
    printf("after %ld relaxation steps: max speed %.3g sqrt(gD)\n", n_relax, v_relaxed / vref);
    printf("max grain speed: first half %.3g, second half %.3g sqrt(gD)\n", v_first / vref, v_second / vref);
    printf("static bed, %zu grains, %ld steps (%.3g sqrt(D/g)) in %.1f s: max speed %.3g sqrt(gD), "
           "E_k max first half %.3g, second half %.3g (m g D per grain), centre-of-mass shift %.3g D, "
           "max overlap %.4f D (start %.4f D)\n",
           n0, done, gf_sim_time_s(sim) / sqrt(D / s.gravity_m_s2), gf_wtime() - t_start, vmax / vref,
           ek_first / (n0 * mgd), ek_second / (n0 * mgd), dy_max / D, ov_max, ov0);
    GF_CHECK(done >= 1000);
    GF_CHECK(vmax < 1e-2 * vref);
    GF_CHECK(v_second <= v_first);
    GF_CHECK(ek_second <= ek_first);
    GF_CHECK(dy_max < 1e-4 * D);
    GF_CHECK(ov_max < 0.01);
    GF_CHECK(fabs(ov_max - ov0) < 1e-3);
    gf_sim_destroy(&sim);
    return gf_test_finish();
}
