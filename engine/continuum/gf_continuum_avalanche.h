/*
 * gf_continuum_avalanche: the dry avalanche (scene avalanche) run by the
 * continuum mu(I) solver instead of grains (method: continuum): a layer of
 * depth h on a rough (no-slip) base, periodic along the slope, gravity
 * g (sin theta, -cos theta), 2-D. The surface is the top side of the grid,
 * an open side (p = 0, zero normal gradient of the velocity, so no shear
 * stress): a uniform layer keeps a flat surface, so no volume-of-fluid
 * phase is needed, and it is one column of cells across the depth, periodic
 * along x with one cell (several cells along x give the same layer to
 * round-off but put dt under the advective limit, u dt < h). Its steady state is the Bagnold profile
 * (gf_mui_oracles.h; GDR MiDi 2004; Jop, Forterre & Pouliquen 2006).
 * The depth, width and angle are the scene's own parameters
 * (bed_height_over_D, width_over_D, incline_deg), so one
 * campaign runs both methods; the law, phi and the cell from the spec's
 * continuum section.
 * Writes diagnostics.nc with the DEM scene's grain_flow_rate
 * Q_g = W phi int u dy (m3/s), fluid_flow_rate (0), bed_packing_fraction
 * (phi), bed_height (h), and surface_velocity, every output.interval_nd.
 */
#ifndef GF_CONTINUUM_AVALANCHE_H
#define GF_CONTINUUM_AVALANCHE_H

#include "continuum/gf_continuum.h"
#include "core/gf_status.h"
#include "gf_run_spec.h"

typedef struct gf_continuum_layer {
    double depth_m, incline_rad;
    double phi;              /* solid fraction: the bulk density is phi rho_s */
    double g_m_s2;
    gf_mui_material mui;
    double cell_m;           /* cell edge: depth / cell_m cells across the layer (rounded) */
    double dt_s;
} gf_continuum_layer;

/* Solver parameters of the inclined layer: x periodic, y no-slip base and open surface. */
gf_continuum_params gf_continuum_layer_params(const gf_continuum_layer *l);
/* The surface velocity u(h), extrapolated from the two top rows of cells with the shape
 * the hydrostatic pressure gives a stress-free surface, u(h) - u(y) ~ (h - y)^{3/2}
 * whatever the law's I; and the flux per unit width int_0^h u dy by the midpoint rule (m2/s). */
void gf_continuum_layer_measure(const gf_continuum *s, double *u_surface_m_s, double *flux_m2_s);
/* Row-mean downslope velocity at the centres of cell row j. */
double gf_continuum_layer_row_velocity(const gf_continuum *s, int j);

typedef struct gf_continuum_avalanche_result {
    long steps;
    double time_s;
    double flow_rate_m3_s;      /* final Q_g */
    double surface_velocity_m_s;
} gf_continuum_avalanche_result;

/* The run's grid cells and time steps, from the spec alone (`grainflow check`'s cost estimate). */
void gf_continuum_avalanche_size(const gf_run_spec *spec, double *cells, double *steps);
/* output_dir and resolved_yaml may be NULL; interrupt (may be NULL) stops the run between steps. */
gf_status gf_continuum_avalanche_run(gf_ctx *ctx, const gf_run_spec *spec, const char *output_dir,
                                     const char *resolved_yaml, volatile int *interrupt,
                                     gf_continuum_avalanche_result *result);

#endif
