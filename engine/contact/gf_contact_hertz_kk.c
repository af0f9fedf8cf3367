/*
 * Viscoelastic Hertz law (Kuwabara & Kono, Jpn. J. Appl. Phys. 26, 1987;
 * Brilliantov, Spahn, Hertzsch & Pöschel, PRE 53, 1996): the Hertz spring of
 * gf_contact_hertz.c with a dashpot proportional to the contact radius,
 *     F_n = k_n s (delta + (3/2) A d(delta)/dt),   s = sqrt(delta/delta_ref),
 * A a dissipative time of the material. Unlike the Tsuji damping of the
 * "hertz" row, the restitution falls with the impact speed,
 *     1 - e = C1 x - C2 x^2 + ...,  x = A alpha^(2/5) v^(1/5),
 * alpha = k_n / (m* sqrt(delta_ref)), C1 = 1.15344, C2 = 0.79826
 * (Schwager & Pöschel, PRE 57, 1998, eq. 24), as measured for ice and steel.
 *
 * The spec's restitution is read as e at the impact speed sqrt(gD) of the
 * mean pair: derive() finds the A that gives it by integrating that collision
 * (the same clipped force as the kernel) and bisecting on A.
 * The tangential part is the Hertz row's (Mindlin stiffness ~ s).
 */
#include "contact/gf_contact.h"

#include <math.h>

void gf_contact_hertz_kk(const gf_contact_params *p, const gf_contact_geom *g, double dt_s, double *hist,
                         double *f_n_out, double f_t_out[3])
{
    const double s = sqrt(g->overlap_m / p->delta_ref_m);
    /* v_n > 0 separating: d(delta)/dt = -v_n */
    double f_n = p->k_n_N_m * s * (g->overlap_m - 1.5 * p->law_constant * g->v_n_m_s);
    if (f_n < 0.0 && !p->allow_attraction)
        f_n = 0.0;
    *f_n_out = f_n;
    gf_contact_tangential(g, p->kt_over_kn * p->k_n_N_m * s, f_n, dt_s, hist, f_t_out);
}

/* Normal force on the relative coordinate of the mean pair. */
static double pair_force(const gf_contact_params *cp, double A, double delta, double ddelta)
{
    if (delta <= 0.0)
        return 0.0;
    const double f = cp->k_n_N_m * sqrt(delta / cp->delta_ref_m) * (delta + 1.5 * A * ddelta);
    return f < 0.0 && !cp->allow_attraction ? 0.0 : f;
}

/* Restitution of the mean pair hitting at speed v with dissipative time A:
 * m* delta'' = -F_n(delta, delta'), classical RK4 from delta = 0, delta' = v,
 * until the grains part (delta < 0); t_c/4000 steps. */
static double pair_restitution(const gf_contact_params *cp, double A, double v)
{
    const double m = cp->m_eff_mean_kg, h = cp->t_contact_s / 4000.0;
    double x = 0.0, u = v;
    for (long k = 0; k < 4000000 && x >= 0.0; ++k) {
        const double a1 = -pair_force(cp, A, x, u) / m;
        const double a2 = -pair_force(cp, A, x + 0.5 * h * u, u + 0.5 * h * a1) / m;
        const double a3 = -pair_force(cp, A, x + 0.5 * h * (u + 0.5 * h * a1), u + 0.5 * h * a2) / m;
        const double a4 = -pair_force(cp, A, x + h * (u + 0.5 * h * a2), u + h * a3) / m;
        x += h * (u + h * (a1 + a2 + a3) / 6.0);
        u += h * (a1 + 2.0 * a2 + 2.0 * a3 + a4) / 6.0;
    }
    return -u / v;
}

/* A such that the mean pair hit at sqrt(gD) rebounds with the spec's
 * restitution: e(A) falls monotonically from 1, bisection to 1e-10. */
static void hertz_kk_derive(const gf_run_spec *spec, gf_contact_params *cp)
{
    gf_contact_hertz_derive(spec, cp);
    const double v = sqrt(spec->gravity_m_s2 * spec->grains.diameter_m), eps = spec->contact.restitution;
    double lo = 0.0, hi = cp->t_contact_s;
    while (pair_restitution(cp, hi, v) > eps && hi < 1e3 * cp->t_contact_s)
        hi *= 2.0;
    for (int k = 0; k < 60 && hi - lo > 1e-10 * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (pair_restitution(cp, mid, v) > eps)
            lo = mid;
        else
            hi = mid;
    }
    cp->law_constant = 0.5 * (lo + hi);
}

const gf_contact_info gf_contact_law_hertz_kk = {
    .name = "hertz_kk",
    .kernel = gf_contact_hertz_kk,
    .n_history = GF_CONTACT_HISTORY,
    .doc = "viscoelastic Hertz, damping ~ contact radius (Kuwabara & Kono 1987; Brilliantov et al. 1996)",
    .derive = hertz_kk_derive,
    .frequency_factor = gf_contact_hertz_frequency_factor,
    .normal_energy = gf_contact_hertz_normal_energy,
    .tangential_energy = gf_contact_hertz_tangential_energy,
};
