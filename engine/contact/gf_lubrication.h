/*
 * Normal lubrication between two grains (or a grain and a wall) closer than
 * the cut-off: Brenner (1961) with an effective roughness eta_e (Izard 2014
 * §2.3.2, digest §4.2),
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
 * returned without evaluating expm1: the same value, and the dense bed's
 * pairs no longer pay for a transcendental call each per step.
 */
#ifndef GF_LUBRICATION_H
#define GF_LUBRICATION_H

#include <math.h>

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
    double c_eff = x < 1e-6 ? c_N_s_m : m_eff_kg * (-expm1(-x)) / dt_s;
    return c_eff < cap ? c_eff : cap;
}

#endif
