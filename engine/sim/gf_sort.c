/*
 * Spatial ordering of the particle store (gf_sim_tuning.sort_every).
 *
 * At every sort_every-th neighbour-list rebuild (gf_neighbours_rebuild, after the
 * periodic wrap and before the list is built) the grains are reordered by the
 * Morton (Z-order) index of their cell, ties kept in the current order, so
 * that grains close in space are close in memory: the pair loop's reads of
 * partner j (positions, radii, velocities, spins) and its writes of the
 * forces on j then hit the same few cache lines and pages instead of arrays
 * of the whole bed (LAMMPS does the same: atom_modify sort). The cells are
 * the list's (edge 2 R_max + lubrication range + skin); Morton order over
 * them keeps the three axes local, where the lexicographic cell order keeps
 * only the fastest one.
 *
 * What moves with a grain: every field of the store (id, flags, radius, mass
 * ...: gf_particles_permute), the predicted velocities (the rebuild runs
 * between the drift that wrote them and the force pass that reads them), the
 * wall history and the sleep counters. The integrator factors, per-pair
 * arrays and reference positions are recomputed by the rebuild; the
 * tangential history of grain pairs is keyed by ids and follows the grains
 * through the list's transfer (gf_nlist.h); outputs and the fluid coupling
 * find grains by id.
 *
 * With threads (and a store large enough to run its chunks in parallel) the
 * order is another: layers of cells across one axis, Morton order of the
 * other two within a layer. The threads' chunks are contiguous ranges of the
 * store, so each cut between two chunks is then a plane across that axis,
 * the one with the smallest cross-section (cut_axis), and the grains next to
 * it lie together in memory. Those grains are read by one core and written
 * by the other at every step; in 3-D Morton order the cut is a jagged surface
 * and, on the settled bed of 1e4 grains, twice as many grains cross it,
 * spread over many more cache lines (docs/notes/benchmarks.md, "Two cores: the cut
 * between the chunks").
 *
 * Determinism and restart: the order is a function of the positions, the
 * current order and the configured thread count only (stable radix sort),
 * and the schedule of the rebuild count, which the checkpoint stores
 * (dataset sort_state): a restarted run sorts at the same rebuilds as the
 * uninterrupted one and is bitwise identical to it. The sort changes which grain of a pair owns it and
 * the order of the force sums: results change at round-off with sort_every.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gf_neighbours.h"

/* The 10 low bits of v spread to every `every`-th bit (bit b to bit
 * b every): interleaving such spreads of the cell indices gives the Morton
 * index (every 3 in 3-D, every 2 within a layer). */
static uint32_t spread_bits(uint32_t v, int every)
{
    uint32_t out = 0;
    for (int b = 0; b < 10; ++b)
        out |= ((v >> b) & 1u) << (b * every);
    return out;
}

/* With threads, the axis along which the store is cut into the threads'
 * chunks: the one whose cut planes cross the fewest grains, i.e. the
 * smallest cross-section of the grains' bounding box, counted twice along a
 * periodic axis (the wrap is one more cut between the first and the last
 * chunk). The grains near a cut are read by one core and written by the
 * other at every step; between the two cores of the test machine a cache
 * line takes ~240 ns (gf-core-latency, docs/notes/benchmarks.md). */
static int cut_axis(const gf_nb_grains *g, size_t n)
{
    double lo[3] = {DBL_MAX, DBL_MAX, DBL_MAX}, hi[3] = {-DBL_MAX, -DBL_MAX, -DBL_MAX};
    const double *c[3] = {g->p->x_m, g->p->y_m, g->p->z_m};
    for (int a = 0; a < 3; ++a)
        for (size_t i = 0; i < n; ++i) {
            lo[a] = c[a][i] < lo[a] ? c[a][i] : lo[a];
            hi[a] = c[a][i] > hi[a] ? c[a][i] : hi[a];
        }
    int best = 0;
    double best_area = DBL_MAX;
    for (int a = 0; a < 3; ++a) {
        int b = (a + 1) % 3, d = (a + 2) % 3;
        double area = (hi[b] - lo[b]) * (hi[d] - lo[d]) * (g->periodic[a] ? 2.0 : 1.0);
        if (area < best_area)
            best = a, best_area = area;
    }
    return best;
}

static uint32_t cell_of(double v, double lo, double L, int nc)
{
    long c = (long)floor((v - lo) / L * nc);
    if (c < 0)
        c = 0; /* grains outside a closed box share the edge cells */
    if (c >= nc)
        c = nc - 1;
    return (uint32_t)c;
}

/* The cell grid of the sort: the list's cells (edge 2 R_max + extra +
 * skin), at most 1024 along an axis (10 bits of a key). */
typedef struct sort_cells {
    int nc[3];
    double lo[3], L[3];
} sort_cells;

static sort_cells sort_grid(const gf_neighbours *nb, const gf_nb_grains *g)
{
    const gf_particles *p = g->p;
    double r_max = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        r_max = p->radius_m[i] > r_max ? p->radius_m[i] : r_max;
    const double cell_min = 2.0 * r_max + nb->extra_m + nb->skin_m;
    sort_cells sc;
    for (int a = 0; a < 3; ++a) {
        sc.lo[a] = g->lo_m[a];
        sc.L[a] = g->hi_m[a] - g->lo_m[a];
        double m = floor(sc.L[a] / cell_min);
        sc.nc[a] = m < 1.0 ? 1 : (m > 1024.0 ? 1024 : (int)m);
    }
    return sc;
}

static uint32_t cell_on(const sort_cells *sc, const double *const c[3], int a, size_t i)
{
    return cell_of(c[a][i], sc->lo[a], sc->L[a], sc->nc[a]);
}

/* Each grain's key: layout 1, layers of cells across the cut axis and Morton
 * order within a layer (any split of the store into chunks is then a plane,
 * and the grains next to it lie together in memory: few cache lines to
 * exchange); layout 0, the Morton index of its cell. */
static void sort_keys(const gf_neighbours *nb, const gf_nb_grains *g, int layout, uint32_t *key)
{
    const size_t n = g->p->n_local;
    const sort_cells sc = sort_grid(nb, g);
    const double *const c[3] = {g->p->x_m, g->p->y_m, g->p->z_m};
    if (layout == 1) {
        const int a = cut_axis(g, n), b = (a + 1) % 3, d = (a + 2) % 3;
        for (size_t i = 0; i < n; ++i)
            key[i] = cell_on(&sc, c, a, i) << 20 | spread_bits(cell_on(&sc, c, b, i), 2) |
                     spread_bits(cell_on(&sc, c, d, i), 2) << 1;
        return;
    }
    for (size_t i = 0; i < n; ++i)
        key[i] = spread_bits(cell_on(&sc, c, 0, i), 3) | spread_bits(cell_on(&sc, c, 1, i), 3) << 1 |
                 spread_bits(cell_on(&sc, c, 2, i), 3) << 2;
}

/* Stable LSD radix sort of the n 30-bit keys key[0..n), two digits of 15
 * bits; key and perm hold 2n entries (the second half scratch). Returns the
 * order: new index q holds old grain order[q]. */
static const size_t *radix_order(uint32_t *key, size_t *perm, size_t *count, size_t n)
{
    uint32_t *k_in = key, *k_out = key + n;
    size_t *p_in = perm, *p_out = perm + n;
    for (size_t i = 0; i < n; ++i)
        perm[i] = i;
    for (int shift = 0; shift < 30; shift += 15) {
        memset(count, 0, ((size_t)1 << 15) * sizeof *count);
        for (size_t i = 0; i < n; ++i)
            count[(k_in[i] >> shift) & 0x7fffu]++;
        size_t sum = 0;
        for (size_t d = 0; d < ((size_t)1 << 15); ++d) {
            size_t c = count[d];
            count[d] = sum;
            sum += c;
        }
        for (size_t i = 0; i < n; ++i) {
            size_t q = count[(k_in[i] >> shift) & 0x7fffu]++;
            k_out[q] = k_in[i];
            p_out[q] = p_in[i];
        }
        uint32_t *tk = k_in;
        k_in = k_out, k_out = tk;
        size_t *tp = p_in;
        p_in = p_out, p_out = tp;
    }
    return p_in;
}

/* The store and every per-grain array that belongs to the grains into the
 * order: the predicted velocities (the rebuild runs between the drift that
 * wrote them and the force pass that reads them), the wall history, the
 * sleep counters. tmp: n (n_walls + 1) 3 doubles. */
static void move_grains(gf_neighbours *nb, const gf_nb_grains *g, const size_t *order, double *tmp)
{
    const size_t n = g->p->n_local, stride = 3 * ((size_t)g->n_walls + 1);
    gf_particles_permute(g->p, order, tmp);
    double *per_grain[3] = {nb->vx_pred, nb->vy_pred, nb->vz_pred};
    for (int a = 0; a < 3; ++a) {
        for (size_t q = 0; q < n; ++q)
            tmp[q] = per_grain[a][order[q]];
        memcpy(per_grain[a], tmp, n * sizeof *tmp);
    }
    for (size_t q = 0; q < n; ++q)
        memcpy(&tmp[q * stride], &g->wall_hist[order[q] * stride], stride * sizeof *tmp);
    memcpy(g->wall_hist, tmp, n * stride * sizeof *tmp);
    if (g->sleep_quiet_steps) {
        long *tq = (long *)tmp;
        for (size_t q = 0; q < n; ++q)
            tq[q] = g->sleep_quiet_steps[order[q]];
        memcpy(g->sleep_quiet_steps, tq, n * sizeof *tq);
    }
}

gf_status gf_sort_grains(gf_ctx *ctx, gf_neighbours *nb, const gf_nb_grains *g, const gf_nb_tuning *t)
{
    const size_t n = g->p->n_local;
    gf_near_list_flush(nb); /* its pairs name grains by index: the list's own history, keyed by ids, follows them */
    if (n < 2)
        return GF_OK;
    const size_t stride = 3 * ((size_t)g->n_walls + 1);
    uint32_t *key = malloc(2 * n * sizeof *key);
    size_t *perm = malloc(2 * n * sizeof *perm);
    size_t *count = malloc(((size_t)1 << 15) * sizeof *count);
    double *tmp = malloc(n * stride * sizeof *tmp); /* >= n doubles: the wall history is the widest */
    if (!key || !perm || !count || !tmp) {
        free(key), free(perm), free(count), free(tmp);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "sim: cannot allocate the grain sort (%zu grains)", n);
    }
    nb->store_layout = gf_sort_layout(t->n_chunks, n);
    sort_keys(nb, g, nb->store_layout, key);
    const size_t *order = radix_order(key, perm, count, n);
    int moved = 0;
    for (size_t q = 0; q < n && !moved; ++q)
        moved = order[q] != q;
    if (moved) {
        move_grains(nb, g, order, tmp);
        nb->n_sorts++;
    }
    free(key), free(perm), free(count), free(tmp);
    return GF_OK;
}

int gf_sort_layout(int n_chunks, size_t n)
{
    return n_chunks > 1 && n >= GF_SIM_PARALLEL_MIN_GRAINS;
}

int gf_sort_enabled(const gf_neighbours *nb, const gf_nb_tuning *t, size_t n)
{
    return nb->sort_every > 0 && (n >= GF_SIM_SORT_MIN_GRAINS || t->sort_forced);
}
