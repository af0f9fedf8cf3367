/*
 * The sim's side of its neighbour upkeep (gf_neighbours.h): the grains and
 * the run values it hands the upkeep, its rebuild calls, and the list
 * counters of gf_sim.h. The upkeep itself reads nothing else of the sim.
 */
#include "gf_sim_internal.h"

gf_nb_grains gf_sim_nb_grains(gf_sim *s)
{
    return (gf_nb_grains){.p = s->p,
                          .lo_m = s->lo_m,
                          .hi_m = s->hi_m,
                          .periodic = s->periodic,
                          .walls = s->walls,
                          .n_walls = s->n_walls,
                          .wall_hist = s->wall_hist,
                          .sleep_quiet_steps = s->sleep_cap == s->p->n_local ? s->sleep_quiet_steps : NULL};
}

gf_nb_tuning gf_sim_nb_tuning(const gf_sim *s)
{
    return (gf_nb_tuning){.n_chunks = s->n_threads,
                          .lub_reach_m = s->lubrication ? s->lub_cutoff_m : 0.0,
                          .k_n_N_m = s->cp.k_n_N_m,
                          .rotation_locked = s->rotation_locked,
                          .sort_forced = s->opt.tuning.sort_every > 0};
}

gf_status gf_sim_reserve(gf_sim *s, size_t n)
{
    GF_TRY(gf_neighbours_reserve(s->ctx, &s->nb, n));
    return gf_sim_reserve_wall_history(s, n);
}

static gf_status rebuild(gf_sim *s, int scheduled)
{
    GF_TRY(gf_sim_reserve(s, s->p->n_local)); /* before the view: the wall history may move */
    const gf_nb_grains g = gf_sim_nb_grains(s);
    const gf_nb_tuning t = gf_sim_nb_tuning(s);
    return gf_neighbours_rebuild(s->ctx, &s->nb, &g, &t, scheduled);
}

gf_status gf_sim_rebuild(gf_sim *s)
{
    return rebuild(s, 1);
}

gf_status gf_sim_rebuild_unscheduled(gf_sim *s)
{
    return rebuild(s, 0);
}

gf_status gf_sim_rebuild_from_ref(gf_sim *s)
{
    GF_TRY(gf_sim_reserve(s, s->p->n_local));
    const gf_nb_grains g = gf_sim_nb_grains(s);
    const gf_nb_tuning t = gf_sim_nb_tuning(s);
    return gf_neighbours_rebuild_from_ref(s->ctx, &s->nb, &g, &t);
}

gf_sim_list_stats gf_sim_list_counters(const gf_sim *s)
{
    const gf_nlist *nl = s->nb.nl;
    gf_sim_list_stats st = {(long)nl->n_builds, s->nb.near.n_builds, nl->n_pairs, 0};
    for (int c = 0; c < nl->n_chunks && s->nb.near.valid; ++c)
        st.near_pairs += s->nb.near.len[c];
    return st;
}
