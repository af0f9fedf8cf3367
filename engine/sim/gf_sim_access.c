/*
 * What drivers, tests and benchmarks may see of a run beyond the plain
 * accessors of gf_sim.c: the neighbour list read-only, the list's upkeep on
 * demand, the derived contact parameters, the coupling and the gauges
 * (gf_sim.h).
 */
#include <string.h>

#include "gf_sim_internal.h"

const gf_nlist *gf_sim_neighbour_list(const gf_sim *s)
{
    gf_near_list_sync(&s->nb); /* the near list's history into the list's (gf_near_list.c) */
    return s->nb.nl;
}

gf_status gf_sim_rebuild_neighbours(gf_sim *s)
{
    return gf_sim_rebuild(s);
}

void gf_sim_rebuild_at_next_step(gf_sim *s)
{
    s->nb.need_build = 1;
}

void gf_sim_forget_pair_history(gf_sim *s)
{
    gf_near_list_flush(&s->nb); /* the list's history is then the only one */
    gf_nlist_clear_history(s->nb.nl);
}

gf_status gf_sim_evaluate_forces(gf_sim *s)
{
    return gf_sim_compute_forces(s);
}

const gf_contact_params *gf_sim_contact_params(const gf_sim *s)
{
    return &s->cp;
}

gf_coupling *gf_sim_coupling(gf_sim *s)
{
    return s->coupling;
}

int gf_sim_fluid_substeps(const gf_sim *s)
{
    return s->coupling ? s->n_substeps : 0;
}

void gf_sim_gravity(const gf_sim *s, double g_m_s2[3])
{
    memcpy(g_m_s2, s->gravity_m_s2, sizeof s->gravity_m_s2);
}

int gf_sim_immersed(const gf_sim *s)
{
    return s->immersed;
}

int gf_sim_gauge_position(const gf_sim *s, const char *name, double x_m[3])
{
    for (int k = 0; k < s->n_gauges; ++k)
        if (strcmp(s->gauges[k].name, name) == 0) {
            memcpy(x_m, s->gauges[k].x_m, sizeof s->gauges[k].x_m);
            return 1;
        }
    return 0;
}

gf_status gf_sim_sort(gf_sim *s)
{
    GF_TRY(gf_sim_reserve(s, s->p->n_local));
    const gf_nb_grains g = gf_sim_nb_grains(s);
    const gf_nb_tuning t = gf_sim_nb_tuning(s);
    GF_TRY(gf_sort_grains(s->ctx, &s->nb, &g, &t));
    GF_TRY(gf_sim_rebuild(s));
    return gf_sim_compute_forces(s);
}
