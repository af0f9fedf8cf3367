/*
 * Standalone SVG 1.1 plotting layer; see gf_svg.h for the model.
 *
 * Nice ticks (Heckbert, "Nice numbers for graph labels", Graphics Gems,
 * 1990): the raw step (hi - lo)/6 is rounded to 1, 2 or 5 times a power of
 * ten, so tick labels stay short and readable; a log axis ticks decades and
 * draws the 2..9 multiples as minor ticks. The pixel map is affine in the
 * axis variable (x or log10 x), which is what the tests invert.
 *
 * Numbers are written with %.2f (0.01 px is far below what any renderer
 * resolves) to keep files small and diff-able.
 */
#include "figures/gf_svg.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct gf_svg {
    gf_ctx *ctx;
    FILE *fp;
    char *path, *tmp;
    double width_px, height_px;
    int n_clip;           /* clip paths defined so far; the current one is n_clip */
};

static const double tick_major_px = 6.0, tick_minor_px = 3.0;
static const double font_px = 13.0;

/* ---------------------------------------------------------------- ticks */

static double nice_step(double range)
{
    double raw = range / 6.0;
    double mag = pow(10.0, floor(log10(raw)));
    double f = raw / mag;
    double m = f < 1.5 ? 1.0 : f < 3.0 ? 2.0 : f < 7.0 ? 5.0 : 10.0;
    return m * mag;
}

/* k * step without binary noise: step = m 10^e with integer m, so
 * (k m) / 10^-e is one correctly rounded division (0.57, not 0.5700000000000001). */
static double tick_value(double k, double step)
{
    double e = floor(log10(step) + 1e-9);
    double m = round(step / pow(10.0, e) * 4.0) / 4.0;   /* 1, 2, 2.5, 5 */
    double v = e < 0 ? k * m / pow(10.0, -e) : k * m * pow(10.0, e);
    return v == 0.0 ? 0.0 : v;   /* no -0 */
}

void gf_svg_nice_range(gf_svg_scale scale, double lo, double hi, double *nice_lo, double *nice_hi)
{
    if (scale == GF_SVG_LOG) {
        if (!(lo > 0.0) || !isfinite(lo))
            lo = 1.0;
        if (!(hi >= lo) || !isfinite(hi))
            hi = lo;
        double klo = floor(log10(lo) + 1e-9), khi = ceil(log10(hi) - 1e-9);
        if (khi <= klo)
            khi = klo + 1.0;
        *nice_lo = pow(10.0, klo);
        *nice_hi = pow(10.0, khi);
        return;
    }
    if (!isfinite(lo) || !isfinite(hi) || hi < lo) {
        lo = 0.0;
        hi = 1.0;
    }
    if (hi - lo <= 1e-12 * fmax(fabs(lo), fabs(hi))) {
        double pad = lo != 0.0 ? 0.1 * fabs(lo) : 1.0;
        lo -= pad;
        hi += pad;
    }
    /* Rounding outwards widens the range, which may change its own nice
     * step (4.1 -> [0, 4.5] would tick by 1 and end between ticks): repeat
     * until the range is a whole number of its own steps (2-3 passes). */
    double step = nice_step(hi - lo);
    for (int pass = 0; pass < 4; ++pass) {
        *nice_lo = floor(lo / step + 1e-9) * step;
        *nice_hi = ceil(hi / step - 1e-9) * step;
        double again = nice_step(*nice_hi - *nice_lo);
        if (fabs(again - step) <= 1e-12 * step)
            break;
        step = again;
    }
}

void gf_svg_ticks_compute(gf_svg_scale scale, double lo, double hi, gf_svg_ticks *t)
{
    t->n_major = t->n_minor = 0;
    if (!(hi > lo) || !isfinite(lo) || !isfinite(hi))
        return;
    if (scale == GF_SVG_LOG) {
        if (!(lo > 0.0))
            return;
        int klo = (int)ceil(log10(lo) - 1e-9), khi = (int)floor(log10(hi) + 1e-9);
        int n_dec = khi - klo + 1;
        int stride = n_dec > 12 ? (n_dec + 7) / 8 : 1;
        for (int k = klo; k <= khi && t->n_major < GF_SVG_MAX_TICKS; k += stride)
            t->major[t->n_major++] = pow(10.0, k);
        if (stride == 1)
            for (int k = klo - 1; k <= khi; ++k)
                for (int m = 2; m <= 9; ++m) {
                    double v = m * pow(10.0, k);
                    if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9) && t->n_minor < GF_SVG_MAX_TICKS)
                        t->minor[t->n_minor++] = v;
                }
        return;
    }
    double step = nice_step(hi - lo);
    double eps = 1e-9 * step;
    for (double k = ceil((lo - eps) / step); k * step <= hi + eps && t->n_major < GF_SVG_MAX_TICKS; k += 1.0)
        t->major[t->n_major++] = tick_value(k, step);
    /* minors: halves of a 1- or 5-step, quarters of a 2-step */
    double m10 = step / pow(10.0, floor(log10(step) + 1e-9));
    double minor = (fabs(m10 - 2.0) < 1e-6) ? step / 4.0 : step / 5.0;
    for (double k = ceil((lo - eps) / minor); k * minor <= hi + eps && t->n_minor < GF_SVG_MAX_TICKS; k += 1.0) {
        double v = tick_value(k, minor);
        double r = v / step;
        if (fabs(r - round(r)) > 1e-6)
            t->minor[t->n_minor++] = v;
    }
}

void gf_svg_tick_label(gf_svg_scale scale, double v, char *buf, int len)
{
    if (scale == GF_SVG_LOG) {
        double k = round(log10(v));
        if (fabs(v / pow(10.0, k) - 1.0) < 1e-9 && fabs(k) >= 4) {
            snprintf(buf, (size_t)len, "10^%d", (int)k);
            return;
        }
    }
    snprintf(buf, (size_t)len, "%g", v);
}

/* ---------------------------------------------------------------- mapping */

static double axis_t(const gf_svg_axis *a, double v)
{
    return a->scale == GF_SVG_LOG ? log10(v) : v;
}

static int axis_ok(const gf_svg_axis *a, double v)
{
    return isfinite(v) && (a->scale != GF_SVG_LOG || v > 0.0);
}

double gf_svg_map_x(const gf_svg_frame *f, double x)
{
    const gf_svg_axis *a = &f->x;
    return f->x0_px + f->w_px * (axis_t(a, x) - axis_t(a, a->lo)) / (axis_t(a, a->hi) - axis_t(a, a->lo));
}

double gf_svg_map_y(const gf_svg_frame *f, double y)
{
    const gf_svg_axis *a = &f->y;
    return f->y0_px + f->h_px - f->h_px * (axis_t(a, y) - axis_t(a, a->lo)) / (axis_t(a, a->hi) - axis_t(a, a->lo));
}

/* ---------------------------------------------------------------- file */

gf_status gf_svg_open(gf_ctx *ctx, const char *path, double width_px, double height_px, gf_svg **out)
{
    *out = NULL;
    if (!path || !*path)
        return GF_FAIL(ctx, GF_ERR_ARG, "svg: empty output path");
    if (!(width_px > 0.0) || !(height_px > 0.0))
        return GF_FAIL(ctx, GF_ERR_ARG, "svg %s: size must be > 0 (got %g x %g)", path, width_px, height_px);
    gf_svg *s = calloc(1, sizeof *s);
    if (!s)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "svg %s: out of memory", path);
    s->ctx = ctx;
    s->width_px = width_px;
    s->height_px = height_px;
    s->path = strdup(path);
    s->tmp = malloc(strlen(path) + 5);
    if (!s->path || !s->tmp) {
        free(s->path);
        free(s->tmp);
        free(s);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "svg %s: out of memory", path);
    }
    sprintf(s->tmp, "%s.tmp", path);
    s->fp = fopen(s->tmp, "w");
    if (!s->fp) {
        gf_status st = GF_FAIL(ctx, GF_ERR_IO, "svg: cannot create %s: %s", s->tmp, strerror(errno));
        free(s->path);
        free(s->tmp);
        free(s);
        return st;
    }
    fprintf(s->fp,
            "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%.0f\" height=\"%.0f\" "
            "viewBox=\"0 0 %.0f %.0f\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" "
            "font-size=\"%.0f\">\n"
            "<rect class=\"background\" x=\"0\" y=\"0\" width=\"%.0f\" height=\"%.0f\" fill=\"white\"/>\n",
            width_px, height_px, width_px, height_px, font_px, width_px, height_px);
    *out = s;
    return GF_OK;
}

static void svg_free(gf_svg *s)
{
    free(s->path);
    free(s->tmp);
    free(s);
}

gf_status gf_svg_close(gf_svg **ps)
{
    if (!ps || !*ps)
        return GF_OK;
    gf_svg *s = *ps;
    *ps = NULL;
    fputs("</svg>\n", s->fp);
    int bad = ferror(s->fp);
    int err = errno;
    if (fclose(s->fp) != 0) {
        bad = 1;
        err = errno;
    }
    gf_status st = GF_OK;
    if (bad) {
        st = GF_FAIL(s->ctx, GF_ERR_IO, "svg: write to %s failed: %s", s->tmp, strerror(err));
        remove(s->tmp);
    } else if (rename(s->tmp, s->path) != 0) {
        st = GF_FAIL(s->ctx, GF_ERR_IO, "svg: cannot rename %s to %s: %s", s->tmp, s->path, strerror(errno));
        remove(s->tmp);
    }
    svg_free(s);
    return st;
}

void gf_svg_abort(gf_svg **ps)
{
    if (!ps || !*ps)
        return;
    gf_svg *s = *ps;
    *ps = NULL;
    fclose(s->fp);
    remove(s->tmp);
    svg_free(s);
}

void gf_svg_write_escaped(gf_svg *s, const char *text)
{
    if (!text)
        return;
    for (const char *c = text; *c; ++c) {
        switch (*c) {
        case '&': fputs("&amp;", s->fp); break;
        case '<': fputs("&lt;", s->fp); break;
        case '>': fputs("&gt;", s->fp); break;
        case '"': fputs("&quot;", s->fp); break;
        case '\'': fputs("&apos;", s->fp); break;
        default:
            /* control characters are not allowed in XML 1.0 text */
            if ((unsigned char)*c < 0x20 && *c != '\t' && *c != '\n')
                fputc(' ', s->fp);
            else
                fputc(*c, s->fp);
        }
    }
}

/* ---------------------------------------------------------------- drawing */

static void text_el(gf_svg *s, double x, double y, const char *anchor, double size, const char *colour,
                    const char *cls, const char *extra, const char *text)
{
    fprintf(s->fp, "<text class=\"%s\" x=\"%.2f\" y=\"%.2f\" text-anchor=\"%s\" font-size=\"%.1f\" fill=\"%s\"%s%s>",
            cls, x, y, anchor, size, colour ? colour : "black", extra ? " " : "", extra ? extra : "");
    gf_svg_write_escaped(s, text);
    fputs("</text>\n", s->fp);
}

void gf_svg_title(gf_svg *s, const gf_svg_frame *f, const char *title)
{
    if (title)
        text_el(s, f->x0_px + 0.5 * f->w_px, f->y0_px - 18.0, "middle", font_px + 3.0, "black", "title", NULL,
                title);
}

void gf_svg_caption(gf_svg *s, const gf_svg_frame *f, const char *text)
{
    if (text)
        text_el(s, f->x0_px, f->y0_px + f->h_px + 64.0, "start", font_px - 2.0, "#555555", "caption", NULL, text);
}

/* A tick label: plain text, or "10" with a superscript exponent for large decades. */
static void tick_label(gf_svg *s, gf_svg_scale scale, double v, double x, double y, const char *anchor)
{
    char buf[48], extra[64];
    gf_svg_tick_label(scale, v, buf, sizeof buf);
    snprintf(extra, sizeof extra, "data-value=\"%.17g\"", v);
    if (strncmp(buf, "10^", 3) == 0) {
        fprintf(s->fp,
                "<text class=\"tick-label\" x=\"%.2f\" y=\"%.2f\" text-anchor=\"%s\" font-size=\"%.1f\" %s>10"
                "<tspan font-size=\"%.1f\" dy=\"-5\">%s</tspan></text>\n",
                x, y, anchor, font_px - 1.0, extra, font_px - 3.0, buf + 3);
        return;
    }
    text_el(s, x, y, anchor, font_px - 1.0, "black", "tick-label", extra, buf);
}

static void axis_ticks(gf_svg *s, const gf_svg_frame *f, int is_x)
{
    const gf_svg_axis *a = is_x ? &f->x : &f->y;
    gf_svg_ticks t;
    gf_svg_ticks_compute(a->scale, a->lo, a->hi, &t);
    double xb = f->x0_px, yb = f->y0_px + f->h_px;
    fprintf(s->fp, "<g class=\"%s-axis\" stroke=\"black\" stroke-width=\"1\">\n", is_x ? "x" : "y");
    for (int i = 0; i < t.n_minor; ++i) {
        if (is_x) {
            double px = gf_svg_map_x(f, t.minor[i]);
            fprintf(s->fp, "<line class=\"tick-minor\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", px, yb,
                    px, yb + tick_minor_px);
        } else {
            double py = gf_svg_map_y(f, t.minor[i]);
            fprintf(s->fp, "<line class=\"tick-minor\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", xb, py,
                    xb - tick_minor_px, py);
        }
    }
    for (int i = 0; i < t.n_major; ++i) {
        if (is_x) {
            double px = gf_svg_map_x(f, t.major[i]);
            fprintf(s->fp,
                    "<line class=\"grid\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#dddddd\"/>\n"
                    "<line class=\"tick-major\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n",
                    px, f->y0_px, px, yb, px, yb, px, yb + tick_major_px);
        } else {
            double py = gf_svg_map_y(f, t.major[i]);
            fprintf(s->fp,
                    "<line class=\"grid\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#dddddd\"/>\n"
                    "<line class=\"tick-major\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n",
                    xb, py, xb + f->w_px, py, xb, py, xb - tick_major_px, py);
        }
    }
    fputs("</g>\n", s->fp);
    fprintf(s->fp, "<g class=\"%s-tick-labels\" stroke=\"none\">\n", is_x ? "x" : "y");
    for (int i = 0; i < t.n_major; ++i) {
        if (is_x)
            tick_label(s, a->scale, t.major[i], gf_svg_map_x(f, t.major[i]), yb + tick_major_px + 14.0, "middle");
        else
            tick_label(s, a->scale, t.major[i], xb - tick_major_px - 4.0, gf_svg_map_y(f, t.major[i]) + 4.5,
                       "end");
    }
    fputs("</g>\n", s->fp);
}

void gf_svg_axes(gf_svg *s, const gf_svg_frame *f)
{
    s->n_clip++;
    fprintf(s->fp,
            "<defs><clipPath id=\"frame%d\"><rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\"/>"
            "</clipPath></defs>\n",
            s->n_clip, f->x0_px, f->y0_px, f->w_px, f->h_px);
    axis_ticks(s, f, 1);
    axis_ticks(s, f, 0);
    fprintf(s->fp,
            "<rect class=\"frame\" x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"none\" "
            "stroke=\"black\" stroke-width=\"1.2\"/>\n",
            f->x0_px, f->y0_px, f->w_px, f->h_px);
    if (f->x.label)
        text_el(s, f->x0_px + 0.5 * f->w_px, f->y0_px + f->h_px + 42.0, "middle", font_px, "black", "axis-label",
                NULL, f->x.label);
    if (f->y.label) {
        double cx = f->x0_px - 58.0, cy = f->y0_px + 0.5 * f->h_px;
        char extra[96];
        snprintf(extra, sizeof extra, "transform=\"rotate(-90 %.2f %.2f)\"", cx, cy);
        text_el(s, cx, cy, "middle", font_px, "black", "axis-label", extra, f->y.label);
    }
}

static void marker_shape(gf_svg *s, gf_svg_marker_shape shape, double size)
{
    double r = 0.5 * size;
    switch (shape) {
    case GF_SVG_SQUARE:
        fprintf(s->fp, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\"/>", -0.85 * r, -0.85 * r,
                1.7 * r, 1.7 * r);
        break;
    case GF_SVG_TRIANGLE:
        /* centroid at the origin: vertices at distance 1.15 r */
        fprintf(s->fp, "<polygon points=\"0,%.2f %.2f,%.2f %.2f,%.2f\"/>", -1.15 * r, 0.996 * r, 0.575 * r,
                -0.996 * r, 0.575 * r);
        break;
    default:
        fprintf(s->fp, "<circle cx=\"0\" cy=\"0\" r=\"%.2f\"/>", r);
    }
}

int gf_svg_marker(gf_svg *s, const gf_svg_frame *f, double x, double y, gf_svg_marker_shape shape,
                  const char *colour, double size_px, const char *tooltip)
{
    return gf_svg_marker_styled(s, f, x, y, shape, colour, size_px, NULL, tooltip);
}

/* Fill and stroke of a marker: filled with its colour, or outlined in it. */
static void marker_paint(gf_svg *s, const char *colour, int hollow)
{
    if (hollow)
        fprintf(s->fp, "fill=\"white\" fill-opacity=\"0.9\" stroke=\"%s\" stroke-width=\"2\"", colour);
    else
        fprintf(s->fp, "fill=\"%s\" fill-opacity=\"0.85\" stroke=\"black\" stroke-width=\"0.6\"", colour);
}

int gf_svg_marker_styled(gf_svg *s, const gf_svg_frame *f, double x, double y, gf_svg_marker_shape shape,
                         const char *colour, double size_px, const gf_svg_marker_style *style, const char *tooltip)
{
    if (!axis_ok(&f->x, x) || !axis_ok(&f->y, y))
        return 0;
    double px = gf_svg_map_x(f, x), py = gf_svg_map_y(f, y);
    /* a point outside the frame (user-set range) is not drawn on the labels */
    double tol = 0.5;
    if (px < f->x0_px - tol || px > f->x0_px + f->w_px + tol || py < f->y0_px - tol || py > f->y0_px + f->h_px + tol)
        return 0;
    double dx = style ? style->dx_px : 0.0;
    fprintf(s->fp, "<g class=\"marker\" transform=\"translate(%.2f,%.2f)\" data-x=\"%.17g\" data-y=\"%.17g\" ",
            px + dx, py, x, y);
    if (dx != 0.0)
        fprintf(s->fp, "data-dx=\"%.2f\" ", dx);
    marker_paint(s, colour, style && style->hollow);
    fputc('>', s->fp);
    if (tooltip) {
        fputs("<title>", s->fp);
        gf_svg_write_escaped(s, tooltip);
        fputs("</title>", s->fp);
    }
    marker_shape(s, shape, size_px);
    fputs("</g>\n", s->fp);
    return 1;
}

static void polyline_open(gf_svg *s, const char *colour, double width_px, const char *dash, const char *cls)
{
    fprintf(s->fp, "<polyline class=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"%.2f\"", cls ? cls : "curve",
            colour, width_px);
    if (dash)
        fprintf(s->fp, " stroke-dasharray=\"%s\"", dash);
    fprintf(s->fp, " stroke-linejoin=\"round\" clip-path=\"url(#frame%d)\" points=\"", s->n_clip);
}

int gf_svg_polyline(gf_svg *s, const gf_svg_frame *f, int n, const double *x, const double *y, const char *colour,
                    double width_px, const char *dash, const char *cls)
{
    int n_lines = 0, in_line = 0, n_pts = 0;
    for (int i = 0; i <= n; ++i) {
        int ok = i < n && axis_ok(&f->x, x[i]) && axis_ok(&f->y, y[i]);
        if (ok) {
            if (!in_line) {
                polyline_open(s, colour, width_px, dash, cls);
                in_line = 1;
                n_pts = 0;
            }
            fprintf(s->fp, "%s%.2f,%.2f", n_pts ? " " : "", gf_svg_map_x(f, x[i]), gf_svg_map_y(f, y[i]));
            n_pts++;
        } else if (in_line) {
            fputs("\"/>\n", s->fp);
            in_line = 0;
            n_lines++;
        }
    }
    return n_lines;
}

int gf_svg_function(gf_svg *s, const gf_svg_frame *f, gf_svg_fn *fn, const void *user, int n, const char *colour,
                    double width_px, const char *dash, const char *cls)
{
    if (n < 2)
        n = 2;
    double *x = malloc(2 * (size_t)n * sizeof *x);
    if (!x)
        return 0;
    double *y = x + n;
    double tlo = axis_t(&f->x, f->x.lo), thi = axis_t(&f->x, f->x.hi);
    for (int i = 0; i < n; ++i) {
        double t = tlo + (thi - tlo) * i / (n - 1);
        x[i] = f->x.scale == GF_SVG_LOG ? pow(10.0, t) : t;
        y[i] = fn(x[i], user);
    }
    int k = gf_svg_polyline(s, f, n, x, y, colour, width_px, dash, cls);
    free(x);
    return k;
}

void gf_svg_region(gf_svg *s, const gf_svg_frame *f, int n, const double *x, const double *y, const char *fill,
                   double opacity)
{
    fprintf(s->fp, "<polygon class=\"region\" fill=\"%s\" fill-opacity=\"%.3f\" stroke=\"none\" "
                   "clip-path=\"url(#frame%d)\" points=\"",
            fill, opacity, s->n_clip);
    int first = 1;
    for (int i = 0; i < n; ++i) {
        if (!axis_ok(&f->x, x[i]) || !axis_ok(&f->y, y[i]))
            continue;
        fprintf(s->fp, "%s%.2f,%.2f", first ? "" : " ", gf_svg_map_x(f, x[i]), gf_svg_map_y(f, y[i]));
        first = 0;
    }
    fputs("\"/>\n", s->fp);
}

void gf_svg_text_data(gf_svg *s, const gf_svg_frame *f, double x, double y, const char *anchor, double size_px,
                      const char *colour, const char *text)
{
    if (!axis_ok(&f->x, x) || !axis_ok(&f->y, y))
        return;
    char extra[48];
    snprintf(extra, sizeof extra, "clip-path=\"url(#frame%d)\"", s->n_clip);
    text_el(s, gf_svg_map_x(f, x), gf_svg_map_y(f, y), anchor, size_px, colour, "annotation", extra, text);
}

double gf_svg_legend_width_px(int longest_label_chars)
{
    /* 0.56 em per character: DejaVu Sans measures ~0.51 em on mixed text,
     * the margin keeps the box around wider glyph mixes */
    return 2.0 * 8.0 + 26.0 + 6.0 + 0.56 * (font_px - 1.0) * (double)longest_label_chars;
}

void gf_svg_legend(gf_svg *s, const gf_svg_frame *f, int corner, int n, const gf_svg_legend_entry *e)
{
    if (n <= 0)
        return;
    const double row = 18.0, pad = 8.0, sample = 26.0, fsz = font_px - 1.0;
    size_t longest = 0;
    for (int i = 0; i < n; ++i)
        if (e[i].label && strlen(e[i].label) > longest)
            longest = strlen(e[i].label);
    double w = gf_svg_legend_width_px((int)longest), h = 2.0 * pad + row * n;
    double x0, y0;
    switch (corner) {
    case 1: x0 = f->x0_px + f->w_px - w - 8.0; y0 = f->y0_px + 8.0; break;
    case 2: x0 = f->x0_px + 8.0; y0 = f->y0_px + f->h_px - h - 8.0; break;
    case 3: x0 = f->x0_px + f->w_px - w - 8.0; y0 = f->y0_px + f->h_px - h - 8.0; break;
    case 4: x0 = f->x0_px + f->w_px + 14.0; y0 = f->y0_px; break;   /* outside, right of the frame */
    default: x0 = f->x0_px + 8.0; y0 = f->y0_px + 8.0;
    }
    fprintf(s->fp, "<g class=\"legend\">\n<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"white\" "
                   "fill-opacity=\"0.9\" stroke=\"#888888\" stroke-width=\"0.8\"/>\n",
            x0, y0, w, h);
    for (int i = 0; i < n; ++i) {
        double cy = y0 + pad + row * (i + 0.5), sx = x0 + pad;
        if (e[i].kind == 2) {
            fprintf(s->fp, "<rect class=\"legend-patch\" x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"10\" "
                           "fill=\"%s\" fill-opacity=\"0.35\" stroke=\"none\"/>\n",
                    sx, cy - 5.0, sample, e[i].colour);
        } else if (e[i].kind == 1) {
            fprintf(s->fp, "<line class=\"legend-line\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" "
                           "stroke-width=\"2\"%s%s%s/>\n",
                    sx, cy, sx + sample, cy, e[i].colour, e[i].dash ? " stroke-dasharray=\"" : "",
                    e[i].dash ? e[i].dash : "", e[i].dash ? "\"" : "");
        } else {
            fprintf(s->fp, "<g class=\"legend-marker\" transform=\"translate(%.2f,%.2f)\" ", sx + 0.5 * sample, cy);
            marker_paint(s, e[i].colour, e[i].hollow);
            fputc('>', s->fp);
            marker_shape(s, e[i].shape, 9.0);
            fputs("</g>\n", s->fp);
        }
        text_el(s, sx + sample + 6.0, cy + 4.5, "start", fsz, "black", "legend-label", NULL, e[i].label);
    }
    fputs("</g>\n", s->fp);
}
