/*
 * Immersed column collapse, dense vs loose (Rondon, Pouliquen & Aussillous,
 * PoF 23, 2011; Izard 2014 ch. 5, spec §7 and §8 rows 35-41), through the full
 * step loop with the unresolved tier. Not a ctest test (minutes): run by
 * tests/fluid/validate_fluid.sh, which writes docs/validation.md.
 *
 * Set-up: the column_collapse scene at a = 0.5, R0 = 16 D, W = 3 D, the seed's
 * fluid and grains (D = 7.6 mm, rho_p/rho_f = 8, eta_f = 1 Pa s: Ar ~ 30,
 * viscous regime). Prints one summary line per run:
 *   phi_i, start time (front past R0 + D/2) in T_visq, run-out R_inf/R0,
 *   H_inf/R0, deposit type (trapezoid when the back keeps >= 90 % of H0),
 *   basal excess pore pressure at x = 13/16 R0: extremum (Pa and / drho g H0)
 *   and its time, E_cx^max / (m g D), wall time split fluid / DEM.
 * Usage: validate_collapse PHI [END_T_VISQ] [LUBRICATION 0|1] [MODE]
 * MODE "dry": the same scene with fluid.model = none; "thin": the unresolved
 * tier with a fluid of negligible density and viscosity (rho_f = 1e-3 kg/m3,
 * eta_f = 1e-7 Pa s). Both run for END_T_VISQ x T_visq of the viscous case
 * and must give the same run-out within 5 % (issue #4's dry limit).
 * "dry_perturbed": the dry run with g changed by 1e-7, to measure how far a
 * perturbation of that size moves the run-out (granular collapses amplify it).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "coupling/gf_coupling.h"
#include "gf_sim.h"
#include "gf_sim_internal.h" /* the coupling handle, for the gauge reading */
#include "scenes/gf_scene.h"

int main(int argc, char **argv)
{
    double phi = argc > 1 ? atof(argv[1]) : 0.6;
    double end_tv = argc > 2 ? atof(argv[2]) : 1.2e4;
    int lub = argc > 3 ? atoi(argv[3]) : 0;
    const char *mode = argc > 4 ? argv[4] : "viscous";
    gf_ctx ctx = {0};
    gf_run_spec spec;
    gf_run_spec_defaults(&spec);
    snprintf(spec.scene, sizeof spec.scene, "column_collapse");
    double D = 7.6e-3, rp = 8000, rf = 1000, eta = 1.0, g = 9.81;
    spec.grains.density_kg_m3 = rp;
    spec.grains.diameter_m = D;
    snprintf(spec.fluid.model, sizeof spec.fluid.model, "unresolved");
    spec.fluid.density_kg_m3 = rf;
    spec.fluid.viscosity_Pa_s = eta;
    spec.fluid.lubrication = lub;
    if (strcmp(mode, "dry") == 0 || strcmp(mode, "dry_perturbed") == 0) {
        if (mode[3] == '_')  /* chaos check: the dry run with g changed by 1e-7 */
            spec.gravity_m_s2 *= 1.0 + 1e-7;
        snprintf(spec.fluid.model, sizeof spec.fluid.model, "none");
        spec.fluid.density_kg_m3 = spec.fluid.viscosity_Pa_s = 0.0;
    } else if (strcmp(mode, "thin") == 0) {
        spec.fluid.density_kg_m3 = 1e-3;
        spec.fluid.viscosity_Pa_s = 1e-7;
    }
    spec.phi_initial = phi;
    spec.aspect_ratio_a = 0.5;
    double R0 = 16 * D, H0 = 0.5 * R0;
    double t_visq = eta / ((rp - rf) * g * H0);
    gf_sim_options opt = {0};
    gf_sim *sim = NULL;
    double t0 = gf_wtime();
    if (gf_sim_create(&ctx, &spec, &opt, &sim) != GF_OK) {
        fprintf(stderr, "validate_collapse: %s\n", ctx.last_msg);
        return 1;
    }
    double t_build = gf_wtime() - t0;
    const gf_scene_desc *sc = gf_scene_find("column_collapse");
    double phm = NAN, phl = NAN;
    if (sc->initial_packing)
        sc->initial_packing(sim, &phm, &phl);
    gf_particles *p = gf_sim_particles(sim);
    double xg[3] = {13.0 / 16.0 * R0, 0.0, 1.5 * D}, xg8[3] = {0.5 * R0, 0.0, 1.5 * D}, xg4[3] = {0.25 * R0, 0.0, 1.5 * D};
    double pb8_min = 0, pb8_max = 0, pb4_min = 0, pb4_max = 0;
    double t_end = end_tv * t_visq, dt = gf_sim_dt_s(sim);
    long n_chunk = (long)ceil(50.0 * t_visq / dt);
    double t_start = NAN, pb_min = 0, pb_max = 0, t_pbmin = 0, t_pbmax = 0, ecx_max = 0, m_mean = 0;
    size_t n_mob = 0;
    for (size_t i = 0; i < p->n_local; ++i)
        if (!(p->flags[i] & GF_P_GLUED))
            m_mean += p->mass_kg[i], ++n_mob;
    m_mean /= (double)n_mob;
    double v[3];
    t0 = gf_wtime();
    printf("# t/T_visq  front/R0  Pb/(drho g H0) at x = 13/16 R0, 8/16 R0, 4/16 R0\n");
    int k = 0;
    while (gf_sim_time_s(sim) < t_end) {
        if (gf_sim_advance(sim, n_chunk) != GF_OK) {
            fprintf(stderr, "validate_collapse: %s\n", ctx.last_msg);
            return 1;
        }
        double t = gf_sim_time_s(sim);
        sc->diagnose(sim, v);
        double pb = sim->coupling ? gf_coupling_excess_pressure_Pa(sim->coupling, xg) : 0.0;
        double pb8 = sim->coupling ? gf_coupling_excess_pressure_Pa(sim->coupling, xg8) : 0.0;
        double pb4 = sim->coupling ? gf_coupling_excess_pressure_Pa(sim->coupling, xg4) : 0.0;
        pb8_min = fmin(pb8_min, pb8), pb8_max = fmax(pb8_max, pb8);
        pb4_min = fmin(pb4_min, pb4), pb4_max = fmax(pb4_max, pb4);
        if (pb < pb_min)
            pb_min = pb, t_pbmin = t;
        if (pb > pb_max)
            pb_max = pb, t_pbmax = t;
        if (isnan(t_start) && v[0] > R0 + 0.5 * D)
            t_start = t;
        double ecx = 0.0;
        for (size_t i = 0; i < p->n_local; ++i)
            if (!(p->flags[i] & GF_P_GLUED))
                ecx += 0.5 * p->mass_kg[i] * p->vx_m_s[i] * p->vx_m_s[i];
        ecx /= (double)n_mob;
        if (ecx > ecx_max)
            ecx_max = ecx;
        if (k++ % 10 == 0)
            printf("%8.0f %7.3f %+8.4f %+8.4f %+8.4f\n", t / t_visq, v[0] / R0, pb / ((rp - rf) * g * H0),
                   pb8 / ((rp - rf) * g * H0), pb4 / ((rp - rf) * g * H0));
    }
    double wall = gf_wtime() - t0;
    sc->diagnose(sim, v);
    double h_back = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        if (!(p->flags[i] & GF_P_GLUED) && p->x_m[i] < 2 * D && p->y_m[i] + p->radius_m[i] > h_back)
            h_back = p->y_m[i] + p->radius_m[i];
    const gf_timers *tm = gf_sim_timers(sim);
    double scale = (rp - rf) * g * H0;
    int dense_sign = fabs(pb_min) > fabs(pb_max) ? -1 : +1;
    printf("SUMMARY [%s] phi_i %.3f (requested %.2f, solid volume/R0 H0 W %.3f) | start %.0f T_visq | R_inf/R0 %.2f | "
           "H_inf/R0 %.3f | back height/H0 %.2f -> %s | Pb extremum %+.0f Pa = %+.3f drho g H0 at %.0f T_visq "
           "(min %+.3f at %.0f, max %+.3f at %.0f) | Pb at 8/16 R0 min %+.3f max %+.3f, at 4/16 R0 min %+.3f max %+.3f | Ecx_max/(mgD) %.4f | grains %zu | wall %.0f s (build %.0f s): "
           "fluid %.1f s, coupling %.1f s, DEM %.1f s, %ld DEM steps, %d per fluid step\n",
           mode, phl, phi, phm, t_start / t_visq, v[0] / R0, v[1] / R0, h_back / H0,
           h_back > 0.9 * H0 ? "trapezoid" : "triangle", dense_sign < 0 ? pb_min : pb_max,
           (dense_sign < 0 ? pb_min : pb_max) / scale, (dense_sign < 0 ? t_pbmin : t_pbmax) / t_visq,
           pb_min / scale, t_pbmin / t_visq, pb_max / scale, t_pbmax / t_visq, pb8_min / scale, pb8_max / scale,
           pb4_min / scale, pb4_max / scale, ecx_max / (m_mean * g * D), n_mob,
           wall, t_build, tm->elapsed_s[GF_T_FLUID], tm->elapsed_s[GF_T_COUPLING],
           tm->elapsed_s[GF_T_FORCE] + tm->elapsed_s[GF_T_NEIGHBOUR] + tm->elapsed_s[GF_T_INTEGRATE],
           gf_sim_step_count(sim), sim->n_substeps);
    gf_sim_destroy(&sim);
    return 0;
}
