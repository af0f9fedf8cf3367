/* Statistics for the stages; methods and sources in gf_post_stats.h. */
#include "stages/gf_post_stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void gf_stats_mean_std(const double *x, size_t n, double *mean, double *std)
{
    double s = 0.0;
    size_t m = 0;
    for (size_t i = 0; i < n; ++i)
        if (isfinite(x[i])) {
            s += x[i];
            ++m;
        }
    *mean = m ? s / (double)m : NAN;
    double v = 0.0;
    for (size_t i = 0; i < n; ++i)
        if (isfinite(x[i]))
            v += (x[i] - *mean) * (x[i] - *mean);
    *std = m > 1 ? sqrt(v / (double)(m - 1)) : NAN;
}

int gf_stats_linfit(const double *x, const double *y, size_t n, double *a, double *b)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    size_t m = 0;
    for (size_t i = 0; i < n; ++i) {
        if (!isfinite(x[i]) || !isfinite(y[i]))
            continue;
        sx += x[i];
        sy += y[i];
        ++m;
    }
    if (m < 2)
        return 0;
    const double mx = sx / (double)m, my = sy / (double)m;
    for (size_t i = 0; i < n; ++i) {
        if (!isfinite(x[i]) || !isfinite(y[i]))
            continue;
        sxx += (x[i] - mx) * (x[i] - mx);
        sxy += (x[i] - mx) * (y[i] - my);
    }
    if (!(sxx > 0.0))
        return 0;
    *b = sxy / sxx;
    *a = my - *b * mx;
    return 1;
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double gf_stats_quantile(const double *x, size_t n, double q)
{
    double *s = malloc((n ? n : 1) * sizeof *s);
    if (!s)
        return NAN;
    size_t m = 0;
    for (size_t i = 0; i < n; ++i)
        if (isfinite(x[i]))
            s[m++] = x[i];
    double v = NAN;
    if (m) {
        qsort(s, m, sizeof *s, cmp_double);
        const double pos = q * (double)(m - 1);
        size_t i0 = (size_t)floor(pos);
        if (i0 >= m - 1)
            v = s[m - 1];
        else
            v = s[i0] + (pos - (double)i0) * (s[i0 + 1] - s[i0]);
    }
    free(s);
    return v;
}

size_t gf_stats_mser(const double *x, size_t n, int batch)
{
    if (batch < 1)
        batch = 1;
    const size_t nb = n / (size_t)batch;
    if (nb < 4)
        return 0;
    double *b = malloc(nb * sizeof *b);
    if (!b)
        return 0;
    for (size_t k = 0; k < nb; ++k) {
        double s = 0;
        for (int j = 0; j < batch; ++j)
            s += x[k * (size_t)batch + (size_t)j];
        b[k] = s / batch;
    }
    /* suffix sums give every MSER(d) in O(nb) */
    double best = INFINITY;
    size_t best_d = 0, m = 0;
    double s1 = 0, s2 = 0;
    double *crit = malloc(nb * sizeof *crit);
    if (!crit) {
        free(b);
        return 0;
    }
    for (size_t k = nb; k-- > 0;) {
        s1 += b[k];
        s2 += b[k] * b[k];
        ++m;
        const double mean = s1 / (double)m;
        crit[k] = (s2 - (double)m * mean * mean) / ((double)m * (double)m);
    }
    for (size_t d = 0; d <= nb / 2; ++d)
        if (crit[d] < best) {
            best = crit[d];
            best_d = d;
        }
    free(crit);
    free(b);
    return best_d * (size_t)batch;
}

double gf_stats_block_sem(const double *x, size_t n)
{
    if (n < 2)
        return NAN;
    double *b = malloc(n * sizeof *b);
    if (!b)
        return NAN;
    memcpy(b, x, n * sizeof *b);
    size_t m = n;
    double chosen = NAN, largest = NAN;
    double prev_se = NAN, prev_err = NAN;
    while (m >= 8) {
        double mean, sd;
        gf_stats_mean_std(b, m, &mean, &sd);
        /* sd uses (m - 1); the standard error of the mean of m block means */
        const double se = sd / sqrt((double)m);
        const double err = se / sqrt(2.0 * (double)(m - 1));
        if (!isfinite(largest) || se > largest)
            largest = se;
        if (isfinite(prev_se) && !isfinite(chosen) && se <= prev_se + prev_err)
            chosen = prev_se;
        prev_se = se;
        prev_err = err;
        for (size_t i = 0; i < m / 2; ++i)
            b[i] = 0.5 * (b[2 * i] + b[2 * i + 1]);
        m /= 2;
    }
    free(b);
    if (!isfinite(largest)) {
        double mean, sd;
        gf_stats_mean_std(x, n, &mean, &sd);
        return sd / sqrt((double)n);
    }
    return isfinite(chosen) ? chosen : largest;
}

void gf_stats_steady(const double *t, const double *x, size_t n, gf_steady *out)
{
    memset(out, 0, sizeof *out);
    out->mean = out->std = out->sem = out->drift_rel = out->t_start_s = NAN;
    /* trailing non-finite samples (unwritten records) are dropped */
    while (n > 0 && !isfinite(x[n - 1]))
        --n;
    if (n < 10)
        return;
    size_t d = gf_stats_mser(x, n, 5);
    out->i_start = d;
    out->t_start_s = t[d];
    gf_stats_mean_std(x + d, n - d, &out->mean, &out->std);
    out->sem = gf_stats_block_sem(x + d, n - d);
    double a, b;
    if (gf_stats_linfit(t + d, x + d, n - d, &a, &b) && out->mean != 0.0)
        out->drift_rel = b * (t[n - 1] - t[d]) / fabs(out->mean);
    out->ok = 1;
}

double gf_stats_settle_time(const double *t, const double *x, size_t n, double band)
{
    while (n > 0 && !isfinite(x[n - 1]))
        --n;
    if (n == 0)
        return NAN;
    const double final = x[n - 1];
    size_t k = n - 1;
    while (k > 0 && fabs(x[k - 1] - final) <= band)
        --k;
    return t[k];
}

double gf_stats_first_reaching(const double *t, const double *x, size_t n, double level)
{
    for (size_t k = 0; k < n; ++k) {
        if (!(x[k] >= level))
            continue;
        if (k == 0 || !isfinite(x[k - 1]) || x[k] == x[k - 1])
            return t[k];
        return t[k - 1] + (t[k] - t[k - 1]) * (level - x[k - 1]) / (x[k] - x[k - 1]);
    }
    return NAN;
}
