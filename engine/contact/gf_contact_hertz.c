/*
 * Hertz-Mindlin normal/tangential law (not used by the thesis, which is
 * linear throughout; provided for comparison, as Djouwe Meffeja 2012 §2.4.3 discusses).
 * With s = sqrt(delta/delta_ref):
 *   F_n = k_n s delta - gamma_n sqrt(s) v_n,   k_t(delta) = kt_over_kn k_n s,
 * i.e. the Hertz force (4/3) E* sqrt(R*) delta^(3/2) written with the linear
 * stiffness k_n at the reference overlap delta_ref (where the two laws have
 * the same secant stiffness), damping ~ delta^(1/4) so that the restitution
 * does not depend on the impact speed (Tsuji, Tanaka & Ishida, Powder
 * Technol. 1992), Mindlin's no-slip stiffness ~ contact radius ~ s.
 */
#include "contact/gf_contact.h"

#include <math.h>

void gf_contact_hertz(const gf_contact_params *p, const gf_contact_geom *g, double dt_s, double *hist,
                      double *f_n_out, double f_t_out[3])
{
    double v_n = g->v_n_m_s;
    double s = sqrt(g->overlap_m / p->delta_ref_m);
    double gamma_n = 2.0 * p->zeta * g->sqrt_mk * sqrt(s);
    double f_n = p->k_n_N_m * s * g->overlap_m - gamma_n * v_n;
    if (f_n < 0.0 && !p->allow_attraction)
        f_n = 0.0;
    *f_n_out = f_n;
    gf_contact_tangential(g, p->kt_over_kn * p->k_n_N_m * s, f_n, dt_s, hist, f_t_out);
}

/* Reference overlap: the peak overlap of the mean pair hit at the free-fall
 * speed sqrt(gD) under the undamped linear law, V sqrt(m* / k_n), so that
 * the two laws coincide at the impacts of a gravity flow. */
void gf_contact_hertz_derive(const gf_run_spec *spec, gf_contact_params *cp)
{
    const double D = spec->grains.diameter_m;
    cp->delta_ref_m = sqrt(spec->gravity_m_s2 * D) * sqrt(cp->m_eff_mean_kg / cp->k_n_N_m);
}

/* The secant stiffness k_n s grows as s = (delta/delta_ref)^(1/2) and the
 * tangent stiffness as 1.5 k_n s; the frequency goes as the square root of
 * the stiffness, (delta/delta_ref)^(1/4) (the factor 1.5 is within the
 * margin of the t_c/5 limit). */
double gf_contact_hertz_frequency_factor(const gf_contact_params *p, double overlap_m)
{
    return p->delta_ref_m > 0.0 ? sqrt(sqrt(overlap_m / p->delta_ref_m)) : 1.0;
}

/* Integral of k_n delta (delta/delta_ref)^(1/2): (2/5) k_n s delta^2. */
double gf_contact_hertz_normal_energy(const gf_contact_params *p, double overlap_m)
{
    return 0.4 * p->k_n_N_m * sqrt(overlap_m / p->delta_ref_m) * overlap_m * overlap_m;
}

/* 1/2 k_t(delta) |xi|^2 with Mindlin's k_t = kt_over_kn k_n s at the current
 * overlap: the energy the spring would give back at fixed overlap. */
double gf_contact_hertz_tangential_energy(const gf_contact_params *p, double overlap_m, double xi2_m2)
{
    const double s = overlap_m > 0.0 ? sqrt(overlap_m / p->delta_ref_m) : 0.0;
    return 0.5 * p->kt_over_kn * p->k_n_N_m * s * xi2_m2;
}

const gf_contact_info gf_contact_law_hertz = {
    .name = "hertz",
    .kernel = gf_contact_hertz,
    .n_history = GF_CONTACT_HISTORY,
    .doc = "Hertz-Mindlin, delta^1/4 damping (Tsuji 1992)",
    .derive = gf_contact_hertz_derive,
    .frequency_factor = gf_contact_hertz_frequency_factor,
    .normal_energy = gf_contact_hertz_normal_energy,
    .tangential_energy = gf_contact_hertz_tangential_energy,
};
