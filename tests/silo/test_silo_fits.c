/*
 * The silo's campaign fits on data drawn from the laws themselves (exact to
 * round-off) and with a known perturbation:
 *  - Beverloo (Beverloo et al. 1961; Djouwe Meffeja 2012 (3.16)): Q sqrt(d/g) =
 *    C 0.5 (6/pi) (D/d - k)^(5/2) at the thesis' k = 1.47, C = 1.7 over
 *    D = 4-18 d gives back k and C to 1e-10 and R^2 = 1; the thesis' own
 *    table value Q(6 d) = 70.9 sqrt(g/d) to its printed digits;
 *  - saturation Q = Q0 (1 - exp(-H/H0)), H0 = 5.7 d (thesis §3.4.1): H0 and
 *    Q0 to 1e-6 (golden section), R^2 = 1; too few heights refused;
 *  - Gaussian A exp(-(x - xc)^2 / (4 b z)) (Nedderman & Tuzun 1979) sampled
 *    on bins of d/2: b to 1e-9; a flat profile has no Gaussian (NaN).
 */
#include <math.h>

#include "gf_test.h"
#include "stages/gf_silo_flow.h"

static double beverloo(double D, double k, double C) { return C * 0.5 * 6.0 / M_PI * pow(D - k, 2.5); }

static void test_beverloo(void)
{
    double D[8], Q[8], k = 0, C = 0, R2 = 0;
    for (int i = 0; i < 8; ++i)
        D[i] = 4.0 + 2.0 * i, Q[i] = beverloo(D[i], 1.47, 1.7);
    GF_CHECK(gf_silo_fit_beverloo(D, Q, 8, &k, &C, &R2));
    GF_CHECK_ABS(k, 1.47, 1e-10);
    GF_CHECK_REL(C, 1.7, 1e-10);
    GF_CHECK_ABS(R2, 1.0, 1e-12);
    GF_CHECK_ABS(beverloo(6.0, 1.47, 1.7), 70.9, 0.05);
    GF_CHECK(!gf_silo_fit_beverloo(D, Q, 2, &k, &C, &R2));
}

static void test_saturation(void)
{
    double H[6] = {4, 6, 9, 13, 18, 25.4}, Q[6], Q0 = 0, H0 = 0, R2 = 0;
    for (int i = 0; i < 6; ++i)
        Q[i] = 1e4 * (1.0 - exp(-H[i] / 5.7));
    GF_CHECK(gf_silo_fit_saturation(H, Q, 6, &Q0, &H0, &R2));
    GF_CHECK_REL(H0, 5.7, 1e-6);
    GF_CHECK_REL(Q0, 1e4, 1e-6);
    GF_CHECK_ABS(R2, 1.0, 1e-9);
    GF_CHECK(!gf_silo_fit_saturation(H, Q, 2, &Q0, &H0, &R2));
}

static void test_gaussian(void)
{
    enum { N = 50 };
    const double d = 5e-4, z = 3.0 * d, b = 0.8 * d, xc = 12.5 * d;
    double x[N], v[N], R2 = 0;
    for (int i = 0; i < N; ++i) {
        x[i] = (i + 0.5) * 0.5 * d;
        v[i] = 0.2 * exp(-(x[i] - xc) * (x[i] - xc) / (4.0 * b * z));
    }
    GF_CHECK_REL(gf_silo_fit_gaussian(x, v, N, z, &R2), b, 1e-9);
    GF_CHECK_ABS(R2, 1.0, 1e-12);
    for (int i = 0; i < N; ++i)
        v[i] = 0.1;
    GF_CHECK(isnan(gf_silo_fit_gaussian(x, v, N, z, &R2)));
}

int main(void)
{
    test_beverloo();
    test_saturation();
    test_gaussian();
    return gf_test_finish();
}
