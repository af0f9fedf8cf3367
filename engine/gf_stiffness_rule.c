/* Contact stiffness from the confining pressure; see gf_stiffness_rule.h. */
#include "gf_stiffness_rule.h"

#include <math.h>

double gf_stiffness_column_pressure_Pa(const gf_run_spec *spec, double phi, double height_m)
{
    return phi * spec->grains.density_kg_m3 * spec->gravity_m_s2 * height_m;
}

double gf_stiffness_k_n(const gf_run_spec *spec, double p_Pa, double overlap_over_D)
{
    return GF_STIFFNESS_CHAIN_FACTOR * p_Pa * spec->grains.diameter_m / overlap_over_D;
}

double gf_stiffness_t_contact_nd(const gf_run_spec *spec, double k_n_N_m)
{
    const double D = spec->grains.diameter_m, l = log(spec->contact.restitution);
    const double m_eff = 0.5 * spec->grains.density_kg_m3 * M_PI * D * D * D / 6.0; /* mean pair */
    const double t_c = sqrt(m_eff * (M_PI * M_PI + l * l) / k_n_N_m);             /* Izard (3.17) inverted */
    return t_c / sqrt(D / spec->gravity_m_s2);
}
