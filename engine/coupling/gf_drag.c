/* Drag closures; formulas and sources in gf_drag.h. */
#include "coupling/gf_drag.h"

#include <math.h>
#include <string.h>

static const char *const drag_names[] = {"di_felice", "beetstra", "tenneti"};

gf_status gf_drag_find(gf_ctx *ctx, const char *name, gf_drag_law *law)
{
    for (int i = 0; i < 3; ++i)
        if (strcmp(name, drag_names[i]) == 0) {
            *law = (gf_drag_law)i;
            return GF_OK;
        }
    return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid.drag: unknown closure '%s' (known: di_felice, beetstra, tenneti)", name);
}

const char *gf_drag_name(gf_drag_law law) { return drag_names[law]; }

double gf_drag_coefficient(gf_drag_law law, double D, double eps, double slip, double rho, double mu)
{
    if (eps > 1.0)
        eps = 1.0;
    if (eps < 0.2)
        eps = 0.2;
    double phi = 1.0 - eps;
    double re = rho * eps * slip * D / mu;
    double stokes = 3.0 * M_PI * mu * D;
    switch (law) {
    case GF_DRAG_DI_FELICE: {
        /* (1/2) C_D rho (pi D^2/4) eps^2 W, with C_D W = (0.63 sqrt(Re) + 4.8)^2 mu/(rho eps D): finite at W = 0 */
        double sre = sqrt(re);
        double cd_w = (0.63 * sre + 4.8) * (0.63 * sre + 4.8) * mu / (rho * eps * D);
        double lre = re > 1e-30 ? log10(re) : -30.0;
        double chi = 3.7 - 0.65 * exp(-0.5 * (1.5 - lre) * (1.5 - lre));
        return 0.5 * cd_w * rho * (M_PI * D * D / 4.0) * pow(eps, 2.0 - chi);
    }
    case GF_DRAG_BEETSTRA: {
        double f = 10.0 * phi / (eps * eps) + eps * eps * (1.0 + 1.5 * sqrt(phi));
        if (re > 0.0)
            f += 0.413 * re / (24.0 * eps * eps) * (1.0 / eps + 3.0 * phi * eps + 8.4 * pow(re, -0.343)) /
                 (1.0 + pow(10.0, 3.0 * phi) * pow(re, -0.5 * (1.0 + 4.0 * phi)));
        return stokes * eps * f;
    }
    case GF_DRAG_TENNETI: {
        double e3 = eps * eps * eps;
        double f = (1.0 + 0.15 * pow(re, 0.687)) / e3 + 5.81 * phi / e3 + 0.48 * cbrt(phi) / (e3 * eps) +
                   phi * phi * phi * re * (0.95 + 0.61 * phi * phi * phi / (eps * eps));
        return stokes * eps * eps * f;
    }
    }
    return stokes;
}
