/*
 * Silo velocity profiles and their Gaussian fits (gf_silo_flow.h;
 * Djouwe Meffeja 2012 §3.5.1, Nedderman & Tuzun 1979).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stages/gf_post_stats.h"
#include "stages/gf_silo_flow.h"
#include "stages/gf_stage_util.h"

double gf_silo_fit_gaussian(const double *x, const double *v, int n, double z, double *R2)
{
    double A[3][3] = {{0}}, B[3] = {0}, vmax = 0.0;
    for (int i = 0; i < n; ++i)
        vmax = isfinite(v[i]) ? fmax(vmax, v[i]) : vmax;
    int m = 0;
    for (int i = 0; i < n; ++i) { /* ln v = c0 + c1 x + c2 x^2 */
        if (!(v[i] > 0.1 * vmax))
            continue;
        double w = v[i] * v[i], ph[3] = {1.0, x[i], x[i] * x[i]}, y = log(v[i]);
        for (int a = 0; a < 3; ++a) {
            B[a] += w * ph[a] * y;
            for (int c = 0; c < 3; ++c)
                A[a][c] += w * ph[a] * ph[c];
        }
        ++m;
    }
    if (m < 4)
        return NAN;
    double c[3], det = 0.0; /* Cramer's rule on the 3 x 3 normal equations */
    for (int k = -1; k < 3; ++k) {
        double M[3][3];
        memcpy(M, A, sizeof M);
        if (k >= 0)
            for (int a = 0; a < 3; ++a)
                M[a][k] = B[a];
        double dk = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                    M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
        if (k < 0)
            det = dk;
        else
            c[k] = dk / det;
    }
    double xlo = INFINITY, xhi = -INFINITY;
    for (int i = 0; i < n; ++i)
        xlo = fmin(xlo, x[i]), xhi = fmax(xhi, x[i]);
    /* a Gaussian wider than the sampled range (sigma^2 = -1/(2 c2)) is not identified */
    if (!(det != 0.0) || !(c[2] < 0.0) || !(sqrt(-0.5 / c[2]) < xhi - xlo))
        return NAN;
    double mean = 0.0, tot = 0.0, res = 0.0;
    for (int i = 0; i < n; ++i)
        mean += v[i] / n;
    for (int i = 0; i < n; ++i) {
        double p = exp(c[0] + c[1] * x[i] + c[2] * x[i] * x[i]);
        tot += (v[i] - mean) * (v[i] - mean), res += (v[i] - p) * (v[i] - p);
    }
    *R2 = tot > 0.0 ? 1.0 - res / tot : NAN;
    return -1.0 / (4.0 * c[2] * z); /* exp(-x^2 / (4 b z)) */
}

enum { N_LEVELS = 6, BINS_PER_D = 2 };
static const double levels[N_LEVELS] = {0.5, 1.0, 2.0, 3.0, 5.0, 8.0};

/* Start of the steady window of discharge_rate (MSER-5), NaN when unknown. */
static double steady_start(gf_ctx *ctx, const gf_stage_in *in)
{
    double t0 = NAN, *t = NULL, *q = NULL;
    size_t nt = 0, nq = 0;
    gf_ncr d;
    if (gf_stage_open(ctx, in, "diagnostics.nc", &d) != GF_OK)
        return NAN;
    if (gf_ncr_var_1d(ctx, &d, "time", &t, &nt) == GF_OK && gf_ncr_var_1d(ctx, &d, "discharge_rate", &q, &nq) == GF_OK &&
        nq == nt && nt > 1) {
        gf_steady s;
        gf_stats_steady(t + 1, q + 1, nt - 1, &s);
        t0 = s.ok ? s.t_start_s : NAN;
    }
    free(t), free(q);
    gf_ncr_close(&d);
    return t0;
}

/* Sums of -v_y per (level, bin) over the frames from t0; returns the frame count (-1 on error). */
static long accumulate(gf_ctx *ctx, gf_ncr *p, const gf_grains_info *g, double t0, double d, double Lx, double Ly,
                       int nb, double *sum, double *cnt)
{
    const size_t n = g->n_all;
    double *t = NULL, *x = malloc(n * sizeof *x + 1), *y = malloc(n * sizeof *y + 1), *z = malloc(n * sizeof *z + 1),
           *v = malloc(n * sizeof *v + 1);
    size_t nt = 0;
    long frames = 0;
    gf_status st = x && y && z && v ? gf_ncr_var_1d(ctx, p, "time", &t, &nt) : GF_ERR_NOMEM;
    for (size_t k = 0; st == GF_OK && k < nt; ++k) {
        if (!(t[k] >= t0))
            continue;
        st = gf_ncr_var_2d_col(ctx, p, "x", k, x, n);
        if (st == GF_OK) st = gf_ncr_var_2d_col(ctx, p, "y", k, y, n);
        if (st == GF_OK) st = gf_ncr_var_2d_col(ctx, p, "z", k, z, n);
        if (st == GF_OK) st = gf_ncr_var_2d_col(ctx, p, "v", k, v, n);
        for (size_t i = 0; st == GF_OK && i < n; ++i) {
            if (!g->mobile[i] || !isfinite(v[i]) || fabs(z[i] - 0.5 * Ly) >= d)
                continue;
            int b = (int)floor(x[i] / Lx * nb);
            for (int h = 0; b >= 0 && b < nb && h < N_LEVELS; ++h)
                if (fabs(y[i] - levels[h] * d) < 0.5 * d)
                    sum[h * nb + b] -= v[i], cnt[h * nb + b] += 1.0;
        }
        frames += st == GF_OK;
    }
    free(t), free(x), free(y), free(z), free(v);
    return st == GF_OK ? frames : -1;
}

static gf_status write_series(gf_ctx *ctx, const gf_stage_in *in, int nb, const double *xc, const double *vd,
                              const double *b, const double *R2, double d)
{
    double zl[N_LEVELS];
    for (int h = 0; h < N_LEVELS; ++h)
        zl[h] = levels[h] * d;
    const gf_postnc_dimension dims[] = {{"x", (size_t)nb}, {"z_level", N_LEVELS}};
    const gf_postnc_series vars[] = {
        {"x", 1, {0}, "m", "bin centre across the orifice", NULL, xc},
        {"z_level", 1, {1}, "m", "height above the orifice plane", NULL, zl},
        {"v_down", 2, {1, 0}, "m s-1", "mean downward grain velocity in the orifice mid-plane", NULL, vd},
        {"b", 1, {1}, "m", "diffusion length of the Gaussian fit (width^2 = 2 b z)", NULL, b},
        {"gauss_R2", 1, {1}, "1", "R^2 of the Gaussian fit", NULL, R2},
    };
    return gf_postnc_write(ctx, in, "profiles", 1, dims, GF_POSTNC_COUNT(dims), vars, GF_POSTNC_COUNT(vars));
}

gf_status gf_silo_profiles(gf_ctx *ctx, const gf_stage_in *in, gf_stage_out *out)
{
    const double t0 = steady_start(ctx, in);
    gf_ncr p;
    GF_TRY(gf_stage_open(ctx, in, "particles.nc", &p));
    const double d = gf_ncr_att_double_or(&p, "grain_diameter_m", NAN);
    const double Lx = gf_ncr_att_double_or(&p, "scene_param_width_x_over_d", NAN) * d;
    const double Ly = gf_ncr_att_double_or(&p, "scene_param_width_z_over_d", NAN) * d;
    const int nb = (int)lround(Lx / d) * BINS_PER_D;
    gf_grains_info g;
    gf_status st = isfinite(t0) && nb > 0 ? gf_stage_grains(ctx, &p, 1, &g)
                                          : GF_FAIL(ctx, GF_ERR_IO, "%s: no steady window or no silo geometry", in->run_dir);
    if (st != GF_OK) {
        gf_ncr_close(&p);
        return st;
    }
    double *sum = calloc((size_t)(N_LEVELS * nb), sizeof *sum), *cnt = calloc((size_t)(N_LEVELS * nb), sizeof *cnt);
    double *xc = malloc((size_t)nb * sizeof *xc), b[N_LEVELS], R2[N_LEVELS];
    long frames = sum && cnt && xc ? accumulate(ctx, &p, &g, t0, d, Lx, Ly, nb, sum, cnt) : -1;
    gf_ncr_close(&p);
    gf_stage_grains_free(&g);
    if (frames <= 0)
        st = frames == 0 ? GF_FAIL(ctx, GF_ERR_IO, "%s/particles.nc: no frame in the steady window", in->run_dir)
                         : GF_FAIL(ctx, GF_ERR_IO, "profiles: cannot read %s/particles.nc", in->run_dir);
    if (st == GF_OK) {
        for (int i = 0; i < nb; ++i)
            xc[i] = (i + 0.5) * Lx / nb;
        for (int k = 0; k < N_LEVELS * nb; ++k) /* per-grain sums over the frames -> mean velocity in the bin */
            sum[k] = cnt[k] > 0.0 ? sum[k] / cnt[k] : 0.0;
        double r2_min = INFINITY;
        int decreasing = 1;
        for (int h = 0; h < N_LEVELS; ++h) {
            R2[h] = NAN;
            b[h] = gf_silo_fit_gaussian(xc, sum + h * nb, nb, levels[h] * d, &R2[h]);
            if (levels[h] >= 3.0)
                r2_min = fmin(r2_min, isfinite(R2[h]) ? R2[h] : -INFINITY);
            if (h >= 2)
                decreasing &= b[h] < b[h - 1];
        }
        gf_post_row_set(out->row, "silo_b_z1_over_d", b[1] / d);
        gf_post_row_set(out->row, "silo_b_z5_over_d", b[4] / d);
        gf_post_row_set(out->row, "silo_gauss_R2_min", r2_min);
        gf_post_row_set(out->row, "silo_b_decreasing", decreasing);
        st = write_series(ctx, in, nb, xc, sum, b, R2, d);
    }
    free(sum), free(cnt), free(xc);
    return st;
}
