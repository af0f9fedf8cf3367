/*
 * Accuracy benchmark figure: error against run time for the settings of one
 * scene (workflows/bench/accuracy), log-log.
 *
 * A setting is Pareto-optimal when no other setting is at the same time
 * cheaper (or as cheap) and more accurate (or as accurate), one of the two
 * strictly: the front is the set of settings worth running, and the
 * recommended default is the cheapest one on it whose error is within the
 * scene's tolerance (chosen by the caller, drawn here as a ring).
 * The front is drawn as a staircase through its points in order of
 * increasing cost: along the front the error falls as the cost grows (by
 * construction), and the step shows that between two front points nothing
 * better is on offer than the cheaper one.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "figures/gf_figures.h"
#include "figures/gf_svg.h"

/* Errors equal to 1e-9 relative are ties: two averages of the same integers
 * (a front measured in whole bins, say) differ in their last bits only. */
static int err_le(double a, double b) { return a <= b + 1e-9 * fabs(b); }
static int err_lt(double a, double b) { return a < b - 1e-9 * fabs(b); }

int gf_fig_pareto_front(int n, const double *cost, const double *error, unsigned char *on_front)
{
    int count = 0;
    for (int i = 0; i < n; ++i) {
        int ok = isfinite(cost[i]) && isfinite(error[i]);
        for (int j = 0; ok && j < n; ++j) {
            if (j == i || !isfinite(cost[j]) || !isfinite(error[j]))
                continue;
            if (cost[j] <= cost[i] && err_le(error[j], error[i]) && (cost[j] < cost[i] || err_lt(error[j], error[i])))
                ok = 0;
        }
        if (on_front)
            on_front[i] = (unsigned char)ok;
        count += ok;
    }
    return count;
}

/* x shifted right by dx_px pixels on a log axis (labels beside their marker). */
static double shift_log(const gf_svg_axis *a, double w_px, double x, double d_px)
{
    return x * pow(10.0, d_px / w_px * (log10(a->hi) - log10(a->lo)));
}

gf_status gf_fig_pareto(gf_ctx *ctx, const char *path, const gf_fig_opts *opt, int n, const double *time_s,
                        const double *error, const char *const *labels, const char *time_label,
                        const char *error_label, double tolerance, int recommended, unsigned char *on_front)
{
    if (n < 0 || (n > 0 && (!time_s || !error)))
        return GF_FAIL(ctx, GF_ERR_ARG, "pareto figure %s: need n >= 0 and time/error arrays (n = %d)",
                       path ? path : "(null)", n);
    if (!path)
        return GF_FAIL(ctx, GF_ERR_ARG, "pareto figure: path is NULL");
    unsigned char *front = calloc((size_t)(n > 0 ? n : 1), 1);
    int *order = malloc(sizeof(int) * (size_t)(n > 0 ? n : 1));
    if (!front || !order) {
        free(front), free(order);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "pareto figure %s: out of memory", path);
    }
    gf_fig_pareto_front(n, time_s, error, front);
    if (on_front)
        memcpy(on_front, front, (size_t)n);

    /* axes: every plottable value, plus the tolerance line */
    double tlo = INFINITY, thi = -INFINITY, elo = INFINITY, ehi = -INFINITY;
    int n_skipped = 0, longest = 0;
    for (int i = 0; i < n; ++i) {
        if (!(isfinite(time_s[i]) && time_s[i] > 0.0 && isfinite(error[i]) && error[i] > 0.0)) {
            n_skipped++;
            continue;
        }
        tlo = fmin(tlo, time_s[i]), thi = fmax(thi, time_s[i]);
        elo = fmin(elo, error[i]), ehi = fmax(ehi, error[i]);
    }
    if (isfinite(tolerance) && tolerance > 0.0)
        elo = fmin(elo, tolerance), ehi = fmax(ehi, tolerance);
    if (!(tlo <= thi))
        tlo = 1e-3, thi = 1.0;
    if (!(elo <= ehi))
        elo = 1e-3, ehi = 1.0;

    double width = opt && opt->width_px > 0 ? opt->width_px : 820.0;
    double height = opt && opt->height_px > 0 ? opt->height_px : 580.0;
    gf_svg_legend_entry leg[4] = {
        {"setting", "#8c8c8c", 0, GF_SVG_CIRCLE, NULL, 0},
        {"Pareto front", "#d62728", 1, GF_SVG_CIRCLE, NULL, 0},
        {"tolerance", "#1f77b4", 1, GF_SVG_CIRCLE, "6,4", 0},
        {"recommended", "#ffbf00", 0, GF_SVG_SQUARE, NULL, 0},
    };
    longest = (int)strlen("Pareto front");
    gf_svg_frame f;
    memset(&f, 0, sizeof f);
    f.x0_px = 88.0;
    f.y0_px = 48.0;
    f.w_px = fmax(160.0, width - f.x0_px - 14.0 - gf_svg_legend_width_px(longest) - 12.0);
    f.h_px = fmax(160.0, height - f.y0_px - 86.0);
    f.x.scale = f.y.scale = GF_SVG_LOG;
    /* one decade of margin on the right of time, for the labels */
    gf_svg_nice_range(GF_SVG_LOG, tlo / 1.5, thi * 6.0, &f.x.lo, &f.x.hi);
    gf_svg_nice_range(GF_SVG_LOG, elo / 1.5, ehi * 1.5, &f.y.lo, &f.y.hi);
    f.x.label = time_label ? time_label : "run time (s)";
    f.y.label = error_label ? error_label : "error (1)";

    gf_svg *s;
    gf_status st = gf_svg_open(ctx, path, width, height, &s);
    if (st != GF_OK) {
        free(front), free(order);
        return st;
    }
    gf_svg_title(s, &f, opt && opt->title ? opt->title : "Error against run time");
    gf_svg_axes(s, &f);
    if (isfinite(tolerance) && tolerance > 0.0) {
        double tx[2] = {f.x.lo, f.x.hi}, ty[2] = {tolerance, tolerance};
        gf_svg_polyline(s, &f, 2, tx, ty, "#1f77b4", 1.4, "6,4", "refline");
    }
    /* front, in order of increasing cost (insertion sort: a few dozen settings) */
    int n_front = 0;
    for (int i = 0; i < n; ++i) {
        if (!front[i])
            continue;
        int k = n_front++;
        while (k > 0 && time_s[order[k - 1]] > time_s[i]) {
            order[k] = order[k - 1];
            --k;
        }
        order[k] = i;
    }
    if (n_front > 1) {
        /* staircase: (t_k, e_k) -> (t_{k+1}, e_k) -> (t_{k+1}, e_{k+1}) */
        int m = 0;
        double *px = malloc(sizeof(double) * (size_t)(2 * n_front)), *py = malloc(sizeof(double) * (size_t)(2 * n_front));
        if (px && py) {
            for (int k = 0; k < n_front; ++k) {
                if (k > 0) {
                    px[m] = time_s[order[k]];
                    py[m++] = error[order[k - 1]];
                }
                px[m] = time_s[order[k]];
                py[m++] = error[order[k]];
            }
            gf_svg_polyline(s, &f, m, px, py, "#d62728", 2.0, NULL, "pareto-front");
        }
        free(px), free(py);
    }
    if (recommended >= 0 && recommended < n) {
        char tip[160];
        snprintf(tip, sizeof tip, "recommended: %s", labels && labels[recommended] ? labels[recommended] : "");
        gf_svg_marker(s, &f, time_s[recommended], error[recommended], GF_SVG_SQUARE, "#ffbf00", 20.0, tip);
    }
    for (int i = 0; i < n; ++i) {
        const char *lab = labels && labels[i] ? labels[i] : "";
        char tip[160];
        snprintf(tip, sizeof tip, "%s%s: time %.3g s, error %.3g", lab, front[i] ? " (front)" : "", time_s[i],
                 error[i]);
        if (!gf_svg_marker(s, &f, time_s[i], error[i], GF_SVG_CIRCLE, front[i] ? "#d62728" : "#8c8c8c",
                           front[i] ? 10.0 : 8.0, tip))
            continue;
        gf_svg_text_data(s, &f, shift_log(&f.x, f.w_px, time_s[i], 8.0), error[i], "start", 10.0,
                         front[i] ? "#8b0000" : "#555555", lab);
    }
    gf_svg_legend(s, &f, 4, 4, leg);
    char cap[160];
    int n_cap = snprintf(cap, sizeof cap, "%d settings, %d on the front", n, n_front);
    if (recommended >= 0 && recommended < n && labels && labels[recommended])
        n_cap += snprintf(cap + n_cap, sizeof cap - (size_t)n_cap, "; recommended %s", labels[recommended]);
    if (n_skipped > 0 && n_cap < (int)sizeof cap)
        snprintf(cap + n_cap, sizeof cap - (size_t)n_cap, "; %d skipped (error or time not > 0)", n_skipped);
    gf_svg_caption(s, &f, cap);
    free(front), free(order);
    return gf_svg_close(&s);
}
