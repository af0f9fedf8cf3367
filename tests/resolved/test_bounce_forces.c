/*
 * The bounce scene's force split (diagnostics hydrodynamic_force_y_over_buoyant_weight and
 * wall_force_y_over_buoyant_weight), on the sphere of Izard 2014 §3.1.5 (rho_p/rho = 8,
 * eta = 0.25 Pa s, D = 15 mm, eta_e/R = 4e-4, lubrication cut-off R/2) released 1.5 D above
 * a no-slip wall, resolved tier at D/dx = 6, to its first contact.
 *
 * Asserted:
 *   - above the lubrication range (gap > R/2) the wall force is exactly 0, and while the sphere
 *     still accelerates downwards the flow's force beyond the buoyancy lies in (0, 1) buoyant
 *     weights: it opposes the fall and, by Newton's law, is smaller than the buoyant weight;
 *   - inside the range, before contact, the wall force is Brenner's (1961) lubrication,
 *     6 pi eta R^2 u/(gap + eta_e) to leading order (Izard 2014 eq. (2.40)), within 5 %: the
 *     DEM applies it as an exponential damping over the step (engine/contact/gf_lubrication.h)
 *     and with the velocity of the force pass, half a step from the one sampled here;
 *   - the two parts and the buoyancy rho_f V g add up to the scene's force_y_over_buoyant_weight
 *     (round-off).
 */
#include <math.h>
#include <stdio.h>

#include "gf_sim.h"
#include "gf_test.h"
#include "scenes/gf_scene.h"

enum { DIAG_FORCE = 2, DIAG_HYDRO = 6, DIAG_WALL = 7, N_DIAG = 8 };

static void bounce_spec(gf_ctx *ctx, gf_run_spec *spec)
{
    gf_run_spec_defaults(spec);
    snprintf(spec->scene, sizeof spec->scene, "bounce");
    spec->grains = (gf_grains_spec){.diameter_m = 0.015, .polydispersity = 0.0, .density_kg_m3 = 8000.0};
    spec->contact.restitution = 0.97;
    spec->contact.t_contact_nd = 2.5e-3;
    spec->contact.friction = spec->contact.wall_friction = 0.25;
    snprintf(spec->fluid.model, sizeof spec->fluid.model, "resolved");
    spec->fluid.density_kg_m3 = 1000.0;
    spec->fluid.viscosity_Pa_s = 0.25;
    spec->fluid.lubrication = 1;
    spec->fluid.roughness_over_R = 4e-4;
    spec->fluid.lub_cutoff_over_R = 0.5;
    spec->fluid.d_over_dx = 6;
    spec->end_time_nd = 6.0;
    GF_CHECK_OK(gf_run_spec_set_param(ctx, spec, "box_over_D", 3.0), ctx);
    GF_CHECK_OK(gf_run_spec_set_param(ctx, spec, "height_over_D", 4.0), ctx);
    GF_CHECK_OK(gf_run_spec_set_param(ctx, spec, "release_depth_over_D", 2.0), ctx);
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    bounce_spec(&ctx, &spec);
    gf_sim *sim = NULL;
    GF_CHECK_OK(gf_sim_create(&ctx, &spec, &(gf_sim_options){.n_threads = 1}, &sim), &ctx);
    if (!sim)
        return gf_test_finish();
    const gf_scene_desc *scene = gf_scene_find("bounce");
    GF_CHECK(scene && scene->n_diag == N_DIAG);
    const gf_particles *p = gf_sim_particles(sim);
    const double D = spec.grains.diameter_m, R = 0.5 * D, eta = spec.fluid.viscosity_Pa_s;
    const double W = (spec.grains.density_kg_m3 - spec.fluid.density_kg_m3) * 4.0 / 3.0 * M_PI * R * R * R *
                     spec.gravity_m_s2;
    const double buoyancy = spec.fluid.density_kg_m3 / (spec.grains.density_kg_m3 - spec.fluid.density_kg_m3);
    double v[N_DIAG], v_prev = 0.0, worst_lub = 0.0, worst_sum = 0.0, hydro_lo = INFINITY, hydro_hi = -INFINITY;
    long n_far = 0, n_lub = 0, n_far_wall = 0;
    while (gf_sim_time_s(sim) < gf_sim_end_time_s(sim)) {
        GF_CHECK_OK(gf_sim_advance(sim, 1), &ctx);
        GF_CHECK_OK(scene->diagnose(sim, v), &ctx);
        double vy = p->vy_m_s[0], gap = v[1] * D;
        if (gap <= 0.0)
            break; /* first contact */
        worst_sum = fmax(worst_sum, fabs(v[DIAG_HYDRO] + v[DIAG_WALL] + buoyancy - v[DIAG_FORCE]));
        if (gap > 0.5 * R) {
            n_far_wall += v[DIAG_WALL] != 0.0;
            if (vy < v_prev && gf_sim_time_s(sim) > 0.2 * sqrt(D / spec.gravity_m_s2)) { /* still accelerating */
                ++n_far;
                hydro_lo = fmin(hydro_lo, v[DIAG_HYDRO]), hydro_hi = fmax(hydro_hi, v[DIAG_HYDRO]);
            }
        } else if (gap > 0.02 * D) {
            double brenner = -6.0 * M_PI * eta * R * R * vy / (gap + spec.fluid.roughness_over_R * R);
            worst_lub = fmax(worst_lub, fabs(v[DIAG_WALL] * W / brenner - 1.0));
            ++n_lub;
        }
        v_prev = vy;
    }
    printf("bounce force split, D/dx 6: %ld samples accelerating above the lubrication range, drag/W in [%.4f, %.4f]; "
           "wall force nonzero there %ld times; %ld samples in the lubrication range, wall force against Brenner "
           "within %.2f %%; |hydro + wall + buoyancy - total| <= %.2g W\n",
           n_far, hydro_lo, hydro_hi, n_far_wall, n_lub, 100.0 * worst_lub, worst_sum);
    GF_CHECK(n_far > 50 && n_lub > 20);
    GF_CHECK(n_far_wall == 0);
    GF_CHECK(hydro_lo > 0.0 && hydro_hi < 1.0);
    GF_CHECK(worst_lub < 0.05);
    GF_CHECK(worst_sum < 1e-9);
    gf_sim_destroy(&sim);
    return gf_test_finish();
}
