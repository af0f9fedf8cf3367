/*
 * Explicit advection and body force, step 1 of gf_fluid (see gf_fluid.h):
 *   work_a = dt [ -(u.grad) u_a + b_a ]   (an increment; gf_viscous adds the rest)
 * in the non-conservative form. For the locally averaged equations this form
 * follows from the conservative one, d(eps u)/dt + div(eps u u), by
 * subtracting u times the averaged continuity equation
 * d eps/dt + div(eps u) = 0, so eps drops out of the advection operator.
 *
 * Discretisation: first-order upwind differences of u_a along each axis,
 * with the advecting velocity at the face of u_a (the other components
 * averaged from their four nearest faces). The scheme is monotone and stable
 * for sum_d |u_d| dt / h_d <= 1 (the CFL limit gf_coupling_dt_max_s keeps
 * with the margin spec.fluid.cfl). Its numerical viscosity |u| h / 2 is
 * below the physical one wherever the cell Reynolds number |u| h / nu < 2,
 * which holds in the viscous and Stokes regimes this tier targets (collapse
 * Re_p < 2.5, Izard 2014 §5.2); at Re_p ~ 20 with h ~ 2.5 D it is not, and the
 * sphere-scale flow is then over-damped (see docs/notes/validation-fluid.md).
 */
#include <string.h>

#include "fluid/gf_fluid.h"

double gf_fluid_advecting_velocity(const gf_grid *g, const double *const u[3], int a, int b, int i, int j, int k)
{
    /* component b at the face of u_a: mean of the four b-faces around it */
    int idx[3] = {i, j, k};
    int m = idx[a];
    int c0 = gf_grid_wrap(g, a, m - 1), c1 = gf_grid_wrap(g, a, m);
    if (c0 < 0)
        c0 = c1;
    if (c1 < 0)
        c1 = c0;
    double s = 0.0;
    for (int side = 0; side < 2; ++side)
        for (int up = 0; up < 2; ++up) {
            int q[3] = {i, j, k};
            q[a] = side ? c1 : c0;
            q[b] += up;
            s += u[b][gf_grid_face(g, b, q[0], q[1], q[2])];
        }
    return 0.25 * s;
}

void gf_fluid_advect(gf_fluid *f, double dt_s)
{
    const gf_grid *g = &f->grid;
    const double *const uu[3] = {f->u[0], f->u[1], f->u[2]};
    for (int a = 0; a < 3; ++a) {
        double *out = f->work[a];
        const double *u = f->u[a];
        memset(out, 0, g->n_faces[a] * sizeof(double));
        GF_GRID_FOR_FREE_FACES(g, a, fi, i, j, k) {
            double adv = 0.0;
            for (int d = 0; d < 3; ++d) {
                if (g->n[d] == 1 && g->periodic[d])
                    continue;  /* a single periodic cell: no variation along d */
                double vd = d == a ? u[fi] : gf_fluid_advecting_velocity(g, uu, a, d, i, j, k);
                double nb = gf_grid_face_neighbour(g, u, a, i, j, k, d, vd > 0.0 ? -1 : +1);
                adv += vd > 0.0 ? vd * (u[fi] - nb) / g->h_m[d] : vd * (nb - u[fi]) / g->h_m[d];
            }
            double b = gf_grid_face_from_cells(g, f->body[a], a, i, j, k);
            out[fi] = dt_s * (b - adv);
        }
        gf_grid_sync_periodic(g, a, out);
    }
}
