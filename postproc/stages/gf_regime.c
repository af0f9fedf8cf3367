/* Regime label from a time scale; the rule and its source are in gf_regime.h. */
#include "stages/gf_regime.h"

#include <math.h>

const char *gf_regime_name(gf_regime_label label)
{
    switch (label) {
    case GF_REGIME_VISCOUS: return "viscous";
    case GF_REGIME_INERTIAL: return "inertial";
    case GF_REGIME_FREE_FALL: return "free-fall";
    case GF_REGIME_TRANSITIONAL: return "transitional";
    default: return "undetermined";
    }
}

gf_status gf_regime_classify(gf_ctx *ctx, double T_s, const gf_scales *sc, gf_regime_result *out)
{
    const double scales[3] = {sc->t_viscous_s, sc->t_inertial_s, sc->t_freefall_s};
    const gf_regime_label labels[3] = {GF_REGIME_VISCOUS, GF_REGIME_INERTIAL, GF_REGIME_FREE_FALL};
    out->label = out->nearest = GF_REGIME_UNDETERMINED;
    out->best_decades = out->confidence_decades = NAN;
    if (!(isfinite(T_s) && T_s > 0.0))
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "regime: flow time T = %g s is not a positive number", T_s);
    int best = -1, second = -1;
    for (int k = 0; k < 3; ++k) {
        out->decades[k] = (isfinite(scales[k]) && scales[k] > 0.0) ? fabs(log10(T_s / scales[k])) : NAN;
        if (!isfinite(out->decades[k]))
            continue;
        if (best < 0 || out->decades[k] < out->decades[best]) {
            second = best;
            best = k;
        } else if (second < 0 || out->decades[k] < out->decades[second]) {
            second = k;
        }
    }
    if (best < 0)
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "regime: no finite reference time scale");
    out->nearest = labels[best];
    out->best_decades = out->decades[best];
    out->confidence_decades = second >= 0 ? out->decades[second] - out->decades[best] : INFINITY;
    if (second < 0)
        out->label = labels[best];   /* dry: free fall is the only regime */
    else
        out->label = (out->best_decades > GF_REGIME_MAX_DECADES ||
                      out->confidence_decades < GF_REGIME_MIN_SEPARATION)
                         ? GF_REGIME_TRANSITIONAL
                         : labels[best];
    return GF_OK;
}
