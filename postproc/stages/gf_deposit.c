/* Deposit envelope from grain positions; method and sources in gf_deposit.h. */
#include "stages/gf_deposit.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stages/gf_post_stats.h"

static int cmp_desc(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

typedef struct edge {
    double left, right;
} edge;

static int cmp_left(const void *a, const void *b)
{
    const double x = ((const edge *)a)->left, y = ((const edge *)b)->left;
    return (x > y) - (x < y);
}

/* Heap toe: grains sorted by their left edge x - r, walked from the wall
 * x = 0 while each starts within half a bin (D/2) of the furthest right edge
 * reached so far; the first larger gap ends the heap. Returns the toe
 * (furthest right edge), 0 if no grain starts near the wall. */
static double heap_toe(const double *x, const double *y, const double *r, const unsigned char *mask, size_t n,
                       double bin)
{
    edge *e = malloc((n ? n : 1) * sizeof *e);
    if (!e)
        return NAN;
    size_t m = 0;
    for (size_t i = 0; i < n; ++i)
        if ((!mask || mask[i]) && isfinite(x[i]) && isfinite(y[i]))
            e[m++] = (edge){x[i] - r[i], x[i] + r[i]};
    qsort(e, m, sizeof *e, cmp_left);
    double reach = 0.0;
    for (size_t k = 0; k < m && e[k].left <= reach + 0.5 * bin; ++k)
        if (e[k].right > reach)
            reach = e[k].right;
    free(e);
    return reach;
}

/* Per-bin heights of the heap (bins of width bin from the wall up to the toe);
 * returns the number of bins, the toe in *front. */
static size_t heap_bins(const double *x, const double *y, const double *r, const unsigned char *mask, size_t n,
                        double bin, double **h_out, double *front)
{
    *h_out = NULL;
    *front = heap_toe(x, y, r, mask, n, bin);
    if (!(*front > 0.0))
        return 0;
    const size_t nb = (size_t)(*front / bin) + 1;
    size_t *cnt = calloc(nb, sizeof *cnt), *off = calloc(nb + 1, sizeof *off), *fill = calloc(nb, sizeof *fill);
    double *tops = malloc((n ? n : 1) * sizeof *tops), *h = calloc(nb, sizeof *h);
    if (!cnt || !off || !tops || !h || !fill) {
        free(cnt), free(off), free(tops), free(h), free(fill);
        return 0;
    }
#define IN_HEAP(i) ((!mask || mask[i]) && isfinite(x[i]) && isfinite(y[i]) && x[i] + r[i] <= *front)
#define BIN_OF(i) (x[i] > 0.0 ? ((size_t)(x[i] / bin) < nb ? (size_t)(x[i] / bin) : nb - 1) : 0)
    for (size_t i = 0; i < n; ++i)
        if (IN_HEAP(i))
            cnt[BIN_OF(i)]++;
    for (size_t b = 0; b < nb; ++b)
        off[b + 1] = off[b] + cnt[b];
    for (size_t i = 0; i < n; ++i)
        if (IN_HEAP(i)) {
            const size_t b = BIN_OF(i);
            tops[off[b] + fill[b]++] = y[i] + r[i];
        }
#undef IN_HEAP
#undef BIN_OF
    /* per bin: drop grains separated from the one below by a vertical gap > D */
    for (size_t b = 0; b < nb; ++b) {
        if (cnt[b] == 0)
            continue;
        double *t = tops + off[b];
        qsort(t, cnt[b], sizeof *t, cmp_desc);
        size_t k = 0;
        while (k + 1 < cnt[b] && t[k] - t[k + 1] > bin)
            ++k;
        h[b] = t[k];
    }
    free(cnt), free(off), free(tops), free(fill);
    *h_out = h;
    return nb;
}

double gf_deposit_front(const double *x, const double *y, const double *r, const unsigned char *mask, size_t n,
                        double bin_m)
{
    double *h = NULL, front = NAN;
    heap_bins(x, y, r, mask, n, bin_m, &h, &front);
    free(h);
    return front;
}

gf_status gf_deposit_envelope(gf_ctx *ctx, const double *x, const double *y, const double *r,
                              const unsigned char *mask, size_t n, double bin_m, gf_deposit *out)
{
    memset(out, 0, sizeof *out);
    out->flank_angle_deg = out->plateau_length_m = NAN;
    out->trapezoid = -1;
    out->bin_m = bin_m;
    if (!(bin_m > 0.0))
        return GF_FAIL(ctx, GF_ERR_ARG, "deposit: bin width must be > 0 (got %g m)", bin_m);
    double *h = NULL, front = 0.0;
    size_t nb = heap_bins(x, y, r, mask, n, bin_m, &h, &front);
    if (!h)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "deposit: out of memory");
    if (nb == 0) {
        free(h);
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "deposit: no grain on the floor near the back wall");
    }
    out->n_bins = nb;
    out->bin_height_m = h;
    out->runout_m = front;
    size_t ib = 0;
    for (size_t b = 0; b < nb; ++b)
        if (h[b] > h[ib])
            ib = b;
    const double H = h[ib];
    out->height_m = H;
    out->back_height_m = nb > 1 ? fmax(h[0], h[1]) : h[0];
    out->area_m2 = 0.0;
    for (size_t b = 0; b < nb; ++b) /* the last bin ends at the toe */
        out->area_m2 += h[b] * (b + 1 < nb ? bin_m : front - (double)b * bin_m);
    double *bx = malloc(nb * sizeof *bx), *by = malloc(nb * sizeof *by);
    if (!bx || !by) {
        free(bx), free(by);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "deposit: out of memory");
    }
    size_t m = 0;
    for (size_t b = ib; b < nb; ++b)
        if (h[b] >= 0.2 * H && h[b] <= 0.8 * H) {
            bx[m] = (b + 0.5) * bin_m;
            by[m++] = h[b];
        }
    double a, s;
    if (m >= 3 && gf_stats_linfit(bx, by, m, &a, &s) && s < 0.0) {
        out->flank_angle_deg = atan(-s) * 180.0 / M_PI;
        out->plateau_length_m = (H - a) / s > 0.0 ? (H - a) / s : 0.0;
        const double need = fmax(2.0 * bin_m, 0.1 * front);
        out->trapezoid = out->plateau_length_m >= need;
    }
    free(bx), free(by);
    return GF_OK;
}

void gf_deposit_free(gf_deposit *d)
{
    free(d->bin_height_m);
    d->bin_height_m = NULL;
}
