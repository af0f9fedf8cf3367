/*
 * The viscous rheology of dense suspensions of Boyer, Guazzelli & Pouliquen,
 * PRL 107, 188301 (2011), eqs. (4)-(5), and what it predicts for the steady
 * layer of an immersed avalanche:
 *
 *   mu(I_v)  = mu1 + (mu2 - mu1)/(1 + I0/I_v) + I_v + (5/2) phi_m sqrt(I_v)
 *   phi(I_v) = phi_m / (1 + sqrt(I_v)),        I_v = eta_f |gamma_dot| / P,
 *
 * with their fitted values mu1 0.32, mu2 0.7, I0 0.005, phi_m 0.585. The
 * "contact part" is the first two terms alone.
 *
 * Layer: a bed of depth h on a periodic incline, no slip at its base, whose
 * grains are driven downslope with a stress ratio tau/P = mu_drive at every
 * depth (tan(theta) for grains in a fluid at rest, a tank; more with the
 * drive of Izard 2014 eq. (4.6), see scenes/gf_scene_avalanche.c). I_v is
 * then uniform, P = phi drho g cos(theta) z at depth z, and the depth-mean
 * speed is U = I_v phi drho g cos(theta) h^2 / (3 eta_f). The flow time of
 * Izard (4.12) over a cell of length L, T = L/U, over the viscous scale
 * T_v = 18 eta_f/(drho g D sin(theta)) (gf_groups.h) is
 *
 *   T/T_v = (L/D) (D/h)^2 tan(theta) / (6 I_v phi),
 *
 * independent of St and r: the viscous plateau a grain-scale method that
 * follows this rheology should find.
 */
#ifndef GF_BOYER_H
#define GF_BOYER_H

typedef struct gf_boyer_law {
    double mu1, mu2, I0, phi_m;
} gf_boyer_law;

/* Boyer et al. (2011)'s fit. */
extern const gf_boyer_law GF_BOYER_2011;

/* mu(I_v); contact_only keeps the first two terms. */
double gf_boyer_mu(const gf_boyer_law *law, double Iv, int contact_only);
/* The I_v at which mu(I_v) = mu (mu increasing in I_v); 0 at or below mu1. */
double gf_boyer_Iv(const gf_boyer_law *law, double mu, int contact_only);
/* phi(I_v). */
double gf_boyer_phi(const gf_boyer_law *law, double Iv);
/* T/T_v of the layer above: stress ratio mu_drive, incline tan(theta), depth
 * h/D, cell length L/D. +inf when mu_drive does not exceed mu1 (no flow). */
double gf_boyer_layer_T_over_Tv(const gf_boyer_law *law, double mu_drive, double tan_theta, double h_over_D,
                                double L_over_D, int contact_only);

#endif
