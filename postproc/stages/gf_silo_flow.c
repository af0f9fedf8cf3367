/*
 * Silo discharge: steady flow rate of a run and the campaign laws
 * (gf_silo_flow.h).
 */
#include "stages/gf_silo_flow.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stages/gf_post_replicates.h"
#include "stages/gf_post_stats.h"
#include "stages/gf_stage_util.h"


static double window_mean(const double *x, size_t i0, size_t n)
{
    double m, sd;
    gf_stats_mean_std(x + i0, n - i0, &m, &sd);
    return m;
}

gf_status gf_silo_flow_rate(gf_ctx *ctx, const gf_stage_in *in, gf_stage_out *out)
{
    gf_ncr f;
    GF_TRY(gf_stage_open(ctx, in, "diagnostics.nc", &f));
    const char *names[5] = {"time", "discharge_rate", "discharge_mass_rate", "orifice_packing_fraction", "fill_height"};
    double *v[5] = {NULL};
    size_t len[5] = {0};
    gf_status st = GF_OK;
    for (int k = 0; k < 5 && st == GF_OK; ++k) {
        st = gf_ncr_var_1d(ctx, &f, names[k], &v[k], &len[k]);
        if (st == GF_OK && len[k] != len[0])
            st = GF_FAIL(ctx, GF_ERR_IO, "%s: %s has %zu samples, time %zu", f.path, names[k], len[k], len[0]);
    }
    const double d = gf_ncr_att_double_or(&f, "grain_diameter_m", NAN), g = gf_ncr_att_double_or(&f, "gravity_m_s2", NAN);
    const double ax = gf_ncr_att_double_or(&f, "scene_param_orifice_x_over_d", NAN);
    const double az = gf_ncr_att_double_or(&f, "scene_param_orifice_z_over_d", NAN);
    gf_steady s = {0};
    if (st == GF_OK && len[0] > 1) /* the first record has no rate (no interval before it) */
        gf_stats_steady(v[0] + 1, v[1] + 1, len[0] - 1, &s);
    if (st == GF_OK && !s.ok)
        st = GF_FAIL(ctx, GF_ERR_IO, "%s: discharge_rate has %zu samples, at least 10 needed for a steady window",
                     f.path, len[0]);
    if (st == GF_OK) {
        gf_post_row *row = out->row;
        size_t i0 = s.i_start + 1, n = len[0];
        gf_post_row_set(row, "silo_D_over_d", 2.0 * ax * az / (ax + az));
        gf_post_row_set(row, "silo_H_over_d", window_mean(v[4], i0, n) / d);
        gf_post_row_set(row, "silo_Q", s.mean);
        gf_post_row_set(row, "silo_Q_sem", s.sem);
        gf_post_row_set(row, "silo_Q_mass", window_mean(v[2], i0, n));
        gf_post_row_set(row, "silo_Q_nd", s.mean * sqrt(d / g));
        gf_post_row_set(row, "silo_phi_out", window_mean(v[3], i0, n));
        gf_post_row_set(row, "silo_t_steady_s", s.t_start_s);
    }
    for (int k = 0; k < 5; ++k)
        free(v[k]);
    gf_ncr_close(&f);
    return st;
}

/* Coefficient of determination of predictions p for y. */
static double r_squared(const double *y, const double *p, int n)
{
    double m = 0.0, ss_tot = 0.0, ss_res = 0.0;
    for (int i = 0; i < n; ++i)
        m += y[i] / n;
    for (int i = 0; i < n; ++i)
        ss_tot += (y[i] - m) * (y[i] - m), ss_res += (y[i] - p[i]) * (y[i] - p[i]);
    return ss_tot > 0.0 ? 1.0 - ss_res / ss_tot : NAN;
}

static int distinct(const double *x, int n, double apart)
{
    int m = 0;
    for (int i = 0; i < n; ++i) {
        int seen = 0;
        for (int j = 0; j < i; ++j)
            seen |= fabs(x[i] - x[j]) < apart;
        m += !seen;
    }
    return m;
}

int gf_silo_fit_beverloo(const double *D_over_d, const double *Q_nd, int n, double *k, double *C, double *R2)
{
    if (n < 3 || distinct(D_over_d, n, 1e-9) < 3)
        return 0;
    double *y = malloc(2 * (size_t)n * sizeof *y), a, b;
    if (!y)
        return 0;
    double *p = y + n;
    for (int i = 0; i < n; ++i)
        y[i] = pow(Q_nd[i], 0.4);
    int ok = gf_stats_linfit(D_over_d, y, (size_t)n, &a, &b) && b > 0.0;
    if (ok) {
        for (int i = 0; i < n; ++i)
            p[i] = a + b * D_over_d[i];
        *k = -a / b;
        *C = pow(b, 2.5) / (0.5 * 6.0 / M_PI); /* rho_n d^3 = phi 6/pi, phi = 0.5 (thesis §3.4.2) */
        *R2 = r_squared(y, p, n);
    }
    free(y);
    return ok;
}

/* Least-squares Q0 at a given H0, and the residual sum of squares. */
static double saturation_rss(const double *H, const double *Q, int n, double H0, double *Q0)
{
    double sfq = 0.0, sff = 0.0, rss = 0.0;
    for (int i = 0; i < n; ++i) {
        double f = 1.0 - exp(-H[i] / H0);
        sfq += f * Q[i], sff += f * f;
    }
    *Q0 = sff > 0.0 ? sfq / sff : NAN;
    for (int i = 0; i < n; ++i) {
        double r = Q[i] - *Q0 * (1.0 - exp(-H[i] / H0));
        rss += r * r;
    }
    return rss;
}

int gf_silo_fit_saturation(const double *H, const double *Q, int n, double *Q0, double *H0, double *R2)
{
    double hmin = INFINITY;
    for (int i = 0; i < n; ++i)
        hmin = fmin(hmin, H[i]);
    if (n < 3 || !(hmin > 0.0) || distinct(H, n, 1e-6 * hmin) < 3)
        return 0;
    /* golden section on log H0 over [hmin / 100, 100 hmin]: one minimum for data that saturate */
    const double phi = 0.5 * (sqrt(5.0) - 1.0);
    double lo = log(hmin / 100.0), hi = log(100.0 * hmin), q;
    for (int it = 0; it < 200 && hi - lo > 1e-10; ++it) {
        double x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo);
        if (saturation_rss(H, Q, n, exp(x1), &q) < saturation_rss(H, Q, n, exp(x2), &q))
            hi = x2;
        else
            lo = x1;
    }
    *H0 = exp(0.5 * (lo + hi));
    saturation_rss(H, Q, n, *H0, Q0);
    double *p = malloc((size_t)n * sizeof *p);
    if (!p)
        return 0;
    for (int i = 0; i < n; ++i)
        p[i] = *Q0 * (1.0 - exp(-H[i] / *H0));
    *R2 = r_squared(Q, p, n);
    free(p);
    return 1;
}

/* The campaign's points: one per replicate set of silo runs (gf_post_replicates.h),
 * the mean of its runs' D, Q, H and phi_out, and count[p] runs in it. On return
 * set[i] is row i's point, -1 for a row without a steady discharge. point_of
 * is scratch of n_rows. Returns the number of points, -1 when out of memory. */
static int silo_points(gf_post_row *rows, int n_rows, int *set, int *point_of, double *D, double *Qnd, double *H,
                       double *Q, double *phi, int *count)
{
    if (gf_post_replicate_groups(rows, n_rows, set) < 0)
        return -1;
    int n = 0;
    for (int i = 0; i < n_rows; ++i)
        point_of[i] = -1;
    for (int i = 0; i < n_rows; ++i) {
        const gf_post_row *r = &rows[i];
        const int first = set[i]; /* still the first run of i's set: only rows before i are rewritten */
        if (!isfinite(gf_post_row_get(r, "silo_Q_nd"))) {
            set[i] = -1;
            continue;
        }
        if (point_of[first] < 0) {
            point_of[first] = n++;
            int p = point_of[first];
            D[p] = Qnd[p] = H[p] = Q[p] = phi[p] = 0.0, count[p] = 0;
        }
        const int p = set[i] = point_of[first];
        D[p] += gf_post_row_get(r, "silo_D_over_d"), Qnd[p] += gf_post_row_get(r, "silo_Q_nd");
        H[p] += gf_post_row_get(r, "silo_H_over_d"), Q[p] += gf_post_row_get(r, "silo_Q");
        phi[p] += gf_post_row_get(r, "silo_phi_out");
        ++count[p];
    }
    for (int p = 0; p < n; ++p)
        D[p] /= count[p], Qnd[p] /= count[p], H[p] /= count[p], Q[p] /= count[p], phi[p] /= count[p];
    return n;
}

void gf_silo_campaign_fits(gf_post_row *rows, int n_rows)
{
    double *buf = calloc(5 * (size_t)(n_rows + 1), sizeof *buf);
    int *set = malloc(3 * (size_t)(n_rows + 1) * sizeof *set);
    if (!buf || !set) {
        free(buf), free(set);
        return;
    }
    double *D = buf, *Qnd = D + n_rows + 1, *H = Qnd + n_rows + 1, *Q = H + n_rows + 1, *phi = Q + n_rows + 1;
    int *count = set + n_rows + 1, *point_of = count + n_rows + 1;
    const int n = silo_points(rows, n_rows, set, point_of, D, Qnd, H, Q, phi, count);
    if (n < 0) {
        free(buf), free(set);
        return;
    }
    double k = NAN, C = NAN, R2b = NAN, Q0 = NAN, H0 = NAN, R2s = NAN, a, b = NAN, R2q = NAN;
    if (!gf_silo_fit_beverloo(D, Qnd, n, &k, &C, &R2b))
        k = C = R2b = NAN;
    if (!(distinct(D, n, 1e-9) == 1 && distinct(H, n, 1.0) >= 3 && gf_silo_fit_saturation(H, Q, n, &Q0, &H0, &R2s)))
        Q0 = H0 = R2s = NAN;
    if (n >= 3 && distinct(D, n, 1e-9) == 1 && gf_stats_linfit(phi, Qnd, (size_t)n, &a, &b)) {
        double *p = H; /* reused: the saturation fit is done */
        for (int j = 0; j < n; ++j)
            p[j] = a + b * phi[j];
        R2q = r_squared(Qnd, p, n);
    } else {
        b = NAN;
    }
    for (int i = 0; i < n_rows; ++i) {
        if (set[i] < 0)
            continue;
        gf_post_row *r = &rows[i];
        gf_post_row_set(r, "silo_replicates", count[set[i]]);
        if (isfinite(k))
            gf_post_row_set(r, "beverloo_k", k), gf_post_row_set(r, "beverloo_C", C),
                gf_post_row_set(r, "beverloo_R2", R2b);
        if (isfinite(H0))
            gf_post_row_set(r, "saturation_Q0", Q0), gf_post_row_set(r, "saturation_H0_over_d", H0),
                gf_post_row_set(r, "saturation_R2", R2s);
        if (isfinite(b))
            gf_post_row_set(r, "Q_phi_slope", b), gf_post_row_set(r, "Q_phi_R2", R2q);
    }
    free(buf), free(set);
}
