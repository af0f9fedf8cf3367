/*
 * resolved_early_acceleration: the settling sphere of the resolved tier
 * (Izard 2014 §2.2.3, Fig. 2.15; docs/resolved.md "Settling sphere"),
 * rho_p/rho = 4, Ar = rho drho g D^3 / eta^2 = 800, scene bounce with
 * free-slip walls everywhere, released 2.5 D below the top of a 4 D x 6 D box,
 * the set-up of tests/resolved/resolved_settling.c's early phase.
 *
 * Observable: the acceleration a/g as t -> 0, 1 - F_h/(m g) with the force
 * fitted as c0 + c1 sqrt(t) + c2 t over t in [0.02, 0.15] sqrt(D/g) (the
 * sqrt(t) term takes the history force out). Reference: the acceleration
 * with the added mass C_M = 1/2 of a sphere started from rest,
 * du/dt = drho g / (rho_p + rho/2) = (2/3) g (Izard 2014 eq. (2.34)).
 * Tolerance 5 % (the early-acceleration criterion of the resolved tier's
 * validation). The smoothed shell of the solid fraction adds to the added
 * mass a share that falls as (dx/D)^2, so the error falls with the grid.
 *
 * Knobs: D/dx in {8, 12, 16} (cell_over_D = dx/D; --quick: 8 and 12), and
 * fluid.ibm_retraction_dx in {0, 0.3} (the profile centred on R - c dx,
 * Breugem, J. Comput. Phys. 231, 2012). The fluid step is held at
 * 0.002 sqrt(D/g) for every grid (cfl = 0.002 D/dx on the free-fall speed
 * sqrt(gD)), so only the grid and the profile change; the fit's window then
 * holds ~65 samples. No contact happens: t_c is set to 0.05 sqrt(D/g) so that
 * the DEM sub-steps only integrate the held hydrodynamic force.
 */
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "bench_accuracy.h"
#include "gf_bench_clock.h"
#include "coupling/gf_coupling_tier.h"
#include "gf_sim.h"
#include "scenes/gf_scene.h"
#include "stages/gf_early_force.h"

#define RES_D 0.01
#define RES_RHO 1000.0
#define RES_RATIO 4.0
#define RES_AR 800.0
#define RES_DT_ND 0.002   /* fluid step and sampling interval, sqrt(D/g) */
#define RES_T_END_ND 0.15 /* end of the early phase, sqrt(D/g) */
#define RES_FIT_FROM_ND 0.02
#define RES_MAX_SAMPLES 128

const double bench_resolved_cells[] = {1.0 / 8, 1.0 / 12, 1.0 / 16};
const double bench_resolved_retract[] = {0.0, 0.3};

int bench_resolved_available(const char **why)
{
    if (!gf_scene_find("bounce") || !gf_coupling_tier_find("resolved")) {
        *why = "scene bounce or the resolved tier not in this build";
        return 0;
    }
    *why = "";
    return 1;
}

gf_status bench_settling_sphere_spec(gf_ctx *ctx, double box_over_D, double height_over_D, gf_run_spec *s)
{
    gf_run_spec_defaults(s);
    const double g = s->gravity_m_s2;
    snprintf(s->scene, sizeof s->scene, "bounce");
    s->grains = (gf_grains_spec){.diameter_m = RES_D, .polydispersity = 0.0, .density_kg_m3 = RES_RATIO * RES_RHO};
    s->fluid.density_kg_m3 = RES_RHO;
    s->fluid.viscosity_Pa_s = sqrt(RES_RHO * (RES_RATIO - 1.0) * RES_RHO * g * pow(RES_D, 3) / RES_AR);
    s->fluid.lubrication = 0;
    s->contact.t_contact_nd = 0.05; /* no contact happens: the DEM steps only integrate the hydrodynamic force */
    GF_TRY(gf_run_spec_set_param(ctx, s, "bottom_no_slip", 0.0));
    GF_TRY(gf_run_spec_set_param(ctx, s, "release_depth_over_D", 2.5));
    GF_TRY(gf_run_spec_set_param(ctx, s, "box_over_D", box_over_D));
    return gf_run_spec_set_param(ctx, s, "height_over_D", height_over_D);
}

static gf_status early_spec(gf_ctx *ctx, const bench_knobs *k, gf_run_spec *s)
{
    GF_TRY(bench_settling_sphere_spec(ctx, 4.0, 6.0, s));
    snprintf(s->fluid.model, sizeof s->fluid.model, "resolved");
    s->fluid.d_over_dx = 1.0 / k->cell_over_D;
    s->fluid.ibm_retraction_dx = k->retract_dx;
    s->fluid.cfl = RES_DT_ND * s->fluid.d_over_dx;
    s->end_time_nd = RES_T_END_ND;
    return GF_OK;
}

/* Runs the early phase, sampling F_h/(m g) (upwards) inside the fit window. */
static gf_status sample_force(gf_sim *sim, double g, double *t, double *F, int *n)
{
    const double tg = sqrt(RES_D / g);
    long chunk = (long)ceil(RES_DT_ND * tg / gf_sim_dt_s(sim));
    const gf_particles *p = gf_sim_particles(sim);
    *n = 0;
    while (gf_sim_time_s(sim) < RES_T_END_ND * tg && *n < RES_MAX_SAMPLES) {
        GF_TRY(gf_sim_advance(sim, chunk));
        double t_nd = gf_sim_time_s(sim) / tg, f = p->fy_N[0] / (p->mass_kg[0] * g);
        if (!isfinite(f))
            return GF_ERR_NUMERIC;
        if (t_nd >= RES_FIT_FROM_ND && t_nd <= RES_T_END_ND + 1e-9)
            t[*n] = t_nd, F[(*n)++] = f;
    }
    return GF_OK;
}

gf_status bench_resolved_measure(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out)
{
    (void)full;
    gf_run_spec spec;
    GF_TRY(early_spec(ctx, k, &spec));
    double t[RES_MAX_SAMPLES], F[RES_MAX_SAMPLES];
    int n = 0;
    gf_sim *sim = NULL;
    double t0 = gf_bench_cpu_time_s();
    GF_TRY(gf_sim_create(ctx, &spec, &(gf_sim_options){.n_threads = 1}, &sim));
    gf_status st = sample_force(sim, spec.gravity_m_s2, t, F, &n);
    double cost = gf_bench_cpu_time_s() - t0;
    gf_sim_destroy(&sim);
    if (st == GF_ERR_NUMERIC)
        return GF_FAIL(ctx, st, "resolved_early_acceleration: non-finite force at D/dx %g", 1.0 / k->cell_over_D);
    GF_TRY(st);
    if (n < 10)
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "resolved_early_acceleration: %d samples in the fit window", n);
    double a = 1.0 - gf_early_force_fit(t, F, n, RES_FIT_FROM_ND, RES_T_END_ND + 1e-9), ref = 2.0 / 3.0;
    *out = (bench_result){a, ref, fabs(a / ref - 1.0), cost, NAN};
    return GF_OK;
}
