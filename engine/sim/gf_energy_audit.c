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
 */
#include <math.h>

#include "gf_sim_internal.h"

static double squared(const double *h)
{
    return h[0] * h[0] + h[1] * h[1] + h[2] * h[2];
}

/* Normal and tangential elastic energy of the grain pairs of the list. */
static void pair_elastic(const gf_sim *s, double *normal_J, double *tangential_J)
{
    const gf_particles *p = s->p;
    const gf_nlist *nl = s->nl;
    const gf_contact_info *law = s->law;
    double en = 0.0, et = 0.0;
    for (size_t i = 0; i < nl->n; ++i)
        for (size_t k = nl->row_start[i]; k < nl->row_start[i + 1]; ++k) {
            const size_t j = (size_t)nl->j[k];
            const double *sh = nl->shift_m[nl->image[k]];
            double dx = p->x_m[i] - p->x_m[j] + sh[0], dy = p->y_m[i] - p->y_m[j] + sh[1];
            double dz = p->z_m[i] - p->z_m[j] + sh[2];
            double overlap = p->radius_m[i] + p->radius_m[j] - sqrt(dx * dx + dy * dy + dz * dz);
            et += law->tangential_energy(&s->cp, fmax(overlap, 0.0), squared(&nl->hist[3 * k]));
            if (overlap > 0.0 && !((p->flags[i] & GF_P_GLUED) && (p->flags[j] & GF_P_GLUED)))
                en += law->normal_energy(&s->cp, overlap);
        }
    *normal_J = en, *tangential_J = et;
}

/* Overlap of grain i with wall w, 0 when apart, inactive or no wall. */
static double wall_overlap(const gf_sim *s, size_t i, int w)
{
    if (w >= s->n_walls || !s->walls[w].active)
        return 0.0;
    const gf_particles *p = s->p;
    const gf_wall *wl = &s->walls[w];
    double c[3] = {p->x_m[i], p->y_m[i], p->z_m[i]}, n[3];
    return fmax(p->radius_m[i] - gf_wall_distance(wl, c, n), 0.0); /* a wall's hole: its rim (gf_sim_internal.h) */
}

/* The same for the grain-wall contacts (glued grains do not touch walls). */
static void wall_elastic(const gf_sim *s, double *normal_J, double *tangential_J)
{
    const gf_particles *p = s->p;
    const gf_contact_info *law = s->law;
    const size_t stride = (size_t)s->n_walls + 1;
    double en = 0.0, et = 0.0;
    for (size_t i = 0; i < p->n_local && s->n_walls > 0; ++i)
        for (size_t w = 0; w < stride; ++w) {
            const double overlap = wall_overlap(s, i, (int)w);
            if (s->wall_hist)
                et += law->tangential_energy(&s->cp, overlap, squared(&s->wall_hist[3 * (i * stride + w)]));
            if (overlap > 0.0 && !(p->flags[i] & GF_P_GLUED))
                en += law->normal_energy(&s->cp, overlap);
        }
    *normal_J = en, *tangential_J = et;
}

gf_status gf_sim_energy_audit(const gf_sim *s, gf_sim_energy *e)
{
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
    gf_sim_near_sync(s); /* the near list's history into the list's (gf_near_list.c) */
    double pair_n, pair_t, wall_n, wall_t;
    pair_elastic(s, &pair_n, &pair_t);
    wall_elastic(s, &wall_n, &wall_t);
    e->elastic_normal_J = pair_n + wall_n;
    e->elastic_tangential_J = pair_t + wall_t;
    e->total_J = e->kinetic_J + e->rotational_J + e->gravity_J + e->elastic_normal_J + e->elastic_tangential_J;
    return GF_OK;
}
