/*
 * The settling scene through the full step loop (gf_sim: contacts, velocity
 * Verlet, sub-cycled unresolved coupling): a homogeneous suspension at
 * phi = 0.2, Re_t = 0.05, settles at the Richardson–Zaki velocity
 * U/U_t = 0.8^4.65 = 0.354 within 10 % (issue #4), as the coupling-only test
 * test_hindered_settling finds with its own minimal integrator.
 * The contact time is raised to 0.1 sqrt(D/g) (grains on a lattice at
 * phi = 0.2 do not touch; the DEM step only has to resolve the drag, which
 * the exponential update does at any step).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gf_sim.h"
#include "gf_test.h"
#include "scenes/gf_scene.h"

int main(void)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    gf_run_spec_defaults(&spec);
    snprintf(spec.scene, sizeof spec.scene, "settling");
    double D = 1e-3, rp = 2500, rf = 1000, g = 9.81;
    spec.grains = (gf_grains_spec){.diameter_m = D, .polydispersity = 0.0, .density_kg_m3 = rp};
    snprintf(spec.fluid.model, sizeof spec.fluid.model, "unresolved");
    spec.fluid.density_kg_m3 = rf;
    spec.fluid.viscosity_Pa_s = sqrt(rf * (rp - rf) * g * D * D * D / (18.0 * 0.05));
    spec.fluid.lubrication = 0;
    spec.contact.t_contact_nd = 0.1;
    spec.end_time_nd = 30.0;
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "mode", 1.0), &ctx);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "phi_suspension", 0.2), &ctx);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "box_over_D", 12.0), &ctx);
    gf_sim_options opt = {0};
    gf_sim *sim = NULL;
    GF_CHECK_OK(gf_sim_create(&ctx, &spec, &opt, &sim), &ctx);
    if (!sim)
        return gf_test_finish();
    double t_end = gf_sim_end_time_s(sim), dt = gf_sim_dt_s(sim);
    double t0 = gf_wtime();
    GF_CHECK_OK(gf_sim_advance(sim, (long)ceil(t_end / dt)), &ctx);
    double wall = gf_wtime() - t0;
    const gf_scene_desc *sc = gf_scene_find("settling");
    double v[3] = {NAN, NAN, NAN};
    GF_CHECK_OK(sc->diagnose(sim, v), &ctx);
    const gf_timers *tm = gf_sim_timers(sim);
    double rz = pow(0.8, 4.65);
    printf("settling scene: %zu grains, t = %.3g s, U/U_St = %.4f vs Richardson-Zaki %.4f (%+.1f %%); wall %.2f s "
           "(fluid %.2f s, coupling %.2f s, force %.2f s)\n",
           gf_sim_particles(sim)->n_local, gf_sim_time_s(sim), v[2], rz, 100 * (v[2] / rz - 1), wall,
           tm->elapsed_s[GF_T_FLUID], tm->elapsed_s[GF_T_COUPLING], tm->elapsed_s[GF_T_FORCE]);
    GF_CHECK_REL(v[2], rz, 0.10);
    gf_sim_destroy(&sim);
    return gf_test_finish();
}
