/* Measurement helpers shared by the scenes; see gf_measure.h for the definitions. */
#include "scenes/gf_measure.h"

#include "particles/gf_packing.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Volume of a sphere below height t measured from its bottom (0 <= t <= 2r): cap pi t^2 (3r - t)/3. */
static double cap_below(double r, double t)
{
    if (t <= 0.0)
        return 0.0;
    if (t >= 2.0 * r)
        return 4.0 / 3.0 * M_PI * r * r * r;
    return M_PI * t * t * (3.0 * r - t) / 3.0;
}

double gf_measure_sphere_slab_volume_m3(double yc, double r, double y0, double y1)
{
    if (y1 <= y0)
        return 0.0;
    double bottom = yc - r;
    return cap_below(r, y1 - bottom) - cap_below(r, y0 - bottom);
}

static int mobile(const gf_particles *p, size_t i)
{
    return !(p->flags[i] & GF_P_GLUED);
}

double gf_measure_solid_fraction_box(const gf_particles *p, const gf_measure_domain *dom, const double lo[3],
                                     const double hi[3], double h, int include_glued)
{
    return gf_packing_solid_fraction_box(p, dom->lo_m, dom->hi_m, dom->periodic, lo, hi, h, include_glued);
}

gf_status gf_measure_profile_y(gf_ctx *ctx, const gf_particles *p, const gf_measure_domain *dom, double y0,
                               double dy, int n_slabs, double *phi, double *u)
{
    if (n_slabs < 1 || !(dy > 0.0))
        return GF_FAIL(ctx, GF_ERR_ARG, "measure: profile needs n_slabs >= 1 and dy > 0 (got %d, %g m)", n_slabs, dy);
    double area = (dom->hi_m[0] - dom->lo_m[0]) * (dom->hi_m[2] - dom->lo_m[2]);
    double *vol = calloc((size_t)n_slabs * 4, sizeof *vol);
    if (!vol)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "measure: cannot allocate %d slabs", n_slabs);
    double *mom = vol + n_slabs;
    for (size_t i = 0; i < p->n_local; ++i) {
        if (!mobile(p, i))
            continue;
        double r = p->radius_m[i], yc = p->y_m[i];
        int k0 = (int)floor((yc - r - y0) / dy), k1 = (int)floor((yc + r - y0) / dy);
        if (k0 < 0)
            k0 = 0;
        if (k1 > n_slabs - 1)
            k1 = n_slabs - 1;
        double v[3] = {p->vx_m_s[i], p->vy_m_s[i], p->vz_m_s[i]};
        for (int k = k0; k <= k1; ++k) {
            double w = gf_measure_sphere_slab_volume_m3(yc, r, y0 + k * dy, y0 + (k + 1) * dy);
            vol[k] += w;
            for (int c = 0; c < 3; ++c)
                mom[3 * k + c] += w * v[c];
        }
    }
    for (int k = 0; k < n_slabs; ++k) {
        if (phi)
            phi[k] = vol[k] / (area * dy);
        if (u)
            for (int c = 0; c < 3; ++c)
                u[3 * k + c] = vol[k] > 0.0 ? mom[3 * k + c] / vol[k] : NAN;
    }
    free(vol);
    return GF_OK;
}

gf_status gf_measure_stress_planes(gf_ctx *ctx, const gf_particles *p, const gf_measure_domain *dom, double y0,
                                   double dy, int n, double *tau, double *sig)
{
    if (n < 1 || !(dy > 0.0))
        return GF_FAIL(ctx, GF_ERR_ARG, "measure: stress planes need n >= 1 and dy > 0 (got %d, %g m)", n, dy);
    double area = (dom->hi_m[0] - dom->lo_m[0]) * (dom->hi_m[2] - dom->lo_m[2]);
    /* per slab: mass, momentum (x, y), second moments m u_x u_y, m u_y u_y, force sums fx, fy */
    double *w = calloc((size_t)n * 7, sizeof *w), fx_beyond = 0.0, fy_beyond = 0.0;
    if (!w)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "measure: cannot allocate %d planes", n);
    for (size_t i = 0; i < p->n_local; ++i) {
        if (!mobile(p, i))
            continue;
        int k = (int)floor((p->y_m[i] - y0) / dy);
        if (k < 0)
            continue; /* below every plane: never "above" */
        if (k >= n) { /* above the last slab: forces only */
            fx_beyond += p->fx_N[i], fy_beyond += p->fy_N[i];
            continue;
        }
        double m = p->mass_kg[i], ux = p->vx_m_s[i], uy = p->vy_m_s[i];
        double *q = &w[7 * k];
        q[0] += m, q[1] += m * ux, q[2] += m * uy, q[3] += m * ux * uy, q[4] += m * uy * uy;
        q[5] += p->fx_N[i], q[6] += p->fy_N[i];
    }
    /* plane k sits at the slab centre: the grains above are the upper half of slab k (by centre,
     * half of its forces on average) and every slab above; use half of slab k's forces */
    double fx_above = fx_beyond, fy_above = fy_beyond;
    for (int k = n - 1; k >= 0; --k) {
        double *q = &w[7 * k];
        double vol = area * dy;
        double kin_xy = 0.0, kin_yy = 0.0;
        if (q[0] > 0.0) {
            double ux = q[1] / q[0], uy = q[2] / q[0];
            kin_xy = (q[3] - q[0] * ux * uy) / vol;
            kin_yy = (q[4] - q[0] * uy * uy) / vol;
        }
        double fx_k = fx_above + 0.5 * q[5], fy_k = fy_above + 0.5 * q[6];
        if (tau)
            tau[k] = -fx_k / area - kin_xy;
        if (sig)
            sig[k] = fy_k / area + kin_yy;
        fx_above += q[5], fy_above += q[6];
    }
    free(w);
    return GF_OK;
}

gf_status gf_measure_silo_vertical_stress(gf_ctx *ctx, const gf_particles *p, double g, double area, double y0,
                                          double dy, int n, double *sigma)
{
    if (n < 1 || !(dy > 0.0) || !(area > 0.0))
        return GF_FAIL(ctx, GF_ERR_ARG, "measure: silo stress needs n >= 1, dy > 0, area > 0");
    for (int k = 0; k < n; ++k) {
        double yk = y0 + (k + 0.5) * dy, f = 0.0;
        for (size_t i = 0; i < p->n_local; ++i) {
            if (p->y_m[i] <= yk)
                continue;
            f += mobile(p, i) ? p->mass_kg[i] * g : p->fy_N[i];
        }
        sigma[k] = f / area;
    }
    return GF_OK;
}

double gf_measure_grain_flow_rate(const gf_particles *p, const gf_measure_domain *dom)
{
    double L = dom->hi_m[0] - dom->lo_m[0], q = 0.0;
    for (size_t i = 0; i < p->n_local; ++i) {
        if (!mobile(p, i))
            continue;
        double r = p->radius_m[i];
        q += 4.0 / 3.0 * M_PI * r * r * r * p->vx_m_s[i];
    }
    return q / L;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double gf_measure_bed_height_m(const double *phi, int n, double y0, double dy, double fraction)
{
    /* plateau: median of the slabs that hold grains (phi > 0.05), robust to the
     * thin glued layer at the base and the dilute surface */
    double *tmp = malloc((size_t)n * sizeof *tmp);
    if (!tmp)
        return NAN;
    int m = 0;
    for (int k = 0; k < n; ++k)
        if (phi[k] > 0.05)
            tmp[m++] = phi[k];
    if (m == 0) {
        free(tmp);
        return NAN;
    }
    qsort(tmp, (size_t)m, sizeof *tmp, cmp_double);
    double plateau = tmp[m / 2];
    free(tmp);
    double level = fraction * plateau;
    for (int k = n - 1; k >= 0; --k)
        if (phi[k] >= level) {
            /* linear interpolation between slab centres k and k + 1 */
            double yk = y0 + (k + 0.5) * dy;
            if (k == n - 1)
                return yk;
            double f = (phi[k] - level) / (phi[k] - phi[k + 1]);
            return yk + f * dy;
        }
    return NAN;
}

gf_status gf_measure_deposit_profile(gf_ctx *ctx, const gf_particles *p, const gf_measure_domain *dom, double x0,
                                     double dx, int n_bins, double min_solid, int max_gap, double *top_out,
                                     double *solid_out, gf_measure_deposit *out)
{
    if (n_bins < 1 || !(dx > 0.0))
        return GF_FAIL(ctx, GF_ERR_ARG, "measure: deposit needs n_bins >= 1 and dx > 0 (got %d, %g m)", n_bins, dx);
    double *top = calloc((size_t)n_bins * 2, sizeof *top);
    if (!top)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "measure: cannot allocate %d bins", n_bins);
    double *solid = top + n_bins;
    double width = dom->hi_m[2] - dom->lo_m[2];
    for (size_t i = 0; i < p->n_local; ++i) {
        if (!mobile(p, i))
            continue;
        int b = (int)floor((p->x_m[i] - x0) / dx);
        if (b < 0 || b >= n_bins)
            continue;
        double r = p->radius_m[i];
        solid[b] += 4.0 / 3.0 * M_PI * r * r * r / (dx * width);
        if (p->y_m[i] + r > top[b])
            top[b] = p->y_m[i] + r;
    }
    out->front_m = NAN;
    out->height_m = 0.0;
    out->height_at_x0_m = top[0];
    int gap = 0, started = 0;
    for (int b = 0; b < n_bins; ++b) {
        if (solid[b] >= min_solid) {
            started = 1;
            gap = 0;
            out->front_m = x0 + (b + 1) * dx;
            if (top[b] > out->height_m)
                out->height_m = top[b];
        } else if (started && ++gap > max_gap) {
            break;
        }
    }
    if (top_out)
        memcpy(top_out, top, (size_t)n_bins * sizeof *top);
    if (solid_out)
        memcpy(solid_out, solid, (size_t)n_bins * sizeof *solid);
    free(top);
    return GF_OK;
}

double gf_measure_profile_extent(const double *h, int n, double dx, double depth)
{
    for (int i = 0; i < n; ++i)
        if (h[i] < depth)
            return i == 0 ? 0.0 : (i - 0.5) * dx + dx * (h[i - 1] - depth) / (h[i - 1] - h[i]);
    return n * dx;
}

gf_status gf_measure_fit_mu_of_I(gf_ctx *ctx, const double *I, const double *mu, int n, double I0, double *mu1,
                                 double *mu2)
{
    /* mu = mu1 (1 - w) + mu2 w with w = I/(I0 + I): normal equations of a 2x2 linear least squares */
    double s00 = 0, s01 = 0, s11 = 0, b0 = 0, b1 = 0;
    for (int k = 0; k < n; ++k) {
        double w = I[k] / (I0 + I[k]), a = 1.0 - w;
        s00 += a * a, s01 += a * w, s11 += w * w;
        b0 += a * mu[k], b1 += w * mu[k];
    }
    double det = s00 * s11 - s01 * s01;
    if (n < 2 || !(fabs(det) > 1e-12 * (s00 * s11 + 1e-300)))
        return GF_FAIL(ctx, GF_ERR_ARG, "measure: mu(I) fit needs >= 2 points at distinct I (got %d)", n);
    *mu1 = (b0 * s11 - b1 * s01) / det;
    *mu2 = (s00 * b1 - s01 * b0) / det;
    return GF_OK;
}

/* Residual of the Janssen fit for a given lambda, with the optimal sigma_inf. */
static double janssen_residual(const double *d, const double *s, int n, double lambda, double *sigma_inf)
{
    double sw = 0, ww = 0;
    for (int k = 0; k < n; ++k) {
        double w = 1.0 - exp(-d[k] / lambda);
        sw += s[k] * w, ww += w * w;
    }
    double a = ww > 0 ? sw / ww : 0.0, res = 0.0;
    for (int k = 0; k < n; ++k) {
        double e = s[k] - a * (1.0 - exp(-d[k] / lambda));
        res += e * e;
    }
    if (sigma_inf)
        *sigma_inf = a;
    return res;
}

gf_status gf_measure_fit_janssen(gf_ctx *ctx, const double *d, const double *s, int n, double lmin, double lmax,
                                 double *sigma_inf, double *lambda, double *rms)
{
    if (n < 3 || !(lmin > 0.0) || !(lmax > lmin))
        return GF_FAIL(ctx, GF_ERR_ARG, "measure: Janssen fit needs >= 3 points and 0 < lambda_min < lambda_max");
    /* coarse log scan, then golden section around the best point */
    int best = 0, m = 200;
    double best_res = INFINITY;
    for (int k = 0; k <= m; ++k) {
        double l = lmin * pow(lmax / lmin, (double)k / m);
        double r = janssen_residual(d, s, n, l, NULL);
        if (r < best_res)
            best_res = r, best = k;
    }
    double a = lmin * pow(lmax / lmin, (double)(best > 0 ? best - 1 : 0) / m);
    double b = lmin * pow(lmax / lmin, (double)(best < m ? best + 1 : m) / m);
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    for (int it = 0; it < 80; ++it) {
        double c = b - g * (b - a), e = a + g * (b - a);
        if (janssen_residual(d, s, n, c, NULL) < janssen_residual(d, s, n, e, NULL))
            b = e;
        else
            a = c;
    }
    *lambda = 0.5 * (a + b);
    double res = janssen_residual(d, s, n, *lambda, sigma_inf);
    if (rms)
        *rms = sqrt(res / n);
    return GF_OK;
}

void gf_measure_fit_runout(const double *a, const double *r, int n, double a0, double *lambda1, double *lambda2)
{
    double s1 = 0, n1 = 0, s2 = 0, n2 = 0;
    for (int k = 0; k < n; ++k) {
        if (a[k] < a0) {
            s1 += a[k] * r[k], n1 += a[k] * a[k];
        } else {
            double f = pow(a[k], 2.0 / 3.0);
            s2 += f * r[k], n2 += f * f;
        }
    }
    *lambda1 = n1 > 0 ? s1 / n1 : NAN;
    *lambda2 = n2 > 0 ? s2 / n2 : NAN;
}

gf_status gf_measure_fit_bagnold(gf_ctx *ctx, const double *y, const double *u, int n, double h, double *A,
                                 double *B, double *rel_rms)
{
    double s00 = 0, s01 = 0, s11 = 0, b0 = 0, b1 = 0, umax = 0;
    int used = 0;
    for (int k = 0; k < n; ++k) {
        if (y[k] < 0.0 || y[k] > h || !isfinite(u[k]))
            continue;
        double f = pow(h, 1.5) - pow(h - y[k], 1.5);
        s00 += f * f, s01 += f, s11 += 1.0;
        b0 += f * u[k], b1 += u[k];
        if (fabs(u[k]) > umax)
            umax = fabs(u[k]);
        ++used;
    }
    double det = s00 * s11 - s01 * s01;
    if (used < 3 || !(det > 0.0))
        return GF_FAIL(ctx, GF_ERR_ARG, "measure: Bagnold fit needs >= 3 points inside [0, h] (got %d)", used);
    *A = (b0 * s11 - b1 * s01) / det;
    *B = (s00 * b1 - s01 * b0) / det;
    double res = 0;
    for (int k = 0; k < n; ++k) {
        if (y[k] < 0.0 || y[k] > h || !isfinite(u[k]))
            continue;
        double e = u[k] - (*A * (pow(h, 1.5) - pow(h - y[k], 1.5)) + *B);
        res += e * e;
    }
    if (rel_rms)
        *rel_rms = umax > 0 ? sqrt(res / used) / umax : 0.0;
    return GF_OK;
}

gf_status gf_measure_chute_bagnold(gf_ctx *ctx, const double *phi, const double *u, int n_slabs, double D,
                                   double g, double theta, gf_measure_chute *out)
{
    *out = (gf_measure_chute){NAN, NAN, NAN, NAN, NAN, NAN, NAN};
    double *y = malloc(2 * (size_t)n_slabs * sizeof *y);
    if (!y)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "measure: cannot allocate %d slabs", n_slabs);
    double *uf = y + n_slabs, h = gf_measure_bed_height_m(phi, n_slabs, 0.0, D, 0.5) - 0.5 * D;
    int n = 0;
    for (int k = 1; k < n_slabs && k * D <= h; ++k) /* slab centre (k + 1/2) D, from the layer's top D/2 */
        y[n] = k * D, uf[n] = u[k], ++n;
    out->h_m = h;
    gf_status st = gf_measure_fit_bagnold(ctx, y, uf, n, h, &out->A, &out->B, &out->rel_rms);
    free(y);
    if (st != GF_OK)
        return st;
    out->slip_over_h = -out->B / (1.5 * out->A * sqrt(h)) / h;
    int top = (int)floor(gf_measure_bed_height_m(phi, n_slabs, 0.0, 1.0, 0.5)), nb = 0;
    double phib = 0.0;
    for (int k = 2; k <= top - 3 && k < n_slabs; ++k)
        phib += phi[k], ++nb;
    if (nb == 0)
        return GF_FAIL(ctx, GF_ERR_ARG, "measure: chute bed of %d slabs too thin for a bulk solid fraction", top);
    out->phi_bulk = phib / nb;
    out->I = 1.5 * out->A * D / sqrt(out->phi_bulk * g * cos(theta));
    return GF_OK;
}
