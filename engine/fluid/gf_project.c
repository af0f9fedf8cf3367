/*
 * Implicit drag and projection, step 3 of gf_fluid (equations in gf_fluid.h).
 *
 * Why drag and pressure are solved together: in a packed bed the drag
 * relaxation time of the fluid, eps rho / beta, is 1e-4-1e-3 s, shorter than
 * the fluid step. The drag is explicit in u** (gf_viscous.c) and made implicit
 * here, u^{n+1} = (u** + dt B u^n - (dt/rho) grad phi)/(1 + dt B), which needs
 * 1/(1 + dt B) inside the pressure equation; a steady state is exact for any
 * dt (eps grad p = -beta (u - v) in a bed: Darcy/Ergun, the pore pressure the
 * column-collapse scene measures).
 * The price is a variable coefficient eps/(1 + dt B), handled by the
 * FFT-preconditioned CG of gf_poisson.
 *
 * Face values of cell fields (eps, beta, beta v) are arithmetic means of the
 * two neighbouring cells; wall faces keep u = 0 and carry no flux.
 */
#include <math.h>
#include <string.h>

#include "fluid/gf_fluid.h"

gf_status gf_fluid_project(gf_ctx *ctx, gf_fluid *f, double dt_s)
{
    const gf_grid *g = &f->grid;
    double rho = f->rho_kg_m3;
    /* 1. drag-relaxed provisional flux w = eps (u** + dt B u^n) / (1 + dt B) and the coefficient eps/(1 + dt B) */
    for (int a = 0; a < 3; ++a) {
        for (int k = 0; k < g->nf[a][2]; ++k)
            for (int j = 0; j < g->nf[a][1]; ++j)
                for (int i = 0; i < g->nf[a][0]; ++i) {
                    int idx[3] = {i, j, k};
                    size_t fi = gf_grid_face(g, a, i, j, k);
                    if (!g->periodic[a] && (idx[a] == 0 || idx[a] == g->n[a])) {
                        f->flux[a][fi] = 0.0;
                        f->a_face[a][fi] = 0.0;
                        continue;
                    }
                    double ef = gf_grid_face_from_cells(g, f->eps, a, i, j, k);
                    double bf = gf_grid_face_from_cells(g, f->beta, a, i, j, k);
                    double bdt = dt_s * bf / (ef * rho);
                    f->flux[a][fi] = ef * (f->work[a][fi] + bdt * f->u[a][fi]) / (1.0 + bdt);
                    f->a_face[a][fi] = ef / (1.0 + bdt);
                }
    }
    /* 2. right-hand side (rho/dt) [div w + (eps - eps_old)/dt] */
    double *rhs = f->tmp[0], *phi = f->tmp[1];
    const double *const w[3] = {f->flux[0], f->flux[1], f->flux[2]};
    gf_grid_divergence(g, w, NULL, rhs);
    for (size_t c = 0; c < g->n_cells; ++c) {
        rhs[c] = rho / dt_s * (rhs[c] + (f->eps[c] - f->eps_old[c]) / dt_s);
        phi[c] = 0.0;
    }
    /* 3. pressure increment */
    const double *const af[3] = {f->a_face[0], f->a_face[1], f->a_face[2]};
    gf_status st = gf_poisson_solve_var(f->poisson, af, rhs, phi, f->poisson_rtol, 400, &f->last_solve);
    if (st == GF_ERR_NOT_CONVERGED)
        return GF_FAIL(ctx, st, "fluid projection: pressure CG did not converge in %d iterations (residual %.3g of %.3g)",
                       f->last_solve.iterations, f->last_solve.residual_final, f->last_solve.residual_initial);
    if (st != GF_OK)
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "fluid projection: non-finite pressure (check the fluid step against "
                       "gf_coupling_dt_max_s)");
    for (size_t c = 0; c < g->n_cells; ++c)
        f->p_Pa[c] += phi[c];
    /* 4. corrected velocity u = (w - (dt/rho) a grad phi) / eps */
    for (int a = 0; a < 3; ++a) {
        double h = g->h_m[a];
        for (int k = 0; k < g->nf[a][2]; ++k)
            for (int j = 0; j < g->nf[a][1]; ++j)
                for (int i = 0; i < g->nf[a][0]; ++i) {
                    int idx[3] = {i, j, k};
                    size_t fi = gf_grid_face(g, a, i, j, k);
                    if (!gf_grid_face_free(g, a, idx[a])) {
                        if (!g->periodic[a])
                            f->u[a][fi] = 0.0;
                        continue;
                    }
                    int lo[3] = {i, j, k};
                    lo[a] = gf_grid_wrap(g, a, idx[a] - 1);
                    int hi[3] = {i, j, k};
                    hi[a] = gf_grid_wrap(g, a, idx[a]);
                    double dp = (phi[gf_grid_cell(g, hi[0], hi[1], hi[2])] - phi[gf_grid_cell(g, lo[0], lo[1], lo[2])]) / h;
                    double ef = gf_grid_face_from_cells(g, f->eps, a, i, j, k);
                    f->u[a][fi] = (f->flux[a][fi] - dt_s / rho * f->a_face[a][fi] * dp) / ef;
                }
        gf_grid_sync_periodic(g, a, f->u[a]);
    }
    /* 5. discrete mass balance of the averaged continuity equation */
    const double *const uu[3] = {f->u[0], f->u[1], f->u[2]};
    gf_grid_divergence(g, uu, f->eps, rhs);
    double res = 0.0;
    for (size_t c = 0; c < g->n_cells; ++c) {
        double r = fabs(rhs[c] * dt_s + f->eps[c] - f->eps_old[c]);
        if (r > res)
            res = r;
    }
    f->last_mass_residual = res;
    return GF_OK;
}
