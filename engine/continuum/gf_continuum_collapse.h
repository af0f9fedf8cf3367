/*
 * gf_continuum_collapse: the dry granular column collapse (scene
 * column_collapse) run by the continuum mu(I) solver instead of grains
 * (method: continuum), after Lagree, Staron & Popinet (JFM 686, 2011): 2-D,
 * the column R0 x H0 against the back wall x = 0 on a no-slip floor, a light
 * Newtonian phase above (density 1/100 of the column's, viscosity
 * 1e-3 rho_p sqrt(g D) D), an open top, a volume-of-fluid free surface.
 * R0, H0 and the domain length come from the scene's own parameters
 * (column_length_over_D, aspect_ratio, domain_length_over_R0), so one
 * campaign runs both methods on the same column; the law and the grid from
 * the spec's continuum section.
 * Writes diagnostics.nc (front_position, deposit_height, packing_fraction,
 * deposit_extent_1D and _2D: the names and measures of the DEM scene) every
 * output.interval_nd when output_dir is set.
 */
#ifndef GF_CONTINUUM_COLLAPSE_H
#define GF_CONTINUUM_COLLAPSE_H

#include "continuum/gf_continuum.h"
#include "core/gf_status.h"
#include "gf_run_spec.h"

typedef struct gf_continuum_collapse_result {
    long steps;
    double time_s;
    double front_m, height_m;     /* final front from the back wall, final height at the back wall */
    double body_front_m;          /* final farthest x where the deposit is at least 2 D deep: its body,
                                     without a front layer one grain thick */
    double column_length_m, column_height_m;
    double mass_drift;            /* relative change of the column's volume */
} gf_continuum_collapse_result;

/* The farthest x of the deposit, contiguous from the back wall x = 0, whose depth sum_j c h_y is at
 * least depth_m, interpolated linearly between column centres where it crosses depth_m
 * (gf_measure_profile_extent); NaN when out of memory. */
double gf_continuum_collapse_extent(const gf_continuum *s, double depth_m);
/* The front as the DEM scene measures it (gf_scene_column_collapse.c): the farthest x of the
 * deposit, contiguous from the back wall x = 0, whose solid height phi sum_j c h_y is at least
 * D/4, interpolated linearly between column centres where it crosses D/4. */
double gf_continuum_collapse_front(const gf_continuum *s, double phi, double D);

/* The run's grid cells and time steps, from the spec alone (`grainflow check`'s cost estimate). */
gf_status gf_continuum_collapse_size(gf_ctx *ctx, const gf_run_spec *spec, double *cells, double *steps);
/* output_dir and resolved_yaml may be NULL; interrupt (may be NULL) stops the run between steps. */
gf_status gf_continuum_collapse_run(gf_ctx *ctx, const gf_run_spec *spec, const char *output_dir,
                                    const char *resolved_yaml, volatile int *interrupt,
                                    gf_continuum_collapse_result *result);

#endif
