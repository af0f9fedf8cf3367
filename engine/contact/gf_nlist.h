/*
 * Verlet neighbour list built from a cell grid (linked cells, Djouwe 2012
 * Alg. 1; Izard 2014 §2.1.2.2 "Verlet tables on contact sub-domains").
 *
 * - Half list: each pair once, in the row of its lower index i (j > i), CSR.
 * - A pair enters when |x_i - x_j| < R_i + R_j + extra + skin, with extra the
 *   lubrication range (0 when dry). Rebuilt only when a grain has moved more
 *   than skin/2 since the last build (the sim checks), so no contact is missed:
 *   two grains close by at most skin between builds.
 * - Periodic axes: each pair stores the image it was found in (a code 0..26
 *   into a table of box shifts), so the force loop adds a shift instead of
 *   rounding; positions are wrapped into the box only at a build (the shifts
 *   would be stale otherwise). Along an axis longer than 2 (2 R_max + extra +
 *   skin) a pair is found in one image at most (minimum image). A narrower
 *   periodic axis (the thesis' 2 D wide column, Izard 2014 Table 5.1) can
 *   hold the same two grains within reach through two images, one on each
 *   side: each image is then its own pair (same i and j, another image code),
 *   and the history follows each by its pair vector across builds. The axis
 *   must still be longer than 2 R_max + extra + skin, so that no grain
 *   reaches its own image (checked).
 * - Cells of edge >= 2 R_max + extra + skin; any count per axis (1 or 2 cells
 *   along a periodic axis are handled by de-duplicating neighbour cells).
 *   Building is O(N) (counting sort of grains by cell).
 * - Tangential history: GF_CONTACT_HISTORY doubles per pair, keyed by the pair
 *   of global ids: a build carries the history of every old pair that is
 *   still a candidate over (swapping its sign if the pair changed rows);
 *   pairs that left the list are forgotten (they were separated by > skin).
 * Owner: gf_sim. Not thread-safe during build; the force loop reads rows in
 * parallel and each pair's history is written by the thread owning its row.
 */
#ifndef GF_NLIST_H
#define GF_NLIST_H

#include <stddef.h>
#include <stdint.h>

#include "core/gf_status.h"

typedef struct gf_nlist {
    size_t n;                /* grains the list was built for */
    size_t n_pairs, cap_pairs;
    size_t *row_start;       /* n + 1 */
    size_t *contacts_before; /* n + 1: contacts of the rows before i at the build (pairs with r < R_i + R_j + extra, walls) */
    int32_t *i;              /* row of each pair (lets the force loop run flat over pairs) */
    int32_t *j;              /* partner index */
    uint8_t *image;          /* index into shift_m */
    double *hist;            /* 3 per pair */
    uint8_t *touching;       /* 1 while the pair is in contact (its history may be non-zero) */
    int multi_image;         /* a periodic axis is narrow enough for two images of one pair */
    double *pair_d;          /* 3 per pair, x_i - x_j + shift at the build; only when multi_image */
    double shift_m[27][3];   /* x_i - x_j + shift_m[image] is the pair vector */
    int periodic[3];
    int narrow[3];           /* periodic and at most 2 (2 R_max + extra + skin) long */
    double lo_m[3], hi_m[3];
    /* cells */
    int nc[3];
    size_t n_cells, cap_cells, cap_grains;
    size_t *cell_start;      /* n_cells + 1 */
    int32_t *cell_grains;    /* grains sorted by cell */
    int32_t *grain_cell;
    /* scratch for the history transfer */
    size_t old_n, old_cap_pairs;
    size_t *old_row_start;
    int32_t *old_j;
    double *old_hist;
    double *old_pair_d;      /* the old list's pair vectors (multi_image) */
    int old_multi_image;
    int64_t *old_row_id;     /* id of the grain of each old row */
    int64_t *row_id;         /* ids of the rows of the current list */
    int64_t *id_to_index;    /* inverse id map, size id_cap */
    size_t id_cap;
    /* split of rows into balanced chunks for threads */
    int n_chunks;
    size_t chunk_row[65];
    /* the grains that rows of an earlier chunk reach (partners beyond that
     * chunk's last row), as runs [reach_run[2r], reach_run[2r + 1]) in index
     * order, made of whole cache lines of doubles (8 grains) */
    size_t n_reach_runs, cap_reach_runs;
    size_t *reach_run;
    uint8_t *reach_mark;     /* scratch, n */
    size_t n_builds;
} gf_nlist;

typedef struct gf_nlist_geom {
    double lo_m[3], hi_m[3];
    int periodic[3];
    double extra_m;          /* range beyond contact (lubrication) */
    double skin_m;
} gf_nlist_geom;

gf_status gf_nlist_create(gf_ctx *ctx, gf_nlist **out);
void gf_nlist_destroy(gf_nlist **nl);

/* Builds the list for grains [0, n) at positions x,y,z (which the caller has
 * wrapped into the periodic box), keeping the history of surviving pairs
 * (ids: global ids). n_chunks: number of cost-balanced row ranges wanted
 * (threads); wall_contacts (NULL: none): the walls each grain touches, which
 * the balance counts as contacts of its row. */
gf_status gf_nlist_build(gf_ctx *ctx, gf_nlist *nl, const gf_nlist_geom *g, size_t n, const double *x,
                         const double *y, const double *z, const double *radius_m, const int64_t *id,
                         const uint8_t *wall_contacts, int n_chunks);

/* Sets the history of pair (id_a, id_b) if it is in the list (restart).
 * image: the pair's image code seen from id_a (x_a - x_b + shift_m[image]),
 * or -1 for the first image found (a checkpoint without images: one image a
 * pair). Returns 1 when found. Needs the ids passed to the last build. */
int gf_nlist_set_history(gf_nlist *nl, const int64_t *id, int64_t id_a, int64_t id_b, int image, const double h[3]);

/* Forgets every pair's history (restart: the checkpoint's contacts replace
 * whatever the scene's own preparation left, which the next build would
 * otherwise carry over to pairs the checkpoint has no history for). */
void gf_nlist_clear_history(gf_nlist *nl);

/* Wraps coordinate into [lo, hi) along periodic axes. */
void gf_nlist_wrap(const gf_nlist_geom *g, size_t n, double *x, double *y, double *z);

#endif
