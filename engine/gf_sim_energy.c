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
 *   - E_el,n = sum 1/2 k_n delta^2 over grain pairs and grain-wall contacts
 *     in overlap (the linear law's spring, Izard 2014 (2.4));
 *   - E_el,t = sum 1/2 k_t |xi|^2, xi the stored tangential spring
 *     (2.5); after a Coulomb slip it holds the capped spring, so this is the
 *     energy the spring can give back.
 * The linear law only (Hertz stores a different potential).
 */
#include <math.h>

#include "gf_sim_internal.h"

static double pair_elastic_normal(const gf_sim *s)
{
    const gf_particles *p = s->p;
    const gf_nlist *nl = s->nl;
    double e = 0.0;
    for (size_t i = 0; i < nl->n; ++i)
        for (size_t k = nl->row_start[i]; k < nl->row_start[i + 1]; ++k) {
            const size_t j = (size_t)nl->j[k];
            if ((p->flags[i] & GF_P_GLUED) && (p->flags[j] & GF_P_GLUED))
                continue;
            const double *sh = nl->shift_m[nl->image[k]];
            double dx = p->x_m[i] - p->x_m[j] + sh[0], dy = p->y_m[i] - p->y_m[j] + sh[1];
            double dz = p->z_m[i] - p->z_m[j] + sh[2];
            double overlap = p->radius_m[i] + p->radius_m[j] - sqrt(dx * dx + dy * dy + dz * dz);
            if (overlap > 0.0)
                e += 0.5 * s->cp.k_n_N_m * overlap * overlap;
        }
    return e;
}

static double wall_elastic_normal(const gf_sim *s)
{
    const gf_particles *p = s->p;
    double e = 0.0;
    for (int w = 0; w < s->n_walls; ++w) {
        const gf_wall *wl = &s->walls[w];
        if (!wl->active)
            continue;
        for (size_t i = 0; i < p->n_local; ++i) {
            double c[3] = {p->x_m[i], p->y_m[i], p->z_m[i]}, n[3];
            double dist = gf_wall_distance(wl, c, n);
            double overlap = p->radius_m[i] - dist;
            if (overlap > 0.0 && !(p->flags[i] & GF_P_GLUED))
                e += 0.5 * s->cp.k_n_N_m * overlap * overlap;
        }
    }
    return e;
}

static double sum_squares(const double *h, size_t n_doubles)
{
    double q = 0.0;
    for (size_t a = 0; a < n_doubles; ++a)
        q += h[a] * h[a];
    return q;
}

gf_status gf_sim_energy_audit(const gf_sim *s, gf_sim_energy *e)
{
    if (s->law->kernel != gf_contact_linear)
        return GF_FAIL(s->ctx, GF_ERR_CONFIG, "energy audit: contact law %s has no linear spring potential",
                       s->law->name);
    const gf_particles *p = s->p;
    const double rho_f = s->immersed ? s->spec.fluid.density_kg_m3 : 0.0, rho_p = s->spec.grains.density_kg_m3;
    const double *g = s->gravity_m_s2;
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
    const double k_t = s->cp.kt_over_kn * s->cp.k_n_N_m;
    gf_sim_near_sync(s); /* the near list's history into the list's (gf_sim_near.c) */
    e->elastic_normal_J = pair_elastic_normal(s) + wall_elastic_normal(s);
    e->elastic_tangential_J = 0.5 * k_t * sum_squares(s->nl->hist, 3 * s->nl->n_pairs);
    if (s->wall_hist && s->n_walls > 0)
        e->elastic_tangential_J += 0.5 * k_t * sum_squares(s->wall_hist, 3 * p->n_local * ((size_t)s->n_walls + 1));
    e->total_J = e->kinetic_J + e->rotational_J + e->gravity_J + e->elastic_normal_J + e->elastic_tangential_J;
    return GF_OK;
}
