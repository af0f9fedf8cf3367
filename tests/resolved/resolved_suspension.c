/*
 * The resolved tier with a periodic gravity axis: the `settling` scene (a
 * fully periodic cube, y up) through fluid.model resolved, whose mean
 * pressure gradient G = -(sum_i (m_i - rho V_i)/V_box) g carries the grains'
 * excess weight (coupling/gf_coupling_resolved.c).
 *
 * check=periodic (default suite):
 *   - mixture momentum: 27 grains on a jittered lattice at phi = 0.2 (4.13 D
 *     box, D/dx = 8, Ar = 20, rho_p/rho = 2, contacts and lubrication on),
 *     P = rho int_box v + sum_i (m_i - rho V_i) v_i (the fluid inside the grains
 *     counted as rigid), sampled to 2 sqrt(D/g): |P| stays below 0.5 % of the
 *     impulse the excess weight would have given without G,
 *     sum_i (m_i - rho V_i) g t. The residue is the truncation of the
 *     non-conservative advection and of the overlapping forcing shells;
 *   - one grain in periodic cubes of 2.5 D and 3 D (D/dx = 8, Ar = 3.6,
 *     Stokes Re 0.2) settles, relative to the zero-volume-flux frame (the box
 *     mean of v, inside the grain too, is the volume flux), at the speed of a
 *     simple cubic array (Hasimoto, J. Fluid Mech. 5, 1959; Sangani & Acrivos,
 *     Int. J. Multiphase Flow 8, 1982, the dilute series
 *     U/U_Stokes = 1 - 1.7601 c + c^3 - 1.5593 c^6 + 3.9799 c^8 - 3.0734 c^10,
 *     c = phi^(1/3)) within 10 %: the resolved drag at D/dx = 8 without the
 *     forcing-radius retraction; the ratio of the two boxes, where that grid
 *     error largely cancels, within 3 %.
 *
 * check=hindered (`slow`): the hindered settling of the random (jittered
 * lattice) suspension at phi = 0.05, 0.1, 0.2, Ar = 20 (isolated Re_T 1.0 by
 * Schiller-Naumann), rho_p/rho = 2, D/dx = 8, against Richardson & Zaki
 * (Trans. Inst. Chem. Eng. 32, 1954) with n(Re_T) = 4.4 Re_T^-0.03 and U_T
 * the isolated sphere's Schiller-Naumann velocity; the same suspensions in
 * the fast tier (unresolved, di_felice and mean_slip, cells of L/3); prints
 * one table row per run (tier, closure, phi, U/U_T, error vs RZ, CPU-s) and
 * asserts nothing but finite speeds (docs/fast-tier.md, docs/resolved.md).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "coupling/gf_coupling.h"
#include "coupling/gf_coupling_diag.h"
#include "gf_sim.h"
#include "gf_test.h"
#include "gf_test_args.h"
#include "gf_test_drag.h"

static const double D = 0.01, RHO = 1000.0, RATIO = 2.0, G = 9.81;
static double D_OVER_DX = 8.0, RETRACT = 0.0;

typedef struct run_case {
    const char *model, *drag; /* fluid.model, fluid.drag (unresolved) */
    int mode;                 /* the scene's mode: 0 one sphere, 1 the suspension */
    double box, phi, ar;      /* box_over_D, phi_suspension, Archimedes number */
    double t_end, t_avg;      /* sqrt(D/g): end, start of the average */
} run_case;

typedef struct run_result {
    double U;        /* <grain settling speed relative to the zero-volume-flux frame>, m/s, downwards */
    double phi;      /* the box's solid fraction */
    double p_max;    /* max |P(t) - P(t1)| / (sum (m - rho V) g (t - t1)) over the samples after the first, t1 */
    double p_offset; /* P(t1) / (sum (m - rho V) g dt), dt the DEM step */
    double cpu_s;
    size_t n_grains;
} run_result;

static double viscosity(double ar) { return sqrt(RHO * (RATIO - 1.0) * RHO * G * D * D * D / ar); }

static gf_status make_sim(gf_ctx *ctx, const run_case *rc, gf_sim **sim)
{
    gf_run_spec spec;
    gf_run_spec_defaults(&spec);
    snprintf(spec.scene, sizeof spec.scene, "settling");
    spec.grains = (gf_grains_spec){.diameter_m = D, .polydispersity = 0.0, .density_kg_m3 = RATIO * RHO};
    snprintf(spec.fluid.model, sizeof spec.fluid.model, "%s", rc->model);
    if (rc->drag)
        snprintf(spec.fluid.drag, sizeof spec.fluid.drag, "%s", rc->drag);
    spec.fluid.density_kg_m3 = RHO;
    spec.fluid.viscosity_Pa_s = viscosity(rc->ar);
    spec.fluid.d_over_dx = D_OVER_DX;
    spec.fluid.ibm_retraction_dx = RETRACT;
    spec.fluid.cfl = 0.3;
    spec.contact.t_contact_nd = 0.05;
    spec.end_time_nd = rc->t_end;
    GF_TRY(gf_run_spec_set_param(ctx, &spec, "mode", rc->mode));
    GF_TRY(gf_run_spec_set_param(ctx, &spec, "box_over_D", rc->box));
    GF_TRY(gf_run_spec_set_param(ctx, &spec, "phi_suspension", rc->phi));
    if (strcmp(rc->model, "unresolved") == 0) { /* three cells a side: the suspension's box, L = n a */
        double a = D * cbrt(M_PI / (6.0 * rc->phi)), L = rc->mode ? lround(rc->box * D / a) * a : rc->box * D;
        spec.fluid.cell_over_D = L / D / 3.0;
    }
    gf_sim_options opt = {.n_threads = 1};
    return gf_sim_create(ctx, &spec, &opt, sim);
}

/* Box mean of the vertical velocity (the volume flux j) and the fluid's momentum rho int_box v, y up. */
static void box_flux(gf_sim *sim, const gf_particles *p, double V_box, double phi, double *j, double *p_fluid)
{
    const gf_coupling *c = gf_sim_coupling(sim);
    const gf_var_info *vars;
    const double *const *f;
    int n[3];
    double lo[3], h[3];
    int nv = gf_coupling_fields(c, n, lo, h, &vars, &f);
    double vp = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        vp += p->vy_m_s[i] / (double)p->n_local;
    if (strcmp(gf_coupling_model(c), "resolved") != 0) { /* the fast tier: j from the mean interstitial velocity */
        double uf[3];
        gf_coupling_mean_fluid_velocity(c, uf);
        *j = phi * vp + (1.0 - phi) * uf[1];
        *p_fluid = NAN;
        return;
    }
    double s = 0.0;
    size_t nc = (size_t)n[0] * n[1] * n[2];
    for (int v = 0; v < nv; ++v)
        if (strcmp(vars[v].name, "v_fluid") == 0)
            for (size_t q = 0; q < nc; ++q)
                s += f[v][q];
    *j = s / (double)nc;
    *p_fluid = RHO * *j * V_box;
}

/* Advances to the end of a fluid step's DEM substeps, where the grains have taken the whole impulse the fluid
 * step gave the fluid: one DEM step at a time until the flux changes (a fluid step began), then the rest of
 * its substeps. */
static gf_status to_cycle_end(gf_sim *sim, const gf_particles *p, double V_box, double phi)
{
    double j0, j, pf;
    box_flux(sim, p, V_box, phi, &j0, &pf);
    for (int s = 0; s < 1000; ++s) {
        GF_TRY(gf_sim_advance(sim, 1));
        box_flux(sim, p, V_box, phi, &j, &pf);
        if (j != j0)
            return gf_sim_advance(sim, gf_sim_fluid_substeps(sim) - 1);
    }
    return GF_OK;
}

static gf_status run(const run_case *rc, run_result *out)
{
    gf_ctx ctx = {0};
    gf_sim *sim = NULL;
    clock_t c0 = clock();
    gf_status st = make_sim(&ctx, rc, &sim);
    if (st != GF_OK) {
        fprintf(stderr, "%s\n", ctx.last_msg);
        return st;
    }
    const gf_particles *p = gf_sim_particles(sim);
    double lo[3], hi[3], excess = 0.0, vs = 0.0;
    int per[3];
    gf_sim_box(sim, lo, hi, per);
    double V_box = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    for (size_t i = 0; i < p->n_local; ++i) {
        double V = M_PI / 6.0 * 8.0 * p->radius_m[i] * p->radius_m[i] * p->radius_m[i];
        vs += V;
        excess += p->mass_kg[i] - RHO * V;
    }
    const double tg = sqrt(D / G);
    long chunk = (long)ceil(0.1 * tg / gf_sim_dt_s(sim));
    double sU = 0.0, t1 = -1.0, P1 = 0.0;
    int nU = 0;
    *out = (run_result){.phi = vs / V_box, .n_grains = p->n_local};
    while (st == GF_OK && gf_sim_time_s(sim) < rc->t_end * tg) {
        st = gf_sim_advance(sim, chunk);
        double j, pf, vp = 0.0, pg = 0.0;
        if (st == GF_OK)
            st = to_cycle_end(sim, p, V_box, out->phi);
        box_flux(sim, p, V_box, out->phi, &j, &pf);
        for (size_t i = 0; i < p->n_local; ++i) {
            double V = M_PI / 6.0 * 8.0 * p->radius_m[i] * p->radius_m[i] * p->radius_m[i];
            vp += p->vy_m_s[i] / (double)p->n_local;
            pg += (p->mass_kg[i] - RHO * V) * p->vy_m_s[i];
        }
        double t = gf_sim_time_s(sim);
        if (isfinite(pf) && t1 < 0.0)
            t1 = t, P1 = pf + pg, out->p_offset = P1 / (excess * G * gf_sim_dt_s(sim));
        else if (isfinite(pf))
            out->p_max = fmax(out->p_max, fabs(pf + pg - P1) / (excess * G * (t - t1)));
        if (t >= rc->t_avg * tg)
            sU += j - vp, nU++;
        if (!isfinite(vp))
            st = GF_ERR_NUMERIC;
    }
    if (st != GF_OK)
        fprintf(stderr, "%s\n", ctx.last_msg);
    out->U = nU ? sU / nU : NAN;
    out->cpu_s = (double)(clock() - c0) / CLOCKS_PER_SEC;
    gf_sim_destroy(&sim);
    return st;
}

/* Sangani & Acrivos (1982): a simple cubic array's settling speed over Stokes', dilute series. */
static double hasimoto(double phi)
{
    double c = cbrt(phi);
    return 1.0 - 1.7601 * c + phi - 1.5593 * phi * phi + 3.9799 * pow(c, 8) - 3.0734 * pow(c, 10);
}

static void check_periodic(double box0, double box1)
{
    run_result r;
    const run_case mix = {"resolved", NULL, 1, 4.1, 0.2, 20.0, 2.0, 1.0};
    GF_CHECK(run(&mix, &r) == GF_OK);
    printf("mixture momentum: %zu grains, phi %.4f, P(t1) = %.3f sum (m - rho V) g dt_DEM, then max |P - P(t1)| / "
           "(sum (m - rho V) g (t - t1)) = %.2e to 2 sqrt(D/g) (%.1f CPU-s)\n", r.n_grains, r.phi, r.p_offset, r.p_max,
           r.cpu_s);
    GF_CHECK(fabs(r.p_offset) <= 1.0);
    GF_CHECK(r.p_max < 1e-3);
    const double boxes[2] = {box0, box1};
    double ratio[2];
    double us = (RATIO - 1.0) * RHO * G * D * D / (18.0 * viscosity(3.6));
    for (int b = 0; b < 2; ++b) {
        const run_case one = {"resolved", NULL, 0, boxes[b], 0.2, 3.6, 5.0, 4.0};
        GF_CHECK(run(&one, &r) == GF_OK);
        ratio[b] = r.U / us;
        printf("one grain, %.1f D periodic cube (phi %.4f): U/U_Stokes %.4f, Hasimoto %.4f (%+.1f %%), Re %.3f, "
               "max |P - P(t1)| %.1e, %.1f CPU-s\n", boxes[b], r.phi, ratio[b], hasimoto(r.phi),
               100.0 * (ratio[b] / hasimoto(r.phi) - 1.0), RHO * r.U * D / viscosity(3.6), r.p_max, r.cpu_s);
        GF_CHECK_REL(ratio[b], hasimoto(r.phi), 0.12);
        GF_CHECK(r.p_max < 1e-3);
    }
    double ph[2] = {M_PI / 6.0 / pow(boxes[0], 3), M_PI / 6.0 / pow(boxes[1], 3)};
    double want = hasimoto(ph[0]) / hasimoto(ph[1]);
    printf("box ratio U(%g D)/U(%g D) %.4f, Hasimoto %.4f (%+.1f %%)\n", boxes[0], boxes[1], ratio[0] / ratio[1], want,
           100.0 * (ratio[0] / ratio[1] / want - 1.0));
    GF_CHECK_REL(ratio[0] / ratio[1], want, 0.03);
}

static void check_hindered(double t_end)
{
    const double ar = 20.0, mu = viscosity(ar);
    double re_t = gf_test_schiller_naumann_Re(ar), ut = re_t * mu / (RHO * D), n = 4.4 * pow(re_t, -0.03);
    printf("hindered settling: Ar %.0f, rho_p/rho %.0f, U_T %.4g m/s (Schiller-Naumann), Re_T %.3f, RZ n %.3f\n",
           ar, RATIO, ut, re_t, n);
    printf("| tier | closure | phi | grains | U/U_T | RZ (1-phi)^n | error vs RZ | CPU-s |\n");
    const double phis[3] = {0.05, 0.1, 0.2}, boxes[3] = {6.6, 5.2, 4.1};
    const char *const models[3][2] = {{"resolved", NULL}, {"unresolved", "di_felice"}, {"unresolved", "mean_slip"}};
    for (int q = 0; q < 3; ++q)
        for (int m = 0; m < 3; ++m) {
            const run_case rc = {models[m][0], models[m][1], 1, boxes[q], phis[q], ar, t_end, 0.5 * t_end};
            run_result r;
            GF_CHECK(run(&rc, &r) == GF_OK);
            double rz = pow(1.0 - r.phi, n);
            printf("| %s | %s | %.4f | %zu | %.4f | %.4f | %+.1f %% | %.1f |\n", models[m][0],
                   models[m][1] ? models[m][1] : "IBM, D/dx 8", r.phi, r.n_grains, r.U / ut, rz,
                   100.0 * (r.U / ut / rz - 1.0), r.cpu_s);
            GF_CHECK(isfinite(r.U) && r.U > 0.0);
        }
}

int main(int argc, char **argv)
{
    char check[16] = "periodic";
    double t_end = 20.0, box0 = 3.0, box1 = 4.0;
    const gf_test_arg keys[] = {{.key = "check", .text = check, .text_size = sizeof check},
                                {.key = "end", .number = &t_end}, {.key = "dx", .number = &D_OVER_DX},
                                {.key = "retract", .number = &RETRACT}, {.key = "box0", .number = &box0},
                                {.key = "box1", .number = &box1}};
    gf_test_parse_args(argc, argv, keys, sizeof keys / sizeof keys[0]);
    if (strcmp(check, "hindered") == 0)
        check_hindered(t_end);
    else
        check_periodic(box0, box1);
    return gf_test_finish();
}
