/*
 * Normal lubrication between two grains (or a grain and a wall) closer than
 * the cut-off: Brenner (1961) with an effective roughness eta_e (Izard 2014
 * §2.3.2, (2.36), (3.18)),
 *     F = -c v_n n,   c = 6 pi eta_f R_eff^2 / (gap + eta_e),
 * R_eff = R_i R_j / (R_i + R_j) (R_i for a wall), gap clamped at 0 in overlap.
 *
 * Time integration. For smooth grains c dt/m* reaches 10-100 at the seed's
 * eta_e/R = 1e-4, where an explicit force overshoots and reverses the
 * approach. The pair's damping alone gives v_n(t+dt) = v_n exp(-c dt/m*); the
 * coefficient that produces exactly this decay over one step is
 *     c_eff = m* (1 - exp(-c dt/m*)) / dt      (= c when c dt/m* << 1).
 * It is capped at m* / (4 dt) so that a grain with up to ~6 lubricated
 * neighbours stays inside the explicit stability bound (Gershgorin on the
 * pair-damping matrix); the cap only acts where the approach is stopped
 * within a few steps anyway (the overdamped limit).
 *
 * The cap binds as soon as 1 - exp(-x) >= 1/4, i.e. x >= ln(4/3) = 0.2877,
 * which is the case of every touching pair (gap 0, c at its largest). Above
 * x = 0.29 (1 - exp(-x) = 0.2517, far from the bound in round-off) the cap is
 * returned as is. Below, c_eff = c phi1(x) with phi1(x) = (1 - exp(-x))/x
 * summed from its Taylor series, sum_k (-x)^k/(k+1)!, to degree 11: the
 * first term left out, x^12/13! < 6e-17 at x = 0.29, is below round-off
 * (test_lubrication_damping: within 2.6e-16 of -expm1(-x)/x over [0, 0.29]). The
 * libm call it replaces took 12 % of an immersed collapse's run time (the
 * pairs near contact but not touching call it every step).
 */
#ifndef GF_LUBRICATION_H
#define GF_LUBRICATION_H

#include <math.h>

/* (1 - exp(-x))/x for 0 <= x <= 0.29: its Taylor series to degree 11 in
 * Estrin's form (pairs of terms, then pairs of pairs with x^2, x^4, x^8):
 * a chain of 7 dependent operations where Horner's has 22, which the pair
 * loop waits on for every lubricated pair (Horner's form took a fifth of
 * its samples). */
static inline double gf_lubrication_phi1(double x)
{
    /* c_k = (-1)^k/(k+1)!, k = 0..11 */
    const double x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
    const double q1 = 1.0 / 6.0 + x * (-1.0 / 24.0);
    const double q2 = 1.0 / 120.0 + x * (-1.0 / 720.0), q3 = 1.0 / 5040.0 + x * (-1.0 / 40320.0);
    const double q4 = 1.0 / 362880.0 + x * (-1.0 / 3628800.0), q5 = 1.0 / 39916800.0 + x * (-1.0 / 479001600.0);
    const double r1 = q2 + x2 * q3, r2 = q4 + x2 * q5;
    /* the small terms first, 1 last: the sum keeps their bits */
    const double tail = (x2 * q1 + x4 * r1) + x8 * r2;
    return 1.0 + (x * (-1.0 / 2.0) + tail);
}

/* Damping coefficient (N s/m) to apply over a step dt_s to a pair of reduced
 * mass m_eff_kg whose Brenner coefficient is c_N_s_m. */
static inline double gf_lubrication_damping(double dt_s, double c_N_s_m, double m_eff_kg)
{
    if (!(m_eff_kg > 0.0) || !isfinite(m_eff_kg))
        return c_N_s_m;
    double x = c_N_s_m * dt_s / m_eff_kg;
    double cap = 0.25 * m_eff_kg / dt_s;
    if (x >= 0.29)
        return cap;
    double c_eff = c_N_s_m * gf_lubrication_phi1(x);
    return c_eff < cap ? c_eff : cap;
}

#endif
