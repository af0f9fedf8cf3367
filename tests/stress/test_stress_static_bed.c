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
 * Immersed modes (third argument "immersed" or "immersed_lub"): the same bed
 * in the seed's viscous fluid of the immersed collapse (D = 7.6 mm,
 * rho_p/rho_f = 8, eta_f = 1 Pa s, Ar ~ 30; Izard 2014 §5.2) through the
 * unresolved tier, without ("immersed") or with ("immersed_lub") the
 * near-contact lubrication. The fluid starts at rest and hydrostatic; a bed
 * at rest drives no flow, so besides the dry claims the excess pore
 * pressure at the basal gauge must stay near zero: after the relaxation,
 * |P_b| < 1e-3 of the bed's buoyant weight per unit area, drho g sum(V_i)/A
 * (a tenth of a percent of what the grains would put on the fluid if the
 * bed liquefied). With lubrication the claims do not hold (ctest labels
 * slow;open): the bed creeps in bursts (the fastest grain grows
 * exponentially, ~0.05 per sqrt(D/g), from 1e-4 to ~4e-3 sqrt(gD), the bed
 * sinks by ~1e-5 D, then falls quiet, and again; docs/notes/benchmarks.md). The
 * bursts need the lubrication (without it the same bed relaxes to 1e-11
 * sqrt(gD)) and its large viscosity (none in water); a smaller damping cap
 * (0.1 instead of 0.25 m* / dt) did not remove them, so they are not the
 * explicit stability limit of the lubrication damping. The energy audit
 * (gf_sim_energy_audit) settles what they are: the total mechanical energy
 * (kinetic, buoyant weight, elastic springs) falls through every burst and
 * never rises above its running minimum, so no energy is created; each burst
 * is the quenched packing leaving a marginal equilibrium, slowly because the
 * near-contact lubrication overdamps it (the grains sink and the energy
 * released is dissipated). The no-creep claims stay open for this mode: the
 * lubricated bed needs far longer than 30 sqrt(D/g) to find a stable state.
 * Claim of every mode: the total mechanical energy never rises above its
 * running minimum by more than 1e-10 m g D per grain (round-off).
 * Usage: test_stress_static_bed [BUDGET_S [MAX_STEPS [immersed|immersed_lub]]]: runs until
 * MAX_STEPS (default 1e7) or BUDGET_S seconds of wall time (0: no limit). The
 * default suite runs 25 s of each mode; the `slow` runs do the full 1e7 steps.
 */
#include <stdlib.h>
#include <string.h>

#include "core/gf_timer.h"
#include "stress_util.h"

/* The seed's grains and fluid of the immersed collapse (Izard 2014 §5.2). */
static void immersed_spec(gf_run_spec *s, int lubricated)
{
    s->fluid.lubrication = lubricated;
    s->grains.diameter_m = 7.6e-3;
    s->grains.density_kg_m3 = 8000.0;
    snprintf(s->fluid.model, sizeof s->fluid.model, "unresolved");
    s->fluid.density_kg_m3 = 1000.0;
    s->fluid.viscosity_Pa_s = 1.0;
}

/* Excess pore pressure at the floor gauge of the settled_bed scene, Pa. */
static double basal_pressure(gf_sim *sim)
{
    double lo[3], hi[3];
    int per[3];
    gf_sim_box(sim, lo, hi, per);
    double x[3] = {0.5 * (lo[0] + hi[0]), lo[1], 0.5 * (lo[2] + hi[2])};
    return gf_sim_excess_pressure_Pa(sim, x);
}

int main(int argc, char **argv)
{
    double budget_s = argc > 1 ? atof(argv[1]) : 25.0;
    long max_steps = argc > 2 ? atol(argv[2]) : 10000000L;
    int immersed = argc > 3 && strncmp(argv[3], "immersed", 8) == 0;
    int lubricated = argc > 3 && strcmp(argv[3], "immersed_lub") == 0;
    gf_ctx ctx = {0};
    gf_run_spec s = gf_test_spec("settled_bed");
    if (immersed)
        immersed_spec(&s, lubricated);
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
    /* immersed: the fluid (and with it the buoyancy) appears at t = 0 and
     * unloads the contacts; that transient is slow in a viscous fluid (the
     * fastest grain at ~0.01 sqrt(gD) until ~20 sqrt(D/g)): 30 sqrt(D/g) */
    long n_relax = (long)ceil((immersed ? 30.0 : 10.0) * sqrt(D / s.gravity_m_s2) / gf_sim_dt_s(sim));
    GF_CHECK_OK(gf_sim_advance(sim, n_relax), &ctx);
    double v_relaxed = stress_max_speed(p);
    const size_t n0 = p->n_local;
    double ycm0 = 0.0, mass = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        ycm0 += p->mass_kg[i] * p->y_m[i], mass += p->mass_kg[i];
    ycm0 /= mass;
    double ov0;
    gf_sim_contact_stats(sim, NULL, &ov0);
    double lo[3], hi[3], vol = 0.0;
    int per[3];
    gf_sim_box(sim, lo, hi, per);
    for (size_t i = 0; i < p->n_local; ++i)
        vol += p->mass_kg[i] / s.grains.density_kg_m3;
    const double p_bed = (s.grains.density_kg_m3 - s.fluid.density_kg_m3) * s.gravity_m_s2 * vol /
                         ((hi[0] - lo[0]) * (hi[2] - lo[2]));
    double pb_relaxed = immersed ? basal_pressure(sim) : 0.0;

    /* samples every 2000 steps (20 t_c), at most 4096 of them over the run */
    long chunk = max_steps / 4000 > 2000 ? max_steps / 4000 : 2000;
    double t_start = gf_wtime(), ek_first = 0.0, ek_second = 0.0, vmax = 0.0, dy_max = 0.0, ov_max = ov0;
    long done = 0;
    int n_samples = 0;
    static double ek[4096], vs[4096], pb[4096], et[4096], tt[4096];
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
        if (n_samples < 4096) {
            pb[n_samples] = immersed ? fabs(basal_pressure(sim)) : 0.0;
            gf_sim_energy e;
            GF_CHECK_OK(gf_sim_energy_audit(sim, &e), &ctx);
            et[n_samples] = e.total_J, tt[n_samples] = gf_sim_time_s(sim);
            ek[n_samples++] = gf_particles_kinetic_energy(p);
        }
        GF_CHECK(p->n_local == n0);
        if (budget_s > 0.0 && gf_wtime() - t_start > budget_s)
            break;
    }
    GF_CHECK_OK(st, &ctx);
    double pb_first = 0.0, pb_second = 0.0;
    for (int k = 0; k < n_samples; ++k) {
        if (k < n_samples / 2)
            ek_first = fmax(ek_first, ek[k]), v_first = fmax(v_first, vs[k]), pb_first = fmax(pb_first, pb[k]);
        else
            ek_second = fmax(ek_second, ek[k]), v_second = fmax(v_second, vs[k]), pb_second = fmax(pb_second, pb[k]);
    }
    double mgd = mass / n0 * s.gravity_m_s2 * D;
    /* energy audit: the largest rise of the total mechanical energy above its
     * running minimum (energy from nowhere), against the energy released */
    double e_min = et[0], rise = 0.0, t_rise = 0.0;
    for (int k = 1; k < n_samples; ++k) {
        if (et[k] - e_min > rise)
            rise = et[k] - e_min, t_rise = tt[k];
        e_min = fmin(e_min, et[k]);
    }
    printf("energy audit: total mechanical energy released %.3g, largest rise above the running minimum %.3g "
           "(at %.3g sqrt(D/g)) (m g D per grain)\n",
           (et[0] - et[n_samples - 1]) / (n0 * mgd), rise / (n0 * mgd), t_rise / sqrt(D / s.gravity_m_s2));
    for (int k = 0; k < n_samples; k += n_samples / 20 > 0 ? n_samples / 20 : 1)
        printf("  t %.1f sqrt(D/g): max speed %.3g sqrt(gD), E - E_0 %+.4g m g D per grain\n",
               tt[k] / sqrt(D / s.gravity_m_s2), vs[k] / vref, (et[k] - et[0]) / (n0 * mgd));
    printf("after %ld relaxation steps: max speed %.3g sqrt(gD)\n", n_relax, v_relaxed / vref);
    printf("max grain speed: first half %.3g, second half %.3g sqrt(gD)\n", v_first / vref, v_second / vref);
    printf("static bed, %zu grains, %ld steps (%.3g sqrt(D/g)) in %.1f s: max speed %.3g sqrt(gD), "
           "E_k max first half %.3g, second half %.3g (m g D per grain), centre-of-mass shift %.3g D, "
           "max overlap %.4f D (start %.4f D)\n",
           n0, done, gf_sim_time_s(sim) / sqrt(D / s.gravity_m_s2), gf_wtime() - t_start, vmax / vref,
           ek_first / (n0 * mgd), ek_second / (n0 * mgd), dy_max / D, ov_max, ov0);
    if (immersed) {
        printf("basal excess pore pressure / (drho g sum V / A = %.4g Pa): after relaxation %+.3g, "
               "max |P_b| first half %.3g, second half %.3g\n",
               p_bed, pb_relaxed / p_bed, pb_first / p_bed, pb_second / p_bed);
        GF_CHECK(pb_first < 1e-3 * p_bed && pb_second < 1e-3 * p_bed);
    }
    /* no energy from nowhere: round-off of the sums (|E_grav| ~ 10 m g D per
     * grain) is ~1e-13 per grain; 1e-10 is 5 orders below a creep burst */
    GF_CHECK(rise < 1e-10 * n0 * mgd);
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
