/*
 * Inline bodies of the contact kernels, so that the pair loop of the step
 * (gf_forces.c) can specialise on the linear law without a call per
 * contact; the table rows (gf_contact_linear.c, gf_contact_tangential.c) wrap
 * the same bodies. Equations: gf_contact.h, gf_contact_tangential.c.
 */
#ifndef GF_CONTACT_KERNELS_H
#define GF_CONTACT_KERNELS_H

#include <math.h>

#include "contact/gf_contact.h"

static inline void gf_contact_tangential_inline(const gf_contact_geom *g, double k_t, double f_n, double dt_s,
                                                double *h, double f_t[3])
{
    const double *n = g->n;
    /* 1. re-projection onto the tangent plane, length preserved:
     * |h - hn n|^2 = |h|^2 (1 - q) with q = hn^2/|h|^2, so the scale is
     * (1 - q)^(-1/2) = 1 + q/2 + 3q^2/8 + O(q^3); per step the normal turns by
     * ~1e-4 rad, q ~ 1e-8, and the series (error < 3e-13 for q < 1e-4) saves a
     * square root on every contact */
    double hn = h[0] * n[0] + h[1] * n[1] + h[2] * n[2];
    if (hn != 0.0) {
        double len2 = h[0] * h[0] + h[1] * h[1] + h[2] * h[2];
        double q = hn * hn / len2;
        double s = q < 1e-4 ? 1.0 + q * (0.5 + 0.375 * q) : (q < 1.0 ? 1.0 / sqrt(1.0 - q) : 0.0);
        h[0] = (h[0] - hn * n[0]) * s, h[1] = (h[1] - hn * n[1]) * s, h[2] = (h[2] - hn * n[2]) * s;
    }
    /* 2. increment by the tangential surface slip */
    const double *v = g->v_rel_m_s;
    double vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
    h[0] += (v[0] - vn * n[0]) * dt_s;
    h[1] += (v[1] - vn * n[1]) * dt_s;
    h[2] += (v[2] - vn * n[2]) * dt_s;
    /* 3. spring force with the Coulomb cap */
    f_t[0] = -k_t * h[0], f_t[1] = -k_t * h[1], f_t[2] = -k_t * h[2];
    double ft2 = f_t[0] * f_t[0] + f_t[1] * f_t[1] + f_t[2] * f_t[2];
    double cap = g->mu * fabs(f_n);
    if (ft2 > cap * cap) {
        double s = cap / sqrt(ft2);
        f_t[0] *= s, f_t[1] *= s, f_t[2] *= s;
        double inv_k = k_t > 0.0 ? 1.0 / k_t : 0.0;
        h[0] = -f_t[0] * inv_k, h[1] = -f_t[1] * inv_k, h[2] = -f_t[2] * inv_k;
    }
}

/* Normal force of the linear law alone (a frictionless run: F_t = 0, gf_skips.c). */
static inline double gf_contact_linear_normal_inline(const gf_contact_params *p, const gf_contact_geom *g,
                                                     double sqrt_mk)
{
    double f_n = p->k_n_N_m * g->overlap_m - 2.0 * p->zeta * sqrt_mk * g->v_n_m_s;
    return (f_n < 0.0 && !p->allow_attraction) ? 0.0 : f_n;
}

static inline void gf_contact_linear_inline(const gf_contact_params *p, const gf_contact_geom *g, double dt_s,
                                            double *hist, double *f_n_out, double f_t_out[3])
{
    double v_n = g->v_n_m_s;
    double gamma_n = 2.0 * p->zeta * g->sqrt_mk;
    double f_n = p->k_n_N_m * g->overlap_m - gamma_n * v_n;
    if (f_n < 0.0 && !p->allow_attraction)
        f_n = 0.0;
    *f_n_out = f_n;
    gf_contact_tangential_inline(g, p->kt_over_kn * p->k_n_N_m, f_n, dt_s, hist, f_t_out);
}

#endif
