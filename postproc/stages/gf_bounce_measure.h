/*
 * The numbers of one sphere-wall bounce from its trace (time, vertical
 * velocity, gap to the wall), one definition for the `bounce` post stage and
 * the resolved-tier harness (tests/resolved/resolved_bounce.c).
 *
 * Definitions (Izard 2014 §3.1.3, eq. (3.19); Gondret, Lance & Petit 2002):
 *   first contact  the first sample with gap <= 0; its start and end are the
 *                  gap's zero crossings, interpolated linearly between samples;
 *   V_T            the largest approach speed while the gap exceeds R, before
 *                  the first contact (the terminal velocity, or nearly);
 *   V_I            the approach speed just before the first contact: the last
 *                  sample with gap > 0 (Izard's V_C, Gondret's impact velocity);
 *   V_R            the first maximum of the upward velocity after the first
 *                  contact starts (0 when the sphere never moves up: no rebound);
 *   e = V_R / V_I  (= -V_R/V_I with signed velocities), eps = V_R / V_T (Izard's ε);
 *   contact time   end minus start of the first contact.
 * Velocities are positive upward (away from the wall); the speeds V_T, V_I
 * and V_R are reported positive.
 *
 * Oblique bounce, at the contact point (Joseph & Hunt, J. Fluid Mech. 510,
 * 2004, §2; Izard 2014 §3.4): with v_c = v_x + R w_z the velocity of the
 * sphere's lowest point along the wall (x the direction of the approach) and
 * V_in, e the normal reference speed and restitution,
 *   Psi_in  = v_c / V_in before the bounce (= tan xi_in),
 *   Psi_out = v_c / V_in at the rebound sample, the one of V_R (= e tan xi_out),
 *   beta    = -Psi_out / Psi_in, the tangential (rotational) restitution,
 *   mu_f    = 2 (1 + beta) Psi_in / (7 (1 + e)), the effective friction: for a
 *             solid sphere (I = 2/5 m R^2) the tangential over the normal
 *             impulse between the two samples, so mu_f = mu_c for a dry contact
 *             that slides throughout.
 * Two references, as for e and eps: at impact (the V_I sample, V_in = V_I,
 * e = V_R/V_I: Joseph & Hunt's velocities just before and after the contact)
 * and on approach (the V_T sample, V_in = V_T, e = eps = V_R/V_T: Izard's
 * reference, before the film slows the normal motion; there xi_in is the
 * angle of the fall, the angle of gravity in the `bounce` scene).
 */
#ifndef GF_BOUNCE_MEASURE_H
#define GF_BOUNCE_MEASURE_H

#include <stddef.h>

typedef struct gf_bounce {
    int touched;            /* a sample with gap <= 0 exists */
    int rebounded;          /* the sphere moved up after the first contact (V_R > 0) */
    int left;               /* the gap became positive again after the first contact */
    double V_T, V_I, V_R;   /* m s-1, positive; NaN when not determined */
    double e, eps;          /* V_R/V_I, V_R/V_T */
    double t_in_s, t_out_s, contact_s;   /* NaN when not determined */
    size_t n_in_contact;    /* samples of the first contact (gap <= 0) */
    size_t k_terminal;      /* sample of V_T (valid when V_T > 0) */
    size_t k_impact;        /* sample of V_I (valid when touched) */
    size_t k_rebound;       /* sample of V_R (valid when rebounded) */
} gf_bounce;

/* beta and mu_f are ratios to Psi_in: below this (0.06 degree) the impact is
 * normal and they are left NaN (a normal bounce's roundoff is no angle). */
#define GF_BOUNCE_PSI_MIN 1e-3

typedef enum gf_bounce_reference { GF_BOUNCE_AT_IMPACT, GF_BOUNCE_AT_APPROACH } gf_bounce_reference;

typedef struct gf_bounce_oblique {
    double e;                             /* the normal restitution used: V_R/V_I or V_R/V_T */
    double psi_in, psi_out, beta, mu_f;   /* NaN when not determined (beta, mu_f: also when |Psi_in| < GF_BOUNCE_PSI_MIN) */
    double xi_in_deg, xi_out_deg;         /* atan(Psi_in), atan(Psi_out / e): contact-point angles to the normal */
} gf_bounce_oblique;

/* t (s), v (m s-1, positive away from the wall), gap (m, surface to wall) at n
 * samples in increasing time; R the sphere's radius (m). */
void gf_bounce_measure(const double *t, const double *v, const double *gap, size_t n, double R, gf_bounce *b);

/* The oblique numbers of bounce b (measured by gf_bounce_measure on the same
 * samples) from the velocity along the wall vx (m s-1) and the spin about the
 * wall-parallel axis normal to x, wz (rad s-1, positive when it moves the
 * lowest point towards +x), with the reference ref. All NaN unless b touched
 * and rebounded. */
void gf_bounce_measure_oblique(const gf_bounce *b, const double *vx, const double *wz, double R,
                               gf_bounce_reference ref, gf_bounce_oblique *o);

/* The linear near-wall approach of a sphere dominated by the film's
 * lubrication (Mongruel, Lamriben, Yahiaoui & Feuillebois, J. Fluid Mech. 661,
 * 2010; Izard 2014 §3.1.3.2): u_p = V_m delta_n/R close to the wall, u_p the
 * approach speed and delta_n the gap. Above it inertia keeps u_p/(delta_n/R)
 * higher (the sphere has not yet slowed to the film's pace); below it the
 * roughness eta_e does (the film force goes as 1/(delta_n + eta_e)); further
 * up, where the sphere still falls at nearly its terminal speed, the ratio is
 * low again because the gap is large. The linear regime is where the ratio is
 * flat: among the samples before the first contact with 0 < delta_n <= x_max R
 * (close to the wall: Brenner's (1961) film force is within 10 % of the full
 * sphere-wall resistance below delta_n = 0.06 R, Cox & Brenner 1967, and
 * Mongruel et al. find the linear regime below 0.1-6 % of R), in time order, the ratio's first minimum once it
 * has fallen by a factor 1 + 2 flat below its running peak, the minimum being
 * over when the ratio rises 1 + 2 flat above it (the smallest ratio if it never
 * falls so: an approach linear throughout), and the samples contiguous with it
 * whose ratio stays within (1 + flat) of it. V_m is the least-squares slope of u_p against delta_n/R through the
 * origin over that window. */
typedef struct gf_bounce_approach {
    double V_m;            /* m s-1; NaN when no sample qualifies */
    double ratio_min;      /* the smallest u_p/(delta_n/R), m s-1 */
    double x_lo, x_hi;     /* the window's smallest and largest delta_n/R */
    size_t k_first, k_last;/* the window's first and last sample (k_first <= k_last) */
    size_t n;              /* samples in the window */
    int after_peak;        /* 1: the minimum follows the fall from the peak; 0: the ratio never fell so */
} gf_bounce_approach;

/* v (m s-1, positive away from the wall) and gap (m) at n samples in
 * increasing time, R (m), x_max the largest gap over R considered (e.g. 0.06),
 * flat the window's relative tolerance (e.g. 0.05). */
void gf_bounce_measure_approach(const double *v, const double *gap, size_t n, double R, double x_max, double flat,
                                gf_bounce_approach *a);

#endif
