/*
 * The contact walk of gf_sim.h (gf_sim_foreach_contact): the pairs of the
 * neighbour list and the grain-wall slots, with their geometry and tangential
 * history, read-only. The near list's history is written back first (it is
 * the current one while the list is held, engine/sim/gf_near_list.c).
 */
#include <math.h>

#include "gf_sim_internal.h"

static int visit_pairs(const gf_sim *s, gf_sim_contact_fn fn, void *user)
{
    const gf_particles *p = s->p;
    const gf_nlist *nl = s->nb.nl;
    const double *pair_meff = s->nb.pair_meff;
    for (size_t i = 0; i < nl->n; ++i)
        for (size_t k = nl->row_start[i]; k < nl->row_start[i + 1]; ++k) {
            const size_t j = (size_t)nl->j[k];
            const double *sh = nl->shift_m[nl->image[k]];
            gf_sim_contact c = {.i = i, .j = j, .wall = -1, .history = &nl->hist[3 * k], .m_eff_kg = pair_meff[k]};
            c.branch_m[0] = p->x_m[i] - p->x_m[j] + sh[0];
            c.branch_m[1] = p->y_m[i] - p->y_m[j] + sh[1];
            c.branch_m[2] = p->z_m[i] - p->z_m[j] + sh[2];
            const double r = sqrt(c.branch_m[0] * c.branch_m[0] + c.branch_m[1] * c.branch_m[1] +
                                  c.branch_m[2] * c.branch_m[2]);
            for (int a = 0; a < 3; ++a)
                c.normal[a] = r > 0.0 ? c.branch_m[a] / r : 0.0;
            c.overlap_m = p->radius_m[i] + p->radius_m[j] - r;
            if (fn(user, &c))
                return 1;
        }
    return 0;
}

static int visit_walls(const gf_sim *s, gf_sim_contact_fn fn, void *user)
{
    const gf_particles *p = s->p;
    const size_t stride = (size_t)s->n_walls + 1;
    if (!s->wall_hist)
        return 0;
    for (size_t i = 0; i < p->n_local; ++i)
        for (int w = 0; w < s->n_walls; ++w) {
            const double x[3] = {p->x_m[i], p->y_m[i], p->z_m[i]};
            gf_sim_contact c = {.i = i, .wall = w, .history = &s->wall_hist[3 * (i * stride + (size_t)w)],
                                .m_eff_kg = p->mass_kg[i]};
            const double dist = gf_wall_distance(&s->walls[w], x, c.normal);
            for (int a = 0; a < 3; ++a)
                c.branch_m[a] = dist * c.normal[a];
            c.overlap_m = s->walls[w].active ? p->radius_m[i] - dist : -INFINITY;
            if (fn(user, &c))
                return 1;
        }
    return 0;
}

gf_status gf_sim_foreach_contact(const gf_sim *s, gf_sim_contact_fn fn, void *user)
{
    if (!fn)
        return GF_FAIL(s->ctx, GF_ERR_ARG, "gf_sim_foreach_contact: no callback");
    gf_near_list_sync(&s->nb);
    if (!visit_pairs(s, fn, user))
        visit_walls(s, fn, user);
    return GF_OK;
}
