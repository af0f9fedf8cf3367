/*
 * The oblique sphere-wall bounce (the `bounce` scene with gravity turned by
 * impact_angle_deg): Joseph & Hunt, J. Fluid Mech. 510 (2004); Izard 2014 §3.4.
 * The thesis' case: a steel sphere (rho_p = 8000 kg/m3, D = 5 mm, eps_max = 0.95,
 * mu_c = 0.106, Joseph & Hunt's values) in a fluid of rho = 1000 kg/m3, eta = 0.1 Pa s,
 * t_c sqrt(g/D) = 4.4e-3, released from rest at (2 D, 8 D, 2 D) in a 10 D x 10 D x 4 D
 * box (D/dx = 10), no-slip impact wall, slip elsewhere, eta_e/R = 1e-4 (the rough,
 * glass-like spheres), lubrication cut-off R/2 and off in overlap (as the normal bounce).
 * Measured at the contact point (postproc/stages/gf_bounce_measure.h): Psi_in = tan xi_in,
 * Psi_out = e tan xi_out, beta = -Psi_out/Psi_in, mu_f = 2 (1 + beta) Psi_in / (7 (1 + e)),
 * with e = V_R/V_I.
 *
 * check=dry (default suite): the same sphere with the fluid off, sampled every DEM step.
 *   mu_f is the tangential over the normal impulse of the contact, so
 *   - gross sliding (Psi_in > 7 mu_c (1 + e)/2 = 0.72 here, xi_in > 36°): mu_f = mu_c,
 *     within 1 % (gravity acts during the contact, ~t_c g / V_I = 1e-3 of the impulses);
 *   - rolling/sticking (Walton 1993; Maw, Barber & Fawcett 1976, their tangential
 *     compliance): mu_f < mu_c and the tangential spring reverses the contact point's
 *     slip, beta > 0; a linear spring and dashpot make the contact scale-free, so beta is
 *     the same at every Psi_in of full stick, beta_0 = -cos(omega_t T) (stick_beta
 *     below), less the slip where F_n -> 0 at the end of the contact: beta within
 *     0.1 of beta_0 = 0.871 at Psi_in <= 0.2 (measured 0.834 at 5°, 0.802 at 10°).
 *   Both at impact (the V_I and V_R samples, Joseph & Hunt's reference): on approach
 *   (V_T) gravity's work between the two samples would enter the impulses.
 * check=sweep (slow): the immersed sphere at xi_in = 10, 20, 30, 40°: Izard 2014 §3.4
 *   finds mu_f > mu_c above 30° and mu_f within Joseph & Hunt's error 0.025 of their
 *   rough-sphere values, which are those of a dry contact (their §5): tested as
 *   |mu_f - mu_c| <= 0.025 on the sliding branch (Psi_out > 0) and mu_f > mu_c at 40°;
 *   beta falls as xi_in grows (partial slip to sliding).
 * Usage: resolved_oblique [check=dry|sweep] [dx=10] [angles=10,20,30,40] [eta_e=1e-4] [threads=n] [overlap=clamp|off|film]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "gf_sim.h"
#include "gf_test.h"
#include "bounce_harness.h"
#include "stages/gf_bounce_measure.h"

enum { TR_T, TR_VY, TR_GAP, TR_VX, TR_WZ, TR_FX, TR_FY, TR_N }; /* TR_F*: the floor's force on the sphere */

typedef struct options {
    int dry, n_angles;
    double dx, eta_e, threads, angles[8];
    const char *overlap; /* fluid.lub_overlap (clamp, off, film); off unless given */
} options;

static void parse(int argc, char **argv, options *o)
{
    *o = (options){.dry = 1, .dx = 10, .eta_e = 1e-4, .n_angles = 4, .angles = {10, 20, 30, 40}};
    const harness_arg table[] = {{"dx", &o->dx}, {"eta_e", &o->eta_e}, {"threads", &o->threads}};
    harness_parse(argc, argv, table, 3);
    const char *check = harness_text(argc, argv, "check"), *v = harness_text(argc, argv, "angles");
    o->dry = !check || strcmp(check, "sweep") != 0;
    o->overlap = harness_text(argc, argv, "overlap");
    if (v)
        for (o->n_angles = 0; o->n_angles < 8 && *v; ++o->n_angles) {
            char *end;
            o->angles[o->n_angles] = strtod(v, &end);
            v = *end ? end + 1 : end;
        }
}

/* Izard 2014 §3.4: the thesis' box, sphere and fluid; the fluid off when dry. */
static gf_run_spec oblique_spec(gf_ctx *ctx, const options *o, double angle_deg)
{
    gf_run_spec spec;
    gf_run_spec_defaults(&spec);
    snprintf(spec.scene, sizeof spec.scene, "bounce");
    spec.grains = (gf_grains_spec){.diameter_m = 5e-3, .polydispersity = 0.0, .density_kg_m3 = 8000.0};
    spec.contact.restitution = 0.95;
    spec.contact.t_contact_nd = 4.4e-3;
    spec.contact.friction = spec.contact.wall_friction = 0.106;
    harness_resolved_fluid(&spec, 1000.0, 0.1, o->eta_e, o->dx);
    if (o->overlap)
        snprintf(spec.fluid.lub_overlap, sizeof spec.fluid.lub_overlap, "%s", o->overlap);
    if (o->dry)
        snprintf(spec.fluid.model, sizeof spec.fluid.model, "none");
    spec.end_time_nd = 12.0;
    const char *keys[] = {"box_over_D", "height_over_D", "span_z_over_D", "release_x_over_D", "release_depth_over_D",
                          "impact_angle_deg"};
    const double values[] = {10.0, 10.0, 4.0, 2.0, 2.0, angle_deg};
    harness_scene_params(ctx, &spec, keys, values, 6);
    return spec;
}

typedef struct bounce_result {
    gf_bounce b;
    gf_bounce_oblique o, o_T;   /* at impact (V_I), on approach (V_T) */
    double J_n, J_t, J_wall_n, J_wall_t; /* impulses from V_I to V_R over m V_I: the sphere's, the floor's share */
    double cpu_s;
} bounce_result;

/* Drops the sphere at angle_deg, samples it (every DEM step near the wall)
 * until `after` sqrt(D/g) past the end of its first contact, and measures. */
static void drop(const options *o, double angle_deg, bounce_result *r)
{
    gf_ctx ctx = {0};
    gf_run_spec spec = oblique_spec(&ctx, o, angle_deg);
    gf_sim_options opt = {.n_threads = (int)o->threads};
    gf_sim *sim = NULL;
    double c0 = (double)clock() / CLOCKS_PER_SEC;
    *r = (bounce_result){.cpu_s = NAN};
    GF_CHECK_OK(gf_sim_create(&ctx, &spec, &opt, &sim), &ctx);
    if (!sim)
        return;
    const double D = spec.grains.diameter_m, R = 0.5 * D, tg = sqrt(D / spec.gravity_m_s2);
    const double after = o->dry ? 0.05 : 1.0, t_end = spec.end_time_nd * tg;
    const gf_particles *p = gf_sim_particles(sim);
    bounce_trace s = {.n_cols = TR_N};
    int touched = 0;
    double t_left = INFINITY;
    while (gf_sim_time_s(sim) < fmin(t_end, t_left + after * tg)) {
        gf_status st = gf_sim_advance(sim, p->y_m[0] - R > 0.6 * D ? 50 : 1);
        if (st != GF_OK) {
            GF_CHECK_OK(st, &ctx);
            break;
        }
        double fw[3];
        gf_sim_wall_force(sim, 0, fw); /* the floor (the scene's only wall): its load, minus the sphere's force */
        double x[TR_N] = {gf_sim_time_s(sim), p->vy_m_s[0], p->y_m[0] - R, p->vx_m_s[0], p->wz_rad_s[0], -fw[0], -fw[1]};
        if (bounce_trace_push(&s, x) != 0) {
            GF_CHECK(!"out of memory for the trace");
            break;
        }
        touched |= x[TR_GAP] <= 0.0;
        if (touched && x[TR_GAP] > 0.0 && !isfinite(t_left))
            t_left = x[TR_T];
    }
    gf_bounce_measure(s.col[TR_T], s.col[TR_VY], s.col[TR_GAP], s.n, R, &r->b);
    gf_bounce_measure_oblique(&r->b, s.col[TR_VX], s.col[TR_WZ], R, GF_BOUNCE_AT_IMPACT, &r->o);
    gf_bounce_measure_oblique(&r->b, s.col[TR_VX], s.col[TR_WZ], R, GF_BOUNCE_AT_APPROACH, &r->o_T);
    /* where the normal and tangential impulses come from, between the V_I and V_R samples: the whole change of
     * the sphere's momentum against the floor's contact and lubrication (the rest: the resolved flow's force) */
    r->J_n = r->J_t = r->J_wall_n = r->J_wall_t = NAN;
    if (r->b.touched && r->b.rebounded && r->b.V_I > 0.0) {
        const double m = p->mass_kg[0], k0 = (double)r->b.k_impact, k1 = (double)r->b.k_rebound;
        double jn = 0.0, jt = 0.0;
        for (size_t k = (size_t)k0 + 1; k <= (size_t)k1 && k < s.n; ++k) {
            const double dt = s.col[TR_T][k] - s.col[TR_T][k - 1];
            jn += s.col[TR_FY][k] * dt, jt += s.col[TR_FX][k] * dt;
        }
        const double mv = m * r->b.V_I;
        r->J_n = m * (s.col[TR_VY][r->b.k_rebound] - s.col[TR_VY][r->b.k_impact]) / mv;
        r->J_t = m * (s.col[TR_VX][r->b.k_rebound] - s.col[TR_VX][r->b.k_impact]) / mv;
        r->J_wall_n = jn / mv, r->J_wall_t = jt / mv;
    }
    r->cpu_s = (double)clock() / CLOCKS_PER_SEC - c0;
    bounce_trace_free(&s);
    gf_sim_destroy(&sim);
}

static void print_oblique(const char *what, const gf_bounce_oblique *o)
{
    printf("  %s: Psi_in %.4f (xi_in %.2f deg), e %.4f, Psi_out %+.4f (xi_out %+.2f deg), beta %+.4f, mu_f %.4f\n",
           what, o->psi_in, o->xi_in_deg, o->e, o->psi_out, o->xi_out_deg, o->beta, o->mu_f);
}

static void print_result(double angle_deg, const bounce_result *r)
{
    printf("xi %4.1f deg: V_T %.4f m/s, V_I %.4f m/s, V_R %.4f m/s, contact %.3g ms; cpu %.1f s\n", angle_deg,
           r->b.V_T, r->b.V_I, r->b.V_R, 1e3 * r->b.contact_s, r->cpu_s);
    print_oblique("at impact  ", &r->o);
    print_oblique("on approach", &r->o_T);
    printf("  impulses V_I -> V_R / (m V_I): normal %.4f (floor %.4f), tangential %+.4f (floor %+.4f): floor's "
           "|J_t|/J_n %.4f\n", r->J_n, r->J_wall_n, r->J_t, r->J_wall_t, fabs(r->J_wall_t) / r->J_wall_n);
}

/* beta_0 = -cos(omega_t T): the tangential spring of a stuck contact turned
 * over the contact's duration T (Walton 1993). With the damping ratio zeta of
 * eps_max (Schäfer et al. 1996) T = pi / (omega_n sqrt(1 - zeta^2)), and the
 * contact point of a solid sphere (I = 2/5 m R^2) oscillates at
 * omega_t = sqrt(7/2 k_t/k_n) omega_n, whatever the pair's mass:
 * omega_t T = pi sqrt(7/2 kt/kn (1 + ln(eps)^2/pi^2)). */
static double stick_beta(const gf_run_spec *spec)
{
    double l = log(spec->contact.restitution) / M_PI;
    return -cos(M_PI * sqrt(3.5 * spec->contact.kt_over_kn * (1.0 + l * l)));
}

static void check_dry(const options *o)
{
    gf_ctx ctx = {0};
    gf_run_spec spec = oblique_spec(&ctx, o, 0.0);
    const double mu_c = spec.contact.wall_friction, beta_0 = stick_beta(&spec);
    const double sliding[] = {45.0, 60.0}, sticking[] = {5.0, 10.0};
    for (int k = 0; k < 2; ++k) {
        bounce_result r;
        drop(o, sliding[k], &r);
        print_result(sliding[k], &r);
        GF_CHECK(r.o.psi_in > 3.5 * mu_c * (1.0 + r.b.e));   /* gross sliding */
        GF_CHECK_REL(r.o.mu_f, mu_c, 0.01);
    }
    for (int k = 0; k < 2; ++k) {
        bounce_result r;
        drop(o, sticking[k], &r);
        print_result(sticking[k], &r);
        printf("  stuck contact: beta_0 = -cos(omega_t T) = %.4f\n", beta_0);
        GF_CHECK(r.o.mu_f < mu_c);
        GF_CHECK_ABS(r.o.beta, beta_0, 0.1);
    }
}

static void check_sweep(const options *o)
{
    const double mu_c = 0.106, tol_mu = 0.025;   /* Joseph & Hunt's error on mu_f (Izard 2014 §3.4) */
    double beta_prev = INFINITY;
    for (int k = 0; k < o->n_angles; ++k) {
        bounce_result r;
        drop(o, o->angles[k], &r);
        print_result(o->angles[k], &r);
        GF_CHECK(r.b.rebounded);
        if (r.o.psi_out > 0.0)   /* sliding branch */
            GF_CHECK_ABS(r.o.mu_f, mu_c, tol_mu);
        if (r.o.xi_in_deg > 30.0)
            GF_CHECK(r.o.mu_f > mu_c);
        GF_CHECK(r.o.beta < beta_prev);
        beta_prev = r.o.beta;
    }
}

int main(int argc, char **argv)
{
    options o;
    parse(argc, argv, &o);
    if (o.dry)
        check_dry(&o);
    else
        check_sweep(&o);
    return gf_test_finish();
}
