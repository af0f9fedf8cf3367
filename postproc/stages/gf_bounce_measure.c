/*
 * One sphere-wall bounce measured from its trace: definitions in
 * gf_bounce_measure.h (Izard 2014 §3.1.3, eq. (3.19); Gondret et al. 2002).
 */
#include "stages/gf_bounce_measure.h"

#include <math.h>

/* Time at which the gap crosses zero between samples a and b (linear). */
static double zero_crossing(const double *t, const double *gap, size_t a, size_t b)
{
    double d = gap[a] - gap[b];
    return d != 0.0 ? t[a] + (t[b] - t[a]) * gap[a] / d : t[b];
}

void gf_bounce_measure(const double *t, const double *v, const double *gap, size_t n, double R, gf_bounce *b)
{
    *b = (gf_bounce){.V_T = NAN, .V_I = NAN, .V_R = NAN, .e = NAN, .eps = NAN, .t_in_s = NAN, .t_out_s = NAN,
                     .contact_s = NAN};
    size_t k1 = 0;
    while (k1 < n && !(gap[k1] <= 0.0))
        ++k1;
    double vt = 0.0;
    for (size_t k = 0; k < k1; ++k)
        if (gap[k] > R && -v[k] > vt) {
            vt = -v[k];
            b->k_terminal = k;
        }
    if (k1 > 0)
        b->V_T = vt;
    if (k1 == n || k1 == 0)
        return;   /* never touched, or in contact from the first sample: no approach to measure */
    b->touched = 1;
    b->k_impact = k1 - 1;
    b->V_I = -v[k1 - 1];
    b->t_in_s = zero_crossing(t, gap, k1 - 1, k1);
    size_t k2 = k1;
    while (k2 < n && gap[k2] <= 0.0)
        ++k2;
    b->n_in_contact = k2 - k1;
    if (k2 < n) {
        b->left = 1;
        b->t_out_s = zero_crossing(t, gap, k2 - 1, k2);
        b->contact_s = b->t_out_s - b->t_in_s;
    }
    /* the first maximum of the upward velocity: the first upward sample, then
       on while the velocity still grows */
    size_t j = k1;
    while (j < n && !(v[j] > 0.0))
        ++j;
    if (j < n) {
        while (j + 1 < n && v[j + 1] > v[j])
            ++j;
        b->rebounded = 1;
        b->k_rebound = j;
        b->V_R = v[j];
    } else {
        b->V_R = 0.0;
    }
    b->e = b->V_I > 0.0 ? b->V_R / b->V_I : NAN;
    b->eps = b->V_T > 0.0 ? b->V_R / b->V_T : NAN;
}

void gf_bounce_measure_oblique(const gf_bounce *b, const double *vx, const double *wz, double R,
                               gf_bounce_reference ref, gf_bounce_oblique *o)
{
    *o = (gf_bounce_oblique){.e = NAN, .psi_in = NAN, .psi_out = NAN, .beta = NAN, .mu_f = NAN, .xi_in_deg = NAN,
                             .xi_out_deg = NAN};
    int at_impact = ref == GF_BOUNCE_AT_IMPACT;
    double v_in = at_impact ? b->V_I : b->V_T;
    size_t k_in = at_impact ? b->k_impact : b->k_terminal;
    if (!b->touched || !b->rebounded || !(v_in > 0.0))
        return;
    const double deg = 180.0 / M_PI;
    o->e = b->V_R / v_in;
    o->psi_in = (vx[k_in] + R * wz[k_in]) / v_in;
    o->psi_out = (vx[b->k_rebound] + R * wz[b->k_rebound]) / v_in;
    o->xi_in_deg = atan(o->psi_in) * deg;
    o->xi_out_deg = atan2(o->psi_out, o->e) * deg;
    if (fabs(o->psi_in) >= GF_BOUNCE_PSI_MIN) {
        o->beta = -o->psi_out / o->psi_in;
        o->mu_f = 2.0 * (1.0 + o->beta) * o->psi_in / (7.0 * (1.0 + o->e));
    }
}

/* A sample of the near-wall approach: before contact, below x_max R, moving towards the wall. */
static int approaching(const double *v, const double *gap, size_t k, double x_max_R)
{
    return gap[k] > 0.0 && gap[k] <= x_max_R && v[k] < 0.0;
}

void gf_bounce_measure_approach(const double *v, const double *gap, size_t n, double R, double x_max, double flat,
                                gf_bounce_approach *a)
{
    const double top = x_max * R;
    *a = (gf_bounce_approach){.V_m = NAN, .ratio_min = NAN, .x_lo = NAN, .x_hi = NAN};
    size_t k1 = 0;   /* the first contact ends the approach */
    while (k1 < n && gap[k1] > 0.0)
        ++k1;
    /* the ratio's first minimum once it has fallen 2 flat below its running peak (the film slowing the sphere),
       ended by a rise 2 flat above it (the roughness); without such a fall, its smallest value */
    size_t k_min = k1;
    double peak = -INFINITY, r_min = INFINITY;
    for (size_t k = 0; k < k1; ++k) {
        if (!approaching(v, gap, k, top))
            continue;
        double r = -v[k] * R / gap[k];
        if (k_min == k1) {
            peak = fmax(peak, r);
            if (r * (1.0 + 2.0 * flat) <= peak)
                k_min = k, r_min = r;
        } else if (r < r_min) {
            k_min = k, r_min = r;
        } else if (r > (1.0 + 2.0 * flat) * r_min) {
            break;
        }
    }
    const int after_peak = k_min < k1;
    for (size_t k = 0; k_min == k1 && k < k1; ++k)
        if (approaching(v, gap, k, top) && -v[k] * R / gap[k] < r_min)
            r_min = -v[k] * R / gap[k], k_min = k;
    if (k_min == k1)
        return;
    const double r_max = (1.0 + flat) * r_min;
    size_t lo = k_min, hi = k_min;
    while (lo > 0 && approaching(v, gap, lo - 1, top) && -v[lo - 1] * R / gap[lo - 1] <= r_max)
        --lo;
    while (hi + 1 < k1 && approaching(v, gap, hi + 1, top) && -v[hi + 1] * R / gap[hi + 1] <= r_max)
        ++hi;
    double sxu = 0.0, sxx = 0.0;
    for (size_t k = lo; k <= hi; ++k) {
        double x = gap[k] / R;
        sxu += -v[k] * x;
        sxx += x * x;
    }
    *a = (gf_bounce_approach){.V_m = sxu / sxx, .ratio_min = r_min, .x_lo = gap[hi] / R, .x_hi = gap[lo] / R,
                              .k_first = lo, .k_last = hi, .n = hi - lo + 1, .after_peak = after_peak};
}
