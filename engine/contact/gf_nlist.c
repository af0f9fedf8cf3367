/* Cell grid + Verlet half list with id-keyed tangential history; see gf_nlist.h. */
#include "contact/gf_nlist.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "contact/gf_contact.h"

gf_status gf_nlist_create(gf_ctx *ctx, gf_nlist **out)
{
    *out = calloc(1, sizeof **out);
    if (!*out)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "nlist: cannot allocate");
    return GF_OK;
}

void gf_nlist_destroy(gf_nlist **pnl)
{
    if (!pnl || !*pnl)
        return;
    gf_nlist *nl = *pnl;
    free(nl->row_start), free(nl->contacts_before);
    free(nl->i), free(nl->j), free(nl->image), free(nl->hist), free(nl->touching);
    free(nl->cell_start), free(nl->cell_grains), free(nl->grain_cell);
    free(nl->old_row_start), free(nl->old_j), free(nl->old_hist), free(nl->old_row_id), free(nl->row_id);
    free(nl->pair_d), free(nl->old_pair_d);
    free(nl->id_to_index);
    free(nl->reach_run), free(nl->reach_mark);
    free(nl);
    *pnl = NULL;
}

static int grow(void **p, size_t elem, size_t n)
{
    void *q = realloc(*p, elem * (n ? n : 1));
    if (!q)
        return 0;
    *p = q;
    return 1;
}

void gf_nlist_wrap(const gf_nlist_geom *g, size_t n, double *x, double *y, double *z)
{
    double *c[3] = {x, y, z};
    for (int a = 0; a < 3; ++a) {
        if (!g->periodic[a])
            continue;
        double lo = g->lo_m[a], L = g->hi_m[a] - g->lo_m[a];
        for (size_t i = 0; i < n; ++i) {
            double v = c[a][i];
            if (v < lo || v >= lo + L) {
                v -= L * floor((v - lo) / L);
                if (v >= lo + L) /* round-off at the upper face */
                    v = lo;
                c[a][i] = v;
            }
        }
    }
}

/* Moves the current list into old_* (history source) and records row ids. */
static gf_status keep_old(gf_ctx *ctx, gf_nlist *nl)
{
    size_t n = nl->n, np = nl->n_pairs;
    if (!grow((void **)&nl->old_row_start, sizeof(size_t), n + 1) ||
        !grow((void **)&nl->old_j, sizeof(int32_t), np) || !grow((void **)&nl->old_hist, 3 * sizeof(double), np))
        return GF_FAIL(ctx, GF_ERR_NOMEM, "nlist: cannot keep the old list (%zu pairs)", np);
    if (n)
        memcpy(nl->old_row_start, nl->row_start, (n + 1) * sizeof(size_t));
    if (np) { /* the first build has no list (NULL arrays) */
        memcpy(nl->old_j, nl->j, np * sizeof(int32_t));
        memcpy(nl->old_hist, nl->hist, 3 * np * sizeof(double));
    }
    nl->old_multi_image = nl->multi_image && np;
    if (nl->old_multi_image) {
        if (!grow((void **)&nl->old_pair_d, 3 * sizeof(double), np))
            return GF_FAIL(ctx, GF_ERR_NOMEM, "nlist: cannot keep the old pair vectors (%zu pairs)", np);
        memcpy(nl->old_pair_d, nl->pair_d, 3 * np * sizeof(double));
    }
    nl->old_n = n;
    /* the row ids of the list being replaced become the old ones */
    int64_t *t = nl->old_row_id;
    nl->old_row_id = nl->row_id;
    nl->row_id = t;
    return GF_OK;
}

static gf_status setup_cells(gf_ctx *ctx, gf_nlist *nl, const gf_nlist_geom *g, double cell_min)
{
    nl->n_cells = 1;
    nl->multi_image = 0;
    for (int a = 0; a < 3; ++a) {
        double L = g->hi_m[a] - g->lo_m[a];
        if (!(L > 0.0))
            return GF_FAIL(ctx, GF_ERR_CONFIG, "nlist: box extent along axis %d must be > 0 (got %g m)", a, L);
        if (g->periodic[a] && !(L > cell_min))
            return GF_FAIL(ctx, GF_ERR_CONFIG,
                           "nlist: periodic axis %d is %g m long; a grain would reach its own image: it needs "
                           "more than %g m (2 R_max + lubrication range + skin)",
                           a, L, cell_min);
        nl->narrow[a] = g->periodic[a] && !(L > 2.0 * cell_min); /* two images of a pair may be within reach */
        nl->multi_image |= nl->narrow[a];
        long nc = (long)floor(L / cell_min);
        if (nc < 1)
            nc = 1;
        if (nc > 1024)
            nc = 1024; /* enough resolution; bounds the cell count of huge boxes */
        nl->nc[a] = (int)nc;
        nl->n_cells *= (size_t)nc;
        nl->lo_m[a] = g->lo_m[a];
        nl->hi_m[a] = g->hi_m[a];
        nl->periodic[a] = g->periodic[a];
    }
    if (nl->n_cells > nl->cap_cells) {
        if (!grow((void **)&nl->cell_start, sizeof(size_t), nl->n_cells + 1))
            return GF_FAIL(ctx, GF_ERR_NOMEM, "nlist: cannot allocate %zu cells", nl->n_cells);
        nl->cap_cells = nl->n_cells;
    }
    for (int sx = -1; sx <= 1; ++sx)
        for (int sy = -1; sy <= 1; ++sy)
            for (int sz = -1; sz <= 1; ++sz) {
                int code = (sx + 1) * 9 + (sy + 1) * 3 + (sz + 1);
                nl->shift_m[code][0] = sx * (g->hi_m[0] - g->lo_m[0]);
                nl->shift_m[code][1] = sy * (g->hi_m[1] - g->lo_m[1]);
                nl->shift_m[code][2] = sz * (g->hi_m[2] - g->lo_m[2]);
            }
    return GF_OK;
}

static int cell_coord(const gf_nlist *nl, int a, double v)
{
    double L = nl->hi_m[a] - nl->lo_m[a];
    long c = (long)floor((v - nl->lo_m[a]) / L * nl->nc[a]);
    if (c < 0)
        c = 0; /* grains outside a closed box share the edge cells */
    if (c >= nl->nc[a])
        c = nl->nc[a] - 1;
    return (int)c;
}

static gf_status sort_into_cells(gf_ctx *ctx, gf_nlist *nl, size_t n, const double *x, const double *y,
                                 const double *z)
{
    if (n > nl->cap_grains) {
        if (!grow((void **)&nl->cell_grains, sizeof(int32_t), n) ||
            !grow((void **)&nl->grain_cell, sizeof(int32_t), n))
            return GF_FAIL(ctx, GF_ERR_NOMEM, "nlist: cannot allocate cell arrays for %zu grains", n);
        nl->cap_grains = n;
    }
    memset(nl->cell_start, 0, (nl->n_cells + 1) * sizeof(size_t));
    for (size_t i = 0; i < n; ++i) {
        int c = (cell_coord(nl, 0, x[i]) * nl->nc[1] + cell_coord(nl, 1, y[i])) * nl->nc[2] +
                cell_coord(nl, 2, z[i]);
        nl->grain_cell[i] = c;
        nl->cell_start[c + 1]++;
    }
    for (size_t c = 0; c < nl->n_cells; ++c)
        nl->cell_start[c + 1] += nl->cell_start[c];
    /* stable fill in index order: deterministic list, rows sorted by j */
    size_t *fill = malloc(nl->n_cells * sizeof(size_t));
    if (!fill)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "nlist: cannot allocate cell fill");
    memcpy(fill, nl->cell_start, nl->n_cells * sizeof(size_t));
    for (size_t i = 0; i < n; ++i)
        nl->cell_grains[fill[nl->grain_cell[i]]++] = (int32_t)i;
    free(fill);
    return GF_OK;
}

/* Distinct neighbour cells of cell (cx,cy,cz), wrapping periodic axes. */
static int neighbour_cells(const gf_nlist *nl, int cx, int cy, int cz, int out[27])
{
    int m = 0;
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz) {
                int c[3] = {cx + dx, cy + dy, cz + dz}, ok = 1;
                for (int a = 0; a < 3; ++a) {
                    if (c[a] < 0 || c[a] >= nl->nc[a]) {
                        if (!nl->periodic[a]) {
                            ok = 0;
                            break;
                        }
                        c[a] = (c[a] + nl->nc[a]) % nl->nc[a];
                    }
                }
                if (!ok)
                    continue;
                int idx = (c[0] * nl->nc[1] + c[1]) * nl->nc[2] + c[2], dup = 0;
                for (int k = 0; k < m; ++k)
                    dup |= out[k] == idx;
                if (!dup)
                    out[m++] = idx;
            }
    return m;
}

static gf_status push_pair(gf_ctx *ctx, gf_nlist *nl, int32_t i, int32_t j, uint8_t image)
{
    if (nl->n_pairs == nl->cap_pairs) {
        size_t cap = nl->cap_pairs ? 2 * nl->cap_pairs : 1024;
        if (!grow((void **)&nl->i, sizeof(int32_t), cap) || !grow((void **)&nl->j, sizeof(int32_t), cap) ||
            !grow((void **)&nl->image, 1, cap) ||
            !grow((void **)&nl->hist, 3 * sizeof(double), cap) || !grow((void **)&nl->touching, 1, cap) ||
            (nl->multi_image && !grow((void **)&nl->pair_d, 3 * sizeof(double), cap)))
            return GF_FAIL(ctx, GF_ERR_NOMEM, "nlist: cannot grow to %zu pairs", cap);
        nl->cap_pairs = cap;
    }
    nl->i[nl->n_pairs] = i;
    nl->j[nl->n_pairs] = j;
    nl->image[nl->n_pairs] = image;
    memset(&nl->hist[3 * nl->n_pairs], 0, 3 * sizeof(double));
    nl->touching[nl->n_pairs] = 0;
    nl->n_pairs++;
    return GF_OK;
}

static void min_image(const gf_nlist *nl, double d[3], int s[3])
{
    for (int a = 0; a < 3; ++a) {
        s[a] = 0;
        if (!nl->periodic[a])
            continue;
        double L = nl->hi_m[a] - nl->lo_m[a];
        if (d[a] > 0.5 * L)
            s[a] = -1;
        else if (d[a] < -0.5 * L)
            s[a] = 1;
        d[a] += s[a] * L;
    }
}

/* Every image of pair (i, j) within reach; d: x_i - x_j in the box. Along a
 * narrow axis the images on both sides are tried (two may be within reach),
 * along the others the nearest only. Each is a pair of its own, with its
 * vector kept for the history transfer (carry_history). */
static gf_status push_images(gf_ctx *ctx, gf_nlist *nl, int32_t i, int32_t j, const double d[3], double reach,
                             double forced, size_t *touching)
{
    double nearest[3] = {d[0], d[1], d[2]};
    int s[3], lo[3], hi[3];
    min_image(nl, nearest, s);
    for (int a = 0; a < 3; ++a) {
        lo[a] = nl->narrow[a] ? -1 : s[a];
        hi[a] = nl->narrow[a] ? 1 : s[a];
    }
    for (int sx = lo[0]; sx <= hi[0]; ++sx)
        for (int sy = lo[1]; sy <= hi[1]; ++sy)
            for (int sz = lo[2]; sz <= hi[2]; ++sz) {
                int code = (sx + 1) * 9 + (sy + 1) * 3 + (sz + 1);
                const double *sh = nl->shift_m[code];
                double e[3] = {d[0] + sh[0], d[1] + sh[1], d[2] + sh[2]};
                double r2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
                if (r2 < reach * reach) {
                    GF_TRY(push_pair(ctx, nl, i, j, (uint8_t)code));
                    memcpy(&nl->pair_d[3 * (nl->n_pairs - 1)], e, sizeof e);
                }
                *touching += r2 < forced * forced;
            }
    return GF_OK;
}

static gf_status fill_rows(gf_ctx *ctx, gf_nlist *nl, const gf_nlist_geom *g, size_t n, const double *x,
                           const double *y, const double *z, const double *r, const uint8_t *wall_contacts)
{
    nl->n_pairs = 0;
    if (nl->multi_image && !grow((void **)&nl->pair_d, 3 * sizeof(double), nl->cap_pairs))
        return GF_FAIL(ctx, GF_ERR_NOMEM, "nlist: cannot allocate pair vectors for %zu pairs", nl->cap_pairs);
    int nb[27];
    size_t touching = 0;
    for (size_t i = 0; i < n; ++i) {
        nl->row_start[i] = nl->n_pairs;
        nl->contacts_before[i] = touching;
        touching += wall_contacts ? wall_contacts[i] : 0;
        int c = nl->grain_cell[i];
        int cz = c % nl->nc[2], cy = (c / nl->nc[2]) % nl->nc[1], cx = c / (nl->nc[2] * nl->nc[1]);
        int m = neighbour_cells(nl, cx, cy, cz, nb);
        for (int k = 0; k < m; ++k)
            for (size_t q = nl->cell_start[nb[k]]; q < nl->cell_start[nb[k] + 1]; ++q) {
                int32_t j = nl->cell_grains[q];
                if ((size_t)j <= i)
                    continue;
                double d[3] = {x[i] - x[j], y[i] - y[j], z[i] - z[j]};
                double reach = r[i] + r[j] + g->extra_m + g->skin_m, forced = r[i] + r[j] + g->extra_m;
                if (nl->multi_image) {
                    GF_TRY(push_images(ctx, nl, (int32_t)i, j, d, reach, forced, &touching));
                    continue;
                }
                int s[3];
                min_image(nl, d, s);
                double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                if (r2 < reach * reach)
                    GF_TRY(push_pair(ctx, nl, (int32_t)i, j, (uint8_t)((s[0] + 1) * 9 + (s[1] + 1) * 3 + (s[2] + 1))));
                touching += r2 < forced * forced; /* a force to compute: contact or lubrication */
            }
    }
    nl->row_start[n] = nl->n_pairs;
    nl->contacts_before[n] = touching;
    return GF_OK;
}

/* Pair vectors of one contact at two builds: equal within the grains' motion
 * (< skin), while two images differ by a period along a narrow axis. */
static int same_image(const gf_nlist *nl, const double *a, const double *b)
{
    for (int q = 0; q < 3; ++q)
        if (nl->narrow[q] && fabs(a[q] - b[q]) > 0.5 * (nl->hi_m[q] - nl->lo_m[q]))
            return 0;
    return 1;
}

/* The slot of pair (row, j) in the list: any image (image < 0, d NULL), the
 * image with that code, or the image whose vector is d's (history transfer). */
static long find_in_row(const gf_nlist *nl, size_t row, int32_t j, int image, const double *d)
{
    for (size_t k = nl->row_start[row]; k < nl->row_start[row + 1]; ++k)
        if (nl->j[k] == j && (image < 0 || nl->image[k] == image) &&
            (!d || !nl->multi_image || same_image(nl, &nl->pair_d[3 * k], d)))
            return (long)k;
    return -1;
}

static gf_status map_ids(gf_ctx *ctx, gf_nlist *nl, size_t n, const int64_t *id)
{
    int64_t max_id = -1;
    for (size_t i = 0; i < n; ++i)
        if (id[i] > max_id)
            max_id = id[i];
    size_t need = (size_t)(max_id + 1);
    if (need > nl->id_cap) {
        if (!grow((void **)&nl->id_to_index, sizeof(int64_t), need))
            return GF_FAIL(ctx, GF_ERR_NOMEM, "nlist: cannot allocate id map (%zu)", need);
        nl->id_cap = need;
    }
    for (size_t k = 0; k < nl->id_cap; ++k)
        nl->id_to_index[k] = -1;
    for (size_t i = 0; i < n; ++i)
        nl->id_to_index[id[i]] = (int64_t)i;
    return GF_OK;
}

/* Pair (id a, id b) seen from a, at image code image (-1: any) or pair
 * vector d (NULL: any): its history set to h. */
static int set_history_at(gf_nlist *nl, int64_t a, int64_t b, int image, const double *d, const double h[3])
{
    if (a < 0 || b < 0 || (size_t)a >= nl->id_cap || (size_t)b >= nl->id_cap)
        return 0;
    int64_t ia = nl->id_to_index[a], ib = nl->id_to_index[b];
    if (ia < 0 || ib < 0)
        return 0;
    double sgn = 1.0, d_row[3];
    if (ia > ib) { /* the pair lives in the row of the lower index, seen from it */
        int64_t t = ia;
        ia = ib, ib = t, sgn = -1.0;
        image = image < 0 ? image : 26 - image; /* the opposite shift */
        if (d) {
            d_row[0] = -d[0], d_row[1] = -d[1], d_row[2] = -d[2];
            d = d_row;
        }
    }
    long slot = find_in_row(nl, (size_t)ia, (int32_t)ib, image, d);
    if (slot < 0)
        return 0;
    double *dst = &nl->hist[3 * slot];
    dst[0] = sgn * h[0], dst[1] = sgn * h[1], dst[2] = sgn * h[2];
    nl->touching[slot] = 1;
    return 1;
}

int gf_nlist_set_history(gf_nlist *nl, const int64_t *id, int64_t a, int64_t b, int image, const double h[3])
{
    (void)id;
    return set_history_at(nl, a, b, image, NULL, h);
}

void gf_nlist_clear_history(gf_nlist *nl)
{
    if (nl->n_pairs == 0)
        return;
    memset(nl->hist, 0, 3 * nl->n_pairs * sizeof(double));
    memset(nl->touching, 0, nl->n_pairs);
}

static void carry_history(gf_nlist *nl, const int64_t *id)
{
    for (size_t r = 0; r < nl->old_n; ++r)
        for (size_t k = nl->old_row_start[r]; k < nl->old_row_start[r + 1]; ++k) {
            const double *h = &nl->old_hist[3 * k];
            if (h[0] == 0.0 && h[1] == 0.0 && h[2] == 0.0)
                continue;
            const double *d = nl->old_multi_image ? &nl->old_pair_d[3 * k] : NULL;
            set_history_at(nl, nl->old_row_id[r], nl->old_row_id[nl->old_j[k]], -1, d, h);
        }
}

/* Cost of the rows before i in the force pass, in units of the scan of one
 * candidate: each candidate 1, each contact (pair or wall; a pair within the
 * lubrication range counts as one) GF_NLIST_CONTACT_COST more, each row 2.
 * Measured on the settled 1e4 bed (docs/notes/benchmarks.md): ~6 ns to scan a
 * candidate, ~24 ns more for a contact's force and scatter, and the floor's
 * wall contacts about as dear as pairs; counting candidates alone left the
 * bottom chunk (its contacts pressed by the weight above, and the floor)
 * 9-10 % dearer than the top one. */
#define GF_NLIST_CONTACT_COST 4.0
static double rows_cost(const gf_nlist *nl, size_t i)
{
    return (double)nl->row_start[i] + GF_NLIST_CONTACT_COST * (double)nl->contacts_before[i] + 2.0 * (double)i;
}

/* Chunk boundaries at equal cost, each rounded down to a multiple of a
 * cache line of doubles: a chunk then starts on a line in every per-grain
 * array, and its thread's vector loops (integration) do no split loads or
 * stores (a boundary 2 doubles off a line made them 1.5-2x slower). */
static void split_rows(gf_nlist *nl, size_t n, int n_chunks)
{
    if (n_chunks < 1)
        n_chunks = 1;
    if (n_chunks > 64)
        n_chunks = 64;
    nl->n_chunks = n_chunks;
    const double per = rows_cost(nl, n) / n_chunks;
    const size_t line = 64 / sizeof(double);
    size_t i = 0;
    nl->chunk_row[0] = 0;
    for (int c = 1; c < n_chunks; ++c) {
        while (i < n && rows_cost(nl, i) < c * per)
            ++i;
        nl->chunk_row[c] = i / line * line;
    }
    nl->chunk_row[n_chunks] = n;
}

static gf_status append_reach_run(gf_ctx *ctx, gf_nlist *nl, size_t i)
{
    if (nl->n_reach_runs == nl->cap_reach_runs) {
        size_t cap = nl->cap_reach_runs ? 2 * nl->cap_reach_runs : 64;
        if (!grow((void **)&nl->reach_run, 2 * sizeof(size_t), cap))
            return GF_FAIL(ctx, GF_ERR_NOMEM, "nlist: cannot allocate the reach runs");
        nl->cap_reach_runs = cap;
    }
    nl->reach_run[2 * nl->n_reach_runs] = i, nl->reach_run[2 * nl->n_reach_runs + 1] = i + 1;
    nl->n_reach_runs++;
    return GF_OK;
}

/* The grains each chunk's rows reach beyond the chunk (j >= its end): the
 * force loop sends those contributions to the chunk's own buffer, and the
 * owner of the grain adds them after the chunks have run, over these runs
 * only (on a store sorted across the cut, a layer of grains per boundary). */
static gf_status find_reach_runs(gf_ctx *ctx, gf_nlist *nl, size_t n)
{
    nl->n_reach_runs = 0;
    if (nl->n_chunks < 2)
        return GF_OK;
    if (!grow((void **)&nl->reach_mark, 1, n))
        return GF_FAIL(ctx, GF_ERR_NOMEM, "nlist: cannot allocate the reach marks");
    memset(nl->reach_mark, 0, n);
    for (int c = 0; c + 1 < nl->n_chunks; ++c) {
        size_t end = nl->chunk_row[c + 1];
        for (size_t k = nl->row_start[nl->chunk_row[c]]; k < nl->row_start[end]; ++k)
            if ((size_t)nl->j[k] >= end)
                nl->reach_mark[nl->j[k]] = 1;
    }
    /* whole cache lines of doubles: loops over the runs, and over the gaps
     * between them, start and end on lines (see split_rows) */
    const size_t line = 64 / sizeof(double);
    for (size_t i = 0; i < n; ++i) {
        if (!nl->reach_mark[i])
            continue;
        size_t first = i / line * line, end = first + line < n ? first + line : n;
        size_t *last_end = nl->n_reach_runs ? &nl->reach_run[2 * nl->n_reach_runs - 1] : NULL;
        if (last_end && first <= *last_end)
            *last_end = end;
        else
            GF_TRY(append_reach_run(ctx, nl, first));
        nl->reach_run[2 * nl->n_reach_runs - 1] = end;
        i = end - 1;
    }
    return GF_OK;
}

gf_status gf_nlist_build(gf_ctx *ctx, gf_nlist *nl, const gf_nlist_geom *g, size_t n, const double *x,
                         const double *y, const double *z, const double *radius_m, const int64_t *id,
                         const uint8_t *wall_contacts, int n_chunks)
{
    double r_max = 0.0;
    for (size_t i = 0; i < n; ++i)
        if (radius_m[i] > r_max)
            r_max = radius_m[i];
    GF_TRY(keep_old(ctx, nl));
    GF_TRY(setup_cells(ctx, nl, g, 2.0 * r_max + g->extra_m + g->skin_m));
    GF_TRY(sort_into_cells(ctx, nl, n, x, y, z));
    if (!grow((void **)&nl->row_start, sizeof(size_t), n + 1) || !grow((void **)&nl->contacts_before, sizeof(size_t), n + 1))
        return GF_FAIL(ctx, GF_ERR_NOMEM, "nlist: cannot allocate rows");
    GF_TRY(fill_rows(ctx, nl, g, n, x, y, z, radius_m, wall_contacts));
    nl->n = n;
    GF_TRY(map_ids(ctx, nl, n, id));
    carry_history(nl, id);
    /* row ids of this build, for the next transfer */
    if (!grow((void **)&nl->row_id, sizeof(int64_t), n))
        return GF_FAIL(ctx, GF_ERR_NOMEM, "nlist: cannot allocate row ids");
    memcpy(nl->row_id, id, n * sizeof(int64_t));
    split_rows(nl, n, n_chunks);
    GF_TRY(find_reach_runs(ctx, nl, n));
    nl->n_builds++;
    return GF_OK;
}
