/* Dimensionless groups and time scales; formulas and sources in gf_groups.h. */
#include "core/gf_groups.h"

#include <math.h>
#include <string.h>

gf_status gf_groups_compute(gf_ctx *ctx, const gf_groups_input *in, gf_scales *out)
{
    memset(out, 0, sizeof *out);
    const double D = in->diameter_m, rho_p = in->grain_density_kg_m3;
    const double rho_f = in->fluid_density_kg_m3, eta = in->viscosity_Pa_s, g = in->gravity_m_s2;
    const double s = in->slope_sin > 0.0 ? in->slope_sin : 1.0;
    if (!(D > 0.0) || !(rho_p > 0.0) || !(g > 0.0))
        return GF_FAIL(ctx, GF_ERR_ARG, "groups: D, rho_p and g must be > 0 (got %g, %g, %g)", D, rho_p, g);
    if (!(rho_f >= 0.0) || !(eta >= 0.0))
        return GF_FAIL(ctx, GF_ERR_ARG, "groups: fluid density and viscosity must be >= 0");
    if (rho_f >= rho_p)
        return GF_FAIL(ctx, GF_ERR_PHYSICS,
                       "groups: grains (%g kg/m3) must be denser than the fluid (%g kg/m3)", rho_p, rho_f);
    const double drho = rho_p - rho_f, g_eff = g * s;

    out->t_grain_s = sqrt(D / g);
    out->t_freefall_s = sqrt(2.0 * rho_p * D / (drho * g_eff));
    out->t0_H_s = in->column_height_m > 0.0 ? sqrt(2.0 * in->column_height_m / g) : 0.0;
    out->t0_R_s = in->column_length_m > 0.0 ? sqrt(2.0 * in->column_length_m / g) : 0.0;
    out->rho_ratio = rho_f > 0.0 ? rho_p / rho_f : INFINITY;
    out->density_ratio_r = rho_f > 0.0 ? sqrt(5.0 * rho_p / (3.0 * rho_f)) : INFINITY;
    out->t_inertial_s = sqrt(rho_f * D) / sqrt(2.0 * drho * g_eff);
    if (eta > 0.0) {
        out->stokes_St = sqrt(rho_p * drho * g_eff * D) * D / (18.0 * sqrt(2.0) * eta);
        out->archimedes_Ar = rho_f * drho * g * D * D * D / (eta * eta);
        out->t_viscous_s = 18.0 * eta / (drho * g_eff * D);
        out->t_visq_s = in->column_height_m > 0.0 ? eta / (drho * g * in->column_height_m) : 0.0;
        out->stokes_velocity_m_s = drho * g * D * D / (18.0 * eta);
    } else {
        out->stokes_St = INFINITY;
        out->archimedes_Ar = rho_f > 0.0 ? INFINITY : 0.0;
    }
    out->reynolds_Re = isfinite(out->density_ratio_r) ? out->stokes_St / out->density_ratio_r : INFINITY;
    return GF_OK;
}

gf_status gf_groups_invert(gf_ctx *ctx, double St, double r, double D, double rho_p, double g_eff,
                           double *rho_f, double *eta)
{
    if (!(St > 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "St must be > 0 (got %g)", St);
    if (!(r > sqrt(5.0 / 3.0)))
        return GF_FAIL(ctx, GF_ERR_PHYSICS,
                       "r = sqrt(5 rho_p / 3 rho_f) must exceed sqrt(5/3) = 1.291 for grains denser than "
                       "the fluid (got %g)", r);
    if (!(D > 0.0) || !(rho_p > 0.0) || !(g_eff > 0.0))
        return GF_FAIL(ctx, GF_ERR_ARG, "groups: D, rho_p and g_eff must be > 0");
    *rho_f = 5.0 * rho_p / (3.0 * r * r);
    const double drho = rho_p - *rho_f;
    *eta = sqrt(rho_p * drho * g_eff * D) * D / (18.0 * sqrt(2.0) * St);
    return GF_OK;
}
