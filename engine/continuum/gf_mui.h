/*
 * gf_mui: the mu(I) friction law of dense granular flow (GDR MiDi 2004;
 * Jop, Forterre & Pouliquen, Nature 441, 2006) and the effective viscosity
 * the continuum solver uses.
 *
 *   I     = |gdot| d / sqrt(P / rho_s)                       inertial number
 *   mu(I) = mu_s + (mu_2 - mu_s) / (I0 / I + 1)
 *   eta   = mu(I) P / |gdot|                                 (Pa s)
 *
 * (Djouwe Meffeja 2012, §4.2, eqs. (4.1)-(4.4)). |gdot| = sqrt(gdot_ij gdot_ij / 2)
 * with gdot_ij = du_i/dx_j + du_j/dx_i (ibid. §4.3.1), so |gdot| = |du/dy| in
 * simple shear.
 *
 * Regularisation (ibid. Annex A): |gdot| is floored at gdot_min (1e-5 1/s
 * there), so eta stays finite where the material is static; eta = 0 where the
 * pressure is not positive (the material has no strength without confinement).
 *
 * The "rate part" eta_rate = (mu(I) - mu_s) P / |gdot| drops the yield stress
 * mu_s P: it is the law the semi-analytic channel of Djouwe Meffeja 2012,
 * §5.4, actually solves (see gf_mui_oracles.h); its small-I limit is the
 * Newtonian viscosity eta_N = d sqrt(rho_s P) (mu_2 - mu_s) / I0 (ibid. (5.28)).
 */
#ifndef GF_MUI_H
#define GF_MUI_H

#include "core/gf_status.h"

typedef struct gf_mui_params {
    double mu_s, mu_2;  /* static and limiting friction, mu_2 > mu_s >= 0 */
    double I0;          /* inertial number at which mu = (mu_s + mu_2)/2, > 0 */
} gf_mui_params;

/* Glass beads, Jop et al. 2005: mu_s = tan 20.9 deg, mu_2 = tan 32.76 deg, I0 = 0.279. */
gf_mui_params gf_mui_glass_beads(void);
/* The rounded values of Djouwe Meffeja 2012's Maxima sheets (Annexes B-D): 0.381, 0.643, 0.279. */
gf_mui_params gf_mui_thesis_maxima(void);
/* The rounded values of the thesis' Matlab code (Annex A): 0.3819, 0.6435, 0.279. */
gf_mui_params gf_mui_thesis_matlab(void);

/* GF_ERR_CONFIG unless 0 <= mu_s < mu_2 and I0 > 0 (all finite); where prefixes the message. */
gf_status gf_mui_check(gf_ctx *ctx, const gf_mui_params *p, const char *where);

/* mu(I) for I >= 0 (mu(0) = mu_s, mu(inf) = mu_2). */
double gf_mui_friction(const gf_mui_params *p, double I);
/* The inverse: I(mu) = I0 (mu - mu_s)/(mu_2 - mu) for mu_s <= mu < mu_2 (0 below mu_s, inf at or above mu_2). */
double gf_mui_inertial_number(const gf_mui_params *p, double mu);

typedef struct gf_mui_material {
    gf_mui_params law;
    double diameter_m;        /* grain diameter d */
    double grain_density_kg_m3; /* rho_s */
    double gdot_min_1_s;      /* regularisation floor of |gdot| (Annex A: 1e-5) */
    int rate_part_only;       /* 1: eta = (mu(I) - mu_s) P/|gdot| (no yield stress) */
} gf_mui_material;

/* GF_ERR_CONFIG on bad law, d <= 0, rho_s <= 0 or gdot_min <= 0. */
gf_status gf_mui_material_check(gf_ctx *ctx, const gf_mui_material *m, const char *where);

/* Regularised effective viscosity (Pa s) at shear rate |gdot| (1/s) and pressure P (Pa). */
double gf_mui_viscosity(const gf_mui_material *m, double gdot_1_s, double pressure_Pa);

/* Newtonian limit of the rate part at pressure P: eta_N = d sqrt(rho_s P) (mu_2 - mu_s)/I0 (Pa s). */
double gf_mui_newtonian_viscosity(const gf_mui_material *m, double pressure_Pa);

#endif
