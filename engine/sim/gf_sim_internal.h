/*
 * The gf_sim object, shared by the files of the sim module only
 * engine/sim/ (gf_sim.c: creation, accessors, builders; gf_step.c: the step
 * loop; gf_sim_neighbours.c: the pieces it hands the neighbour upkeep,
 * gf_neighbours.h; gf_forces.c and gf_pairs_blocked.c: the pair and wall
 * loops; gf_run.c: outputs; ...). Not a public header: drivers, scenes,
 * tests and benchmarks use gf_sim.h.
 */
#ifndef GF_SIM_INTERNAL_H
#define GF_SIM_INTERNAL_H

#include <math.h>
#include <stdatomic.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "contact/gf_contact.h"
#include "contact/gf_lubrication.h"
#include "contact/gf_nlist.h"
#include "gf_neighbours.h"
#include "coupling/gf_coupling.h"
#include "gf_sim.h"
#include "scenes/gf_scene.h"
#include "integrate/gf_integrate.h"

#define GF_SIM_MAX_GAUGES 64
#define GF_SIM_MAX_THREADS GF_NB_MAX_CHUNKS

typedef struct gf_gauge {
    char name[GF_NAME_LEN];
    double x_m[3];
} gf_gauge;

/* Force accumulators, one per chunk of the pair loop, each on cache lines
 * of its own: the counters a thread updates while it runs its chunk must not
 * share a line with the next chunk's pointers, which the other thread reads.
 * A chunk adds the forces on its own rows, and on partners before far_from,
 * into the particle store; those on partners at or beyond far_from (grains
 * of later chunks, which their own thread is writing) into far. */
typedef struct gf_sim_accum {
    _Alignas(64) double *far[6];
    size_t far_from;  /* the chunk's end; n for the last chunk, whose far is the store */
    double *buf[6];   /* the chunk's own far buffer (not for the last chunk) */
    void *buf_block;  /* owns buf[0..5], staggered (core/gf_soa.h) */
    size_t cap;
    double wall_force_N[GF_SIM_MAX_WALLS][3];
    size_t n_contacts;
    double max_overlap_m;
    int finished;     /* the pair loop finished the chunk's grains outside the reach runs (gf_sim_finish_rows) */
    gf_drift_d2 finished_d2;
    double finish_s;  /* wall time of those finishes (the integrate timer's share of the force pass) */
    /* the number of the force evaluation whose pair rows this chunk has
     * finished (its buffer is complete, and it reads no grain any more) */
    _Atomic unsigned long pairs_done;
} gf_sim_accum;

/* Where the step loop stands between two of its operations (gf_step.c owns
 * the transitions; the fused force pass of gf_forces.c writes its result).
 * The phases, in the order a step goes through them:
 *   STALE      F in the store does not belong to x (a builder added or moved
 *              grains, changed a wall): the next gf_sim_advance rebuilds the
 *              list and evaluates F(t) first;
 *   AT_T       x(t), v(t), F(t): what a caller sees between advances;
 *   KICK_OWED  x(t), F(t), and v one half-kick short of v(t): the closing
 *              half-kick is deferred to the next opening one (or flush_kick);
 *   MOVED      kicked and drifted: x(t + dt), v(t + dt/2), the predicted
 *              velocities v* for the dashpot, and the forces of the n_moved
 *              grains zeroed (the next force pass accumulates into them). */
typedef enum gf_step_phase { GF_STEP_STALE = 0, GF_STEP_AT_T, GF_STEP_KICK_OWED, GF_STEP_MOVED } gf_step_phase;
typedef struct gf_step_state {
    gf_step_phase phase;
    size_t n_moved;
    int fuse;               /* asks the force pass to end the step and run the next kick-drift (gf_forces.c) */
    int fused;              /* it did (phase MOVED): fused_d2 is the displacement the next step checks */
    gf_drift_d2 fused_d2;
    double fused_s;         /* thread 0's wall time in that pass (given to the integrate timer) */
} gf_step_state;

/* The sim, in parts: each anonymous part lists the file that owns it
 * (writes it; the others read it). */
struct gf_sim {
    struct { /* the run, set at creation and by the scene's builder calls (gf_sim.c) */
        gf_ctx *ctx;                /* borrowed from the creator */
        gf_run_spec spec;
        gf_sim_options opt;         /* strings borrowed */
        const gf_scene_desc *scene;
        gf_scales scales;
        gf_particles *p;
        gf_rng rng;
        gf_timers timers;
        double lo_m[3], hi_m[3];
        int periodic[3], box_set;
        double gravity_m_s2[3];
        gf_gauge gauges[GF_SIM_MAX_GAUGES];
        int n_gauges;
        int fluid_bc[3][2], fluid_bc_set[3][2];
        int n_threads;
        int in_build;
        int rotation_locked;        /* gf_sim_set_rotation_locked: inverse inertias held at 0 */
        double scene_counters[GF_SIM_SCENE_COUNTERS]; /* gf_sim_scene_counters; checkpointed */
    };
    struct { /* walls (gf_sim.c adds them; gf_wall_forces.c their contacts and loads) */
        gf_wall walls[GF_SIM_MAX_WALLS];
        int n_walls;
        double *wall_hist;          /* 3 doubles per (grain, wall): [3 (i (n_walls + 1) + w)] */
        size_t wall_hist_cap;
    };
    struct { /* the clock (gf_step.c) */
        double t_s, dt_s, t_end_s;
        long step;
    };
    struct { /* the contact law and lubrication (gf_sim.c, gf_fluid_setup.c) */
        const gf_contact_info *law;
        gf_contact_params cp;
        int lubrication;
        double lub_eta_Pa_s, lub_roughness_m, lub_cutoff_m;
        gf_lub_overlap lub_overlap; /* the film in overlap: clamped gap (default), off, elastic (gf_lubrication.h) */
    };
    gf_neighbours nb;               /* neighbour upkeep (gf_neighbours.h; its pieces: gf_sim_neighbours.c) */
    gf_step_state stepper;          /* where the step loop stands (gf_step.c) */
    struct { /* the force pass (gf_forces.c) */
        unsigned long force_count;  /* force evaluations so far (gf_sim_accum.pairs_done) */
        gf_sim_accum acc[GF_SIM_MAX_THREADS];
        size_t n_contacts;
        double max_overlap_m;
    };
    struct { /* the fluid (gf_fluid_setup.c; the sub-cycling: gf_step.c) */
        int immersed;
        char fluid_reason[384];     /* why this fluid tier (fluid_model_reason attribute) */
        gf_coupling *coupling;
        int n_substeps;             /* DEM steps per fluid step, re-chosen at every fluid step */
        long next_fluid_step;       /* step index of the next fluid step */
    };
    struct { /* sleeping grains (gf_sleep.c; only with contact.sleep_speed_nd > 0) */
        long *sleep_quiet_steps;    /* steps each grain has stayed below the sleep speed */
        size_t sleep_cap;
        long n_sleep_events, n_wake_events;
    };
    unsigned skips;                 /* work this run does not need: GF_SKIP_* bits, decided once (gf_skips.c) */
};

/* This thread's number t and the team's size m inside a parallel region
 * (0 of 1 without OpenMP). */
typedef struct gf_team {
    int t, m;
} gf_team;
static inline gf_team gf_sim_team(void)
{
#ifdef _OPENMP
    return (gf_team){omp_get_thread_num(), omp_get_num_threads()};
#else
    return (gf_team){0, 1};
#endif
}

/* c = a x b */
static inline void gf_cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* The integrator's passes over grain ranges (gf_kicks.c). The grains thread
 * t of m integrates: its chunk's rows when the list has one chunk per
 * thread, else an even split. */
void gf_sim_thread_grains(const gf_sim *s, size_t n, int t, int m, size_t *i0, size_t *i1);
/* The kicks' per-grain factors (no inverse inertia without torques). */
gf_integrate_factors gf_sim_integrate_factors(const gf_sim *s);
/* n_kicks half-kicks then the drift of grains [i0, i1) (gf_integrate_kick_drift). */
gf_drift_d2 gf_sim_kick_drift_range(gf_sim *s, size_t i0, size_t i1, int n_kicks);
/* Runs pass on each thread's grains (gf_sim_thread_grains) in one parallel
 * region, serially below GF_SIM_PARALLEL_MIN_GRAINS; returns the largest
 * of the displacements the passes return. */
typedef gf_drift_d2 gf_sim_grain_pass(gf_sim *s, size_t i0, size_t i1, void *user);
gf_drift_d2 gf_sim_grain_passes(gf_sim *s, gf_sim_grain_pass *pass, void *user);
/* gf_sim_finish_range on the grains of [i0, i1) outside the list's reach
 * runs (in_runs 0) or inside them (1). */
gf_drift_d2 gf_sim_finish_runs(gf_sim *s, size_t i0, size_t i1, int in_runs);
/* Grain-wall contacts of grains [i0, i1) into f (gf_wall_forces.c). */
void gf_sim_wall_rows(gf_sim *s, size_t i0, size_t i1, double *const f[6], gf_sim_accum *acc);

/* Evaluates contact (+ lubrication) forces and wall forces at the current
 * state into the particle store (cleared first). gf_forces.c. */
gf_status gf_sim_compute_forces(gf_sim *s);

/* The end of a step and the start of the next for grains [i0, i1), once
 * their contact forces are complete (gf_kicks.c; gf_step.c: fused_step): the held fluid
 * forces, the closing half-kick, the next opening half-kick and drift.
 * Returns their largest squared displacement since the last build. */
gf_drift_d2 gf_sim_finish_range(gf_sim *s, size_t i0, size_t i1);
/* The same for thread t of m: the grains of its chunk. */
gf_drift_d2 gf_sim_finish_share(gf_sim *s, int t, int m);
/* Requests into the L2 the lines of [i0, i1) that gf_sim_finish_range reads
 * and the pair loop does not (displacement references, mass factors): for a
 * store beyond the caches, the row-batch finish asks for the next batch's. */
void gf_sim_prefetch_finish(const gf_sim *s, size_t i0, size_t i1);
/* Element-wise largest of n displacement pairs. */
static inline gf_drift_d2 gf_drift_d2_max(const gf_drift_d2 *d, int n)
{
    gf_drift_d2 m = {0.0, 0.0};
    for (int t = 0; t < n; ++t) {
        m.build = d[t].build > m.build ? d[t].build : m.build;
        m.near = d[t].near > m.near ? d[t].near : m.near;
    }
    return m;
}
/* Grain-grain contacts (and lubrication, when on) of rows [i0, i1) of the
 * list into f[0..5] (fx..tz), for the linear law: the blocked, vectorised
 * loop of gf_pairs_blocked.c, bitwise the generic loop's results. finish: the
 * rows are the whole store (one chunk) and the step ends with them: each
 * batch of completed rows gets its walls and gf_sim_finish_range at once
 * (gf_sim_finish_rows); returns their largest squared displacements. */
gf_drift_d2 gf_sim_pair_rows_blocked_linear(gf_sim *s, size_t i0, size_t i1, double *const f[6], gf_sim_accum *acc,
                                            int finish);
/* Wall contacts of grains [i0, i1), whose pair forces are complete, then
 * gf_sim_finish_range on them. gf_kicks.c. */
gf_drift_d2 gf_sim_finish_rows(gf_sim *s, size_t i0, size_t i1, double *const f[6], gf_sim_accum *acc);
/* The sim's side of neighbour upkeep (gf_sim_neighbours.c): the grains and
 * run values it hands gf_neighbours.h, and its calls on them. */
gf_nb_grains gf_sim_nb_grains(gf_sim *s);
gf_nb_tuning gf_sim_nb_tuning(const gf_sim *s);
/* Rebuilds the neighbour list from the current positions (wrapping periodic
 * axes first), with the sort schedule. */
gf_status gf_sim_rebuild(gf_sim *s);
/* The same without the sort schedule (no sort, the rebuild count unchanged). */
gf_status gf_sim_rebuild_unscheduled(gf_sim *s);
/* Builds the list from the saved reference positions (restart). */
gf_status gf_sim_rebuild_from_ref(gf_sim *s);
/* Allocates per-grain sim arrays (reference positions, wall history) for n grains. */
gf_status gf_sim_reserve(gf_sim *s, size_t n);
/* The wall history for n grains (gf_wall_forces.c): new grains start without. */
gf_status gf_sim_reserve_wall_history(gf_sim *s, size_t n);
/* Re-strides the wall history after a wall was added (history kept). gf_wall_forces.c. */
gf_status gf_sim_relayout_walls(gf_sim *s, int n_walls_old);

/* Puts quiet grains in contact to sleep and wakes sleeping grains touched by
 * moving ones; called every GF_SLEEP_EVERY steps after the step's last kick
 * when contact.sleep_speed_nd > 0. gf_sleep.c. */
#define GF_SLEEP_EVERY 10
gf_status gf_sim_sleep_update(gf_sim *s);
/* Wakes every sleeping grain and restarts the quiet counters (a wall was
 * removed: grains asleep against it cannot see that their support left). */
void gf_sim_sleep_wake_all(gf_sim *s);

/* Skips (gf_skips.c). Decided from the spec and the scene before build()
 * (gf_sim_decide_skips) and dropped when a scene adds what defeats one (a
 * frictional wall: gf_sim_skips_wall_added); nothing is decided when
 * gf_sim_tuning.keep_all_work is set. */
gf_status gf_sim_decide_skips(gf_sim *s);
void gf_sim_skips_wall_added(gf_sim *s, double friction);
/* DEM steps per fluid step from the current state (gf_step.c). */
void gf_sim_choose_substeps(gf_sim *s);
/* The fluid tier of the run from the scene and spec.fluid (auto: from the
 * regime), lubrication included; the coupling, once the scene is built. */
gf_status gf_sim_setup_fluid(gf_sim *s);
gf_status gf_sim_create_coupling(gf_sim *s);
/* Brenner lubrication from spec.fluid (roughness, cut-off, viscosity). gf_fluid_setup.c. */
gf_status gf_sim_setup_lubrication(gf_sim *s);

#endif
