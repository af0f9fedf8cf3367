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
} gf_bounce;

/* t (s), v (m s-1, positive away from the wall), gap (m, surface to wall) at n
 * samples in increasing time; R the sphere's radius (m). */
void gf_bounce_measure(const double *t, const double *v, const double *gap, size_t n, double R, gf_bounce *b);

#endif
