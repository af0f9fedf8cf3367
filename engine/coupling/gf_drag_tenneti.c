/*
 * tenneti — Tenneti, Garg & Subramaniam, Int. J. Multiphase Flow 37 (2011),
 * particle-resolved DNS of fixed random arrays; their F is the TOTAL average
 * fluid force (mean pressure gradient included) over 3 pi eta D eps W:
 *   F = F_isol/eps^3 + F_phi + F_phiRe,  F_isol = 1 + 0.15 Re^0.687 (Schiller–Naumann),
 *   F_phi = 5.81 phi/eps^3 + 0.48 phi^{1/3}/eps^4,  F_phiRe = phi^3 Re (0.95 + 0.61 phi^3/eps^2).
 * The drag alone is eps times the total (van der Hoef et al., JFM 528, 2005:
 * in a bed the mean pressure gradient carries the fraction phi of the total),
 * so K = 3 pi eta D eps^2 F. Some implementations omit this factor and use the
 * total force as drag, counting the mean pressure gradient twice.
 */
#include <math.h>

#include "coupling/gf_drag.h"

static double tenneti(double D, double eps, double slip, double rho, double mu)
{
    double phi = 1.0 - eps;
    double re = rho * eps * slip * D / mu;
    double e3 = eps * eps * eps;
    double f = (1.0 + 0.15 * pow(re, 0.687)) / e3 + 5.81 * phi / e3 + 0.48 * cbrt(phi) / (e3 * eps) +
               phi * phi * phi * re * (0.95 + 0.61 * phi * phi * phi / (eps * eps));
    return 3.0 * M_PI * mu * D * eps * eps * f;
}

const gf_drag_info gf_drag_law_tenneti = {
    .name = "tenneti",
    .summary = "Tenneti, Garg & Subramaniam (2011) fixed-array DNS fit, drag part",
    .coefficient = tenneti,
};
