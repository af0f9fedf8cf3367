/* Cell-integrated Gaussian kernel and its transfers; see gf_average.h. */
#include "coupling/gf_average.h"

#include <math.h>

#include "core/gf_clones.h"

static int fold(const gf_grid *g, int d, int m)
{
    int n = g->n[d];
    if (g->periodic[d]) {
        m %= n;
        return m < 0 ? m + n : m;
    }
    while (m < 0 || m >= n) {  /* mirror across the wall, repeatedly for kernels wider than the box */
        if (m < 0)
            m = -1 - m;
        if (m >= n)
            m = 2 * n - 1 - m;
    }
    return m;
}

static void kernel_1d(const gf_grid *g, int d, double sigma, double x, gf_kernel_1d *k)
{
    double h = g->h_m[d], lo = g->lo_m[d];
    int half = (int)ceil(3.0 * sigma / h) + 1;
    if (2 * half + 1 > GF_KERNEL_MAX)
        half = (GF_KERNEL_MAX - 1) / 2;
    int c = (int)floor((x - lo) / h);
    double s2 = sqrt(2.0) * sigma, sum = 0.0;
    k->n = 0;
    for (int m = c - half; m <= c + half; ++m) {
        double a = (lo + m * h - x) / s2, b = (lo + (m + 1) * h - x) / s2;
        double w = 0.5 * (erf(b) - erf(a));
        if (w <= 0.0)
            continue;
        int cell = fold(g, d, m), j;
        for (j = 0; j < k->n; ++j)
            if (k->cell[j] == cell)
                break;
        if (j == k->n) {
            k->cell[k->n] = cell;
            k->w[k->n] = 0.0;
            ++k->n;
        }
        k->w[j] += w;
        sum += w;
    }
    for (int j = 0; j < k->n; ++j)
        k->w[j] /= sum;
}

void gf_average_kernel(const gf_grid *g, double sigma_m, const double x_m[3], gf_kernel *k)
{
    for (int d = 0; d < 3; ++d)
        kernel_1d(g, d, sigma_m, x_m[d], &k->ax[d]);
}

double gf_average_interpolate(const gf_grid *g, const gf_kernel *k, const double *field)
{
    double s = 0.0;
    const gf_kernel_1d *kx = &k->ax[0], *ky = &k->ax[1], *kz = &k->ax[2];
    for (int c = 0; c < kz->n; ++c)
        for (int b = 0; b < ky->n; ++b) {
            double wyz = ky->w[b] * kz->w[c];
            size_t row = gf_grid_cell(g, 0, ky->cell[b], kz->cell[c]);
            for (int a = 0; a < kx->n; ++a)
                s += wyz * kx->w[a] * field[row + (size_t)kx->cell[a]];
        }
    return s;
}

/* The lane loops vectorise in an AVX-512 clone chosen at load time (one
 * vector per cell); ISO C mode keeps fused multiply-adds out of both clones,
 * so they give the same bits. */
#ifdef _OPENMP
#define GF_LANE_SIMD _Pragma("omp simd")
#else
#define GF_LANE_SIMD
#endif

void gf_average_interleave(size_t n_cells, const double *const *fields, int n_fields, double *lanes)
{
    for (size_t c = 0; c < n_cells; ++c)
        for (int f = 0; f < GF_AVERAGE_LANES; ++f)
            lanes[c * GF_AVERAGE_LANES + (size_t)f] = f < n_fields ? fields[f][c] : 0.0;
}

void gf_average_deinterleave(size_t n_cells, const double *lanes, int n_fields, double *const *fields)
{
    for (size_t c = 0; c < n_cells; ++c)
        for (int f = 0; f < n_fields; ++f)
            fields[f][c] = lanes[c * GF_AVERAGE_LANES + (size_t)f];
}

GF_AVX512_CLONES void gf_average_interpolate_lanes(const gf_grid *g, const gf_kernel *k, const double *lanes,
                                                 double out[GF_AVERAGE_LANES])
{
    double s[GF_AVERAGE_LANES] = {0.0};
    const gf_kernel_1d *kx = &k->ax[0], *ky = &k->ax[1], *kz = &k->ax[2];
    for (int c = 0; c < kz->n; ++c)
        for (int b = 0; b < ky->n; ++b) {
            double wyz = ky->w[b] * kz->w[c];
            size_t row = gf_grid_cell(g, 0, ky->cell[b], kz->cell[c]);
            for (int a = 0; a < kx->n; ++a) {
                const double w = wyz * kx->w[a];
                const double *l = lanes + (row + (size_t)kx->cell[a]) * GF_AVERAGE_LANES;
                for (int f = 0; f < GF_AVERAGE_LANES; ++f)
                    s[f] += w * l[f];
            }
        }
    for (int f = 0; f < GF_AVERAGE_LANES; ++f)
        out[f] = s[f];
}

GF_AVX512_CLONES void gf_average_spread_lanes(const gf_grid *g, const gf_kernel *k, const double value[GF_AVERAGE_LANES],
                                            double *lanes)
{
    double v[GF_AVERAGE_LANES], wyz[GF_AVERAGE_LANES];
    const double vol = g->h_m[0] * g->h_m[1] * g->h_m[2];
    for (int f = 0; f < GF_AVERAGE_LANES; ++f)
        v[f] = value[f] / vol;
    const gf_kernel_1d *kx = &k->ax[0], *ky = &k->ax[1], *kz = &k->ax[2];
    for (int c = 0; c < kz->n; ++c)
        for (int b = 0; b < ky->n; ++b) {
            for (int f = 0; f < GF_AVERAGE_LANES; ++f)
                wyz[f] = v[f] * ky->w[b] * kz->w[c];
            size_t row = gf_grid_cell(g, 0, ky->cell[b], kz->cell[c]);
            for (int a = 0; a < kx->n; ++a) {
                const double wa = kx->w[a]; /* read once: the stores below could alias the kernel */
                double *l = lanes + (row + (size_t)kx->cell[a]) * GF_AVERAGE_LANES;
                GF_LANE_SIMD
                for (int f = 0; f < GF_AVERAGE_LANES; ++f)
                    l[f] += wyz[f] * wa;
            }
        }
}

void gf_average_spread(const gf_grid *g, const gf_kernel *k, double value, double *field)
{
    double v = value / (g->h_m[0] * g->h_m[1] * g->h_m[2]);
    const gf_kernel_1d *kx = &k->ax[0], *ky = &k->ax[1], *kz = &k->ax[2];
    for (int c = 0; c < kz->n; ++c)
        for (int b = 0; b < ky->n; ++b) {
            double wyz = v * ky->w[b] * kz->w[c];
            size_t row = gf_grid_cell(g, 0, ky->cell[b], kz->cell[c]);
            for (int a = 0; a < kx->n; ++a)
                field[row + (size_t)kx->cell[a]] += wyz * kx->w[a];
        }
}

double gf_average_self_overlap(const gf_kernel *k)
{
    double s = 1.0;
    for (int d = 0; d < 3; ++d) {
        double sd = 0.0;
        for (int j = 0; j < k->ax[d].n; ++j)
            sd += k->ax[d].w[j] * k->ax[d].w[j];
        s *= sd;
    }
    return s;
}
