/* The mean pressure gradient of a periodic gravity axis; equation and sources in gf_weight_balance.h. */
#include "coupling/gf_weight_balance.h"

#include <math.h>

void gf_weight_balance_gradient(const gf_grid *g, const gf_particles *p, double rho_f_kg_m3,
                                const double gravity_m_s2[3], double G_Pa_m[3])
{
    for (int d = 0; d < 3; ++d)
        G_Pa_m[d] = 0.0;
    double vs = 0.0, ms = 0.0, vbox = 1.0;
    for (size_t i = 0; i < p->n_local; ++i) {
        if (p->flags[i] & GF_P_GLUED)
            return;
        double r = p->radius_m[i];
        vs += 4.0 / 3.0 * M_PI * r * r * r;
        ms += p->mass_kg[i];
    }
    if (vs <= 0.0)
        return;
    for (int d = 0; d < 3; ++d)
        vbox *= g->h_m[d] * g->n[d];
    double excess = ms / vbox - rho_f_kg_m3 * vs / vbox; /* phi_mean (rho_p - rho_f) */
    for (int d = 0; d < 3; ++d)
        if (g->periodic[d])
            G_Pa_m[d] = -excess * gravity_m_s2[d];
}
