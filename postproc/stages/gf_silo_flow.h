/*
 * Silo discharge (scene silo; Djouwe Meffeja 2012, ch. 3): the steady flow
 * rate of one run, for the flow_rate stage, and the laws fitted over a
 * campaign of runs (gf_post_campaign), written into the silo rows.
 *
 * Per run (diagnostics.nc: discharge_rate, discharge_mass_rate,
 * orifice_packing_fraction, fill_height; attributes grain_diameter_m,
 * gravity_m_s2, scene_param_orifice_{x,z}_over_d): the steady window of
 * Q(t) by MSER-5 and its standard error by block averaging (gf_post_stats.h),
 * as for the avalanches' Q_g; Q in grains/s, kg/s and sqrt(g/d) units, and
 * phi_out and the fill height averaged over the same window. The orifice
 * size is the hydraulic diameter D = 2 Ltx Lty / (Ltx + Lty) (thesis §3.4.2).
 *
 * Over a campaign (each law when its runs are there), through one point per
 * experiment: runs that differ only by their seed (gf_post_replicates.h) are
 * one point, the mean of their D, Q, H and phi_out (silo_replicates in each
 * row says how many), so that seeds drawn again sharpen a law as a longer run
 * would, and are not counted as points of their own:
 *  - Beverloo (Beverloo, Leniger & van de Velde 1961; thesis (3.16)):
 *    Q = C rho_n sqrt(g) (D - k d)^(5/2), rho_n = phi (6 / pi d^3), so that
 *    Q^(2/5) is linear in D: the line a + b D through (D/d, (Q sqrt(d/g))^(2/5))
 *    gives k = -a/b and C = b^(5/2) / (phi 6/pi), with phi = 0.5 as the
 *    thesis takes it (§3.4.2); R^2 of the line. Three distinct D at least.
 *  - saturation with the fill height (thesis §3.4.1): Q = Q0 (1 - exp(-H/H0)),
 *    linear in Q0 for a given H0, which a golden-section search finds over
 *    [0.1 d, 100 d]; R^2. Three distinct H (1 d apart) at least.
 *  - Q against phi_out (thesis §3.4.3-3.4.4): the line Q = a + b phi_out and
 *    its R^2, over the points. Three points at least.
 */
#ifndef GF_SILO_FLOW_H
#define GF_SILO_FLOW_H

#include "stages/gf_stage.h"

/* The per-run steady discharge (flow_rate stage, scene silo). */
gf_status gf_silo_flow_rate(gf_ctx *ctx, const gf_stage_in *in, gf_stage_out *out);

/* The campaign fits, set in every silo row that took part (rows of other scenes untouched). */
void gf_silo_campaign_fits(gf_post_row *rows, int n_rows);

/* Beverloo line through n points (D/d, Q sqrt(d/g)): k, C (phi = 0.5) and R^2.
 * Returns 0 when fewer than 3 distinct D or a non-increasing line. */
int gf_silo_fit_beverloo(const double *D_over_d, const double *Q_nd, int n, double *k, double *C, double *R2);
/* Q = Q0 (1 - exp(-H/H0)) through n points; returns 0 with fewer than 3 distinct H. */
int gf_silo_fit_saturation(const double *H, const double *Q, int n, double *Q0, double *H0, double *R2);

/* Kinematic model (Nedderman & Tuzun 1979; thesis (3.13)-(3.15)): the downward
 * velocity across the orifice at height z is a Gaussian
 * A exp(-(x - x_c)^2 / (4 b z)). Weighted log-linear least squares over the n
 * bins (x, v) above 10 % of the peak (weights v^2: the error of ln v scales as
 * 1/v); *R2 on v over every bin. Returns b (units of x), NaN when fewer than
 * 4 bins, no maximum, or a width sigma = sqrt(2 b z) beyond the sampled range. */
double gf_silo_fit_gaussian(const double *x, const double *v, int n, double z, double *R2);

/* The profiles stage for the silo: v_y(x) across the orifice's mid-plane
 * (|z - Ly/2| < d) in slabs of d at z = 0.5, 1, 2, 3, 5, 8 d, bins of d/2,
 * averaged over the particles.nc frames of the steady window; the Gaussian
 * fit of each (post_profiles.nc: x, z_level, v_down, b, gauss_R2) and in the
 * row b at 1 d and 5 d, the smallest R^2 at z >= 3 d and whether b decreases
 * from 1 d up (thesis §3.5.1, Fig. 3.13). */
gf_status gf_silo_profiles(gf_ctx *ctx, const gf_stage_in *in, gf_stage_out *out);

#endif
