/*
 * gf_measure: measurements shared by the dry and immersed scenes, on a plain
 * particle store (no simulation handle, so each one is unit-tested on
 * synthetic grains). Axes: x streamwise, y vertical (bed-normal), z
 * transverse. Only mobile grains (not GF_P_GLUED) are measured unless said.
 *
 * Volume-weighted averages use the EXACT volume of each sphere inside a
 * horizontal slab [y0, y1] (spherical-cap formula), so a profile on slabs of
 * thickness D is the phase average <.>_g of Izard 2014 (4.7)-(4.8) with the
 * grain indicator as alpha, and the solid fraction of a slab is
 *     phi(y) = sum_i V_i(slab) / (A dy)                               (2.10)
 * (A the footprint). Box averages (interior of a column) use sampling of
 * the indicator function on a regular lattice of spacing h (error O(h^2)
 * per grain surface, below 1e-3 in phi at h = D/20).
 *
 * Free surface and front (Izard §5.3-5.5, Lajeunesse et al. PoF 2005): the
 * deposit is binned along x; in each bin the "solid height" is
 *     h_s(x) = sum_{i in bin} V_i / (dx W)
 * (the height the grains would have at phi = 1) and the envelope is the
 * highest grain top y_i + R_i. The front is the farthest bin, contiguous with
 * the main deposit (gaps of at most max_gap bins), whose solid height is at
 * least min_solid_height: a few saltating grains ahead of the deposit carry
 * little solid height and do not move the front.
 *
 * Fits: mu(I) = mu1 + (mu2 - mu1) I/(I0 + I) with I0 fixed is linear in
 * (mu1, mu2) (Jop, Forterre & Pouliquen, Nature 2006); the Janssen profile
 * sigma(d) = sigma_inf (1 - exp(-d/lambda)) is linear in sigma_inf for a
 * given lambda, which a golden-section search finds; the run-out law
 * (R_inf - R0)/R0 = lambda1 a (a < a0), lambda2 a^(2/3) (a >= a0) is a
 * one-coefficient least-squares fit on each side (Lube et al. JFM 2004,
 * Lajeunesse et al. PoF 2005).
 */
#ifndef GF_MEASURE_H
#define GF_MEASURE_H

#include <stddef.h>

#include "core/gf_status.h"
#include "particles/gf_particles.h"

/* The box the grains live in: periodic axes wrap (images are measured). */
typedef struct gf_measure_domain {
    double lo_m[3], hi_m[3];
    int periodic[3];
} gf_measure_domain;

/* Volume (m^3) of a sphere of radius r centred at height yc inside the slab [y0, y1]. */
double gf_measure_sphere_slab_volume_m3(double yc_m, double r_m, double y0_m, double y1_m);

/* Solid fraction of the box [lo, hi] by sampling the grain indicator on a
 * lattice of spacing h_m (periodic images included). glued grains count when
 * include_glued. Returns NaN for an empty box. */
double gf_measure_solid_fraction_box(const gf_particles *p, const gf_measure_domain *dom, const double lo_m[3],
                                     const double hi_m[3], double h_m, int include_glued);

/* Profiles on n_slabs slabs of thickness dy from y0 over the whole x-z
 * footprint of dom: solid fraction phi[k] and volume-weighted mean velocity
 * u[3*k + c] (NaN where empty). Either output may be NULL. */
gf_status gf_measure_profile_y(gf_ctx *ctx, const gf_particles *p, const gf_measure_domain *dom, double y0_m,
                               double dy_m, int n_slabs, double *phi, double *u);

/* Stress on the horizontal planes y_k = y0 + (k + 1/2) dy by the method of
 * planes (Todd, Evans & Daivis PRE 1995), with a grain "above" when its
 * centre is: the force per unit area that the material above receives
 * through the plane, from the forces accumulated in the store (contacts and
 * fluid; gravity is not in the store), plus the kinetic momentum flux of the
 * slab [y0 + k dy, y0 + (k + 1) dy] about its mass-weighted mean velocity:
 *   tau_k = -(1/A) sum_{above} f_x,i - (1/V_k) sum_{slab} m_i u'_x u'_y
 *   sig_k = +(1/A) sum_{above} f_y,i + (1/V_k) sum_{slab} m_i u'_y u'_y
 * (A the x-z footprint, V_k = A dy). tau is the shear stress resisting a
 * flow towards +x and sig the normal stress sigma_yy (compression > 0): for
 * steady uniform flow on an incline they equal the weight per unit area
 * above the plane times sin(theta) and cos(theta). Only mobile grains are
 * summed, so forces from glued grains (rough walls) count as external. */
gf_status gf_measure_stress_planes(gf_ctx *ctx, const gf_particles *p, const gf_measure_domain *dom, double y0_m,
                                   double dy_m, int n_planes, double *tau_Pa, double *sig_Pa);


/* Vertical stress in a silo whose side walls are glued grains (Izard 2014
 * §2.1.3.2), from the static balance of the grains above each plane
 * y_k = y0 + (k + 1/2) dy:
 *     sigma_yy(y_k) S = sum_{mobile, y_i > y_k} m_i g + sum_{glued, y_j > y_k} f_y,j
 * (the walls hold the grains up by minus the force the grains exert on the
 * glued grains, accumulated in the store at the last force evaluation).
 * g_m_s2 = |g| along -y; area_m2 = S. Assignment by centre smooths the
 * profile over ~D. Valid at rest (no inertia term). */
gf_status gf_measure_silo_vertical_stress(gf_ctx *ctx, const gf_particles *p, double g_m_s2, double area_m2,
                                          double y0_m, double dy_m, int n_planes, double *sigma_Pa);

/* Grain flow rate Q_g = (1/L) sum_i V_i u_i (m^3/s) along x, L = box length in x. */
double gf_measure_grain_flow_rate(const gf_particles *p, const gf_measure_domain *dom);

/* Top of the bed: the height below which a fraction `fraction` (e.g. 0.5) of
 * the solid-fraction plateau remains, from profile phi on slabs of dy from y0:
 * the highest y where phi >= fraction * (median of phi over the lower half of
 * the filled slabs). Returns NaN for an empty bed. */
double gf_measure_bed_height_m(const double *phi, int n_slabs, double y0_m, double dy_m, double fraction);

/* Deposit binned along x on [x0, x0 + n_bins dx] over the transverse width of dom. */
typedef struct gf_measure_deposit {
    double front_m;           /* farthest x (bin upper edge) of the contiguous deposit; NaN if none */
    double height_m;          /* highest grain top among bins with enough solid */
    double height_at_x0_m;    /* envelope in the first bin (back wall) */
} gf_measure_deposit;

/* top_m[n_bins] (highest y + R per bin, 0 where empty) and solid_m[n_bins]
 * (solid height h_s) may be NULL. min_solid_height_m: bins below it are empty
 * for the front; max_gap: empty bins tolerated inside the deposit. */
gf_status gf_measure_deposit_profile(gf_ctx *ctx, const gf_particles *p, const gf_measure_domain *dom, double x0_m,
                                     double dx_m, int n_bins, double min_solid_height_m, int max_gap,
                                     double *top_m, double *solid_m, gf_measure_deposit *out);

/* Extent of a deposit profile h[0..n) on bins (cells) of dx from the back
 * wall x = 0: the x where h first falls below depth_m, linear between the
 * centres of the last bin at or above it and the first below (0 when the
 * first bin is below, n dx when none is). The same measure for the grains'
 * binned heights and the continuum's columns, so that their deposits are
 * compared point for point (docs/continuum.md, "Column collapse"). */
double gf_measure_profile_extent(const double *h_m, int n, double dx_m, double depth_m);

/* Least-squares mu1, mu2 of mu(I) = mu1 + (mu2 - mu1) I/(I0 + I) at fixed I0.
 * Errors: fewer than 2 points or all at the same I. */
gf_status gf_measure_fit_mu_of_I(gf_ctx *ctx, const double *I, const double *mu, int n, double I0, double *mu1,
                                 double *mu2);

/* Janssen fit sigma(d) = sigma_inf (1 - exp(-d/lambda)) over depth d (m) and
 * stress sigma (Pa); lambda searched in [lambda_min, lambda_max]. rms_Pa:
 * residual rms (may be NULL). */
gf_status gf_measure_fit_janssen(gf_ctx *ctx, const double *depth_m, const double *sigma_Pa, int n,
                                 double lambda_min_m, double lambda_max_m, double *sigma_inf_Pa, double *lambda_m,
                                 double *rms_Pa);

/* Run-out law: lambda1 from points with a < a0 (r = lambda1 a), lambda2 from
 * a >= a0 (r = lambda2 a^(2/3)); NaN when a side has no point. */
void gf_measure_fit_runout(const double *a, const double *runout, int n, double a0, double *lambda1,
                           double *lambda2);

/* Least-squares fit of the Bagnold profile u(y) = A ((h)^(3/2) - (h - y)^(3/2)) + B
 * for 0 <= y <= h (y from the base); returns A, B and the rms relative to max |u|. */
gf_status gf_measure_fit_bagnold(gf_ctx *ctx, const double *y_m, const double *u_m_s, int n, double h_m, double *A,
                                 double *B, double *rel_rms);

/* The seed's reading of a steady chute flow (Izard 2014 §2.1.3.3, (2.23)),
 * from a time-averaged profile on slabs of D from the floor y = 0 (glued
 * half-grains centred on it): phi and the downslope velocity u per slab.
 *   h: the flowing depth above the glued layer's top (D/2), i.e. the bed
 *      height (half-plateau of phi) less D/2;
 *   A, B, rel_rms: the Bagnold fit u = A (h^(3/2) - (h - y)^(3/2)) + B over
 *      the slab centres 1 D and up, y measured from D/2;
 *   slip_over_h: the Robin slip length of (2.22), lambda = -B / (1.5 A h^(1/2)), over h;
 *   phi_bulk: phi over the slabs from 2 D above the floor to 3 D below the top;
 *   I: with hydrostatic P = rho_p phi g cos(theta) (h - y) and
 *      du/dy = 1.5 A (h - y)^(1/2), a uniform I = 1.5 A D / sqrt(phi g cos(theta)). */
typedef struct gf_measure_chute {
    double h_m, A, B, rel_rms, slip_over_h, phi_bulk, I;
} gf_measure_chute;

gf_status gf_measure_chute_bagnold(gf_ctx *ctx, const double *phi, const double *u, int n_slabs, double D_m,
                                   double g_m_s2, double theta_rad, gf_measure_chute *out);

#endif
