/*
 * Campaign figures drawn with the SVG layer (gf_svg.h); see gf_figures.h.
 *
 * Regime diagram. The boundaries come from two sources that disagree by a
 * factor of ten in St (Izard 2014 §4.1.4.2), so both are drawn:
 *   Courrech du Pont et al., PRL 90 044301 (2003), single-grain experiments:
 *     St_c = 10 (viscous | free fall, for r >= 4), Re*_c = St/r = 2.5, i.e.
 *     r = St/2.5 (viscous | inertial, for r < 4), r_c = 4 (inertial | free
 *     fall, St >= 10). The three lines meet at (St, r) = (10, 4).
 *   Izard 2014 (avalanches of the seed): St = 1 for r >= 4, r = 4 St for
 *     r < 4 (Re*_c = 0.25), r_c = 4 for St >= 1; they meet at (1, 4).
 * Runout. Planar dry collapse, (R_inf - R0)/R0 = l1 a for a < a0 and
 * l2 a^(2/3) beyond: Lube et al. 2005 l1 = 1.2, l2 = 1.9, a0 ≈ 1.8-2.8 (we
 * switch at 2.3, mid-range); Lajeunesse et al. 2005 l1 = 1.8, l2 = 2.3,
 * a0 ≈ 3. The published fits are not continuous at a0, so each branch is
 * drawn as its own piece rather than joined by an invented segment.
 *
 * Layout: one frame with the legend outside on the right, so that a legend
 * never hides a data point.
 */
#include "figures/gf_figures.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "figures/gf_svg.h"

static const char *const regime_names[GF_FIG_REGIME_COUNT] = {"undetermined", "viscous", "inertial",
                                                               "free-fall", "transitional"};
static const char *const regime_colours[GF_FIG_REGIME_COUNT] = {"#8c8c8c", "#1f77b4", "#ff7f0e", "#2ca02c",
                                                                 "#9467bd"};
static const char *const shape_names[GF_FIG_SHAPE_COUNT] = {"undetermined", "triangle", "trapezoid"};
static const char *const shape_colours[GF_FIG_SHAPE_COUNT] = {"#8c8c8c", "#d62728", "#1f77b4"};
static const gf_svg_marker_shape shape_markers[GF_FIG_SHAPE_COUNT] = {GF_SVG_CIRCLE, GF_SVG_TRIANGLE,
                                                                      GF_SVG_SQUARE};
/* Tableau 10: distinguishable, colour-blind-aware defaults for curves. */
static const char *const palette[10] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                        "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

static const double marker_px = 9.0;
enum { legend_max_rows = 14 };

gf_fig_regime gf_fig_regime_from_name(const char *name)
{
    if (!name)
        return GF_FIG_REGIME_UNDETERMINED;
    if (strcmp(name, "viscous") == 0)
        return GF_FIG_REGIME_VISCOUS;
    if (strcmp(name, "inertial") == 0)
        return GF_FIG_REGIME_INERTIAL;
    if (strcmp(name, "free-fall") == 0 || strcmp(name, "free_fall") == 0 || strcmp(name, "freefall") == 0)
        return GF_FIG_REGIME_FREE_FALL;
    if (strcmp(name, "transitional") == 0)
        return GF_FIG_REGIME_TRANSITIONAL;
    return GF_FIG_REGIME_UNDETERMINED;
}

const char *gf_fig_regime_name(gf_fig_regime r)
{
    return (int)r >= 0 && r < GF_FIG_REGIME_COUNT ? regime_names[r] : regime_names[0];
}

gf_fig_shape gf_fig_shape_from_name(const char *name)
{
    if (name && strcmp(name, "triangle") == 0)
        return GF_FIG_SHAPE_TRIANGLE;
    if (name && strcmp(name, "trapezoid") == 0)
        return GF_FIG_SHAPE_TRAPEZOID;
    return GF_FIG_SHAPE_UNDETERMINED;
}

const char *gf_fig_shape_name(gf_fig_shape s)
{
    return (int)s >= 0 && s < GF_FIG_SHAPE_COUNT ? shape_names[s] : shape_names[0];
}

/* ---------------------------------------------------------------- helpers */

typedef struct page {
    double width_px, height_px;
    const char *title;
} page;

static page page_of(const gf_fig_opts *opt, const char *default_title)
{
    page p = {760.0, 560.0, default_title};
    if (opt) {
        if (opt->width_px > 0)
            p.width_px = opt->width_px;
        if (opt->height_px > 0)
            p.height_px = opt->height_px;
        if (opt->title)
            p.title = opt->title;
    }
    return p;
}

/* Frame with room for tick labels and axis labels on the left/bottom, and
 * for the legend (labels up to legend_chars long) outside on the right. */
static gf_svg_frame frame_of(const page *p, int legend_chars)
{
    gf_svg_frame f;
    memset(&f, 0, sizeof f);
    f.x0_px = 88.0;
    f.y0_px = 48.0;
    f.w_px = fmax(120.0, p->width_px - f.x0_px - 14.0 - gf_svg_legend_width_px(legend_chars) - 12.0);
    f.h_px = fmax(120.0, p->height_px - f.y0_px - 86.0);
    return f;
}

/* Range of the values usable on an axis of that scale; returns the count. */
static int data_range(int n, const double *v, int positive_only, double *lo, double *hi)
{
    int k = 0;
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int i = 0; i < n; ++i) {
        if (!isfinite(v[i]) || (positive_only && !(v[i] > 0.0)))
            continue;
        *lo = fmin(*lo, v[i]);
        *hi = fmax(*hi, v[i]);
        k++;
    }
    return k;
}

/* The range of the values usable on an axis (data_range), or [lo_empty,
 * hi_empty] when there is none. */
static void data_range_or(int n, const double *v, int positive_only, double lo_empty, double hi_empty, double *lo,
                          double *hi)
{
    if (data_range(n, v, positive_only, lo, hi) == 0) {
        *lo = lo_empty;
        *hi = hi_empty;
    }
}

/* The figure's file at path, with the page's title over the frame and the
 * frame's axes drawn. */
static gf_status open_figure(gf_ctx *ctx, const char *path, const page *p, const gf_svg_frame *f, gf_svg **s)
{
    GF_TRY(gf_svg_open(ctx, path, p->width_px, p->height_px, s));
    gf_svg_title(*s, f, p->title);
    gf_svg_axes(*s, f);
    return GF_OK;
}

/* AUTO: log when the positive data span at least 1.5 decades and nothing is <= 0. */
static gf_svg_scale choose_scale(gf_fig_scale want, int n, const double *v)
{
    if (want == GF_FIG_SCALE_LOG)
        return GF_SVG_LOG;
    if (want == GF_FIG_SCALE_LINEAR)
        return GF_SVG_LINEAR;
    double lo, hi, plo, phi;
    int n_all = data_range(n, v, 0, &lo, &hi);
    int n_pos = data_range(n, v, 1, &plo, &phi);
    if (n_pos < 2 || n_pos < n_all)
        return GF_SVG_LINEAR;
    return log10(phi / plo) >= 1.5 ? GF_SVG_LOG : GF_SVG_LINEAR;
}

/* Widens [lo, hi] by a fraction of its span (of its decades on a log
 * axis) at the ends asked for, so that markers do not sit on the frame. */
static void pad_range(gf_svg_scale scale, double *lo, double *hi, int pad_lo, int pad_hi)
{
    const double frac = 0.04;
    if (scale == GF_SVG_LOG) {
        double dec = fmax(log10(*hi / *lo), 0.3);
        if (pad_lo)
            *lo /= pow(10.0, frac * dec);
        if (pad_hi)
            *hi *= pow(10.0, frac * dec);
        return;
    }
    double span = *hi - *lo > 0.0 ? *hi - *lo : fmax(fabs(*hi), 1.0);
    if (pad_lo)
        *lo -= frac * span;
    if (pad_hi)
        *hi += frac * span;
}

static void set_axis(gf_svg_axis *a, gf_svg_scale scale, double lo, double hi, const char *label)
{
    a->scale = scale;
    a->label = label;
    gf_svg_nice_range(scale, lo, hi, &a->lo, &a->hi);
}

static gf_status check_arrays(gf_ctx *ctx, const char *what, const char *path, int n, const void *a,
                              const void *b)
{
    if (!path)
        return GF_FAIL(ctx, GF_ERR_ARG, "%s: NULL output path", what);
    if (n < 0)
        return GF_FAIL(ctx, GF_ERR_ARG, "%s %s: negative run count %d", what, path, n);
    if (n > 0 && (!a || !b))
        return GF_FAIL(ctx, GF_ERR_ARG, "%s %s: NULL data array for %d runs", what, path, n);
    return GF_OK;
}

static void skipped_caption(gf_svg *s, const gf_svg_frame *f, int n_skipped, const char *why)
{
    if (n_skipped <= 0)
        return;
    char buf[160];
    snprintf(buf, sizeof buf, "%d run%s not shown (%s)", n_skipped, n_skipped == 1 ? "" : "s", why);
    gf_svg_caption(s, f, buf);
}

/* ---------------------------------------------------------------- variants */

enum { max_variants = 8, GF_FIG_VARIANT_LABEL_LEN = 128 };

static int n_variants_of(const gf_fig_opts *opt)
{
    if (!opt || opt->n_variants <= 1 || !opt->variant)
        return 1;
    return opt->n_variants < max_variants ? opt->n_variants : max_variants;
}

/* Variant of run i (0 when there is one, or its index is out of range). */
static int variant_of(const gf_fig_opts *opt, int i)
{
    int nv = n_variants_of(opt);
    if (nv <= 1)
        return 0;
    int v = opt->variant[i];
    return v >= 0 && v < nv ? v : 0;
}

/* Marker style of run i: every other variant hollow, the variants at one
 * point side by side, 0.7 marker widths apart (8 px or more at 11 px). */
static gf_svg_marker_style variant_style(const gf_fig_opts *opt, int i, double size_px)
{
    int nv = n_variants_of(opt), v = variant_of(opt, i);
    gf_svg_marker_style st = {v % 2, 0.0};
    if (nv > 1)
        st.dx_px = ((double)v - 0.5 * (nv - 1)) * 0.75 * size_px;
    return st;
}

/* Legend rows for the variants that have a marker drawn (drawn[v]): the
 * name and how its markers are drawn, "dry: filled markers", "immersed: outlined markers". */
static int variant_legend(const gf_fig_opts *opt, const int *drawn, gf_svg_legend_entry *e,
                          char (*text)[GF_FIG_VARIANT_LABEL_LEN])
{
    int nv = n_variants_of(opt), n_e = 0;
    if (nv <= 1)
        return 0;
    for (int v = 0; v < nv; ++v) {
        if (!drawn[v])
            continue;
        const char *name = opt->variant_names && opt->variant_names[v] ? opt->variant_names[v] : "(variant)";
        snprintf(text[n_e], GF_FIG_VARIANT_LABEL_LEN, "%s: %s markers", name, v % 2 ? "outlined" : "filled");
        e[n_e] = (gf_svg_legend_entry){text[n_e], "#555555", 0, GF_SVG_CIRCLE, NULL, v % 2};
        n_e++;
    }
    return n_e;
}

/* Longest variant row ("<name>: outlined markers"), for the legend's width. */
enum { variant_suffix_chars = 18 };
static int variant_chars(const gf_fig_opts *opt, int at_least)
{
    int nv = n_variants_of(opt);
    for (int v = 0; nv > 1 && opt->variant_names && v < nv; ++v)
        if (opt->variant_names[v] && (int)strlen(opt->variant_names[v]) + variant_suffix_chars > at_least)
            at_least = (int)strlen(opt->variant_names[v]) + variant_suffix_chars;
    return at_least;
}

/* ---------------------------------------------------------------- regime diagram */

/* One set of boundaries, three pieces meeting at (St_c, r_c = 4):
 * St = St_c for r >= 4 (viscous | free fall), r = 4 for St >= St_c
 * (inertial | free fall), r = St / Re*_c for r < 4 (viscous | inertial),
 * with Re*_c = St_c / 4 so that the pieces join. */
static void draw_regime_boundaries(gf_svg *s, const gf_svg_frame *f, double St_c, double Re_c, const char *colour,
                                   const char *dash)
{
    const double r_c = 4.0;
    double xv[2] = {St_c, St_c}, yv[2] = {r_c, f->y.hi};
    gf_svg_polyline(s, f, 2, xv, yv, colour, 1.6, dash, "refline");
    double xh[2] = {St_c, f->x.hi}, yh[2] = {r_c, r_c};
    gf_svg_polyline(s, f, 2, xh, yh, colour, 1.6, dash, "refline");
    double xl[2] = {Re_c * f->y.lo, St_c}, yl[2] = {f->y.lo, St_c / Re_c};
    gf_svg_polyline(s, f, 2, xl, yl, colour, 1.6, dash, "refline");
}

/* Markers coloured by regime; marks the regimes drawn in present[]; returns the runs skipped. */
static int plot_runs_by_regime(gf_svg *s, const gf_svg_frame *f, const gf_fig_opts *opt, int n_runs,
                               const double *x, const double *y, const gf_fig_regime *regime, const char *xname,
                               const char *yname, int present[GF_FIG_REGIME_COUNT], int *drawn_variant)
{
    int n_skipped = 0;
    for (int i = 0; i < n_runs; ++i) {
        gf_fig_regime g = regime ? regime[i] : GF_FIG_REGIME_UNDETERMINED;
        if ((int)g < 0 || g >= GF_FIG_REGIME_COUNT)
            g = GF_FIG_REGIME_UNDETERMINED;
        const char *colour = regime ? regime_colours[g] : palette[0];
        char tip[128];
        snprintf(tip, sizeof tip, "%s = %.3g, %s = %.3g (%s)", xname, x[i], yname, y[i], regime_names[g]);
        gf_svg_marker_style style = variant_style(opt, i, marker_px);
        if (gf_svg_marker_styled(s, f, x[i], y[i], GF_SVG_CIRCLE, colour, marker_px, &style, tip)) {
            present[g] = 1;
            if (drawn_variant)
                drawn_variant[variant_of(opt, i)] = 1;
        } else {
            n_skipped++;
        }
    }
    return n_skipped;
}

/* Legend rows for the regimes present, in a fixed order; returns the count. */
static int regime_legend(const int present[GF_FIG_REGIME_COUNT], gf_svg_legend_entry *e)
{
    static const gf_fig_regime order[] = {GF_FIG_REGIME_VISCOUS, GF_FIG_REGIME_INERTIAL, GF_FIG_REGIME_FREE_FALL,
                                          GF_FIG_REGIME_TRANSITIONAL, GF_FIG_REGIME_UNDETERMINED};
    int n_e = 0;
    for (int k = 0; k < GF_FIG_REGIME_COUNT; ++k)
        if (present[order[k]])
            e[n_e++] = (gf_svg_legend_entry){regime_names[order[k]], regime_colours[order[k]], 0, GF_SVG_CIRCLE, NULL, 0};
    return n_e;
}

gf_status gf_fig_regime_diagram(gf_ctx *ctx, const char *path, const gf_fig_opts *opt, int n_runs,
                                const double *stokes_St, const double *density_ratio_r,
                                const gf_fig_regime *regime)
{
    GF_TRY(check_arrays(ctx, "regime diagram", path, n_runs, stokes_St, density_ratio_r));
    page p = page_of(opt, "Flow regimes in the (St, r) plane");
    gf_svg_frame f = frame_of(&p, (int)strlen("Courrech du Pont et al. 2003"));
    double slo, shi, rlo, rhi;
    data_range_or(n_runs, stokes_St, 1, 1.0, 1.0, &slo, &shi);
    data_range_or(n_runs, density_ratio_r, 1, 4.0, 4.0, &rlo, &rhi);
    pad_range(GF_SVG_LOG, &slo, &shi, 1, 1);
    pad_range(GF_SVG_LOG, &rlo, &rhi, 1, 1);
    /* always show both sets of boundaries: St from 0.1 to 100, r from 1 to 20 */
    set_axis(&f.x, GF_SVG_LOG, fmin(slo, 0.1), fmax(shi, 100.0), "Stokes number St");
    set_axis(&f.y, GF_SVG_LOG, fmin(rlo, 1.0), fmax(rhi, 20.0), "density ratio r = sqrt(5 rho_p / (3 rho_f))");

    gf_svg *s;
    GF_TRY(open_figure(ctx, path, &p, &f, &s));

    const char *cdp = "#333333", *izd = "#b22222";
    draw_regime_boundaries(s, &f, 10.0, 2.5, cdp, "7,4");    /* Courrech du Pont et al. 2003 */
    draw_regime_boundaries(s, &f, 1.0, 0.25, izd, "2,3");    /* Izard 2014 */
    const double r_c = 4.0;
    /* region names, placed where every boundary set agrees */
    gf_svg_text_data(s, &f, f.x.lo * 1.6, sqrt(r_c * f.y.hi), "start", 13.0, "#555555", "viscous");
    gf_svg_text_data(s, &f, f.x.hi / 1.6, f.y.hi / 1.6, "end", 13.0, "#555555", "free fall");
    gf_svg_text_data(s, &f, f.x.hi / 1.6, f.y.lo * 1.4, "end", 13.0, "#555555", "inertial");

    int present[GF_FIG_REGIME_COUNT] = {0};
    int n_skipped =
        plot_runs_by_regime(s, &f, NULL, n_runs, stokes_St, density_ratio_r, regime, "St", "r", present, NULL);
    gf_svg_legend_entry e[GF_FIG_REGIME_COUNT + 2];
    int n_e = regime_legend(present, e);
    e[n_e++] = (gf_svg_legend_entry){"Courrech du Pont et al. 2003", cdp, 1, GF_SVG_CIRCLE, "7,4", 0};
    e[n_e++] = (gf_svg_legend_entry){"Izard 2014", izd, 1, GF_SVG_CIRCLE, "2,3", 0};
    gf_svg_legend(s, &f, 4, n_e, e);
    skipped_caption(s, &f, n_skipped, "St or r not finite and > 0");
    return gf_svg_close(&s);
}

/* ---------------------------------------------------------------- deposit shape */

gf_status gf_fig_deposit_shape(gf_ctx *ctx, const char *path, const gf_fig_opts *opt, int n_runs,
                               const double *aspect_ratio_a, const double *phi_initial, const gf_fig_shape *shape)
{
    GF_TRY(check_arrays(ctx, "deposit-shape figure", path, n_runs, aspect_ratio_a, phi_initial));
    page p = page_of(opt, "Deposit shape in the (a, Phi_i) plane");
    gf_svg_frame f = frame_of(&p, variant_chars(opt, (int)strlen("undetermined")));
    gf_svg_scale xs = opt && opt->x_scale == GF_FIG_SCALE_LOG ? GF_SVG_LOG : GF_SVG_LINEAR;
    gf_svg_scale ys = opt && opt->y_scale == GF_FIG_SCALE_LOG ? GF_SVG_LOG : GF_SVG_LINEAR;
    double alo, ahi, plo, phi;
    data_range_or(n_runs, aspect_ratio_a, xs == GF_SVG_LOG, 0.5, 2.0, &alo, &ahi);
    data_range_or(n_runs, phi_initial, ys == GF_SVG_LOG, 0.55, 0.6, &plo, &phi);
    if (xs == GF_SVG_LINEAR)
        alo = fmin(alo, 0.0);   /* a starts at the origin: a = 0 is "no column" */
    pad_range(xs, &alo, &ahi, xs == GF_SVG_LOG, 1);
    pad_range(ys, &plo, &phi, 1, 1);
    set_axis(&f.x, xs, alo, ahi, "aspect ratio a = H0 / R0");
    set_axis(&f.y, ys, plo, phi, "initial packing fraction Phi_i");

    gf_svg *s;
    GF_TRY(open_figure(ctx, path, &p, &f, &s));
    int present[GF_FIG_SHAPE_COUNT] = {0}, drawn_variant[max_variants] = {0};
    int n_skipped = 0;
    for (int i = 0; i < n_runs; ++i) {
        gf_fig_shape g = shape ? shape[i] : GF_FIG_SHAPE_UNDETERMINED;
        if ((int)g < 0 || g >= GF_FIG_SHAPE_COUNT)
            g = GF_FIG_SHAPE_UNDETERMINED;
        char tip[96];
        snprintf(tip, sizeof tip, "a = %.3g, Phi_i = %.3g (%s)", aspect_ratio_a[i], phi_initial[i], shape_names[g]);
        gf_svg_marker_style style = variant_style(opt, i, 11.0);
        if (gf_svg_marker_styled(s, &f, aspect_ratio_a[i], phi_initial[i], shape_markers[g], shape_colours[g], 11.0,
                                 &style, tip)) {
            present[g] = 1;
            drawn_variant[variant_of(opt, i)] = 1;
        } else {
            n_skipped++;
        }
    }
    gf_svg_legend_entry e[GF_FIG_SHAPE_COUNT + max_variants];
    int n_e = 0;
    static const gf_fig_shape order[] = {GF_FIG_SHAPE_TRIANGLE, GF_FIG_SHAPE_TRAPEZOID, GF_FIG_SHAPE_UNDETERMINED};
    for (int k = 0; k < GF_FIG_SHAPE_COUNT; ++k)
        if (present[order[k]])
            e[n_e++] = (gf_svg_legend_entry){shape_names[order[k]], shape_colours[order[k]], 0, shape_markers[order[k]],
                                             NULL, 0};
    char variant_text[max_variants][GF_FIG_VARIANT_LABEL_LEN];
    n_e += variant_legend(opt, drawn_variant, e + n_e, variant_text);
    gf_svg_legend(s, &f, 4, n_e, e);
    skipped_caption(s, &f, n_skipped, "a or Phi_i not finite");
    return gf_svg_close(&s);
}

/* ---------------------------------------------------------------- runout */

typedef struct runout_law {
    double lambda, exponent;
} runout_law;

static double runout_branch(double a, const void *user)
{
    const runout_law *l = user;
    return l->lambda * pow(a, l->exponent);
}

/* One branch l a^e drawn over [a_from, a_to] intersected with the x range. */
static void draw_branch(gf_svg *s, const gf_svg_frame *f, double lambda, double exponent, double a_from,
                        double a_to, const char *colour, const char *dash)
{
    a_from = fmax(a_from, f->x.lo);
    a_to = fmin(a_to, f->x.hi);
    if (!(a_to > a_from))
        return;
    enum { N = 64 };
    double x[N], y[N];
    runout_law l = {lambda, exponent};
    for (int i = 0; i < N; ++i) {
        double t = (double)i / (N - 1);
        x[i] = f->x.scale == GF_SVG_LOG ? a_from * pow(a_to / a_from, t) : a_from + (a_to - a_from) * t;
        y[i] = runout_branch(x[i], &l);
    }
    gf_svg_polyline(s, f, N, x, y, colour, 1.6, dash, "refline");
}

/* The legend names both branches: the published fits jump at a0. */
static const char *const lube_label = "Lube 2005 (dry): 1.2a | 1.9a^(2/3)";
static const char *const laj_label = "Lajeunesse 2005 (dry): 1.8a | 2.3a^(2/3)";

gf_status gf_fig_runout(gf_ctx *ctx, const char *path, const gf_fig_opts *opt, int n_runs,
                        const double *aspect_ratio_a, const double *runout_norm, const gf_fig_regime *regime)
{
    GF_TRY(check_arrays(ctx, "runout figure", path, n_runs, aspect_ratio_a, runout_norm));
    page p = page_of(opt, "Normalised runout against aspect ratio");
    gf_svg_frame f = frame_of(&p, (int)strlen(laj_label));
    gf_svg_scale xs = choose_scale(opt ? opt->x_scale : GF_FIG_SCALE_AUTO, n_runs, aspect_ratio_a);
    gf_svg_scale ys = choose_scale(opt ? opt->y_scale : GF_FIG_SCALE_AUTO, n_runs, runout_norm);
    double alo, ahi, rlo, rhi;
    data_range_or(n_runs, aspect_ratio_a, xs == GF_SVG_LOG, 0.5, 10.0, &alo, &ahi);
    data_range_or(n_runs, runout_norm, ys == GF_SVG_LOG, 0.5, 10.0, &rlo, &rhi);
    if (xs == GF_SVG_LINEAR)
        alo = fmin(alo, 0.0);
    if (ys == GF_SVG_LINEAR)
        rlo = fmin(rlo, 0.0);
    pad_range(xs, &alo, &ahi, xs == GF_SVG_LOG, 1);
    pad_range(ys, &rlo, &rhi, ys == GF_SVG_LOG, 1);
    set_axis(&f.x, xs, alo, ahi, "aspect ratio a = H0 / R0");
    set_axis(&f.y, ys, rlo, rhi, "normalised runout (R_inf - R0) / R0");

    gf_svg *s;
    GF_TRY(open_figure(ctx, path, &p, &f, &s));
    const char *lube = "#333333", *laj = "#b22222";
    /* Lube et al. 2005 give the change of regime as a range, a0 = 1.8-2.8: shade it (where the axis reaches it) */
    int transition_drawn = f.x.hi > 1.8 && f.x.lo < 2.8;
    if (transition_drawn) {
        double bx[4] = {1.8, 2.8, 2.8, 1.8}, by[4] = {f.y.lo, f.y.lo, f.y.hi, f.y.hi};
        gf_svg_region(s, &f, 4, bx, by, "#999999", 0.18);
    }
    double tiny = f.x.scale == GF_SVG_LOG ? f.x.lo : 0.0;
    /* Lube et al. 2005, switch at a0 = 2.3 (published 1.8-2.8) */
    draw_branch(s, &f, 1.2, 1.0, tiny, 2.3, lube, "7,4");
    draw_branch(s, &f, 1.9, 2.0 / 3.0, 2.3, f.x.hi, lube, "7,4");
    /* Lajeunesse et al. 2005, a0 = 3 */
    draw_branch(s, &f, 1.8, 1.0, tiny, 3.0, laj, "2,3");
    draw_branch(s, &f, 2.3, 2.0 / 3.0, 3.0, f.x.hi, laj, "2,3");

    int present[GF_FIG_REGIME_COUNT] = {0}, drawn_variant[max_variants] = {0};
    int n_skipped = plot_runs_by_regime(s, &f, opt, n_runs, aspect_ratio_a, runout_norm, regime, "a", "runout",
                                        present, drawn_variant);
    gf_svg_legend_entry e[GF_FIG_REGIME_COUNT + 3 + max_variants];
    int n_e = 0;
    if (regime)
        n_e = regime_legend(present, e);
    else if (present[GF_FIG_REGIME_UNDETERMINED])
        e[n_e++] = (gf_svg_legend_entry){"runs", palette[0], 0, GF_SVG_CIRCLE, NULL, 0};
    char variant_text[max_variants][GF_FIG_VARIANT_LABEL_LEN];
    n_e += variant_legend(opt, drawn_variant, e + n_e, variant_text);
    e[n_e++] = (gf_svg_legend_entry){lube_label, lube, 1, GF_SVG_CIRCLE, "7,4", 0};
    e[n_e++] = (gf_svg_legend_entry){laj_label, laj, 1, GF_SVG_CIRCLE, "2,3", 0};
    if (transition_drawn)
        e[n_e++] = (gf_svg_legend_entry){"Lube 2005 transition a0", "#999999", 2, GF_SVG_CIRCLE, NULL, 0};
    gf_svg_legend(s, &f, 4, n_e, e);
    skipped_caption(s, &f, n_skipped, ys == GF_SVG_LOG || xs == GF_SVG_LOG ? "not finite and > 0 on a log axis"
                                                                             : "not finite");
    return gf_svg_close(&s);
}

/* ---------------------------------------------------------------- time series */

/* Axes of a time-series plot from every finite sample (returns their count): x linear unless LOG
 * is asked (a time axis); y log when asked, or under AUTO when every value
 * is > 0 and they span at least 1.5 decades (energies decaying to rest). */
static int series_axes(const gf_fig_opts *opt, int n_series, const gf_fig_series *series, const char *x_label,
                        const char *y_label, gf_svg_frame *f)
{
    gf_fig_scale want_x = opt ? opt->x_scale : GF_FIG_SCALE_AUTO, want_y = opt ? opt->y_scale : GF_FIG_SCALE_AUTO;
    gf_svg_scale xs = want_x == GF_FIG_SCALE_LOG ? GF_SVG_LOG : GF_SVG_LINEAR;
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    double ypos_lo = INFINITY, ypos_hi = -INFINITY;
    int all_pos = 1, n_y = 0;
    for (int k = 0; k < n_series; ++k)
        for (int i = 0; i < series[k].n; ++i) {
            double x = series[k].x[i], y = series[k].y[i];
            if (!isfinite(x) || !isfinite(y) || (xs == GF_SVG_LOG && !(x > 0.0)))
                continue;
            xlo = fmin(xlo, x);
            xhi = fmax(xhi, x);
            ylo = fmin(ylo, y);
            yhi = fmax(yhi, y);
            n_y++;
            if (y > 0.0) {
                ypos_lo = fmin(ypos_lo, y);
                ypos_hi = fmax(ypos_hi, y);
            } else {
                all_pos = 0;
            }
        }
    gf_svg_scale ys = GF_SVG_LINEAR;
    if (want_y == GF_FIG_SCALE_LOG ||
        (want_y == GF_FIG_SCALE_AUTO && all_pos && n_y >= 2 && log10(ypos_hi / ypos_lo) >= 1.5))
        ys = GF_SVG_LOG;
    if (ys == GF_SVG_LOG) {
        ylo = ypos_lo;
        yhi = ypos_hi;
    }
    if (n_y == 0) {
        xlo = ylo = 0.0;
        xhi = yhi = 1.0;
    }
    set_axis(&f->x, xs, xlo, xhi, x_label);
    set_axis(&f->y, ys, ylo, yhi, y_label);
    return n_y;
}

gf_status gf_fig_timeseries(gf_ctx *ctx, const char *path, const gf_fig_opts *opt, const char *x_label,
                            const char *y_label, int n_series, const gf_fig_series *series)
{
    if (!path)
        return GF_FAIL(ctx, GF_ERR_ARG, "time-series figure: NULL output path");
    if (n_series < 1 || !series)
        return GF_FAIL(ctx, GF_ERR_ARG, "time-series figure %s: no series (n_series = %d)", path, n_series);
    for (int k = 0; k < n_series; ++k)
        if (series[k].n < 0 || (series[k].n > 0 && (!series[k].x || !series[k].y)))
            return GF_FAIL(ctx, GF_ERR_ARG, "time-series figure %s: series %d has n = %d and NULL data", path, k,
                           series[k].n);
    page p = page_of(opt, NULL);
    int legend_chars = 16;   /* "... and 99 more" */
    for (int k = 0; k < n_series && k < legend_max_rows; ++k)
        if (series[k].label && (int)strlen(series[k].label) > legend_chars)
            legend_chars = (int)strlen(series[k].label);
    if (legend_chars > 40)
        legend_chars = 40;   /* keep a frame; a longer label overflows the page, not the plot */
    gf_svg_frame f = frame_of(&p, legend_chars);
    int n_finite = series_axes(opt, n_series, series, x_label, y_label, &f);

    gf_svg *s;
    GF_TRY(open_figure(ctx, path, &p, &f, &s));
    /* a series with nothing drawn has no legend row; past legend_max_rows the
     * last row says how many more were drawn */
    gf_svg_legend_entry e[legend_max_rows];
    int n_rows = 0, n_drawn = 0, n_empty = 0;
    for (int k = 0; k < n_series; ++k) {
        const char *col = palette[k % 10];
        /* past ten curves, colours repeat: the dash pattern tells them apart */
        const char *dash = (k / 10) % 3 == 0 ? NULL : (k / 10) % 3 == 1 ? "6,3" : "2,2";
        if (gf_svg_polyline(s, &f, series[k].n, series[k].x, series[k].y, col, 1.8, dash, "curve") == 0) {
            n_empty++;
            continue;
        }
        if (n_rows < legend_max_rows)
            e[n_rows++] = (gf_svg_legend_entry){series[k].label ? series[k].label : "(unnamed)", col, 1, GF_SVG_CIRCLE,
                                                dash, 0};
        n_drawn++;
    }
    char more[48];
    if (n_drawn > n_rows) {
        n_rows = legend_max_rows - 1;
        snprintf(more, sizeof more, "... and %d more", n_drawn - n_rows);
        e[n_rows++] = (gf_svg_legend_entry){more, "white", 1, GF_SVG_CIRCLE, NULL, 0};
    }
    gf_svg_legend(s, &f, 4, n_rows, e);
    if (n_finite > 0 && n_empty > 0) {
        char cap[96];
        snprintf(cap, sizeof cap, "%d series not shown (no finite sample)", n_empty);
        gf_svg_caption(s, &f, cap);
    }
    if (n_finite == 0)
        gf_svg_caption(s, &f, "no finite sample to draw (every value is NaN or missing)");
    return gf_svg_close(&s);
}
