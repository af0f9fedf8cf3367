/*
 * gf_mui_oracles: steady, fully developed mu(I) flows solved semi-analytically
 * (Djouwe Meffeja 2012, chapter 5), the exact references of the continuum
 * solver's validation. Dimensionless throughout (the thesis' variables).
 *
 * Plane Couette with gravity (ibid. §5.3). A layer of height H between a fixed
 * bottom plate and a top plate moving at U0 under the normal pressure P0,
 * dP/dx = 0, hydrostatic pressure P* = P/P0 = 1 + eps Lambda (1 - y*):
 *   Lambda = H/d,  eps = rho g d / P0,  alpha = U0 / sqrt(P0 / rho_s).
 * The shear stress is uniform, mu(I) P* = k1 (eq. (5.3)), so
 *   gdot*(y*) = (Lambda I0/alpha) sqrt(P*) (k1 - mu_s P*)/(mu_2 P* - k1)   (5.5)
 * and k1 follows from u*(0) = 0, u*(1) = 1. Above the critical height Lambda_c
 * (where gdot*(0) = 0, k1 = mu_s (1 + eps Lambda_c)) the bottom layer
 * y* < 1 - Lambda_c/Lambda is static and the flowing top layer is the
 * critical profile rescaled (ibid. Annex B).
 *
 * Plane Poiseuille without gravity (ibid. §5.4). Plates H apart, driven by
 * G = -dP/dx > 0 at uniform P0: beta = sqrt(G H / P0), u* = u / sqrt(G H/rho_s),
 * closed form (5.17)-(5.19), a solution only for beta < beta_max = sqrt(2 (mu_2 - mu_s)).
 * This is the flow of the rate part of the law, (mu(I) - mu_s) P0 = G (H/2 - y)
 * on the lower half: the yield stress mu_s P0 is taken to "drop out" of the
 * momentum balance (ibid. (5.27)), which holds only where gdot keeps one sign.
 *
 * Numerics: the Couette shear rate is integrated by GSL's doubly adaptive
 * quadrature (CQUAD) and k1, Lambda_c are found by Brent's method on brackets
 * the physics gives (GSL, Galassi et al.); the closed form (5.6) is kept as a
 * cross-check (it loses digits as eps Lambda -> 0 through its 1/eps prefactor).
 */
#ifndef GF_MUI_ORACLES_H
#define GF_MUI_ORACLES_H

#include "continuum/gf_mui.h"

typedef struct gf_couette {
    gf_mui_params law;
    double eps, alpha, Lambda;  /* the problem */
    double Lambda_c;            /* critical height (inf when eps = 0) */
    double k1;                  /* shear stress / P0 of the flowing layer */
    double y_static;            /* top of the static bottom layer (0 when Lambda <= Lambda_c) */
} gf_couette;

/* Solves the Couette problem. GF_ERR_ARG on eps < 0, alpha <= 0, Lambda <= 0 or a bad law;
 * GF_ERR_NOT_CONVERGED if a root is not bracketed or does not converge. */
gf_status gf_couette_solve(gf_ctx *ctx, const gf_mui_params *law, double eps, double alpha, double Lambda,
                           gf_couette *out);
/* Critical height Lambda_c(eps, alpha) > 0 for eps > 0 (inf for eps = 0). */
gf_status gf_couette_critical_height(gf_ctx *ctx, const gf_mui_params *law, double eps, double alpha,
                                     double *Lambda_c);
/* u*(y*) and gdot*(y*) of a solved problem, 0 <= y* <= 1. */
double gf_couette_velocity(const gf_couette *c, double y);
double gf_couette_shear_rate(const gf_couette *c, double y);
/* Closed form (5.6) of u*(y*) - u*(0) over a fully sheared layer (eps > 0; cross-check only). */
double gf_couette_velocity_closed_form(const gf_mui_params *law, double eps, double alpha, double Lambda, double k1,
                                       double y);
/* The eps = 0 stress: k1 = mu(alpha/Lambda) = mu_s + dmu alpha/(alpha + I0 Lambda). */
double gf_couette_k1_no_gravity(const gf_mui_params *law, double alpha, double Lambda);
/* Simplified linear-profile estimate of Lambda_c, the root of (5.14). */
double gf_couette_critical_height_linear(const gf_mui_params *law, double eps, double alpha);

/* beta_max = sqrt(2 (mu_2 - mu_s)). */
double gf_poiseuille_beta_max(const gf_mui_params *law);
/* GF_ERR_ARG unless 0 < beta < beta_max and Lambda > 0. */
gf_status gf_poiseuille_check(gf_ctx *ctx, const gf_mui_params *law, double beta, double Lambda);
/* u*(y*), 0 <= y* <= 1 (symmetric), eq. (5.18); needs a checked (beta, Lambda). */
double gf_poiseuille_velocity(const gf_mui_params *law, double beta, double Lambda, double y);
/* U_max* = u*(1/2), eq. (5.19). */
double gf_poiseuille_umax(const gf_mui_params *law, double beta, double Lambda);
/* Newtonian limit beta Lambda I0 / (8 (mu_2 - mu_s)), eq. (5.21). */
double gf_poiseuille_umax_newtonian(const gf_mui_params *law, double beta, double Lambda);

/*
 * Steady uniform flow down a rough incline (Bagnold profile; GDR MiDi 2004,
 * §3.2; Jop, Forterre & Pouliquen, JFM 541, 2005, §3; Jop et al. 2006). A
 * layer of depth h at angle theta, hydrostatic P = phi rho_s g cos(theta)
 * (h - y) and tau = tan(theta) P, so mu(I) = tan(theta) everywhere: I is
 * uniform, I(theta) = I0 (tan theta - mu_s)/(mu_2 - tan theta), and
 *   u(y) = (2/3) I sqrt(phi g cos theta) / d (h^{3/2} - (h - y)^{3/2}).
 * Steady flow exists only for atan(mu_s) < theta < atan(mu_2): below, the
 * layer stays static; above, it accelerates without bound. Dimensional (SI).
 */
typedef struct gf_bagnold {
    gf_mui_params law;
    double theta_rad, phi, g_m_s2, d_m, h_m;
} gf_bagnold;

/* The start and stop angles atan(mu_s), atan(mu_2) (rad). */
double gf_bagnold_theta_start(const gf_mui_params *law);
double gf_bagnold_theta_stop(const gf_mui_params *law);
/* I(theta); 0 at or below atan(mu_s), inf at or above atan(mu_2). */
double gf_bagnold_inertial_number(const gf_bagnold *b);
/* u(y) for 0 <= y <= h (m/s); 0 when the layer does not flow, inf when it has no steady state. */
double gf_bagnold_velocity(const gf_bagnold *b, double y_m);
/* Surface velocity u(h) and the flux per unit width int_0^h u dy = (3/5) h u(h) (m2/s). */
double gf_bagnold_surface_velocity(const gf_bagnold *b);
double gf_bagnold_flux(const gf_bagnold *b);

#endif
