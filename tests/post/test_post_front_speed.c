/*
 * Front speed from sampled front positions (gf_post_rate.h) against fronts
 * of known speed, sampled as the engine and the deposit stage sample them:
 *  - constant speeds U = 20, 22 and 25 mm/s read, as the column_collapse
 *    diagnostic front_position is, as the upper edge of the bin of D = 7.6 mm
 *    holding the front, every sqrt(D/g) = 27.8 ms: the estimates must be
 *    within 5 % of U and within 3 standard errors, and tell the three apart
 *    (the former fixed five-sample slope gave steps of D / (5 dt));
 *  - a tanh front of known peak speed dR / (2 tau), continuous (the grains'
 *    toe) and in bins of D;
 *  - a front that advances 1.5 D over the record: not resolved (NaN);
 *  - a continuous front with grain-scale jitter (uniform +-D/4): within 3 sigma.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gf_test.h"
#include "stages/gf_post_rate.h"

enum { NT = 300 };
static const double D = 7.6e-3, DT = 0.0278, R0 = 10 * 7.6e-3, REL = 0.1;

static double binned(double x) { return (floor(x / D) + 1.0) * D; }

static void test_constant_speeds_in_bins(void)
{
    static double t[NT], x[NT];
    const double U[3] = {0.020, 0.022, 0.025};
    double est[3];
    for (int k = 0; k < 3; ++k) {
        for (int i = 0; i < NT; ++i) {
            t[i] = i * DT;
            x[i] = binned(R0 + 0.3 * D + U[k] * t[i]);
        }
        gf_rate_estimate e = gf_rate_max_resolved(t, x, NT, D, REL);
        est[k] = e.rate;
        printf("binned front U = %.4f m/s: estimate %.5f +- %.5f m/s (error %+.2f %%, %.1f sigma), window %.3f s "
               "(%zu samples)\n",
               U[k], e.rate, e.sigma, 100.0 * (e.rate / U[k] - 1.0), (e.rate - U[k]) / e.sigma, e.window,
               e.n_samples);
        GF_CHECK_REL(e.rate, U[k], 0.05);
        GF_CHECK(fabs(e.rate - U[k]) <= 3.0 * e.sigma);
    }
    GF_CHECK(est[0] < est[1] && est[1] < est[2]);
}

static void tanh_front(double *t, double *x, int quantise, double tau, double dR)
{
    for (int i = 0; i < NT; ++i) {
        t[i] = i * DT;
        double xf = R0 + dR * 0.5 * (1.0 + tanh((t[i] - 0.5 * NT * DT) / tau));
        x[i] = quantise ? binned(xf) : xf;
    }
}

static void test_tanh_front(void)
{
    static double t[NT], x[NT];
    const double tau = 1.0, dR = 1.5 * R0, umax = dR / (2.0 * tau);
    tanh_front(t, x, 0, tau, dR);
    gf_rate_estimate c = gf_rate_max_resolved(t, x, NT, 0.0, REL);
    tanh_front(t, x, 1, tau, dR);
    gf_rate_estimate b = gf_rate_max_resolved(t, x, NT, D, REL);
    printf("tanh front, peak %.5f m/s: continuous %.5f (error %+.2f %%), bins of D %.5f +- %.5f (error %+.2f %%, "
           "window %.2f tau)\n",
           umax, c.rate, 100.0 * (c.rate / umax - 1.0), b.rate, b.sigma, 100.0 * (b.rate / umax - 1.0),
           b.window / tau);
    GF_CHECK_REL(c.rate, umax, 0.01);
    GF_CHECK_REL(b.rate, umax, 0.10);
}

static void test_unresolved_front(void)
{
    static double t[NT], x[NT];
    for (int i = 0; i < NT; ++i) {
        t[i] = i * DT;
        x[i] = binned(R0 + 1.5 * D * i / (NT - 1.0));
    }
    gf_rate_estimate e = gf_rate_max_resolved(t, x, NT, D, REL);
    printf("front advancing 1.5 D in bins of D: %g (not resolved)\n", e.rate);
    GF_CHECK(isnan(e.rate));
}

static void test_jittered_front(void)
{
    static double t[NT], x[NT];
    const double U = 0.02;
    srand(7);
    for (int i = 0; i < NT; ++i) {
        t[i] = i * DT;
        x[i] = R0 + U * t[i] + 0.5 * D * ((double)rand() / RAND_MAX - 0.5);
    }
    gf_rate_estimate e = gf_rate_max_resolved(t, x, NT, 0.0, REL);
    printf("jittered front U = %.4f m/s: estimate %.5f +- %.5f (error %+.2f %%, %.1f sigma)\n", U, e.rate, e.sigma,
           100.0 * (e.rate / U - 1.0), (e.rate - U) / e.sigma);
    GF_CHECK(fabs(e.rate - U) <= 3.0 * e.sigma);
}

int main(void)
{
    test_constant_speeds_in_bins();
    test_tanh_front();
    test_unresolved_front();
    test_jittered_front();
    return gf_test_finish();
}
