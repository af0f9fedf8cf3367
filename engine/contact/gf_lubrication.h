/*
 * Normal lubrication between two grains (or a grain and a wall) closer than
 * the cut-off: Brenner (1961) with an effective roughness eta_e (Izard 2014
 * §2.3.2, (2.36), (3.18)),
 *     F = -c v_n n,   c = 6 pi eta_f R_eff^2 / (gap + eta_e),
 * R_eff = R_i R_j / (R_i + R_j) (R_i for a wall).
 *
 * While the surfaces overlap (fluid.lub_overlap), Brenner's gap is not
 * defined; three choices:
 *   clamp  the gap clamped at 0: the constant damping 6 pi eta R_eff^2/eta_e
 *          over the whole contact (the default);
 *   off    no film force: the contact law alone;
 *   film   the film keeps the elastic thickness of Izard 2014 §3.1.4,
 *          eq. (3.28): the contact's elastic stress balances the film's
 *          pressure when R_eff/eta_c = sqrt(k_n/(6 pi eta V_C)), V_C the impact
 *          speed; the gap is then eta_c (plus eta_e, as outside contact).
 *          Over a linear contact of half-period pi sqrt(m* / k_n) the film's
 *          damping 6 pi eta R_eff^2/eta_c then takes exp(-(pi/2)/sqrt(St_C))
 *          of the rebound, St_C = m* V_C/(6 pi eta R_eff^2) (eq. (3.29)):
 *          the loss of the contact stage depends on the impact's Stokes
 *          number alone, not on the stiffness the DEM chooses for its step
 *          (where clamp's loss, 6 pi eta R_eff^2 t_c/(2 m* eta_e), does).
 *          V_C is read from the contact's state: for a linear spring
 *          v_n^2 + (k_n/m*) delta^2 stays V_C^2 but for the damping.
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

/* What the film does while the surfaces overlap (fluid.lub_overlap). */
typedef enum { GF_LUB_OVERLAP_CLAMP = 0, GF_LUB_OVERLAP_OFF = 1, GF_LUB_OVERLAP_FILM = 2 } gf_lub_overlap;

extern const char *const gf_lub_overlap_names[]; /* "clamp", "off", "film", NULL: in the enum's order */

/* The mode called name; -1 when there is none. */
int gf_lub_overlap_from_name(const char *name, gf_lub_overlap *out);

/* The film's gap (m) in an overlap of overlap_m > 0 with normal velocity
 * v_n_m_s: 0 (clamp) or the elastic thickness eta_c of Izard 2014 eq. (3.28)
 * (film), R_eff sqrt(6 pi eta V_C/k_n) with V_C^2 = v_n^2 + (k_n/m*) delta^2.
 * A pair of infinite reduced mass (glued grains) reads V_C = |v_n|. */
static inline double gf_lubrication_overlap_gap(gf_lub_overlap mode, double r_eff_m, double eta_Pa_s, double k_n_N_m,
                                                double m_eff_kg, double v_n_m_s, double overlap_m)
{
    if (mode != GF_LUB_OVERLAP_FILM)
        return 0.0;
    double w2 = (m_eff_kg > 0.0 && isfinite(m_eff_kg)) ? k_n_N_m / m_eff_kg : 0.0;
    double v_c = sqrt(v_n_m_s * v_n_m_s + w2 * overlap_m * overlap_m);
    return r_eff_m * sqrt(6.0 * M_PI * eta_Pa_s * v_c / k_n_N_m);
}

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
