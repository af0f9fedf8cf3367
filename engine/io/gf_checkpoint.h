/*
 * The checkpoint file of one simulation (HDF5, through gf_restart): the
 * datasets a restarted run needs to continue bitwise (engine/sim/gf_sim_checkpoint.c
 * says what each one is for and fills this view of its state). The sim
 * hands over pointers to its own arrays and scalars; writing reads them,
 * reading fills them (after checking the grain and wall counts against
 * the scene the restart built). Plain data: this module knows nothing of
 * the sim.
 */
#ifndef GF_CHECKPOINT_H
#define GF_CHECKPOINT_H

#include <stddef.h>
#include <stdint.h>

#include "coupling/gf_coupling.h"
#include "particles/gf_particles.h"

#define GF_CHECKPOINT_MAX_WALLS 16

typedef struct gf_checkpoint_view {
    const char *scene;          /* for the messages */
    gf_particles *p;            /* ids, flags and the per-grain fields (gf_checkpoint.c lists them) */
    long *step;
    double *t_s, *dt_s, *t_end_s, *max_overlap_m;
    size_t *n_contacts;
    uint64_t *rng_s;            /* 4 words */
    double *gravity_m_s2;       /* 3 */
    long *n_rebuilds;           /* the sort schedule */
    int *store_layout;          /* order of the store; -1: never sorted */
    int layout_saved;           /* read: 1 when the checkpoint holds the layout */
    double *scene_counters;
    int n_scene_counters;
    int n_walls;
    int *wall_active[GF_CHECKPOINT_MAX_WALLS];
    double *wall_force_N[GF_CHECKPOINT_MAX_WALLS]; /* 3 each */
    double *ref_m[3];           /* positions at the last neighbour build, n each */
    double *wall_hist;          /* 3 (n_walls + 1) per grain */
    /* grain pairs with a tangential history: written from these; read into
     * arrays the reader allocates (the caller frees them) */
    int64_t *pair_ids;          /* 2 per pair */
    double *pair_hist;          /* 3 per pair */
    uint8_t *pair_image;        /* 1 per pair: the image code seen from the first id (gf_nlist.h); NULL when
                                 * read from a checkpoint without it (one image a pair) */
    size_t n_pairs;
} gf_checkpoint_view;

/* Writes v (and the coupling's state when coupling is not NULL, with the
 * fluid-step schedule) to path (a temporary name, renamed when complete; on
 * failure the previous checkpoint stays). */
gf_status gf_checkpoint_write(gf_ctx *ctx, const char *path, const gf_checkpoint_view *v, const gf_coupling *coupling,
                              long next_fluid_step, int n_substeps);
/* Reads path into v; the clock's time step into *dt_saved_s (the caller
 * checks it against the run's) and its end time into *t_end_saved_s. The
 * sort schedule and layout and the scene counters are optional (older
 * checkpoints). */
gf_status gf_checkpoint_read(gf_ctx *ctx, const char *path, gf_checkpoint_view *v, double *dt_saved_s,
                             double *t_end_saved_s);
/* The coupling's state and the fluid-step schedule (a checkpoint without a
 * fluid is refused by the coupling). */
gf_status gf_checkpoint_read_coupling(gf_ctx *ctx, const char *path, gf_coupling *coupling, long *next_fluid_step,
                                      int *n_substeps);

#endif
