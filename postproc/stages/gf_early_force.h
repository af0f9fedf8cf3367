/*
 * The force on a sphere released from rest, extrapolated to t -> 0: the fit
 * F(t) = c0 + c1 sqrt(t) + c2 t over a window [t0, t1], returning c0. The
 * history (Basset) force of a sphere starting from rest grows as sqrt(t), so
 * a straight line through the early force or the slope of u(t) over any
 * finite window both fall below the added-mass value (Izard 2014 §2.2.3,
 * eq. (2.34): a = (rho_p - rho) g / (rho_p + rho/2), i.e. (2/3) g at
 * rho_p/rho = 4). Used by the resolved settling validation and by the
 * accuracy benchmark, so both measure the same thing.
 */
#ifndef GF_EARLY_FORCE_H
#define GF_EARLY_FORCE_H

/* c0 of the least-squares fit over the samples with t0 <= t[i] <= t1 (GSL);
 * NaN with fewer than four samples in the window. */
double gf_early_force_fit(const double *t, const double *F, int n, double t0, double t1);

#endif
