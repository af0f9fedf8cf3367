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
