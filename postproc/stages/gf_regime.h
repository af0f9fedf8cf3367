/*
 * Flow-regime label from a flow time scale T compared with the viscous,
 * inertial and free-fall times T_v, T_i, T_ff of gf_groups.h (Izard 2014
 * §4.1.4.2, made operational):
 *   - the label is the scale T_x minimising d_x = |log10(T / T_x)|;
 *   - "transitional" if the best d_x > log10(2) = 0.301 decade (T is more
 *     than a factor 2 from every scale), or if the two best differ by less
 *     than 0.1 decade (the thesis calls transitional the points that fit
 *     neither scaling);
 *   - confidence = d_second − d_best, in decades (how far the nearest
 *     competing scale is).
 * Scales that are zero or not finite (dry runs: T_v = T_i = 0) do not compete;
 * with a single competing scale (a dry run) the label is that scale, free
 * fall, whatever the distance: there is nothing to be transitional with
 * (best_decades still says how far T is from it).
 * The thesis classified by eye from the slopes of T/T_x against St. Its
 * points read as "≈ 1" sit up to a factor 2 from their scale (Table 4.2:
 * inertial points at T/T_i = 1.3-1.9, viscous at T/T_v = 1.0-1.95), and the
 * thesis' own scatter about its scales is a factor 2 as well
 * (Fig. 4.7-4.10), so the band is a factor 2. A narrower band, 0.2
 * decade (a factor 1.58), labels 10 of those 19 unambiguous points
 * transitional (tests/post/test_post_regime.c prints both).
 */
#ifndef GF_REGIME_H
#define GF_REGIME_H

#include "core/gf_groups.h"

typedef enum gf_regime_label {
    GF_REGIME_UNDETERMINED = 0,
    GF_REGIME_VISCOUS,
    GF_REGIME_INERTIAL,
    GF_REGIME_FREE_FALL,
    GF_REGIME_TRANSITIONAL
} gf_regime_label;

#define GF_REGIME_MAX_DECADES 0.30103   /* log10(2): a factor 2 */
#define GF_REGIME_MIN_SEPARATION 0.1

typedef struct gf_regime_result {
    gf_regime_label label;      /* with the transitional rule */
    gf_regime_label nearest;    /* the best scale alone */
    double decades[3];          /* |log10(T/T_x)| for v, i, ff (NaN if the scale does not compete) */
    double best_decades, confidence_decades;
} gf_regime_result;

/* "viscous", "inertial", "free-fall", "transitional", "undetermined". */
const char *gf_regime_name(gf_regime_label label);
/* Classifies T (s) against sc's T_v, T_i, T_ff. Errors: T not finite and > 0. */
gf_status gf_regime_classify(gf_ctx *ctx, double T_s, const gf_scales *sc, gf_regime_result *out);

#endif
