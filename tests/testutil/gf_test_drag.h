/*
 * Reference drag of an isolated sphere for the settling tests: the terminal
 * Reynolds number of the Schiller & Naumann (1933) correlation, C_D = 24/Re
 * (1 + 0.15 Re^0.687), from the force balance C_D Re^2 = (4/3) Ar with
 * Ar = rho_f (rho_p - rho_f) g D^3 / eta^2 (Izard 2014 eq. (2.35)).
 */
#ifndef GF_TEST_DRAG_H
#define GF_TEST_DRAG_H

#include <math.h>

/* Re_T for Archimedes number Ar, by bisection on log Re over [1e-8, 1e6]
 * (200 halvings: converged to round-off). */
static inline double gf_test_schiller_naumann_Re(double Ar)
{
    double lo = 1e-8, hi = 1e6;
    for (int it = 0; it < 200; ++it) {
        double Re = sqrt(lo * hi);
        double f = 24.0 * Re * (1.0 + 0.15 * pow(Re, 0.687)) - 4.0 / 3.0 * Ar;
        if (f > 0)
            hi = Re;
        else
            lo = Re;
    }
    return sqrt(lo * hi);
}

#endif
