/*
 * Neighbour upkeep of the sim: the Verlet list and what hangs on each of its
 * builds (gf_neighbours.c), the near list inside it (gf_near_list.c) and the
 * spatial order of the particle store (gf_sort.c).
 *
 * The state they own is one gf_neighbours (a member of the sim). Their
 * functions take that state, the grains as they read them (gf_nb_grains)
 * and the few run values they need (gf_nb_tuning), never the sim itself, as
 * contact/gf_nlist.h takes positions, radii, ids and the box: they call
 * nothing of gf_sim. The sim's files hand them the pieces
 * (gf_sim_neighbours.c).
 */
#ifndef GF_NEIGHBOURS_H
#define GF_NEIGHBOURS_H

#include <stddef.h>
#include <stdint.h>

#include "contact/gf_nlist.h"
#include "core/gf_status.h"
#include "gf_wall.h"
#include "particles/gf_particles.h"

#define GF_NB_MAX_CHUNKS 64 /* the row chunks of the list (gf_nlist.chunk_row) */
#define GF_SIM_PARALLEL_MIN_GRAINS 1000 /* below: chunks run serially (fork/join costs more) */

/* Near list (gf_near_list.c): the neighbour list's pairs within skin_m of
 * the contact (or lubrication) range, with their per-pair data, which the
 * blocked pair loop scans instead of the whole list. Chunk c's pairs are
 * stored from nl->row_start[nl->chunk_row[c]] (len[c] of them). While
 * valid, the history and contact flags of the pairs it holds are its own
 * (the list's copies are stale until gf_near_list_flush). */
typedef struct gf_near_list {
    double skin_m;              /* 0: no near list */
    int held;                   /* built and not written back: its history is the current one */
    int valid;                  /* held, and no grain has moved skin/2 since it was built */
    int use;                    /* this force evaluation scans it (set by the fused step alone, gf_step.c) */
    int32_t *i, *j, *k;         /* rows, partners, and offset of each pair in the chunk's part of the list */
    uint8_t *image, *touching;
    double *hist, *sqrt_mk, *meff;
    size_t cap;
    size_t len[GF_NB_MAX_CHUNKS]; /* pairs of each chunk (its thread writes its own, once a build) */
    long n_builds;
} gf_near_list;

/* What the neighbour upkeep owns (gf_neighbours.c unless said). */
typedef struct gf_neighbours {
    gf_nlist *nl;
    double *x_ref, *y_ref, *z_ref;  /* positions at the last neighbour build */
    double *vx_pred, *vy_pred, *vz_pred; /* predicted v(t+dt) for the dashpot (gf_integrate.h; written by the drift) */
    double *inv_mass, *inv_inertia, *mobile; /* integrator factors, refreshed at every neighbour build */
    double *contact_inv_mass;       /* 1/m in contacts, 0 for glued grains (infinite mass) */
    double *x_near, *y_near, *z_near; /* positions at the last near-list build (gf_near_list.c) */
    void *ref_block;                /* owns the thirteen arrays above, staggered (core/gf_soa.h) */
    size_t ref_cap;
    double *pair_meff, *pair_sqrt_mk; /* per neighbour pair: m*, sqrt(m* k_n) */
    size_t pair_cap;
    double skin_m, extra_m;
    int need_build;
    /* grains within reach of each wall until the next neighbour build, ascending
     * (wall w: wall_cand[wall_cand_start[w] .. wall_cand_start[w + 1]]); valid
     * while wall_cand_walls == n_walls and wall_cand_grains == n_local */
    int32_t *wall_cand;
    size_t wall_cand_start[GF_SIM_MAX_WALLS + 1], wall_cand_cap, wall_cand_grains;
    int wall_cand_walls;
    uint8_t *wall_contacts;     /* walls each grain touches at the last build (cost of its row), n */
    size_t wall_contacts_cap;
    int sort_every;             /* rebuilds between sorts; 0: never */
    long n_rebuilds;            /* rebuilds on the schedule (checkpointed: the sort schedule) */
    long n_sorts;               /* sorts that moved a grain (gf_sort.c) */
    int store_layout;           /* order the store was last sorted into (gf_sort_layout); -1: never sorted */
    gf_near_list near;          /* gf_near_list.c */
} gf_neighbours;

/* The grains as the upkeep reads them, and the per-grain data of other owners
 * that moves with them. */
typedef struct gf_nb_grains {
    gf_particles *p;            /* positions (wrapped into the periodic box at a build), radii, ids, flags,
                                   masses; reordered by the sort */
    const double *lo_m, *hi_m;  /* the box, 3 each */
    const int *periodic;        /* 3 */
    const gf_wall *walls;
    int n_walls;
    double *wall_hist;          /* 3 (n_walls + 1) doubles per grain: cleared beyond a wall's reach, sorted */
    long *sleep_quiet_steps;    /* the sleep counters, moved by the sort; NULL unless sized for the store */
} gf_nb_grains;

/* The run values the upkeep needs. */
typedef struct gf_nb_tuning {
    int n_chunks;               /* row chunks wanted of the list (the configured threads) */
    double lub_reach_m;         /* lubrication cut-off; 0 without lubrication */
    double k_n_N_m;             /* normal stiffness: sqrt(m* k_n) per pair */
    int rotation_locked;        /* inverse inertias held at 0 */
    int sort_forced;            /* the sort period was set: sort whatever the store's size */
} gf_nb_tuning;

/* gf_neighbours.c */
/* Allocates the per-grain arrays (reference positions, predicted velocities,
 * integrator factors) for n grains, contents kept. */
gf_status gf_neighbours_reserve(gf_ctx *ctx, gf_neighbours *nb, size_t n);
/* Rebuilds the list from the current positions, wrapping periodic axes
 * first; scheduled: the sort schedule runs (a sort every sort_every calls,
 * counted in n_rebuilds). */
gf_status gf_neighbours_rebuild(gf_ctx *ctx, gf_neighbours *nb, const gf_nb_grains *g, const gf_nb_tuning *t,
                                int scheduled);
/* Builds the list from the saved reference positions (restart). */
gf_status gf_neighbours_rebuild_from_ref(gf_ctx *ctx, gf_neighbours *nb, const gf_nb_grains *g,
                                         const gf_nb_tuning *t);
/* Frees what nb owns (the near list included); nb is zeroed. */
void gf_neighbours_free(gf_neighbours *nb);

/* gf_near_list.c. At each step, after the neighbour build decision: whether
 * this step's force evaluation scans the near list (not when the pair loop
 * runs the normal law alone), and whether it must be rebuilt first (near_d2:
 * the largest squared displacement since its last build). */
void gf_near_list_check(gf_near_list *nr, double near_d2, int normal_only);
/* Builds chunk c's part of the near list (writing the part it replaces back
 * first) and takes its grains' positions as the new reference; by the
 * chunk's thread, before its pair rows. */
void gf_near_list_build_chunk(gf_neighbours *nb, const gf_particles *p, double lub_reach_m, int c);
/* Writes the near list's history and contact flags back into the neighbour
 * list and drops it: before a list build or a force evaluation over the
 * whole list. */
void gf_near_list_flush(gf_neighbours *nb);
/* The same write-back, the near list kept (its pairs' history unchanged):
 * for readers of the list's history (energy, stress, checkpoint). */
void gf_near_list_sync(const gf_neighbours *nb);
/* Reserves the near list for the current neighbour list (after a build). */
gf_status gf_near_list_reserve(gf_ctx *ctx, gf_neighbours *nb);
void gf_near_list_free(gf_near_list *nr);

/* gf_sort.c. Reorders the store by the Morton index of each grain's cell,
 * with every per-grain array that belongs to the grains. */
gf_status gf_sort_grains(gf_ctx *ctx, gf_neighbours *nb, const gf_nb_grains *g, const gf_nb_tuning *t);
/* The order gf_sort_grains puts a store of n grains in: 0 Morton order (one
 * thread, or a store too small to run its chunks in parallel), 1 layers
 * across the cut axis (threads). */
int gf_sort_layout(int n_chunks, size_t n);
/* 1 when a store of n grains is sorted at all (sort_every, store size). */
int gf_sort_enabled(const gf_neighbours *nb, const gf_nb_tuning *t, size_t n);
/* Grains below which the default schedule does not sort (the store fits in the caches). */
#define GF_SIM_SORT_MIN_GRAINS 2048
/* Default sort period, in neighbour-list rebuilds. */
#define GF_SIM_SORT_EVERY_DEFAULT 20

#endif
