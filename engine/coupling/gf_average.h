/*
 * gf_average: grain <-> grid transfer of the unresolved tier.
 *
 * Kernel. Each grain carries a separable Gaussian of standard deviation
 * sigma (>= one cell, spec default sigma = max cell edge, i.e. 2 D at
 * cell_over_D = 2), integrated exactly over each cell:
 *   w_i(cell) = prod_d [ erf((x_d,hi - X_d)/(sqrt2 sigma)) - erf((x_d,lo - X_d)/(sqrt2 sigma)) ] / 2,
 * truncated at 3 sigma and renormalised so that sum_cells w_i = 1 exactly.
 *   - conservative: sum_cells (1 - eps) V_cell = sum_i V_i to round-off, so the
 *     averaged continuity equation has no spurious source;
 *   - smooth: w_i is C-infinity in the grain position, so a grain crossing a
 *     cell face moves eps continuously (no cell-size noise, which a
 *     particle-centroid-in-cell rule would inject into the pressure);
 *   - wider than a cell: the averaging volume (2 pi)^{3/2} sigma^3 ~ 125 D^3
 *     holds ~ 150 grains at phi = 0.6, a meaningful local average
 *     (Capecelatro & Desjardins, J. Comput. Phys. 238, 2013 use the same idea).
 * Walls fold the part of the kernel beyond the wall back into the domain
 * (mirror image), periodic axes wrap, so conservation holds at boundaries.
 *
 * The same weights interpolate grid fields to the grain (u_f, grad p) and
 * spread grain quantities (drag coefficient, reaction force) to the grid, so
 * the momentum given to the fluid equals the momentum taken from the grains.
 */
#ifndef GF_AVERAGE_H
#define GF_AVERAGE_H

#include "fluid/gf_grid.h"

#define GF_KERNEL_MAX 40

typedef struct gf_kernel_1d {
    int n;
    int cell[GF_KERNEL_MAX];
    double w[GF_KERNEL_MAX];
} gf_kernel_1d;

typedef struct gf_kernel {
    gf_kernel_1d ax[3];
} gf_kernel;

/* Weights of a grain at x (m) with kernel width sigma (m). */
void gf_average_kernel(const gf_grid *g, double sigma_m, const double x_m[3], gf_kernel *k);
/* sum_cells w field[cell] */
double gf_average_interpolate(const gf_grid *g, const gf_kernel *k, const double *field);
/* The per-grain transfers of a fluid step with the cell fields interleaved,
 * GF_AVERAGE_LANES values per cell (one cache line, one AVX-512 vector;
 * unused lanes zero), so that each cell of a kernel is read or written once
 * for all its fields. Bitwise the results of one gf_average_interpolate and
 * one gf_average_spread per field: every lane forms the same products and
 * sums them in the same order. `lanes` holds n_cells * GF_AVERAGE_LANES
 * doubles. */
enum { GF_AVERAGE_LANES = 8 };
/* lanes[cell][f] = fields[f][cell] for f < n_fields, 0 beyond */
void gf_average_interleave(size_t n_cells, const double *const *fields, int n_fields, double *lanes);
/* fields[f][cell] = lanes[cell][f] for f < n_fields */
void gf_average_deinterleave(size_t n_cells, const double *lanes, int n_fields, double *const *fields);
/* out[f] = sum_cells w lanes[cell][f], every lane */
void gf_average_interpolate_lanes(const gf_grid *g, const gf_kernel *k, const double *lanes,
                                  double out[GF_AVERAGE_LANES]);
/* lanes[cell][f] += value[f] w / V_cell, every lane */
void gf_average_spread_lanes(const gf_grid *g, const gf_kernel *k, const double value[GF_AVERAGE_LANES], double *lanes);
/* field[cell] += value w / V_cell (a density) */
void gf_average_spread(const gf_grid *g, const gf_kernel *k, double value, double *field);
/* sum_cells w^2 (self-overlap of the kernel, 1/cells) */
double gf_average_self_overlap(const gf_kernel *k);

#endif
