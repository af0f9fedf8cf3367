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
 */
#include <stdlib.h>
#include <string.h>

#include "gf_sim_internal.h"
#include "io/gf_restart.h"

gf_status gf_sim_restore(gf_sim *s, const char *path);
gf_status gf_sim_restore_coupling(gf_sim *s, const char *path);

#define GF_CK_F64_FIELDS(X)                                                                                     \
    X(x_m) X(y_m) X(z_m) X(vx_m_s) X(vy_m_s) X(vz_m_s) X(wx_rad_s) X(wy_rad_s) X(wz_rad_s) X(fx_N) X(fy_N)    \
    X(fz_N) X(tx_N_m) X(ty_N_m) X(tz_N_m) X(radius_m) X(mass_kg) X(inertia_kg_m2)

static gf_status write_all(gf_sim *s, gf_restart *r)
{
    gf_particles *p = s->p;
    gf_sim_near_sync(s); /* the near list's history into the list's (gf_near_list.c) */
    size_t n = p->n_local;
    int64_t counts[3] = {(int64_t)n, s->step, p->next_id};
    double clock[5] = {s->t_s, s->dt_s, s->t_end_s, s->max_overlap_m, (double)s->n_contacts};
    GF_TRY(gf_restart_put_i64(r, "counts", 3, counts));
    GF_TRY(gf_restart_put_f64(r, "clock", 5, clock));
    GF_TRY(gf_restart_put_u64(r, "rng", 4, s->rng.s));
    GF_TRY(gf_restart_put_f64(r, "gravity", 3, s->gravity_m_s2));
    GF_TRY(gf_restart_put_i64(r, "sort_state", 1, (const int64_t[1]){s->n_rebuilds}));
    GF_TRY(gf_restart_put_i64(r, "sort_layout", 1, (const int64_t[1]){s->store_layout}));
    GF_TRY(gf_restart_put_f64(r, "scene_counters", GF_SIM_SCENE_COUNTERS, s->scene_counters));
    uint8_t active[GF_SIM_MAX_WALLS];
    double wall_force[3 * GF_SIM_MAX_WALLS];
    for (int w = 0; w < s->n_walls; ++w) {
        active[w] = (uint8_t)s->walls[w].active;
        memcpy(&wall_force[3 * w], s->walls[w].force_N, 3 * sizeof(double));
    }
    GF_TRY(gf_restart_put_u8(r, "wall_active", (size_t)s->n_walls, active));
    GF_TRY(gf_restart_put_f64(r, "wall_force", 3 * (size_t)s->n_walls, wall_force));
    GF_TRY(gf_restart_put_i64(r, "id", n, p->id));
    GF_TRY(gf_restart_put_u8(r, "flags", n, p->flags));
#define GF_CK_PUT(f) GF_TRY(gf_restart_put_f64(r, #f, n, p->f));
    GF_CK_F64_FIELDS(GF_CK_PUT)
#undef GF_CK_PUT
    GF_TRY(gf_restart_put_f64(r, "x_ref", n, s->x_ref));
    GF_TRY(gf_restart_put_f64(r, "y_ref", n, s->y_ref));
    GF_TRY(gf_restart_put_f64(r, "z_ref", n, s->z_ref));
    GF_TRY(gf_restart_put_f64(r, "wall_history", 3 * n * (size_t)(s->n_walls + 1), s->wall_hist));
    /* grain-pair history: only pairs that carry one */
    const gf_nlist *nl = s->nl;
    size_t m = 0;
    for (size_t k = 0; k < nl->n_pairs; ++k)
        m += nl->hist[3 * k] != 0.0 || nl->hist[3 * k + 1] != 0.0 || nl->hist[3 * k + 2] != 0.0;
    int64_t *ids = malloc((2 * m + 1) * sizeof(int64_t));
    double *h = malloc((3 * m + 1) * sizeof(double));
    if (!ids || !h) {
        free(ids), free(h);
        return GF_FAIL(s->ctx, GF_ERR_NOMEM, "checkpoint: cannot allocate %zu contacts", m);
    }
    size_t q = 0;
    for (size_t i = 0; i < nl->n; ++i)
        for (size_t k = nl->row_start[i]; k < nl->row_start[i + 1]; ++k) {
            const double *hk = &nl->hist[3 * k];
            if (hk[0] == 0.0 && hk[1] == 0.0 && hk[2] == 0.0)
                continue;
            ids[2 * q] = p->id[i], ids[2 * q + 1] = p->id[nl->j[k]];
            memcpy(&h[3 * q], hk, 3 * sizeof(double));
            ++q;
        }
    gf_status st = gf_restart_put_i64(r, "contact_ids", 2 * m, ids);
    if (st == GF_OK)
        st = gf_restart_put_f64(r, "contact_history", 3 * m, h);
    free(ids), free(h);
    if (st == GF_OK && s->coupling) {
        st = gf_restart_put_i64(r, "fluid_schedule", 2, (const int64_t[2]){s->next_fluid_step, s->n_substeps});
        if (st == GF_OK)
            st = gf_coupling_save(s->coupling, r);
    }
    return st;
}

gf_status gf_sim_checkpoint(gf_sim *s, const char *path)
{
    if (s->stepper.phase != GF_STEP_AT_T)
        GF_TRY(gf_sim_compute_forces(s));
    gf_restart *r = NULL;
    GF_TRY(gf_restart_create(s->ctx, path, &r));
    gf_status st = write_all(s, r);
    if (st != GF_OK) {
        gf_restart_abort(&r); /* the previous checkpoint stays */
        return st;
    }
    return gf_restart_close(&r);
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
static gf_status resort_for_threads(gf_sim *s, gf_restart *r)
{
    if (!gf_restart_has(r, "sort_layout"))
        return GF_OK;
    int64_t layout = -1;
    GF_TRY(gf_restart_get_i64(r, "sort_layout", 1, &layout));
    s->store_layout = (int)layout;
    if (layout < 0 || layout == gf_sim_sort_layout(s) || !gf_sim_sorts(s))
        return GF_OK;
    GF_TRY(gf_sim_sort_grains(s));
    return gf_sim_rebuild_unscheduled(s);
}

static gf_status read_all(gf_sim *s, gf_restart *r)
{
    gf_particles *p = s->p;
    int64_t counts[3];
    double clock[5];
    GF_TRY(gf_restart_get_i64(r, "counts", 3, counts));
    if ((size_t)counts[0] != p->n_local)
        return GF_FAIL(s->ctx, GF_ERR_CONFIG,
                       "restart: checkpoint holds %lld grains but scene %s builds %zu (different spec?)",
                       (long long)counts[0], s->spec.scene, p->n_local);
    size_t n = p->n_local;
    GF_TRY(gf_restart_get_f64(r, "clock", 5, clock));
    GF_TRY(gf_restart_get_u64(r, "rng", 4, s->rng.s));
    GF_TRY(gf_restart_get_f64(r, "gravity", 3, s->gravity_m_s2));
    int64_t sort_state = 0; /* checkpoints without it: the next rebuild sorts */
    if (gf_restart_has(r, "sort_state"))
        GF_TRY(gf_restart_get_i64(r, "sort_state", 1, &sort_state));
    s->n_rebuilds = (long)sort_state;
    if (gf_restart_has(r, "scene_counters")) /* checkpoints without them: scenes that keep none */
        GF_TRY(gf_restart_get_f64(r, "scene_counters", GF_SIM_SCENE_COUNTERS, s->scene_counters));
    size_t nw = 0;
    GF_TRY(gf_restart_len(r, "wall_active", &nw));
    if (nw != (size_t)s->n_walls)
        return GF_FAIL(s->ctx, GF_ERR_CONFIG, "restart: checkpoint has %zu walls, scene %s builds %d", nw,
                       s->spec.scene, s->n_walls);
    uint8_t active[GF_SIM_MAX_WALLS];
    double wall_force[3 * GF_SIM_MAX_WALLS];
    GF_TRY(gf_restart_get_u8(r, "wall_active", nw, active));
    GF_TRY(gf_restart_get_f64(r, "wall_force", 3 * nw, wall_force));
    for (int w = 0; w < s->n_walls; ++w) {
        s->walls[w].active = active[w];
        memcpy(s->walls[w].force_N, &wall_force[3 * w], 3 * sizeof(double));
    }
    GF_TRY(gf_restart_get_i64(r, "id", n, p->id));
    GF_TRY(gf_restart_get_u8(r, "flags", n, p->flags));
#define GF_CK_GET(f) GF_TRY(gf_restart_get_f64(r, #f, n, p->f));
    GF_CK_F64_FIELDS(GF_CK_GET)
#undef GF_CK_GET
    GF_TRY(gf_sim_reserve(s, n));
    GF_TRY(gf_restart_get_f64(r, "x_ref", n, s->x_ref));
    GF_TRY(gf_restart_get_f64(r, "y_ref", n, s->y_ref));
    GF_TRY(gf_restart_get_f64(r, "z_ref", n, s->z_ref));
    GF_TRY(gf_restart_get_f64(r, "wall_history", 3 * n * (size_t)(s->n_walls + 1), s->wall_hist));
    p->next_id = counts[2];
    s->step = counts[1];
    s->t_s = clock[0], s->max_overlap_m = clock[3], s->n_contacts = (size_t)clock[4];
    if (!(s->spec.end_time_nd > 0.0)) /* a spec end time wins: a restart may extend the run */
        s->t_end_s = clock[2];
    if (clock[1] != s->dt_s)
        return GF_FAIL(s->ctx, GF_ERR_CONFIG, "restart: checkpoint dt = %.17g s, spec gives %.17g s", clock[1], s->dt_s);
    gf_nlist_clear_history(s->nl); /* the preparation's contacts are not the checkpoint's */
    GF_TRY(gf_sim_rebuild_from_ref(s));
    size_t m2 = 0;
    GF_TRY(gf_restart_len(r, "contact_ids", &m2));
    size_t m = m2 / 2;
    int64_t *ids = malloc((2 * m + 1) * sizeof(int64_t));
    double *h = malloc((3 * m + 1) * sizeof(double));
    gf_status st = ids && h ? GF_OK : GF_FAIL(s->ctx, GF_ERR_NOMEM, "restart: cannot allocate contacts");
    if (st == GF_OK)
        st = gf_restart_get_i64(r, "contact_ids", 2 * m, ids);
    if (st == GF_OK)
        st = gf_restart_get_f64(r, "contact_history", 3 * m, h);
    for (size_t q = 0; st == GF_OK && q < m; ++q)
        if (!gf_nlist_set_history(s->nl, p->id, ids[2 * q], ids[2 * q + 1], &h[3 * q]))
            st = GF_FAIL(s->ctx, GF_ERR_IO, "restart: contact (%lld, %lld) of the checkpoint is not a neighbour pair",
                         (long long)ids[2 * q], (long long)ids[2 * q + 1]);
    free(ids), free(h);
    s->stepper.phase = GF_STEP_AT_T;
    GF_TRY(st);
    return resort_for_threads(s, r);
}

gf_status gf_sim_restore(gf_sim *s, const char *path)
{
    gf_restart *r = NULL;
    GF_TRY(gf_restart_open(s->ctx, path, &r));
    gf_status st = read_all(s, r);
    gf_restart_close(&r);
    return st;
}

gf_status gf_sim_restore_coupling(gf_sim *s, const char *path)
{
    gf_restart *r = NULL;
    GF_TRY(gf_restart_open(s->ctx, path, &r));
    int64_t schedule[2] = {0, 0};
    gf_status st = gf_coupling_load(s->coupling, r); /* refuses a checkpoint without fluid */
    if (st == GF_OK)
        st = gf_restart_get_i64(r, "fluid_schedule", 2, schedule);
    gf_restart_close(&r);
    GF_TRY(st);
    s->next_fluid_step = (long)schedule[0];
    s->n_substeps = (int)schedule[1];
    return GF_OK;
}
