/*
 * The Beverloo figure: (Q sqrt(d/g))^(2/5) against D/d (gf_figures.h). The
 * law Q = C phi (6/pi) sqrt(g/d) (D/d - k)^(5/2) in grains per second
 * (Beverloo, Leniger & van de Velde 1961; Djouwe Meffeja 2012 (3.16)) is the
 * straight line (C phi 6/pi)^(2/5) (D/d - k) in these axes.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "figures/gf_figures.h"
#include "figures/gf_svg.h"

typedef struct beverloo_line {
    double k, C;
} beverloo_line;

static double q25(double D, const void *user)
{
    const beverloo_line *l = user;
    return D > l->k ? pow(l->C * 0.5 * 6.0 / M_PI, 0.4) * (D - l->k) : NAN;
}

gf_status gf_fig_beverloo(gf_ctx *ctx, const char *path, const gf_fig_opts *opt, int n_runs, const double *D_over_d,
                          const double *Q_nd, double k, double C)
{
    if (n_runs < 0 || (n_runs > 0 && (!D_over_d || !Q_nd)))
        return GF_FAIL(ctx, GF_ERR_ARG, "Beverloo figure %s: no data", path);
    double W = opt && opt->width_px > 0 ? opt->width_px : 760.0, Hp = opt && opt->height_px > 0 ? opt->height_px : 560.0;
    double xhi = 4.0, yhi = 1.0;
    for (int i = 0; i < n_runs; ++i)
        if (isfinite(D_over_d[i]) && isfinite(Q_nd[i]) && Q_nd[i] > 0.0)
            xhi = fmax(xhi, D_over_d[i]), yhi = fmax(yhi, pow(Q_nd[i], 0.4));
    const beverloo_line thesis = {1.47, 1.7}, fit = {k, C};
    yhi = fmax(yhi, q25(xhi, &thesis));
    char fit_label[96];
    snprintf(fit_label, sizeof fit_label, "fit: k = %.3g, C = %.3g (phi = 0.5)", k, C);
    gf_svg_frame f;
    memset(&f, 0, sizeof f);
    f.x0_px = 88.0, f.y0_px = 48.0;
    f.w_px = fmax(120.0, W - f.x0_px - 26.0 - gf_svg_legend_width_px((int)strlen(fit_label)));
    f.h_px = fmax(120.0, Hp - f.y0_px - 86.0);
    f.x = (gf_svg_axis){GF_SVG_LINEAR, 0.0, ceil(1.1 * xhi), "orifice size D / d (hydraulic diameter)"};
    f.y = (gf_svg_axis){GF_SVG_LINEAR, 0.0, ceil(1.1 * yhi), "(Q sqrt(d/g))^(2/5), Q in grains per second"};
    gf_svg *s;
    GF_TRY(gf_svg_open(ctx, path, W, Hp, &s));
    gf_svg_title(s, &f, opt && opt->title ? opt->title : "Silo discharge: Beverloo law, Q^(2/5) against D");
    gf_svg_axes(s, &f);
    gf_svg_function(s, &f, q25, &thesis, 128, "#b22222", 1.6, "7,4", "refline");
    gf_svg_legend_entry e[3];
    int n_e = 0;
    if (isfinite(k) && isfinite(C)) {
        gf_svg_function(s, &f, q25, &fit, 128, "#1f77b4", 1.6, NULL, "curve");
        e[n_e++] = (gf_svg_legend_entry){fit_label, "#1f77b4", 1, GF_SVG_CIRCLE, NULL, 0};
    }
    e[n_e++] = (gf_svg_legend_entry){"Djouwe Meffeja 2012: k = 1.47, C = 1.7", "#b22222", 1, GF_SVG_CIRCLE, "7,4", 0};
    e[n_e++] = (gf_svg_legend_entry){"runs", "#1f77b4", 0, GF_SVG_CIRCLE, NULL, 0};
    int skipped = 0;
    for (int i = 0; i < n_runs; ++i) {
        char tip[64];
        snprintf(tip, sizeof tip, "D = %.3g d, Q = %.4g sqrt(g/d)", D_over_d[i], Q_nd[i]);
        skipped += !gf_svg_marker(s, &f, D_over_d[i], Q_nd[i] > 0.0 ? pow(Q_nd[i], 0.4) : NAN, GF_SVG_CIRCLE,
                                  "#1f77b4", 9.0, tip);
    }
    gf_svg_legend(s, &f, 4, n_e, e);
    if (skipped) {
        char cap[64];
        snprintf(cap, sizeof cap, "%d run(s) skipped: no steady flow rate", skipped);
        gf_svg_caption(s, &f, cap);
    }
    return gf_svg_close(&s);
}
