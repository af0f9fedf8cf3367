/*
 * Mechanical energy of the grains, for audits: a system whose only forces
 * are contacts (elastic springs and dissipative dashpots, Coulomb slip,
 * lubrication), gravity and the drag and buoyancy of a fluid at rest can only
 * lose the sum
 *     E = E_kin + E_rot + E_grav + E_el,n + E_el,t,
 * so a rise of E is energy from nowhere (a numerical defect) and motion with
 * E falling is the release of stored energy (settling, creep).
 *   - E_grav = -sum (m_i - rho_f V_i) g . x_i over mobile grains: buoyant
 *     weight, the potential of gravity and of the hydrostatic part of the
 *     fluid pressure (rho_f = 0 when dry);
 *   - E_el,n: the law's normal potential (gf_contact_info.normal_energy;
 *     1/2 k_n delta^2 for the linear law, Izard 2014 (2.4)) over grain pairs
 *     and grain-wall contacts in overlap;
 *   - E_el,t: the law's tangential spring energy at each stored spring xi
 *     (1/2 k_t |xi|^2 for the linear law, (2.5)); after a Coulomb slip xi
 *     holds the capped spring, so this is the energy the spring can give back.
 * Read through the public API alone (gf_sim_foreach_contact).
 */
#include <math.h>

#include "contact/gf_contact.h"
#include "gf_sim.h"

static double squared(const double *h)
{
    return h[0] * h[0] + h[1] * h[1] + h[2] * h[2];
}

/* Normal and tangential elastic energy, summed apart for the grain pairs of
 * the neighbour list and for the grain-wall contacts (walls: glued grains
 * touch none; an inactive wall stores no energy). */
typedef struct elastic_sums {
    const gf_particles *p;
    const gf_contact_info *law;
    const gf_contact_params *cp;
    double pair_n, pair_t, wall_n, wall_t;
} elastic_sums;

static int add_elastic(void *user, const gf_sim_contact *c)
{
    elastic_sums *e = user;
    const uint8_t *flags = e->p->flags;
    const double overlap = fmax(c->overlap_m, 0.0);
    const double tangential = e->law->tangential_energy(e->cp, overlap, squared(c->history));
    if (c->wall < 0) {
        e->pair_t += tangential;
        if (c->overlap_m > 0.0 && !((flags[c->i] & GF_P_GLUED) && (flags[c->j] & GF_P_GLUED)))
            e->pair_n += e->law->normal_energy(e->cp, c->overlap_m);
        return 0;
    }
    e->wall_t += tangential;
    if (overlap > 0.0 && !(flags[c->i] & GF_P_GLUED))
        e->wall_n += e->law->normal_energy(e->cp, overlap);
    return 0;
}

gf_status gf_sim_energy_audit(const gf_sim *s, gf_sim_energy *e)
{
    const gf_particles *p = gf_sim_particles((gf_sim *)s);
    const gf_run_spec *spec = gf_sim_spec(s);
    const double rho_f = gf_sim_immersed(s) ? spec->fluid.density_kg_m3 : 0.0, rho_p = spec->grains.density_kg_m3;
    double g[3];
    gf_sim_gravity(s, g);
    *e = (gf_sim_energy){0};
    for (size_t i = 0; i < p->n_local; ++i) {
        if (p->flags[i] & GF_P_GLUED)
            continue;
        const double m = p->mass_kg[i], v2 = p->vx_m_s[i] * p->vx_m_s[i] + p->vy_m_s[i] * p->vy_m_s[i] +
                                              p->vz_m_s[i] * p->vz_m_s[i];
        const double w2 = p->wx_rad_s[i] * p->wx_rad_s[i] + p->wy_rad_s[i] * p->wy_rad_s[i] +
                          p->wz_rad_s[i] * p->wz_rad_s[i];
        e->kinetic_J += 0.5 * m * v2;
        e->rotational_J += 0.5 * 0.4 * m * p->radius_m[i] * p->radius_m[i] * w2; /* solid sphere */
        const double m_buoyant = m * (1.0 - rho_f / rho_p);
        e->gravity_J -= m_buoyant * (g[0] * p->x_m[i] + g[1] * p->y_m[i] + g[2] * p->z_m[i]);
    }
    elastic_sums sums = {.p = p, .law = gf_contact_find(spec->contact.law), .cp = gf_sim_contact_params(s)};
    if (!sums.law)
        return GF_FAIL(gf_sim_ctx((gf_sim *)s), GF_ERR_CONFIG, "energy audit: unknown contact law '%s'",
                       spec->contact.law);
    GF_TRY(gf_sim_foreach_contact(s, add_elastic, &sums));
    e->elastic_normal_J = sums.pair_n + sums.wall_n;
    e->elastic_tangential_J = sums.pair_t + sums.wall_t;
    e->total_J = e->kinetic_J + e->rotational_J + e->gravity_J + e->elastic_normal_J + e->elastic_tangential_J;
    return GF_OK;
}
