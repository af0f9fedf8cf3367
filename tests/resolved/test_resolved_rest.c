/*
 * A sphere at rest on a wall in the resolved tier presses on it with its buoyant weight
 * (rho_p - rho) V g: Archimedes, whatever the method. rho_p/rho = 2, where the two answers
 * differ most (a factor rho_p/(rho_p - rho) = 2), released 0.6 D above the no-slip floor of
 * the bounce scene in a viscous fluid (Ar = 10), the thesis' lubrication (eta_e/R 4e-4, cut-off
 * R/2, off in overlap), D/dx = 8 in a 4 D box, run to 32 sqrt(D/g) (the film has drained and the
 * sphere rests in contact from ~29); the wall's force (contact and lubrication) is the
 * diagnostic wall_force_y_over_buoyant_weight.
 *
 * Asserted:
 *   - with fluid.ibm_contact_correction (the default) the wall force is the buoyant weight
 *     within 1 %;
 *   - with Izard's force formula alone, F = -(rho rho_p/(rho_p - rho)) int f (Izard 2014 eq.
 *     (2.32); correction 0), it is the dry weight m g, rho_p/(rho_p - rho) = 2 buoyant
 *     weights, within 1 %: what the correction is for (engine/coupling/gf_coupling_resolved.c,
 *     "The contact correction"). The fluid is at rest by then, so the forcing integral
 *     vanishes and the formula carries no buoyancy; only the correction puts it back.
 */
#include <math.h>
#include <stdio.h>

#include "gf_sim.h"
#include "gf_test.h"
#include "scenes/gf_scene.h"

enum { DIAG_VY = 0, DIAG_GAP = 1, DIAG_WALL = 7, N_DIAG = 8 };

#define RATIO 2.0
#define AR 10.0
#define T_END_ND 32.0

/* Wall force over the buoyant weight at T_END_ND, with the correction on or off. */
static double wall_force_at_rest(gf_ctx *ctx, int correction)
{
    const double rho = 1000.0, g = 9.81, eta = 0.1;
    const double D = cbrt(AR * eta * eta / (rho * rho * (RATIO - 1.0) * g)); /* Ar = (drho/rho) g D^3 / nu^2 */
    gf_run_spec spec;
    gf_run_spec_defaults(&spec);
    snprintf(spec.scene, sizeof spec.scene, "bounce");
    spec.gravity_m_s2 = g;
    spec.grains = (gf_grains_spec){.diameter_m = D, .polydispersity = 0.0, .density_kg_m3 = RATIO * rho};
    snprintf(spec.fluid.model, sizeof spec.fluid.model, "resolved");
    spec.fluid.density_kg_m3 = rho;
    spec.fluid.viscosity_Pa_s = eta;
    spec.fluid.lubrication = 1; /* the thesis' (Izard 2014 §3.1.2.2): without it the sphere keeps hopping on the wall */
    spec.fluid.roughness_over_R = 4e-4;
    spec.fluid.lub_cutoff_over_R = 0.5;
    snprintf(spec.fluid.lub_overlap, sizeof spec.fluid.lub_overlap, "off");
    spec.fluid.d_over_dx = 8.0;
    spec.fluid.ibm_contact_correction = correction;
    spec.end_time_nd = T_END_ND;
    GF_CHECK_OK(gf_run_spec_set_param(ctx, &spec, "box_over_D", 4.0), ctx);
    GF_CHECK_OK(gf_run_spec_set_param(ctx, &spec, "height_over_D", 4.0), ctx);
    GF_CHECK_OK(gf_run_spec_set_param(ctx, &spec, "release_depth_over_D", 2.9), ctx); /* 0.6 D above the floor */
    gf_sim *sim = NULL;
    double v[N_DIAG] = {NAN};
    GF_CHECK_OK(gf_sim_create(ctx, &spec, &(gf_sim_options){.n_threads = 1}, &sim), ctx);
    if (!sim)
        return NAN;
    long n = (long)ceil(T_END_ND * sqrt(D / g) / gf_sim_dt_s(sim));
    GF_CHECK_OK(gf_sim_advance(sim, n), ctx);
    const gf_scene_desc *d = gf_scene_find("bounce");
    GF_CHECK(d && d->diagnose && d->n_diag == N_DIAG);
    if (d && d->diagnose && d->n_diag == N_DIAG)
        GF_CHECK_OK(d->diagnose(sim, v), ctx);
    gf_sim_destroy(&sim);
    printf("correction %d: gap %.4g D, velocity %.3g m/s, wall force %.4f W at %g sqrt(D/g)\n", correction, v[DIAG_GAP],
           v[DIAG_VY], v[DIAG_WALL], T_END_ND);
    return v[DIAG_WALL];
}

int main(void)
{
    gf_ctx ctx = {0};
    const double with = wall_force_at_rest(&ctx, 1), without = wall_force_at_rest(&ctx, 0);
    printf("sphere at rest on the wall, rho_p/rho %.0f: wall force / buoyant weight %.4f with the contact correction "
           "(1 expected), %.4f with Izard's formula alone (rho_p/(rho_p - rho) = %.4f)\n",
           RATIO, with, without, RATIO / (RATIO - 1.0));
    GF_CHECK_REL(with, 1.0, 0.01);
    GF_CHECK_REL(without, RATIO / (RATIO - 1.0), 0.01);
    return gf_test_finish();
}
