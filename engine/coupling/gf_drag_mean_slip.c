/*
 * mean_slip — a drag closure for dense sheared suspensions, built to be
 * consistent with the viscous rheology mu(I_v), I_v = eta gamma_dot / P, of
 * Boyer, Guazzelli & Pouliquen, PRL 107, 188301 (2011).
 *
 * An averaged drag law (Di Felice 1994 and the fixed-array fits) is a law for
 * the MEAN slip between a suspension and its fluid. Applied to each grain's
 * own velocity it also drags every grain's motion about the local mean flow
 * with the dense-bed coefficient (about 11 x Stokes at phi = 0.6), which in a
 * sheared bed acts as an effective viscosity of a few hundred eta
 * (docs/notes/validation-avalanche.md). The particle simulations that
 * reproduce mu(I_v) split the two (Trulsson, Andreotti & Claudin, PRL 109,
 * 118305, 2012: a Stokes drag on each grain's velocity relative to the mean
 * flow; Ness & Sun, PRE 91, 012201, 2015: the same plus pairwise lubrication):
 *
 *   F_d = K (u_f - <v>) + K' (<v> - v),
 *
 *   K  = Di Felice (1994) at the mean slip |u_f - <v>| (so the mean motion of a
 *        suspension, hindered settling and the pore-pressure drag of a bed,
 *        is di_felice's: Richardson–Zaki with n = 4.7),
 *   K' = 3 pi eta D (1 + 0.15 Re'^0.687), Re' = rho |<v> - v| D / eta: the
 *        isolated-sphere drag on the grain-scale motion (Trulsson et al. 2012),
 *        with the Schiller & Naumann (1933) fluid-inertia correction, which is
 *        the resistance a grain meets when its own motion has a finite
 *        Reynolds number (the inertial regime of Courrech du Pont et al. 2003),
 *
 * with <v> the kernel average of the grains' velocities at the grain (the
 * same kernel as the fluid fraction). The resistance to the relative motion
 * of touching neighbours is the DEM pair loop's lubrication force (Brenner
 * 1961 with a roughness cut-off, spec.fluid.lubrication), as in Ness & Sun.
 * A lone grain has <v> = v, so it gets the full Di Felice drag.
 */
#include <math.h>

#include "coupling/gf_drag.h"

static double mean_slip_drag(double D, double eps, double slip, double rho, double mu)
{
    return gf_drag_law_di_felice.coefficient(D, eps, slip, rho, mu);
}

static double grain_scale_resistance(double D, double eps, double slip, double rho, double mu)
{
    (void)eps;  /* an isolated-sphere law: the dense part is the lubrication of the pair loop */
    double re = rho * slip * D / mu;
    return 3.0 * M_PI * mu * D * (1.0 + 0.15 * pow(re, 0.687));
}

const gf_drag_info gf_drag_law_mean_slip = {
    .name = "mean_slip",
    .summary = "Di Felice on the mean slip + isolated-sphere drag on the grain-scale motion (Trulsson et al. 2012)",
    .coefficient = mean_slip_drag,
    .fluctuation = grain_scale_resistance,
};
