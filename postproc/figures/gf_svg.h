/*
 * A small plotting layer writing standalone SVG 1.1 files.
 *
 * Model: a figure is one page (width x height px) holding one plot frame.
 * A frame maps data coordinates to pixels by two axes, each linear or
 * logarithmic (base 10):
 *     px = x0 + w (t(x) - t(lo)) / (t(hi) - t(lo)),  t = identity or log10,
 * with y pointing up (SVG y grows downwards, so py = y0 + h - ...).
 * Ticks: "nice" 1-2-5 steps on linear axes (Heckbert, Graphics Gems 1990),
 * decades with minor ticks at 2..9 on log axes. Everything drawn inside the
 * frame is clipped to it (clipPath), so a reference line that leaves the
 * plot cannot run over the labels.
 *
 * Every element carries a class ("marker", "curve", "refline", "region",
 * "tick-label", ...) and markers carry data-x / data-y with the plotted
 * value, so that tests can parse the file as XML and find what was drawn.
 * Text is escaped (&, <, >, ", '). The file is written to "<path>.tmp" and
 * renamed by gf_svg_close; gf_svg_abort removes it.
 */
#ifndef GF_SVG_H
#define GF_SVG_H

#include "core/gf_status.h"

typedef struct gf_svg gf_svg;

typedef enum gf_svg_scale { GF_SVG_LINEAR = 0, GF_SVG_LOG } gf_svg_scale;
typedef enum gf_svg_marker_shape { GF_SVG_CIRCLE = 0, GF_SVG_SQUARE, GF_SVG_TRIANGLE } gf_svg_marker_shape;

typedef struct gf_svg_axis {
    gf_svg_scale scale;
    double lo, hi;          /* data range shown; lo < hi, both > 0 on a log axis */
    const char *label;      /* with units, e.g. "Stokes number St (1)" */
} gf_svg_axis;

/* Pixel frame of the plot and its two axes (plain data). */
typedef struct gf_svg_frame {
    double x0_px, y0_px, w_px, h_px;   /* top-left corner and size */
    gf_svg_axis x, y;
} gf_svg_frame;

#define GF_SVG_MAX_TICKS 64

typedef struct gf_svg_ticks {
    int n_major, n_minor;
    double major[GF_SVG_MAX_TICKS];
    double minor[GF_SVG_MAX_TICKS];
} gf_svg_ticks;

/* Ticks inside [lo, hi]: 1-2-5 steps aiming at about 5..8 majors (linear),
 * decades plus 2..9 minors (log; when the range spans more than 12 decades
 * the majors skip decades and minors are dropped). */
void gf_svg_ticks_compute(gf_svg_scale scale, double lo, double hi, gf_svg_ticks *out);
/* "Nice" range that encloses [lo, hi] (linear: multiples of the tick step;
 * log: whole decades). Degenerate or empty ranges are widened. */
void gf_svg_nice_range(gf_svg_scale scale, double lo, double hi, double *nice_lo, double *nice_hi);
/* Tick label text: "0.5", "10", "1e+06" (%g); log decades as "10^k" for |k| >= 4, else plain. */
void gf_svg_tick_label(gf_svg_scale scale, double value, char *buf, int len);

/* Data -> pixel. */
double gf_svg_map_x(const gf_svg_frame *f, double x);
double gf_svg_map_y(const gf_svg_frame *f, double y);

/* Creates "<path>.tmp" and writes the SVG header. Returns owned handle. */
gf_status gf_svg_open(gf_ctx *ctx, const char *path, double width_px, double height_px, gf_svg **out);
/* Writes the closing tag, closes and renames into place. Accepts NULL *s. */
gf_status gf_svg_close(gf_svg **s);
/* Closes and removes the temporary file. Accepts NULL *s. */
void gf_svg_abort(gf_svg **s);

/* Title above the frame, centred. */
void gf_svg_title(gf_svg *s, const gf_svg_frame *f, const char *title);
/* Frame, grid-less ticks, tick labels and axis labels; defines the clip path. */
void gf_svg_axes(gf_svg *s, const gf_svg_frame *f);
/* Caption line below the x-axis label (small, grey), e.g. "3 runs skipped". */
void gf_svg_caption(gf_svg *s, const gf_svg_frame *f, const char *text);

/* A marker at data (x, y); skipped (returns 0) when it cannot be mapped
 * (non-finite, or <= 0 on a log axis); 1 when drawn. tooltip may be NULL. */
int gf_svg_marker(gf_svg *s, const gf_svg_frame *f, double x, double y, gf_svg_marker_shape shape,
                  const char *colour, double size_px, const char *tooltip);
/* How a marker is drawn: filled with its colour (hollow = 0), or outlined in
 * it on white (hollow = 1); shifted by dx_px from its data position, so that
 * runs of several variants at one data point stand side by side (the
 * element keeps the data position in data-x, data-y). */
typedef struct gf_svg_marker_style {
    int hollow;
    double dx_px;
} gf_svg_marker_style;
int gf_svg_marker_styled(gf_svg *s, const gf_svg_frame *f, double x, double y, gf_svg_marker_shape shape,
                         const char *colour, double size_px, const gf_svg_marker_style *style, const char *tooltip);
/* Polyline through the points; non-mappable points break it into pieces.
 * dash: NULL solid, else an SVG dash array, e.g. "6,4". cls: CSS class
 * ("curve", "refline"). Returns the number of <polyline> elements written. */
int gf_svg_polyline(gf_svg *s, const gf_svg_frame *f, int n, const double *x, const double *y, const char *colour,
                    double width_px, const char *dash, const char *cls);
/* y = f(x) sampled at n points across the x range (log-spaced on a log axis). */
typedef double gf_svg_fn(double x, const void *user);
int gf_svg_function(gf_svg *s, const gf_svg_frame *f, gf_svg_fn *fn, const void *user, int n, const char *colour,
                    double width_px, const char *dash, const char *cls);
/* Shaded polygon (data coordinates), clipped to the frame. */
void gf_svg_region(gf_svg *s, const gf_svg_frame *f, int n, const double *x, const double *y, const char *fill,
                   double opacity);
/* Text at data coordinates (clipped to the frame), anchor "start"/"middle"/"end". */
void gf_svg_text_data(gf_svg *s, const gf_svg_frame *f, double x, double y, const char *anchor, double size_px,
                      const char *colour, const char *text);

typedef struct gf_svg_legend_entry {
    const char *label;
    const char *colour;
    int kind;                        /* 0: marker, 1: line, 2: shaded patch */
    gf_svg_marker_shape shape;       /* kind 0 */
    const char *dash;                /* kind 1: NULL solid */
    int hollow;                      /* kind 0: outlined, as gf_svg_marker_style */
} gf_svg_legend_entry;

/* Width of the legend box for labels of at most that many characters
 * (to reserve room for an outside legend before placing the frame). */
double gf_svg_legend_width_px(int longest_label_chars);
/* Legend box in a corner of the frame: corner 0 top-left, 1 top-right,
 * 2 bottom-left, 3 bottom-right, 4 outside, right of the frame. */
void gf_svg_legend(gf_svg *s, const gf_svg_frame *f, int corner, int n, const gf_svg_legend_entry *entries);

/* Writes text with XML escaping (&, <, >, ", '). */
void gf_svg_write_escaped(gf_svg *s, const char *text);

#endif
