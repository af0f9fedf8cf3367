/*
 * Stage bounce on synthetic sphere-wall traces with known answers
 * (definitions: postproc/stages/gf_bounce_measure.h).
 *
 * Rebound trace: D = 15 mm, rho_p = 8000, rho_f = 1000, eta = 0.25 Pa s (the
 * sphere of Izard 2014 §3.1.5). The sphere falls at the constant speed
 * V0 = 0.2 m/s from a gap of 2 D (weight balanced by drag), then hits the wall
 * through a linear spring-dashpot, m δ'' = -k δ - c δ' with δ the overlap,
 * of contact time t_c = π/ω_d = 2 ms and exit restitution 0.6, i.e.
 * ζ = -ln 0.6 / sqrt(π² + ln² 0.6) (exact solution
 * δ = V0/ω_d exp(-ζ ω0 t) sin(ω_d t)), then flies freely (v = 0.6 V0 - g τ)
 * until it is back at the wall. Sampled every t_c/200.
 * Known answers:
 *   V_T = V_I = V0 (the approach is at constant speed);
 *   V_R, the first maximum of the upward velocity, comes where the spring-dashpot
 *     force vanishes, at ω_d t* = π - atan2(2ζ s, 1 - 2ζ²) with s = sqrt(1 - ζ²),
 *     before the surfaces separate, and is V0 exp(-ζ ω_d t* / s) exactly (the
 *     restitution of the same law clipped at zero force: Schwager & Pöschel,
 *     Phys. Rev. E 78, 2008), 0.6323 V0 here, so e = eps = 0.6323;
 *   St = rho_p V0 D/(9 eta) = 10.667; St_T = (rho_p + rho_f/2) V0 D/(9 eta) = 11.333;
 *   contact (gap <= 0) = t_c = 2 ms; eps/eps_max with the run's restitution
 *     attribute 0.6: 1.0538.
 * Tolerances: St and V_I 1e-9 relative (exact samples); e and the contact time
 * 1e-3 relative (the sampled maximum and the linearly interpolated zero
 * crossings err by O((dt/t_c)²) ~ 1e-5).
 *
 * No-rebound traces (below St ~ 10 a sphere does not rebound: Gondret et al.
 * 2002): (a) the same fall, then the sphere sinks into the wall to a rest
 * overlap δ_s = 1e-5 m, δ = δ_s (1 - exp(-V0 t/δ_s)), never moving up: e = 0,
 * V_I = V0, with a "not determined: no rebound" note; (b) the approach slows
 * exponentially (a lubrication film) and never touches: V_T = V0 only, a note,
 * no e. A diagnostics file without gap_over_D is not a bounce: no note.
 *
 * Linear approach (gf_bounce_measure_approach): (a) the film trace above, whose
 * gap decays as exp(-t/tau) with tau = R/V0, so u = V0 gap/R below R: V_m = V0
 * to roundoff, the window the whole of 0 < gap <= R/2; (b) a trace
 * u = V0 (x + e + c x^2), x = gap/R (a roughness offset e and an inertial excess
 * c x^2), below x = 0.1 and the speed there above (the terminal fall, whose ratio
 * u/x falls below the linear regime's at large gaps and must not be taken), whose ratio u/x = V0 (1 + e/x + c x) has its minimum V0 (1 + 2 sqrt(e c))
 * at x = sqrt(e/c) and leaves (1 + flat) of it at the roots of
 * c x^2 - ((1 + flat)(1 + 2 sqrt(e c)) - 1) x + e = 0: the minimum within 1e-6,
 * the edges within the sample spacing (0.2 %), V_m (an x^2-weighted mean of the
 * ratio) between the minimum and (1 + flat) times it.
 */
#include <math.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_post_synth.h"
#include "gf_test.h"
#include "stages/gf_bounce_measure.h"
#include "stages/gf_stage.h"
#include "synth_stage.h"

#define NMAX 50000

static const double D = 0.015, V0 = 0.2, G = 9.81, TC = 2e-3, E_EXIT = 0.6, DT = TC / 200.0;

typedef struct trace {
    double t[NMAX], v[NMAX], gap_over_D[NMAX];
    size_t n;
} trace;

static void push(trace *tr, double t, double v, double gap)
{
    if (tr->n >= NMAX) {   /* a trace longer than the arrays: a test bug, stop here */
        fprintf(stderr, "test_post_bounce: more than %d samples\n", NMAX);
        exit(1);
    }
    tr->t[tr->n] = t, tr->v[tr->n] = v, tr->gap_over_D[tr->n] = gap / D;
    tr->n++;
}

/* Constant-speed fall from 2 D; returns the impact time (between samples). */
static double fall(trace *tr)
{
    const double t1 = 2.0 * D / V0 + 0.37 * DT;   /* off the sampling grid */
    for (double t = 0.0; t < t1; t = tr->n * DT)
        push(tr, t, -V0, V0 * (t1 - t));
    return t1;
}

static void rebound_trace(trace *tr, double *VR_first_max)
{
    const double z = -log(E_EXIT) / sqrt(M_PI * M_PI + log(E_EXIT) * log(E_EXIT)), s = sqrt(1.0 - z * z);
    const double wd = M_PI / TC, w0 = wd / s, ts = (M_PI - atan2(2.0 * z * s, 1.0 - 2.0 * z * z)) / wd;
    *VR_first_max = V0 * exp(-z * w0 * ts);
    const double t1 = fall(tr), t2 = t1 + TC, VR = E_EXIT * V0;
    for (double t = tr->n * DT; t < t2 + 2.0 * VR / G; t = tr->n * DT) {
        if (t < t2) {
            double u = t - t1, a = exp(-z * w0 * u);
            double delta = V0 / wd * a * sin(wd * u), ddelta = V0 * a * (cos(wd * u) - z * w0 / wd * sin(wd * u));
            push(tr, t, -ddelta, -delta);
        } else {
            double u = t - t2;
            push(tr, t, VR - G * u, VR * u - 0.5 * G * u * u);
        }
    }
}

static void rest_trace(trace *tr)
{
    const double t1 = fall(tr), ds = 1e-5;
    for (double t = tr->n * DT; t < t1 + 0.01; t = tr->n * DT)
        push(tr, t, -V0 * exp(-V0 * (t - t1) / ds), -ds * (1.0 - exp(-V0 * (t - t1) / ds)));
}

static void film_trace(trace *tr)
{
    const double t1 = 1.5 * D / V0, g1 = 0.5 * D, tau = g1 / V0;
    for (double t = 0.0; t < t1 + 0.15; t = tr->n * DT) /* down to a gap of 0.02 R */
        if (t < t1)
            push(tr, t, -V0, 2.0 * D - V0 * t);
        else
            push(tr, t, -V0 * exp(-(t - t1) / tau), g1 * exp(-(t - t1) / tau));
}

/* diagnostics.nc of a bounce run, with the contact law's attributes. */
static void write_run(const char *dir, const trace *tr, int with_gap)
{
    synth_meta m;
    synth_meta_default(&m, "bounce1", "bounce");
    m.D = D, m.rho_p = 8000.0, m.rho_f = 1000.0, m.eta = 0.25, m.g = G;
    const char *names[] = {"sphere_velocity_y", with_gap ? "gap_over_D" : "gap_elsewhere"};
    const char *units[] = {"m s-1", "1"};
    const double *vals[] = {tr->v, tr->gap_over_D};
    GF_CHECK(synth_diagnostics(dir, &m, tr->n, tr->t, 2, names, units, vals) == 0);
    char path[600];
    snprintf(path, sizeof path, "%s/diagnostics.nc", dir);
    int nc, rc = nc_open(path, NC_WRITE, &nc);
    double eps_max = E_EXIT, tc = TC;
    if (rc == NC_NOERR) {
        rc = nc_redef(nc);
        if (rc == NC_NOERR) rc = nc_put_att_double(nc, NC_GLOBAL, "restitution", NC_DOUBLE, 1, &eps_max);
        if (rc == NC_NOERR) rc = nc_put_att_double(nc, NC_GLOBAL, "t_contact_s", NC_DOUBLE, 1, &tc);
        nc_close(nc);
    }
    GF_CHECK(rc == NC_NOERR);
}

static gf_status run_stage(const char *name, const trace *tr, int with_gap, gf_post_row *row, gf_ctx *ctx)
{
    char dir[512];
    synth_scratch(dir, sizeof dir, name);
    write_run(dir, tr, with_gap);
    gf_post_row_init(row, dir);
    *ctx = (gf_ctx){0};
    return synth_stage(ctx, gf_stage_bounce, dir, "bounce", 0, row);
}

static void check_rebound(void)
{
    static trace tr;
    double VR = 0.0;
    rebound_trace(&tr, &VR);
    gf_post_row row;
    gf_ctx ctx;
    GF_CHECK_OK(run_stage("bounce_rebound", &tr, 1, &row, &ctx), &ctx);
    const double St = 8000.0 * V0 * D / (9.0 * 0.25), StT = 8500.0 * V0 * D / (9.0 * 0.25), e = VR / V0;
    printf("rebound: V_I %.6f (%.6f), V_R %.6f (%.6f), e %.7f (%.7f), St %.4f (%.4f), St_T %.4f (%.4f), "
           "contact %.8g s (%.8g), eps/eps_max %.5f (%.5f)\n",
           gf_post_row_get(&row, "bounce_V_I"), V0, gf_post_row_get(&row, "bounce_V_R"), VR,
           gf_post_row_get(&row, "bounce_e"), e, gf_post_row_get(&row, "bounce_St"), St,
           gf_post_row_get(&row, "bounce_St_T"), StT, gf_post_row_get(&row, "bounce_contact_s"), TC,
           gf_post_row_get(&row, "bounce_eps_over_eps_max"), e / E_EXIT);
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_V_I"), V0, 1e-9);
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_V_T"), V0, 1e-9);
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_St"), St, 1e-9);
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_St_T"), StT, 1e-9);
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_e"), e, 1e-3);
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_eps"), e, 1e-3);
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_eps_over_eps_max"), e / E_EXIT, 1e-3);
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_contact_s"), TC, 1e-3);
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_contact_over_tc"), 1.0, 1e-3);
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_t_impact_s"), 2.0 * D / V0 + 0.37 * DT, 1e-6);
}

static void check_no_rebound(void)
{
    static trace tr;
    gf_post_row row;
    gf_ctx ctx;
    rest_trace(&tr);
    gf_status st = run_stage("bounce_rest", &tr, 1, &row, &ctx);
    printf("at rest on the wall: status %d, e %g, V_I %g, note '%s'\n", (int)st, gf_post_row_get(&row, "bounce_e"),
           gf_post_row_get(&row, "bounce_V_I"), ctx.last_msg);
    GF_CHECK(st == GF_ERR_UNSUPPORTED && strstr(ctx.last_msg, "not determined: no rebound"));
    GF_CHECK_ABS(gf_post_row_get(&row, "bounce_e"), 0.0, 0.0);
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_V_I"), V0, 1e-9);
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_St"), 8000.0 * V0 * D / (9.0 * 0.25), 1e-9);

    tr.n = 0;
    film_trace(&tr);
    st = run_stage("bounce_film", &tr, 1, &row, &ctx);
    printf("never touched: status %d, V_T %g, e %g, note '%s'\n", (int)st, gf_post_row_get(&row, "bounce_V_T"),
           gf_post_row_get(&row, "bounce_e"), ctx.last_msg);
    GF_CHECK(st == GF_ERR_UNSUPPORTED && strstr(ctx.last_msg, "not determined: the sphere never touched"));
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_V_T"), V0, 1e-9);
    GF_CHECK(isnan(gf_post_row_get(&row, "bounce_e")));
    GF_CHECK_REL(gf_post_row_get(&row, "bounce_V_m"), V0, 1e-9); /* the film's exponential approach is linear */

    st = run_stage("bounce_not_a_bounce", &tr, 0, &row, &ctx);
    GF_CHECK(st == GF_ERR_UNSUPPORTED && ctx.last_msg[0] == '\0');
}

static void check_approach(void)
{
    static trace tr;
    tr.n = 0;
    film_trace(&tr);
    const double R = 0.5 * D;
    static double gap[NMAX];
    for (size_t k = 0; k < tr.n; ++k)
        gap[k] = tr.gap_over_D[k] * D;
    gf_bounce_approach a;
    gf_bounce_measure_approach(tr.v, gap, tr.n, R, 0.5, 0.05, &a);
    GF_CHECK_REL(a.V_m, V0, 1e-9);
    GF_CHECK(a.x_hi <= 0.5 && a.x_hi > 0.499 && a.k_last == tr.n - 1 && !a.after_peak);
    /* (b): 4000 samples from x = 0.5 down to 1e-4, uniform in log x */
    const double e = 2e-4, c = 5.0, flat = 0.05;
    double v[4000], g[4000];
    for (int k = 0; k < 4000; ++k) {
        double x = 0.5 * pow(2e-4, k / 3999.0);
        double xs = fmin(x, 0.1);   /* above 0.1 R a constant speed: the ratio low there, peaking at 0.1 R */
        g[k] = x * R, v[k] = -V0 * (xs + e + c * xs * xs);
    }
    gf_bounce_measure_approach(v, g, 4000, R, 0.5, flat, &a);
    const double r_min = V0 * (1.0 + 2.0 * sqrt(e * c)), b = (1.0 + flat) * r_min / V0 - 1.0;
    const double x_lo = (b - sqrt(b * b - 4.0 * c * e)) / (2.0 * c), x_hi = (b + sqrt(b * b - 4.0 * c * e)) / (2.0 * c);
    GF_CHECK_REL(a.ratio_min, r_min, 1e-6);
    GF_CHECK_REL(a.x_lo, x_lo, 2e-3);
    GF_CHECK_REL(a.x_hi, x_hi, 2e-3);
    GF_CHECK(a.V_m >= r_min && a.V_m <= (1.0 + flat) * r_min && a.after_peak);
    printf("approach: V_m %.6f (V0 %.3f, ratio min %.6f), window x %.5f-%.5f (exact %.5f-%.5f)\n", a.V_m, V0,
           a.ratio_min, a.x_lo, a.x_hi, x_lo, x_hi);
}

int main(void)
{
    check_rebound();
    check_no_rebound();
    check_approach();
    return gf_test_finish();
}
