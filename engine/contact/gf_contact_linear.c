/*
 * Linear spring-dashpot normal law (Schäfer, Dippel & Wolf 1996; Izard 2014
 * (2.4), (3.13)): F_n = k_n delta - gamma_n v_n, clipped at 0 unless the run
 * allows attraction (the clip is Izard §3.1.2.2; it raises the restitution
 * above eps_max: 0.550 for 0.5, see gf_contact_clipped_restitution).
 * gamma_n = 2 zeta sqrt(m* k_n) (see gf_contact.h for why per-pair damping
 * and a shared stiffness). Tangential part: gf_contact_tangential.
 */
#include "contact/gf_contact.h"
#include "contact/gf_contact_kernels.h"

void gf_contact_linear(const gf_contact_params *p, const gf_contact_geom *g, double dt_s, double *hist,
                       double *f_n_out, double f_t_out[3])
{
    gf_contact_linear_inline(p, g, dt_s, hist, f_n_out, f_t_out);
}

/* Potential of the spring, 1/2 k_n delta^2 (Izard 2014 (2.4)). */
static double linear_normal_energy(const gf_contact_params *p, double overlap_m)
{
    return 0.5 * p->k_n_N_m * overlap_m * overlap_m;
}

/* 1/2 k_t |xi|^2: after a Coulomb slip xi holds the capped spring (2.5), so
 * this is the energy the spring can give back. */
static double linear_tangential_energy(const gf_contact_params *p, double overlap_m, double xi2_m2)
{
    return 0.5 * p->kt_over_kn * p->k_n_N_m * xi2_m2;
}

const gf_contact_info gf_contact_law_linear = {
    .name = "linear",
    .kernel = gf_contact_linear,
    .n_history = GF_CONTACT_HISTORY,
    .doc = "spring-dashpot, clipped, vector tangential spring (Izard 2014)",
    .normal_energy = linear_normal_energy,
    .tangential_energy = linear_tangential_energy,
};
