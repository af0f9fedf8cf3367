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
 *    on bins of d/2: b to 1e-9; a flat profile has no Gaussian (NaN);
 *  - replicates: a study of Q against phi_out drawn with two seeds, each
 *    pair scattered about the line by +-delta, is fitted through the pairs'
 *    means (R^2 = 1, silo_replicates 2), while a run whose spec differs by
 *    more than its seed stays a point of its own (R^2 < 1).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

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

/* A run directory whose run.yaml differs from its study's only where asked. */
static void silo_row(gf_post_row *row, const char *root, int k, double e_n, int seed, double end_time, double phi,
                     double Q_nd)
{
    char dir[512], p[600];
    snprintf(dir, sizeof dir, "%s/run%02d", root, k);
    mkdir(dir, 0700);
    snprintf(p, sizeof p, "%s/run.yaml", dir);
    FILE *f = fopen(p, "w");
    GF_CHECK(f != NULL);
    if (f) {
        fprintf(f, "# resolved spec of run%02d\nname: silo_restitution\nseed: %d\nend_time: %g\nscene:\n"
                   "  name: silo\ncontact:\n  restitution: %g\n  friction: 0.5\n",
                k, seed, end_time, e_n);
        fclose(f);
    }
    gf_post_row_init(row, dir);
    gf_post_row_set(row, "silo_D_over_d", 6.0);
    gf_post_row_set(row, "silo_H_over_d", 15.0);
    gf_post_row_set(row, "silo_Q", Q_nd * 140.07);
    gf_post_row_set(row, "silo_Q_nd", Q_nd);
    gf_post_row_set(row, "silo_phi_out", phi);
}

static void test_replicates(void)
{
    char root[] = "/tmp/gf_silo_replicates_XXXXXX";
    GF_CHECK(mkdtemp(root) != NULL);
    enum { N = 7 };
    gf_post_row *rows = calloc(N, sizeof *rows);
    const double e_n[3] = {0.1, 0.5, 0.9}, phi[3] = {0.394, 0.390, 0.385}, delta = 0.3;
    for (int i = 0; i < 3; ++i) /* Q sqrt(d/g) = 32 + 400 (phi - 0.39) on the pairs' means */
        for (int s = 0; s < 2; ++s)
            silo_row(&rows[2 * i + s], root, 2 * i + s, e_n[i], s + 1, 600.0, phi[i],
                     32.0 + 400.0 * (phi[i] - 0.39) + (s ? -delta : delta));
    gf_silo_campaign_fits(rows, 2 * 3);
    GF_CHECK_ABS(gf_post_row_get(&rows[0], "Q_phi_R2"), 1.0, 1e-12);
    GF_CHECK_REL(gf_post_row_get(&rows[5], "Q_phi_slope"), 400.0, 1e-9);
    GF_CHECK_ABS(gf_post_row_get(&rows[3], "silo_replicates"), 2.0, 0.0);
    /* a shorter run of e_n = 0.1 is another experiment: a point of its own, off the line */
    silo_row(&rows[6], root, 6, 0.1, 3, 120.0, 0.394, 32.0 + 400.0 * 0.004 + 1.0);
    gf_silo_campaign_fits(rows, N);
    GF_CHECK_ABS(gf_post_row_get(&rows[6], "silo_replicates"), 1.0, 0.0);
    GF_CHECK(gf_post_row_get(&rows[0], "Q_phi_R2") < 0.99);
    free(rows);
    gf_test_remove_tree(root);
}

int main(void)
{
    test_beverloo();
    test_saturation();
    test_gaussian();
    test_replicates();
    return gf_test_finish();
}
