/* Largest resolved rate of a sampled series; method and sources in gf_post_rate.h. */
#include "stages/gf_post_rate.h"

#include <math.h>
#include <stdlib.h>

/* Running sums of a window, about the origin (t0, x0) of its first sample
 * (keeps the centred sums accurate when t is large, e.g. seconds since 2000). */
typedef struct sums {
    double m, st, sx, stt, stx, sxx;
} sums;

static void add(sums *s, double t, double x)
{
    s->m += 1.0, s->st += t, s->sx += x, s->stt += t * t, s->stx += t * x, s->sxx += x * x;
}

/* Slope of the window and S_tt; 0 when it cannot give one. */
static int fit(const sums *s, double *b, double *ctt)
{
    if (s->m < 3.0)
        return 0;
    *ctt = s->stt - s->st * s->st / s->m;
    if (!(*ctt > 0.0))
        return 0;
    *b = (s->stx - s->st * s->sx / s->m) / *ctt;
    return 1;
}

/* The scatter of the samples about a smooth curve, from their second
 * differences (x_{k+1} - 2 x_k + x_{k-1} has variance 6 s^2 for independent
 * errors of variance s^2). One value for the whole series, so that no window
 * is chosen for a lucky residual. */
static double scatter(const double *x, size_t n)
{
    double sum = 0.0;
    size_t m = 0;
    for (size_t k = 1; k + 1 < n; ++k) {
        double d2 = x[k + 1] - 2.0 * x[k] + x[k - 1];
        if (isfinite(d2))
            sum += d2 * d2, ++m;
    }
    return m ? sqrt(sum / (6.0 * (double)m)) : 0.0;
}

/* Uncertainty of the steepest of n_indep windows' slopes: the scatter s
 * over S_tt, times sqrt(1 + 2 ln n_indep) because the steepest of n_indep
 * independent noisy slopes exceeds the true one by up to sqrt(2 ln n_indep)
 * standard errors (the expected maximum of n_indep standard normals, e.g.
 * David & Nagaraja, Order Statistics, 3rd ed. 2003, §4.4); and the rounding
 * of positions to steps of q, which is not independent from sample to sample
 * (a slow front stays in one bin for many samples) and bounds the slope only
 * through the window's ends, q / T. */
static double sigma_of(double s, double ctt, double q, double T, double n_indep)
{
    double rounding = T > 0.0 ? q / T : INFINITY;
    double selection = 1.0 + 2.0 * log(fmax(n_indep, 1.0));
    return sqrt(s * s / ctt * selection + rounding * rounding);
}

/* Steepest window of w finite samples: its slope, sigma, centre, duration. */
static gf_rate_estimate steepest(const double *t, const double *x, size_t n, size_t w, double s, double q)
{
    gf_rate_estimate best = {NAN, NAN, NAN, NAN, 0};
    for (size_t i = 0; i < n; ++i) {
        if (!isfinite(t[i]) || !isfinite(x[i]))
            continue;
        sums acc = {0};
        size_t j = i;
        for (; j < n && acc.m < (double)w; ++j)
            if (isfinite(t[j]) && isfinite(x[j]))
                add(&acc, t[j] - t[i], x[j] - x[i]);
        double b, ctt;
        if (acc.m < (double)w || !fit(&acc, &b, &ctt))
            break;   /* fewer than w samples left */
        if (!(b <= best.rate))
            best = (gf_rate_estimate){b, sigma_of(s, ctt, q, t[j - 1] - t[i], (double)n / (double)w),
                                      0.5 * (t[i] + t[j - 1]), t[j - 1] - t[i], w};
    }
    return best;
}

gf_rate_estimate gf_rate_max_resolved(const double *t, const double *x, size_t n, double q, double rel)
{
    const double s = q > 0.0 ? 0.0 : scatter(x, n);
    for (size_t w = GF_RATE_MIN_SAMPLES; w <= n; ++w) {
        gf_rate_estimate e = steepest(t, x, n, w, s, q);
        if (isnan(e.rate))
            break;
        if (e.rate > 0.0 && e.sigma <= rel * e.rate)
            return e;
    }
    return (gf_rate_estimate){NAN, NAN, NAN, NAN, 0};
}
