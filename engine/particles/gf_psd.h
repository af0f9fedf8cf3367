/*
 * gf_psd: grain size distributions.
 *
 * The seeds give only the relative spread p of the radius about the mean R
 * (10 % in the Janssen silo, the dry chute, the dry collapse and the
 * avalanches; 5 % in the immersed collapse: Izard 2014 §2.1.3, §4.1.2.2,
 * §5.2) and not the shape, which the thesis leaves unspecified. The one shape
 * implemented is the simplest: R_i uniform in
 * [R(1-p), R(1+p)]. Its purpose is only to prevent crystallisation; 10 % is
 * enough for that and small enough to avoid segregation (Izard §4.1.2.2).
 *
 * Moments of the uniform law, used to size packings (volume per grain):
 *     <R^3> = R^3 (1 + p^2),          E[V] = (4/3) pi R^3 (1 + p^2).
 */
#ifndef GF_PSD_H
#define GF_PSD_H

#include "core/gf_rng.h"
#include "core/gf_status.h"

typedef struct gf_psd {
    double mean_radius_m;     /* R = D/2 */
    double polydispersity;    /* p in [0, 0.5): R_i uniform in [R(1-p), R(1+p)] */
} gf_psd;

/* Checks R > 0 and 0 <= p < 0.5 (GF_ERR_CONFIG naming the field). */
gf_status gf_psd_check(gf_ctx *ctx, const gf_psd *psd);
/* One radius drawn from the distribution, m. */
double gf_psd_draw_radius_m(const gf_psd *psd, gf_rng *rng);
/* Largest radius the distribution can produce, m. */
double gf_psd_max_radius_m(const gf_psd *psd);
/* Mean grain volume E[(4/3) pi R_i^3] = (4/3) pi R^3 (1 + p^2), m^3. */
double gf_psd_mean_volume_m3(const gf_psd *psd);

#endif
