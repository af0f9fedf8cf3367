/*
 * gf_poisson: the pressure Poisson solves of the projection step, on the
 * cell-centred MAC pressure grid, with FFTW (Frigo & Johnson, Proc. IEEE 93,
 * 2005). This file pair is the only FFTW caller of the engine.
 *
 * Constant coefficient, L phi = f with L the 7-point Laplacian:
 *   - wall axis (zero normal flux at the wall faces, i.e. homogeneous Neumann
 *     for cell-centred unknowns): the DCT-II (FFTW_REDFT10) diagonalises L,
 *     inverse DCT-III (FFTW_REDFT01), eigenvalues (2 cos(pi m/n) - 2)/h^2;
 *   - periodic axis: the real DFT in half-complex order (FFTW_R2HC/HC2R),
 *     eigenvalues (2 cos(2 pi m/n) - 2)/h^2 for frequency m.
 *   One 3-D r2r transform each way, O(N log N); the constant mode (null
 *   space of the pure Neumann/periodic problem) is set to zero, so the
 *   solution has zero mean and the right-hand side's mean is ignored.
 *
 * Variable coefficient, div(a grad phi) = f with a > 0 on faces (a = 0 on
 * walls): the locally averaged projection needs it, a being the fluid
 * fraction (divided by 1 + implicit drag factor). Solved by conjugate
 * gradients on -div(a grad .) (SPD on zero-mean fields) preconditioned by the
 * constant-coefficient FFT solve with the mean of a. The preconditioned
 * operator has condition number about max(a)/min(a) (2-10 here), so CG needs
 * 10-30 iterations whatever the grid size: a cost of O(N log N) per
 * iteration, measured and reported through gf_solve_stats.
 */
#ifndef GF_POISSON_H
#define GF_POISSON_H

#include "core/gf_status.h"
#include "fluid/gf_grid.h"

typedef struct gf_poisson_plan gf_poisson_plan;

typedef struct gf_solve_stats {
    int iterations;
    double residual_initial, residual_final;  /* 2-norms of the (mean-free) residual */
    double seconds;                           /* wall time of the solve */
} gf_solve_stats;

/* Returns owned plan for grid g (borrowed; must outlive the plan). */
gf_status gf_poisson_plan_create(gf_ctx *ctx, const gf_grid *g, gf_poisson_plan **out);
void gf_poisson_plan_destroy(gf_poisson_plan **plan);

/* Re-plans the transforms as z-planes then z-lines shared among n_threads OpenMP threads (and runs the
 * pointwise loops on as many): the result is bitwise the same for any n_threads >= 1, but differs by rounding
 * from the 3-D plans a plan is created with (which the unresolved tier keeps). Not thread-safe (FFTW's
 * planner): call it from one thread. */
gf_status gf_poisson_plan_set_threads(gf_ctx *ctx, gf_poisson_plan *plan, int n_threads);
/* The thread count set (1 by default); NULL: 1. */
int gf_poisson_plan_threads(const gf_poisson_plan *plan);

/* L phi = rhs, zero-mean phi. rhs and phi are cell arrays; may alias. */
void gf_poisson_solve_const(gf_poisson_plan *plan, const double *rhs, double *phi);

/* div(a grad phi) = rhs, a given on faces (face arrays of gf_grid, wall faces ignored).
 * phi holds the initial guess on entry (any; its mean is removed).
 * GF_ERR_NOT_CONVERGED when ||r|| > rtol ||rhs|| after max_iter iterations. */
gf_status gf_poisson_solve_var(gf_poisson_plan *plan, const double *const a_face[3], const double *rhs, double *phi,
                               double rtol, int max_iter, gf_solve_stats *stats);

/* y = div(a grad x) (the operator of gf_poisson_solve_var). */
void gf_poisson_apply_var(const gf_grid *g, const double *const a_face[3], const double *x, double *y);

#endif

/*
 * Helmholtz solve of the implicit viscous step, (1 - c L) u = b for one face
 * component a (c = nu dt), with the velocity boundary conditions of gf_grid:
 * per axis the sine/cosine transform that diagonalises the MAC stencil,
 *   along a, wall:            faces 1..n-1, u = 0 on the walls  -> DST-I   (RODFT00)
 *   across, no-slip both:     cells, ghost -u                   -> DST-II  (RODFT10/01)
 *   across, free-slip both:   cells, ghost +u                   -> DCT-II  (REDFT10/01)
 *   across, no-slip low / free-slip high (or reverse)           -> RODFT11 / REDFT11
 *   periodic:                                                   -> R2HC/HC2R
 * so the viscous step is exact (no iteration) and costs two FFTs.
 */
typedef struct gf_helmholtz_plan gf_helmholtz_plan;
gf_status gf_helmholtz_plan_create(gf_ctx *ctx, const gf_grid *g, int a, gf_helmholtz_plan **out);
void gf_helmholtz_plan_destroy(gf_helmholtz_plan **plan);
/* As gf_poisson_plan_set_threads, for the Helmholtz transforms of one component. */
gf_status gf_helmholtz_plan_set_threads(gf_ctx *ctx, gf_helmholtz_plan *plan, int n_threads);
/* In place on the face array u of component a; wall faces untouched, periodic duplicates synced. */
void gf_helmholtz_solve(gf_helmholtz_plan *plan, double c_m2, double *u);
