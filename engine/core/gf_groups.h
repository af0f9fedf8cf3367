/*
 * Dimensionless groups and reference time scales, computed in one place.
 *
 * Definitions (Izard 2014, §4.1.1, §4.1.3, §5.3):
 *   St   = sqrt(rho_p drho g_eff D) D / (18 sqrt(2) eta_f)      Courrech du Pont et al., PRL 90 (2003)
 *   r    = sqrt(5 rho_p / (3 rho_f))                           (the seed's density ratio)
 *   Ar   = rho_f drho g D^3 / eta_f^2
 *   Re*  = St / r
 *   T_v  = 18 eta_f / (drho g_eff D)                           viscous time over one D
 *   T_i  = sqrt(rho_f D) / sqrt(2 drho g_eff)                  inertial time over one D
 *   T_ff = sqrt(2 rho_p D / (drho g_eff))                      free-fall time over one D
 *   T_visq = eta_f / (drho g H0)                               collapse viscous time (§5.3)
 *   T0 = sqrt(2 H0 / g), t0 = sqrt(2 R0 / g)                   free fall over H0 and R0
 * with drho = rho_p - rho_f and g_eff = g sin(theta): theta is the incline for
 * avalanches; for a column collapse the grains fall vertically and g_eff = g
 * (slope_sin = 1). With no fluid (rho_f = eta_f = 0) St, r and Ar are +inf and
 * T_v, T_i, T_visq are 0: the free-fall limit.
 *
 * The inverse map, used by campaigns at fixed D, rho_p, g, theta (Izard 2014 §4.1.1):
 *   rho_f = 5 rho_p / (3 r^2),  eta_f = sqrt(rho_p drho g_eff D) D / (18 sqrt(2) St).
 * It needs r > sqrt(5/3) (grains denser than the fluid).
 */
#ifndef GF_GROUPS_H
#define GF_GROUPS_H

#include "core/gf_status.h"

typedef struct gf_groups_input {
    double diameter_m;
    double grain_density_kg_m3;
    double fluid_density_kg_m3;   /* 0: dry */
    double viscosity_Pa_s;        /* 0: dry */
    double gravity_m_s2;
    double slope_sin;             /* sin(theta); 1 for vertical fall */
    double column_height_m;       /* H0, 0 if not a collapse */
    double column_length_m;       /* R0, 0 if not a collapse */
} gf_groups_input;

typedef struct gf_scales {
    double stokes_St, density_ratio_r, archimedes_Ar, reynolds_Re;  /* Re* = St / r */
    double rho_ratio;                       /* rho_p / rho_f */
    double t_viscous_s, t_inertial_s, t_freefall_s;  /* T_v, T_i, T_ff */
    double t_visq_s;                        /* T_visq (collapse) */
    double t0_H_s, t0_R_s;                  /* T0 = sqrt(2H0/g), t0 = sqrt(2R0/g) */
    double t_grain_s;                       /* sqrt(D/g) */
    double stokes_velocity_m_s;             /* drho g D^2 / (18 eta_f) */
} gf_scales;

/* Fills *out from *in. Errors: non-positive D, rho_p or g; rho_f >= rho_p. */
gf_status gf_groups_compute(gf_ctx *ctx, const gf_groups_input *in, gf_scales *out);

/* Fluid density and viscosity that realise (St, r) at fixed D, rho_p, g_eff.
 * Errors: St <= 0, r <= sqrt(5/3). */
gf_status gf_groups_invert(gf_ctx *ctx, double stokes_St, double density_ratio_r, double diameter_m,
                           double grain_density_kg_m3, double g_eff_m_s2, double *fluid_density_kg_m3,
                           double *viscosity_Pa_s);

#endif
