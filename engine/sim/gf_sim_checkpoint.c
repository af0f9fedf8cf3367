/*
 * Checkpoint and restart (Izard 2014 §2.1.2.1: positions, velocities, spins
 * and the tangential overlap of every active contact), written so that a
 * restarted run is BITWISE identical to an uninterrupted one:
 *   - the full velocity-Verlet state: x, v, w and the forces/torques F(t)
 *     that the next half-kick uses (recomputing them would change the
 *     velocity-dependent part, evaluated at v(t - dt/2) in the original run);
 *   - the positions of the last neighbour build (x_ref): the restart rebuilds
 *     the list from them, which reproduces the original list, pair order
 *     included (so forces are summed in the same order), and the rebuild
 *     criterion sees the same displacements;
 *   - the store in its current order (the spatial sort permutes it, gf_sort.c),
 *     the rebuild count that schedules the next sort and the layout of that
 *     order (one thread or several: a run on the other layout re-sorts);
 *   - tangential history of grain pairs keyed by global ids, and of
 *     (grain, wall) pairs; wall active flags, gravity (a scene may tilt it
 *     at start), RNG state, clock and step count, contact statistics.
 * The restart rebuilds the scene (box, walls, grains) from the spec, skips
 * scene->start (it already ran before the checkpoint) and overwrites the
 * state. The grain count must match. Same thread count => same bits.
 * Immersed runs add the fluid and coupling state (gf_coupling_save: face
 * velocities, pressure, fluid fraction, the grains' held fluid forces) and
 * the fluid-step schedule (the step of the next fluid step and the substep
 * count), restored once the coupling exists (gf_sim_restore_coupling).
 * The file itself is io/gf_checkpoint.c's: this side hands it a view of the
 * sim's state and rebuilds the list from what comes back.
 */
#include <stdlib.h>
#include <string.h>

#include "gf_sim_internal.h"
#include "io/gf_checkpoint.h"

_Static_assert(GF_SIM_MAX_WALLS <= GF_CHECKPOINT_MAX_WALLS, "the checkpoint holds every wall");

gf_status gf_sim_restore(gf_sim *s, const char *path);
gf_status gf_sim_restore_coupling(gf_sim *s, const char *path);

/* The sim's state as the checkpoint file sees it: pointers into the sim. */
static gf_checkpoint_view state_view(gf_sim *s)
{
    gf_checkpoint_view v = {.scene = s->spec.scene, .p = s->p, .step = &s->step, .t_s = &s->t_s, .dt_s = &s->dt_s,
                            .t_end_s = &s->t_end_s, .max_overlap_m = &s->max_overlap_m,
                            .n_contacts = &s->n_contacts, .rng_s = s->rng.s, .gravity_m_s2 = s->gravity_m_s2,
                            .n_rebuilds = &s->nb.n_rebuilds, .store_layout = &s->nb.store_layout,
                            .scene_counters = s->scene_counters, .n_scene_counters = GF_SIM_SCENE_COUNTERS,
                            .n_walls = s->n_walls, .ref_m = {s->nb.x_ref, s->nb.y_ref, s->nb.z_ref},
                            .wall_hist = s->wall_hist};
    for (int w = 0; w < s->n_walls; ++w)
        v.wall_active[w] = &s->walls[w].active, v.wall_force_N[w] = s->walls[w].force_N;
    return v;
}

/* The grain pairs that carry a tangential history, keyed by global ids, in
 * the list's order. */
static gf_status collect_pairs(gf_sim *s, gf_checkpoint_view *v)
{
    const gf_particles *p = s->p;
    const gf_nlist *nl = s->nb.nl;
    size_t m = 0;
    for (size_t k = 0; k < nl->n_pairs; ++k)
        m += nl->hist[3 * k] != 0.0 || nl->hist[3 * k + 1] != 0.0 || nl->hist[3 * k + 2] != 0.0;
    v->pair_ids = malloc((2 * m + 1) * sizeof(int64_t));
    v->pair_hist = malloc((3 * m + 1) * sizeof(double));
    v->pair_image = malloc(m + 1);
    v->n_pairs = m;
    if (!v->pair_ids || !v->pair_hist || !v->pair_image)
        return GF_FAIL(s->ctx, GF_ERR_NOMEM, "checkpoint: cannot allocate %zu contacts", m);
    size_t q = 0;
    for (size_t i = 0; i < nl->n; ++i)
        for (size_t k = nl->row_start[i]; k < nl->row_start[i + 1]; ++k) {
            const double *hk = &nl->hist[3 * k];
            if (hk[0] == 0.0 && hk[1] == 0.0 && hk[2] == 0.0)
                continue;
            v->pair_ids[2 * q] = p->id[i], v->pair_ids[2 * q + 1] = p->id[nl->j[k]];
            memcpy(&v->pair_hist[3 * q], hk, 3 * sizeof(double));
            v->pair_image[q] = nl->image[k];
            ++q;
        }
    return GF_OK;
}

gf_status gf_sim_checkpoint(gf_sim *s, const char *path)
{
    if (s->stepper.phase != GF_STEP_AT_T)
        GF_TRY(gf_sim_compute_forces(s));
    gf_near_list_sync(&s->nb); /* the near list's history into the list's (gf_near_list.c) */
    gf_checkpoint_view v = state_view(s);
    gf_status st = collect_pairs(s, &v);
    if (st == GF_OK)
        st = gf_checkpoint_write(s->ctx, path, &v, s->coupling, s->next_fluid_step, s->n_substeps);
    free(v.pair_ids), free(v.pair_hist), free(v.pair_image);
    return st;
}

/* A store sorted for another thread layout (a bed prepared on one thread and
 * continued on two, or the reverse) is sorted into this run's at once: the
 * threads' chunks are contiguous ranges of the store, and in the other order
 * the cut between them is a jagged surface whose grains cross between the
 * cores' caches at every step (docs/notes/benchmarks.md, "Two cores: the cut
 * between the chunks"; a settled bed may not reach its next scheduled sort
 * for thousands of steps). The run is then not the bitwise continuation of
 * the checkpointed one, which it could not be anyway: its chunks differ. The
 * list is rebuilt at the current positions (the contact history follows by
 * ids, the forces and the wall history move with the grains); the sort
 * schedule (sort_state) is left as it was. */
static gf_status resort_for_threads(gf_sim *s, int layout_saved)
{
    const gf_nb_grains g = gf_sim_nb_grains(s);
    const gf_nb_tuning t = gf_sim_nb_tuning(s);
    const size_t n = s->p->n_local;
    if (!layout_saved || s->nb.store_layout < 0 || s->nb.store_layout == gf_sort_layout(t.n_chunks, n) ||
        !gf_sort_enabled(&s->nb, &t, n))
        return GF_OK;
    GF_TRY(gf_sort_grains(s->ctx, &s->nb, &g, &t));
    return gf_sim_rebuild_unscheduled(s);
}

/* The checkpoint's pair histories into the list rebuilt from the saved
 * reference positions (which reproduces the original list). */
static gf_status apply_pairs(gf_sim *s, const gf_checkpoint_view *v)
{
    gf_nlist_clear_history(s->nb.nl); /* the preparation's contacts are not the checkpoint's */
    GF_TRY(gf_sim_rebuild_from_ref(s));
    for (size_t q = 0; q < v->n_pairs; ++q)
        if (!gf_nlist_set_history(s->nb.nl, s->p->id, v->pair_ids[2 * q], v->pair_ids[2 * q + 1],
                                  v->pair_image ? v->pair_image[q] : -1, &v->pair_hist[3 * q]))
            return GF_FAIL(s->ctx, GF_ERR_IO, "restart: contact (%lld, %lld) of the checkpoint is not a neighbour pair",
                           (long long)v->pair_ids[2 * q], (long long)v->pair_ids[2 * q + 1]);
    return GF_OK;
}

gf_status gf_sim_restore(gf_sim *s, const char *path)
{
    GF_TRY(gf_sim_reserve(s, s->p->n_local));
    gf_checkpoint_view v = state_view(s);
    double dt_saved = 0.0, t_end_saved = 0.0;
    gf_status st = gf_checkpoint_read(s->ctx, path, &v, &dt_saved, &t_end_saved);
    if (st == GF_OK && !(s->spec.end_time_nd > 0.0)) /* a spec end time wins: a restart may extend the run */
        s->t_end_s = t_end_saved;
    if (st == GF_OK && dt_saved != s->dt_s)
        st = GF_FAIL(s->ctx, GF_ERR_CONFIG, "restart: checkpoint dt = %.17g s, spec gives %.17g s", dt_saved, s->dt_s);
    if (st == GF_OK)
        st = apply_pairs(s, &v);
    free(v.pair_ids), free(v.pair_hist), free(v.pair_image);
    s->stepper.phase = GF_STEP_AT_T;
    GF_TRY(st);
    return resort_for_threads(s, v.layout_saved);
}

gf_status gf_sim_restore_coupling(gf_sim *s, const char *path)
{
    return gf_checkpoint_read_coupling(s->ctx, path, s->coupling, &s->next_fluid_step, &s->n_substeps);
}
