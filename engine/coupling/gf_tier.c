/* The `fluid: auto` tier rule; physics, thresholds and sources in gf_tier.h. */
#include "coupling/gf_tier.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "coupling/gf_coupling_tier.h"

const char *gf_tier_name(gf_tier tier)
{
    int n = 0;
    return tier == GF_TIER_NONE ? "none" : gf_coupling_tier_all(&n)[0]->name;
}

static void set(gf_tier_choice *out, gf_tier tier)
{
    out->tier = tier;
    out->model = gf_tier_name(tier);
}

/* The first registered tier that accepts the run; its answer, and the
 * refusals before it, appended to the regime's reason. */
static gf_status pick_fluid_tier(gf_ctx *ctx, double St, double r, gf_tier_choice *out)
{
    gf_tier_query q = {.stokes_St = St, .density_ratio_r = r};
    int n = 0;
    const gf_coupling_tier *const *all = gf_coupling_tier_all(&n);
    for (int i = 0; i < n; ++i) {
        char why[160] = "";
        if (!all[i]->auto_fits)
            continue;
        int fits = all[i]->auto_fits(&q, why, sizeof why);
        size_t used = strlen(out->reason);
        snprintf(out->reason + used, sizeof out->reason - used, "; %s%s", fits ? "" : "not ", why);
        if (fits) {
            out->tier = GF_TIER_FLUID;
            out->model = all[i]->name;
            return GF_OK;
        }
    }
    return GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "fluid: auto: no registered coupling tier accepts St = %g, r = %g", St, r);
}

gf_status gf_tier_choose(gf_ctx *ctx, double St, double r, gf_tier_choice *out)
{
    out->reason[0] = '\0';
    set(out, GF_TIER_UNRESOLVED);
    if (isnan(St) || isnan(r))
        return GF_FAIL(ctx, GF_ERR_ARG, "fluid: auto: St = %g and r = %g must be numbers", St, r);
    if (!(St > 0.0))
        return GF_FAIL(ctx, GF_ERR_PHYSICS, "fluid: auto: St = %g must be > 0", St);
    if (!(r > sqrt(5.0 / 3.0)))
        return GF_FAIL(ctx, GF_ERR_PHYSICS,
                       "fluid: auto: r = %g <= sqrt(5/3) = 1.291: grains not denser than the fluid cannot settle", r);
    if (isinf(St) && isinf(r)) {
        set(out, GF_TIER_NONE);
        snprintf(out->reason, sizeof out->reason, "dry run: no fluid given (St = r = inf)");
        return GF_OK;
    }
    const int fast = St >= GF_TIER_DRY_MIN_STOKES, light = r >= GF_TIER_DRY_MIN_R;
    const double buoy = 5.0 / (3.0 * r * r); /* rho_f / rho_p */
    if (fast && light) {
        set(out, GF_TIER_NONE);
        snprintf(out->reason, sizeof out->reason,
                 "free fall: St = %.3g >= %g and r = %.3g >= %g (T_ff/T_v = %.3g, T_ff/T_i = %.3g, buoyancy %.2g %% of "
                 "weight)",
                 St, GF_TIER_DRY_MIN_STOKES, r, GF_TIER_DRY_MIN_R, 2.0 * St, 2.0 * sqrt(0.6) * r, 100.0 * buoy);
        return GF_OK;
    }
    if (!fast && !light) {
        snprintf(out->reason, sizeof out->reason,
                 "viscous/inertial: St = %.3g < %g and r = %.3g < %g: drag and pore pressure matter", St,
                 GF_TIER_DRY_MIN_STOKES, r, GF_TIER_DRY_MIN_R);
    } else if (!fast) {
        snprintf(out->reason, sizeof out->reason,
                 "viscous: St = %.3g < %g (T_ff/T_v = %.3g): drag and pore pressure matter", St,
                 GF_TIER_DRY_MIN_STOKES, 2.0 * St);
    } else {
        snprintf(out->reason, sizeof out->reason,
                 "inertial: r = %.3g < %g (T_ff/T_i = %.3g, buoyancy %.2g %% of weight): fluid inertia and pore "
                 "pressure matter",
                 r, GF_TIER_DRY_MIN_R, 2.0 * sqrt(0.6) * r, 100.0 * buoy);
    }
    return pick_fluid_tier(ctx, St, r, out);
}

gf_status gf_tier_from_scales(gf_ctx *ctx, const gf_scales *scales, gf_tier_choice *out)
{
    if (!scales || !out)
        return GF_FAIL(ctx, GF_ERR_ARG, "gf_tier_from_scales: NULL argument");
    return gf_tier_choose(ctx, scales->stokes_St, scales->density_ratio_r, out);
}
