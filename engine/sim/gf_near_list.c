/*
 * Near list: a second, thinner Verlet skin inside the neighbour list.
 *
 * The neighbour list (contact/gf_nlist.h) holds every pair closer than
 * R_i + R_j + extra + skin, so that it stays valid until a grain has moved
 * skin/2: in a settled bed of 1e5 grains, 4.2 pairs per grain for 2.1
 * contacts. The blocked pair loop (gf_pairs_blocked.c) scans instead the list's
 * pairs closer than R_i + R_j + extra + near skin, taken from the list
 * itself (no cell search) with their per-pair data (rows, partners, images,
 * tangential history, contact flags, m* and sqrt(m* k_n)) whenever a grain
 * has moved half the near skin since the last near build, and at every
 * neighbour build.
 *
 * A pair left out was at least the near skin beyond the contact (or
 * lubrication) range and neither grain has moved half of it since, so it is
 * still out of range: the full scan would neither add it nor change its
 * history (it has none: a pair flagged in contact is always kept). The
 * candidates, their order and so every force are those of the full scan, and
 * the neighbour-build schedule does not depend on the near list: the results
 * are bitwise the same (tests/engine/test_near_list.c) and a restart needs
 * nothing of it. While the near list holds its pairs' history, the
 * neighbour list's copy is stale; gf_near_list_flush writes it back before
 * anything reads the list's history. The same idea is the inner skin of
 * two-level Verlet lists in molecular dynamics.
 *
 * What it saves is memory traffic: the step reads per-pair data for ~1.1-1.5
 * pairs per contact instead of 2. What it costs: the drift measures each
 * grain's displacement from a second reference (three more reads per grain
 * and step), and a near build is one pass over the chunk's part of the list.
 * Measured in docs/notes/benchmarks.md ("Near list").
 */
#include <stdlib.h>
#include <string.h>

#include "gf_neighbours.h"

void gf_near_list_check(gf_near_list *nr, double near_d2, int normal_only)
{
    nr->use = nr->skin_m > 0.0 && !normal_only; /* skin 0 unless the loop is the blocked one */
    if (nr->valid && near_d2 > 0.25 * nr->skin_m * nr->skin_m)
        nr->valid = 0;
}

void gf_near_list_free(gf_near_list *nr)
{
    free(nr->i), free(nr->j), free(nr->k), free(nr->image), free(nr->touching);
    free(nr->hist), free(nr->sqrt_mk), free(nr->meff);
    nr->i = nr->j = nr->k = NULL, nr->image = nr->touching = NULL, nr->hist = nr->sqrt_mk = nr->meff = NULL;
    nr->cap = 0;
}

gf_status gf_near_list_reserve(gf_ctx *ctx, gf_neighbours *nb)
{
    gf_near_list *nr = &nb->near;
    if (nr->skin_m <= 0.0 || nb->nl->n_pairs <= nr->cap)
        return GF_OK;
    gf_near_list_free(nr); /* nothing held: a neighbour build precedes */
    size_t cap = nb->nl->n_pairs + nb->nl->n_pairs / 4 + 64;
    nr->i = malloc(cap * sizeof *nr->i), nr->j = malloc(cap * sizeof *nr->j), nr->k = malloc(cap * sizeof *nr->k);
    nr->image = malloc(cap), nr->touching = malloc(cap);
    nr->hist = malloc(3 * cap * sizeof(double)), nr->sqrt_mk = malloc(cap * sizeof(double));
    nr->meff = malloc(cap * sizeof(double));
    if (!nr->i || !nr->j || !nr->k || !nr->image || !nr->touching || !nr->hist || !nr->sqrt_mk || !nr->meff) {
        gf_near_list_free(nr);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "sim: cannot allocate the near list (%zu pairs)", cap);
    }
    nr->cap = cap;
    return GF_OK;
}

/* Chunk c's pairs of the near list back into the neighbour list: history
 * and contact flags (the only per-pair data the pair loop writes). */
static void write_back_chunk(const gf_near_list *nr, gf_nlist *nl, int c)
{
    const size_t k0 = nl->row_start[nl->chunk_row[c]], m1 = k0 + nr->len[c];
    for (size_t m = k0; m < m1; ++m) {
        const size_t k = k0 + (size_t)nr->k[m];
        nl->hist[3 * k] = nr->hist[3 * m];
        nl->hist[3 * k + 1] = nr->hist[3 * m + 1];
        nl->hist[3 * k + 2] = nr->hist[3 * m + 2];
        nl->touching[k] = nr->touching[m];
    }
}

void gf_near_list_sync(const gf_neighbours *nb)
{
    if (!nb->near.held)
        return;
    for (int c = 0; c < nb->nl->n_chunks; ++c)
        write_back_chunk(&nb->near, nb->nl, c);
}

void gf_near_list_flush(gf_neighbours *nb)
{
    gf_near_list_sync(nb);
    nb->near.held = nb->near.valid = 0;
}

void gf_near_list_build_chunk(gf_neighbours *nb, const gf_particles *p, double lub_reach_m, int c)
{
    gf_near_list *nr = &nb->near;
    const gf_nlist *nl = nb->nl;
    if (nr->held)
        write_back_chunk(nr, nb->nl, c);
    const size_t i0 = nl->chunk_row[c], i1 = nl->chunk_row[c + 1];
    const size_t k0 = nl->row_start[i0], k1 = nl->row_start[i1];
    const double *x = p->x_m, *y = p->y_m, *z = p->z_m, *R = p->radius_m;
    const double *pair_sqrt_mk = nb->pair_sqrt_mk, *pair_meff = nb->pair_meff;
    const double range = lub_reach_m + nr->skin_m;
    size_t m = k0;
    for (size_t k = k0; k < k1; ++k) { /* branch-free compaction: every field is written, the count advances or not */
        const int32_t i = nl->i[k], j = nl->j[k];
        const double *sh = nl->shift_m[nl->image[k]];
        double dx = x[i] - x[j] + sh[0], dy = y[i] - y[j] + sh[1], dz = z[i] - z[j] + sh[2];
        double reach = R[i] + R[j] + range;
        nr->i[m] = i, nr->j[m] = j, nr->k[m] = (int32_t)(k - k0), nr->image[m] = nl->image[k];
        nr->touching[m] = nl->touching[k];
        nr->hist[3 * m] = nl->hist[3 * k], nr->hist[3 * m + 1] = nl->hist[3 * k + 1];
        nr->hist[3 * m + 2] = nl->hist[3 * k + 2];
        nr->sqrt_mk[m] = pair_sqrt_mk[k], nr->meff[m] = pair_meff[k];
        m += (size_t)((dx * dx + dy * dy + dz * dz < reach * reach) | (nl->touching[k] != 0));
    }
    nr->len[c] = m - k0;
    memcpy(nb->x_near + i0, x + i0, (i1 - i0) * sizeof(double));
    memcpy(nb->y_near + i0, y + i0, (i1 - i0) * sizeof(double));
    memcpy(nb->z_near + i0, z + i0, (i1 - i0) * sizeof(double));
}
