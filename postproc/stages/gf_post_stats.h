/*
 * Statistics shared by the stages (pure functions on arrays).
 *
 * Steady state: MSER (marginal standard error rule; White, Simulation 69
 * (1997) 323; White, Cobb & Spratt, WSC 2000). The truncation index d
 * minimises  MSER(d) = sum_{i>=d} (x_i - mean_d)^2 / (n - d)^2  over
 * d <= n/2, computed on batch means of 5 samples (MSER-5): it removes the
 * initial transient that would bias the mean while keeping as many samples
 * as possible. The steady start is the time of the first kept sample.
 *
 * Uncertainty of a time average of correlated samples: block averaging
 * (Flyvbjerg & Petersen, J. Chem. Phys. 91 (1989) 461). Pairs of samples are
 * averaged repeatedly; the naive standard error s_k / sqrt(n_k - 1) of the
 * level-k block means grows with k while blocks are shorter than the
 * correlation time and reaches a plateau once they are longer. The estimate
 * is the first level whose successor does not exceed it by more than its own
 * statistical error s_k / sqrt(2 (n_k - 1)); the largest estimate with at
 * least 8 blocks if no plateau is reached (conservative).
 */
#ifndef GF_POST_STATS_H
#define GF_POST_STATS_H

#include <stddef.h>

/* Mean and standard deviation (n - 1) of the finite values. */
void gf_stats_mean_std(const double *x, size_t n, double *mean, double *std);
/* Least-squares line y = a + b x; returns 0 if fewer than 2 points. */
int gf_stats_linfit(const double *x, const double *y, size_t n, double *a, double *b);
/* q-quantile (0..1) by linear interpolation of the sorted values; NaN if n == 0. Does not modify x. */
double gf_stats_quantile(const double *x, size_t n, double q);

/* MSER-batch truncation index (in samples) of the series x[0..n). */
size_t gf_stats_mser(const double *x, size_t n, int batch);
/* Block-averaging standard error of the mean of x[0..n). */
double gf_stats_block_sem(const double *x, size_t n);

/* Steady window of a series: detection (MSER-5), mean, std, standard error, drift. */
typedef struct gf_steady {
    size_t i_start;       /* first sample of the steady window */
    double t_start_s;     /* its time */
    double mean, std, sem;
    double drift_rel;     /* (slope of a line fit over the window) x (window length) / |mean| */
    int ok;               /* 0 when fewer than 10 finite samples */
} gf_steady;
void gf_stats_steady(const double *t, const double *x, size_t n, gf_steady *out);

/* Earliest t_k such that |x_j - x_{n-1}| <= band for every j >= k. */
double gf_stats_settle_time(const double *t, const double *x, size_t n, double band);

/* First time x reaches level, linear between the samples that bracket it; NAN when it never does. */
double gf_stats_first_reaching(const double *t, const double *x, size_t n, double level);

#endif
