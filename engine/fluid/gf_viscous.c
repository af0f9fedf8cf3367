/*
 * Momentum increment with semi-implicit viscosity, step 2 of gf_fluid (see gf_fluid.h):
 *   (1 - dt nu L) delta = dt [ r + nu L u^n - grad p^n / rho + B (vbar - u^n) ],   u** = u^n + delta,
 * nu = mu / rho, r the explicit rates of gf_advect.c already in f->work.
 * Backward Euler for the viscous term, so there is no viscous time-step
 * limit (the explicit limit dt < h^2/(6 nu) would cost 10^2-10^4 steps per
 * collapse time at eta_f = 1 Pa s and h = D/10 in the resolved tier); advection
 * stays explicit, hence "semi-implicit". Writing it for the increment makes
 * steady states exact for any dt (see gf_fluid.h).
 *
 * The averaged viscous term (1/(eps rho)) div(eps tau) is approximated by
 * nu L u, i.e. the terms in grad(eps) are dropped: a common simplification
 * of unresolved CFD-DEM, justified because the kernel-smoothed eps varies
 * over several cells while, in packed regions where it varies, drag and
 * pressure dominate the momentum balance (Darcy regime).
 *
 * Solver: the constant-coefficient operator is diagonalised exactly by the
 * sine/cosine/Fourier transforms matching each component's boundary
 * conditions (gf_helmholtz_solve in gf_poisson.c): two FFTs per component,
 * no iteration, O(N log N).
 */
#include <math.h>

#include "fluid/gf_fluid.h"

gf_status gf_fluid_viscous(gf_ctx *ctx, gf_fluid *f, double dt_s)
{
    const gf_grid *g = &f->grid;
    double rho = f->rho_kg_m3, nu = f->mu_Pa_s / rho;
    for (int a = 0; a < 3; ++a) {
        double *r = f->work[a];
        const double *u = f->u[a];
        GF_GRID_FOR_FREE_FACES(g, a, fi, i, j, k) {
            int lo[3] = {i, j, k}, hi[3] = {i, j, k};
            lo[a] = gf_grid_wrap(g, a, lo[a] - 1);  /* the cells either side of the face */
            hi[a] = gf_grid_wrap(g, a, hi[a]);
            double dp = (f->p_Pa[gf_grid_cell(g, hi[0], hi[1], hi[2])] -
                         f->p_Pa[gf_grid_cell(g, lo[0], lo[1], lo[2])]) / g->h_m[a];
            double ef = gf_grid_face_from_cells(g, f->eps, a, i, j, k);
            double bf = gf_grid_face_from_cells(g, f->beta, a, i, j, k);
            double bvf = gf_grid_face_from_cells(g, f->beta_v[a], a, i, j, k);
            r[fi] += dt_s * (nu * gf_grid_face_laplacian(g, u, a, i, j, k) - dp / rho +
                             (bvf - bf * u[fi]) / (ef * rho));
        }
        gf_grid_sync_periodic(g, a, r);
        gf_helmholtz_solve(f->visc[a], dt_s * nu, r);
        double s = 0.0;
        for (size_t q = 0; q < g->n_faces[a]; ++q) {
            r[q] += u[q];
            s += r[q] * r[q];
        }
        if (!isfinite(s))
            return GF_FAIL(ctx, GF_ERR_NUMERIC, "fluid viscous step: non-finite velocity (component %d)", a);
    }
    return GF_OK;
}
