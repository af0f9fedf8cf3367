/*
 * The campaign grid over the dimensionless groups (St, r, a, Phi_i).
 *
 * Each axis is a list of values, a single value, or a range
 * {from, to, num, scale: lin|log}: lin gives from + (to - from) k/(num - 1),
 * log gives from (to/from)^(k/(num - 1)) (equal ratios, what a regime map over
 * St = 1e-2 .. 1e3 needs), k = 0 .. num-1, the end points exact.
 * combine: product (default) takes every combination, St slowest and Phi_i
 * fastest; zip takes the k-th value of every axis together (all axes the same
 * length), for lists of points such as Izard's Table 4.2 (St, r) pairs.
 */
#ifndef GF_GRID_H
#define GF_GRID_H

#include "config/gf_cfg.h"

#define GF_GRID_MAX_POINTS 100000

typedef struct gf_grid_axis {
    int n;                       /* 0: the group is not on the grid */
    double *values;
    const gf_cfg_node *node;     /* for located errors (borrowed from the doc) */
} gf_grid_axis;

typedef struct gf_grid {
    gf_grid_axis axes[4];        /* St, r, a, Phi_i (gf_group_names) */
    int zip;
    int n_points;                /* 1 when there is no grid */
    const gf_cfg_node *node;
} gf_grid;

/* Reads grid: (node may be NULL: one point, no group). Errors GF_ERR_CONFIG located. */
gf_status gf_grid_read(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, gf_grid *grid);
/* Values of point k (0 <= k < n_points); NaN for groups not on the grid. */
void gf_grid_point(const gf_grid *grid, int k, double values[4]);
void gf_grid_free(gf_grid *grid);

#endif
