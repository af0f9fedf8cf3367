/*
 * Campaign figures (SVG 1.1, standalone, no external dependency).
 *
 * Each function takes plain arrays (one entry per run, already read from
 * summary.nc or computed by a stage); the figures layer never opens netCDF.
 * A figure is written to "<path>.tmp" and renamed on success, so a failed
 * post-processing never leaves a truncated SVG that looks complete.
 *
 * The reference lines drawn are the published ones (Izard 2014 §4.1.4.2
 * and the papers below):
 *   regime diagram (St, r), log-log:
 *     Courrech du Pont, Gondret, Perrin & Rabaud, PRL 90 (2003): St_c ≈ 10
 *       (viscous | free fall), r_c ≈ 4 (inertial | free fall),
 *       Re*_c = St/r = 2.5, i.e. the line r = St / 2.5 (viscous | inertial);
 *     Izard 2014 §4.1.4.2: St ≈ 1 for r >= 4, and r = 4 St for r < 4.
 *   runout (R_inf - R0)/R0 against a (dry collapse, planar):
 *     Lube et al. 2005: 1.2 a and 1.9 a^(2/3);
 *     Lajeunesse et al. 2005: 1.8 a and 2.3 a^(2/3).
 *
 * Non-finite or non-positive values on a log axis are skipped (counted in the
 * caption), never plotted at a made-up place.
 */
#ifndef GF_FIGURES_H
#define GF_FIGURES_H

#include "core/gf_status.h"

/* Flow regime labels of a run (colour of its marker). */
typedef enum gf_fig_regime {
    GF_FIG_REGIME_UNDETERMINED = 0,
    GF_FIG_REGIME_VISCOUS,
    GF_FIG_REGIME_INERTIAL,
    GF_FIG_REGIME_FREE_FALL,
    GF_FIG_REGIME_TRANSITIONAL,
    GF_FIG_REGIME_COUNT
} gf_fig_regime;

/* "viscous", "inertial", "free-fall" (also "free_fall", "freefall"),
 * "transitional"; anything else (NULL, "undetermined") -> GF_FIG_REGIME_UNDETERMINED. */
gf_fig_regime gf_fig_regime_from_name(const char *name);
/* "viscous", "inertial", "free-fall", "transitional", "undetermined" (the
 * word of the summary table's regime and deposit_shape columns). */
const char *gf_fig_regime_name(gf_fig_regime regime);

/* Deposit shape of a collapse run (marker of its point). */
typedef enum gf_fig_shape {
    GF_FIG_SHAPE_UNDETERMINED = 0,
    GF_FIG_SHAPE_TRIANGLE,
    GF_FIG_SHAPE_TRAPEZOID,
    GF_FIG_SHAPE_COUNT
} gf_fig_shape;

/* "triangle", "trapezoid"; anything else -> GF_FIG_SHAPE_UNDETERMINED ("undetermined"). */
gf_fig_shape gf_fig_shape_from_name(const char *name);
const char *gf_fig_shape_name(gf_fig_shape shape);

typedef enum gf_fig_scale {
    GF_FIG_SCALE_AUTO = 0,   /* log when every finite value is > 0 and they span >= 1.5 decades */
    GF_FIG_SCALE_LINEAR,
    GF_FIG_SCALE_LOG
} gf_fig_scale;

/* Optional settings; pass NULL (or a zeroed struct) for the defaults. */
typedef struct gf_fig_opts {
    const char *title;         /* NULL: the figure's default title */
    int width_px, height_px;   /* 0: 760 x 560 */
    gf_fig_scale x_scale, y_scale;  /* used by runout and timeseries; the regime diagram is always log-log */
    /* Runs of several variants (e.g. dry and immersed) in deposit_shape and
     * runout: variant[i] in [0, n_variants) for run i, variant_names[v] in
     * the legend. Variant 0 is drawn filled, the next hollow (alternating),
     * and the variants at one data point side by side, so that none hides
     * another. n_variants <= 1 or NULL arrays: one variant, nothing shifted. */
    int n_variants;
    const int *variant;
    const char *const *variant_names;
} gf_fig_opts;

/* Runs in the (St, r) plane, log-log, coloured by regime, with the published
 * boundaries. stokes_St, density_ratio_r, regime: n_runs entries (borrowed);
 * regime may be NULL (all undetermined). Runs with St or r not finite and > 0 are
 * skipped. Errors: GF_ERR_ARG (NULL arrays with n_runs > 0, n_runs < 0),
 * GF_ERR_IO (path). */
gf_status gf_fig_regime_diagram(gf_ctx *ctx, const char *path, const gf_fig_opts *opt, int n_runs,
                                const double *stokes_St, const double *density_ratio_r,
                                const gf_fig_regime *regime);

/* Runs in the (a, Phi_i) plane (linear axes unless opt says otherwise),
 * marker by deposit shape (triangle / trapezoid / undetermined = circle). shape
 * may be NULL (all undetermined). Variants as in gf_fig_opts. */
gf_status gf_fig_deposit_shape(gf_ctx *ctx, const char *path, const gf_fig_opts *opt, int n_runs,
                               const double *aspect_ratio_a, const double *phi_initial, const gf_fig_shape *shape);

/* Normalised runout (R_inf - R0)/R0 against a, with the dry laws of Lube et
 * al. 2005 and Lajeunesse et al. 2005 as reference curves. Axes AUTO by
 * default (log when the data span decades). regime may be NULL (one colour).
 * The shaded transition range of Lube et al. (a0 = 1.8-2.8) is drawn, and
 * named in the legend, only when the a axis reaches it. */
gf_status gf_fig_runout(gf_ctx *ctx, const char *path, const gf_fig_opts *opt, int n_runs,
                        const double *aspect_ratio_a, const double *runout_norm, const gf_fig_regime *regime);

/* Silo discharge (Djouwe Meffeja 2012 §3.4.2, Fig. 3.8): (Q sqrt(d/g))^(2/5)
 * against the orifice size D/d, one marker per run, with the campaign's
 * Beverloo line (k, C with phi = 0.5; NaN: not drawn) and the thesis' own
 * (k = 1.47, C = 1.7). Linear axes. */
gf_status gf_fig_beverloo(gf_ctx *ctx, const char *path, const gf_fig_opts *opt, int n_runs, const double *D_over_d,
                          const double *Q_nd, double k, double C);
/* One curve of a time series (borrowed). label may be NULL. */
typedef struct gf_fig_series {
    const char *label;
    int n;
    const double *x;
    const double *y;
} gf_fig_series;

/* Several runs' curves on one plot, with a legend: front position against
 * time, basal excess pore pressure traces, ... x_label and y_label carry the
 * units, e.g. "t (s)", "excess pore pressure (Pa)". Non-finite samples break
 * a curve; a series with no finite sample is not drawn and not in the legend
 * (the caption counts it). x is linear unless opt->x_scale is LOG; y follows opt->y_scale
 * (AUTO as above). No default title (opt->title). Past 14 series the legend
 * lists 13 and "... and N more"; colours repeat every 10 with a new dash.
 * Errors: GF_ERR_ARG (n_series < 1, series with n > 0 and NULL x/y). */
gf_status gf_fig_timeseries(gf_ctx *ctx, const char *path, const gf_fig_opts *opt, const char *x_label,
                            const char *y_label, int n_series, const gf_fig_series *series);

/* Accuracy benchmark of one scene: error against run time (wall or CPU
 * seconds, time_label says which; NULL: "run time (s)"), log-log, one
 * marker per setting labelled by labels[i] (e.g. "dt=tc/50 skin=0.1"), the
 * Pareto front (no other setting is both cheaper and more accurate) joined
 * and highlighted, the scene's tolerance as a dashed horizontal line and the
 * recommended setting (index recommended, -1: none) marked with a ring.
 * Settings with a non-finite or non-positive time or error are skipped and
 * counted in the caption. on_front (may be NULL) receives 1/0 per setting.
 * Errors: GF_ERR_ARG (n < 0, NULL arrays with n > 0), GF_ERR_IO (path). */
gf_status gf_fig_pareto(gf_ctx *ctx, const char *path, const gf_fig_opts *opt, int n, const double *time_s,
                        const double *error, const char *const *labels, const char *time_label,
                        const char *error_label, double tolerance, int recommended, unsigned char *on_front);
/* The Pareto front alone (minimise both cost and error): on_front[i] = 1 when
 * no j has cost_j <= cost_i and err_j <= err_i with one strict (errors equal
 * to 1e-9 relative count as equal); points with a non-finite value are never
 * on it. Returns the number on the front. */
int gf_fig_pareto_front(int n, const double *cost, const double *error, unsigned char *on_front);

#endif
