/* Uniform radius distribution; see gf_psd.h. */
#include "particles/gf_psd.h"

#include <math.h>

gf_status gf_psd_check(gf_ctx *ctx, const gf_psd *psd)
{
    if (!(psd->mean_radius_m > 0.0) || !isfinite(psd->mean_radius_m))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "grains: mean radius must be > 0 (got %g m)", psd->mean_radius_m);
    if (!(psd->polydispersity >= 0.0 && psd->polydispersity < 0.5))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "grains: polydispersity must be in [0, 0.5) (got %g)",
                       psd->polydispersity);
    return GF_OK;
}

double gf_psd_draw_radius_m(const gf_psd *psd, gf_rng *rng)
{
    double p = psd->polydispersity;
    return psd->mean_radius_m * gf_rng_range(rng, 1.0 - p, 1.0 + p);
}

double gf_psd_max_radius_m(const gf_psd *psd)
{
    return psd->mean_radius_m * (1.0 + psd->polydispersity);
}

double gf_psd_mean_volume_m3(const gf_psd *psd)
{
    /* E[R^3] for R uniform on [R(1-p), R(1+p)]: ((1+p)^4 - (1-p)^4) / (8p) R^3 = (1 + p^2) R^3. */
    double r = psd->mean_radius_m, p = psd->polydispersity;
    return 4.0 / 3.0 * M_PI * r * r * r * (1.0 + p * p);
}
