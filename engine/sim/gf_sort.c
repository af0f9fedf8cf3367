/*
 * Spatial ordering of the particle store (gf_sim_tuning.sort_every).
 *
 * At every sort_every-th neighbour-list rebuild (gf_sim_rebuild, after the
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

#include "gf_sim_internal.h"

/* 10 bits of v spread to every third bit (v < 1024). */
static uint32_t spread3(uint32_t v)
{
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

/* 10 bits of v spread to every second bit (v < 1024). */
static uint32_t spread2(uint32_t v)
{
    v &= 0x3ffu;
    v = (v | (v << 8)) & 0x00ff00ffu;
    v = (v | (v << 4)) & 0x0f0f0f0fu;
    v = (v | (v << 2)) & 0x33333333u;
    v = (v | (v << 1)) & 0x55555555u;
    return v;
}

/* With threads, the axis along which the store is cut into the threads'
 * chunks: the one whose cut planes cross the fewest grains, i.e. the
 * smallest cross-section of the grains' bounding box, counted twice along a
 * periodic axis (the wrap is one more cut between the first and the last
 * chunk). The grains near a cut are read by one core and written by the
 * other at every step; between the two cores of the test machine a cache
 * line takes ~240 ns (gf-core-latency, docs/notes/benchmarks.md). */
static int cut_axis(const gf_sim *s, size_t n)
{
    double lo[3] = {DBL_MAX, DBL_MAX, DBL_MAX}, hi[3] = {-DBL_MAX, -DBL_MAX, -DBL_MAX};
    const double *c[3] = {s->p->x_m, s->p->y_m, s->p->z_m};
    for (int a = 0; a < 3; ++a)
        for (size_t i = 0; i < n; ++i) {
            lo[a] = c[a][i] < lo[a] ? c[a][i] : lo[a];
            hi[a] = c[a][i] > hi[a] ? c[a][i] : hi[a];
        }
    int best = 0;
    double best_area = DBL_MAX;
    for (int a = 0; a < 3; ++a) {
        int b = (a + 1) % 3, d = (a + 2) % 3;
        double area = (hi[b] - lo[b]) * (hi[d] - lo[d]) * (s->periodic[a] ? 2.0 : 1.0);
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

gf_status gf_sim_sort_grains(gf_sim *s)
{
    gf_particles *p = s->p;
    const size_t n = p->n_local;
    gf_sim_near_flush(s); /* its pairs name grains by index: the list's own history, keyed by ids, follows them */
    if (n < 2)
        return GF_OK;
    double r_max = 0.0;
    for (size_t i = 0; i < n; ++i)
        r_max = p->radius_m[i] > r_max ? p->radius_m[i] : r_max;
    const double cell_min = 2.0 * r_max + s->extra_m + s->skin_m;
    int nc[3];
    double L[3];
    for (int a = 0; a < 3; ++a) {
        L[a] = s->hi_m[a] - s->lo_m[a];
        double m = floor(L[a] / cell_min);
        nc[a] = m < 1.0 ? 1 : (m > 1024.0 ? 1024 : (int)m);
    }
    const size_t stride = 3 * ((size_t)s->n_walls + 1);
    uint32_t *key = malloc(2 * n * sizeof *key);
    size_t *perm = malloc(2 * n * sizeof *perm);
    size_t *count = malloc(((size_t)1 << 15) * sizeof *count);
    double *tmp = malloc(n * stride * sizeof *tmp); /* >= n doubles: the wall history is the widest */
    if (!key || !perm || !count || !tmp) {
        free(key), free(perm), free(count), free(tmp);
        return GF_FAIL(s->ctx, GF_ERR_NOMEM, "sim: cannot allocate the grain sort (%zu grains)", n);
    }
    const double *c[3] = {p->x_m, p->y_m, p->z_m};
    s->store_layout = gf_sim_sort_layout(s);
    if (s->store_layout == 1) {
        /* layers of cells across the cut axis, Morton order within a layer:
         * any split of the store into chunks is then a plane, and the grains
         * next to it lie together in memory (few cache lines to exchange) */
        const int a = cut_axis(s, n), b = (a + 1) % 3, d = (a + 2) % 3;
        for (size_t i = 0; i < n; ++i) {
            key[i] = cell_of(c[a][i], s->lo_m[a], L[a], nc[a]) << 20 |
                     spread2(cell_of(c[b][i], s->lo_m[b], L[b], nc[b])) |
                     spread2(cell_of(c[d][i], s->lo_m[d], L[d], nc[d])) << 1;
            perm[i] = i;
        }
    } else {
        for (size_t i = 0; i < n; ++i) {
            key[i] = spread3(cell_of(c[0][i], s->lo_m[0], L[0], nc[0])) |
                     spread3(cell_of(c[1][i], s->lo_m[1], L[1], nc[1])) << 1 |
                     spread3(cell_of(c[2][i], s->lo_m[2], L[2], nc[2])) << 2;
            perm[i] = i;
        }
    }
    /* stable LSD radix sort of the 30-bit keys, two digits of 15 bits */
    uint32_t *k_in = key, *k_out = key + n;
    size_t *p_in = perm, *p_out = perm + n;
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
    const size_t *order = p_in; /* new index q holds old grain order[q] */
    int moved = 0;
    for (size_t q = 0; q < n && !moved; ++q)
        moved = order[q] != q;
    if (moved) {
        gf_particles_permute(p, order, tmp);
        double *per_grain[3] = {s->vx_pred, s->vy_pred, s->vz_pred};
        for (int a = 0; a < 3; ++a) {
            for (size_t q = 0; q < n; ++q)
                tmp[q] = per_grain[a][order[q]];
            memcpy(per_grain[a], tmp, n * sizeof *tmp);
        }
        for (size_t q = 0; q < n; ++q)
            memcpy(&tmp[q * stride], &s->wall_hist[order[q] * stride], stride * sizeof *tmp);
        memcpy(s->wall_hist, tmp, n * stride * sizeof *tmp);
        if (s->sleep_quiet_steps && s->sleep_cap == n) {
            long *tq = (long *)tmp;
            for (size_t q = 0; q < n; ++q)
                tq[q] = s->sleep_quiet_steps[order[q]];
            memcpy(s->sleep_quiet_steps, tq, n * sizeof *tq);
        }
        s->n_sorts++;
    }
    free(key), free(perm), free(count), free(tmp);
    return GF_OK;
}

int gf_sim_sort_layout(const gf_sim *s)
{
    return s->n_threads > 1 && s->p->n_local >= GF_SIM_PARALLEL_MIN_GRAINS;
}

int gf_sim_sorts(const gf_sim *s)
{
    return s->sort_every > 0 && (s->p->n_local >= GF_SIM_SORT_MIN_GRAINS || s->opt.tuning.sort_every > 0);
}
