/*
 * The largest rate dx/dt that a sampled series resolves: the front speed of
 * a collapse from its positions.
 *
 * Why not the steepest line over a fixed number of samples: a front read in
 * bins of D at output intervals dt moves in steps of D, and over a few
 * samples its slope can only take values k D / (w dt); four immersed runs of
 * one campaign then report the same speed to six digits. Here every window
 * of consecutive samples has a least-squares slope b with its standard error
 *
 *     sigma_b = s / sqrt(S_tt),  S_tt = sum (t_k - t_mean)^2,
 *
 * where s is the larger of the residual scatter about the line
 * (sqrt(SSR / (m - 2)), m samples) and the resolution of x, q / sqrt(12)
 * (the standard deviation of a uniform rounding error over a step q; q = 0
 * for a continuous x). From each start the window grows from
 * GF_RATE_MIN_SAMPLES samples until sigma_b <= rel * b: the shortest window
 * that resolves its slope to rel. The largest slope so resolved is the
 * estimate, reported with its sigma_b, window centre and duration. A series
 * that never resolves a positive slope (a front that moves less than a few q
 * over the whole record) gives no estimate (NaN) rather than a number made of
 * its bins. Standard errors of least-squares slopes: e.g. Press et al.,
 * Numerical Recipes, 3rd ed. (2007), §15.2, eq. (15.2.9).
 */
#ifndef GF_POST_RATE_H
#define GF_POST_RATE_H

#include <stddef.h>

enum { GF_RATE_MIN_SAMPLES = 5 };

typedef struct gf_rate_estimate {
    double rate;      /* largest resolved slope (x units per t unit), NaN if none */
    double sigma;     /* its standard error */
    double t_at;      /* centre of its window */
    double window;    /* duration of its window */
    size_t n_samples; /* samples in its window */
} gf_rate_estimate;

/* t increasing; non-finite samples are skipped. q >= 0, rel in (0, 1). */
gf_rate_estimate gf_rate_max_resolved(const double *t, const double *x, size_t n, double q, double rel);

#endif
