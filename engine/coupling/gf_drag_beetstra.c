/*
 * beetstra — Beetstra, van der Hoef & Kuipers, AIChE J. 53 (2007), fitted to
 * lattice-Boltzmann drag in fixed random arrays, normalised by the Stokes drag
 * at the superficial velocity, F = F_d / (3 pi eta D eps W):
 *   F = 10 phi/eps^2 + eps^2 (1 + 1.5 sqrt(phi))
 *       + 0.413 Re/(24 eps^2) [1/eps + 3 phi eps + 8.4 Re^-0.343] / [1 + 10^{3 phi} Re^{-(1 + 4 phi)/2}],
 *   K = 3 pi eta D eps F.
 * Its Stokes limit is Carman–Kozeny (10 phi/eps^2 <=> 180 in the Kozeny
 * constant) plus a small correction.
 */
#include <math.h>

#include "coupling/gf_drag.h"

static double beetstra(double D, double eps, double slip, double rho, double mu)
{
    double phi = 1.0 - eps;
    double re = rho * eps * slip * D / mu;
    double f = 10.0 * phi / (eps * eps) + eps * eps * (1.0 + 1.5 * sqrt(phi));
    if (re > 0.0)
        f += 0.413 * re / (24.0 * eps * eps) * (1.0 / eps + 3.0 * phi * eps + 8.4 * pow(re, -0.343)) /
             (1.0 + pow(10.0, 3.0 * phi) * pow(re, -0.5 * (1.0 + 4.0 * phi)));
    return 3.0 * M_PI * mu * D * eps * f;
}

const gf_drag_info gf_drag_law_beetstra = {
    .name = "beetstra",
    .summary = "Beetstra, van der Hoef & Kuipers (2007) fixed-array fit; Carman-Kozeny/Ergun",
    .coefficient = beetstra,
};
