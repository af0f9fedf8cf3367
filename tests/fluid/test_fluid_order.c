/*
 * Convergence order of the complete fluid step (gf_fluid: advection,
 * implicit viscous step, projection) in cell size h, against exact solutions
 * (engine/fluid/gf_fluid_exact.h). The Poisson solve alone is second order
 * (test_poisson_order); this test covers the whole step.
 *
 *  1. Start-up of plane Poiseuille flow between no-slip walls, n = 8, 16, 32
 *     cells across the channel, up to t = 0.1 L^2/nu (the slowest transient
 *     mode is still at exp(-pi^2 0.1) = 37 % of its start). Advection and
 *     pressure vanish: the viscous step and the no-slip ghost cells are
 *     second-order accurate, so the order must be 2: accepted [1.8, 2.2].
 *  2. Decaying Taylor-Green vortex, Re = U/(nu k) = 10, periodic box
 *     [0, 2 pi]^2, n = 16, 32, 64 cells per side, up to t = 1/(U k)
 *     (amplitude exp(-0.2)). The cell Reynolds number U h/nu is 3.9, 2.0,
 *     1.0: the first-order upwind advection (gf_advect.c), whose numerical
 *     viscosity |u| h/2 is of the order of nu here, dominates the error and
 *     the order must be that of the scheme, 1: accepted [0.75, 1.25] for
 *     both pairs (measured 0.87 and 0.93: the order approaches 1 from below
 *     as the O(h^2) part of the error fades).
 * Time step: scaled with h^2 (diffusive scaling), dt = 0.1 h^2 (Poiseuille,
 * units L^2/nu) and dt = 0.25 h^2 (Taylor-Green, units 1/(U k); CFL
 * sum |u| dt/h <= 0.2), so that the O(dt) time error is O(h^2) and the
 * spatial error dominates. Checked here: dividing dt by 4 on the middle
 * grid changes the error by less than 15 % (Poiseuille, where the time
 * error is O(h^2) like the spatial one) and 5 % (Taylor-Green). About 1.5
 * CPU s in all.
 */
#include <math.h>
#include <stdio.h>

#include "fluid/gf_fluid_exact.h"
#include "gf_test.h"

typedef struct order_case {
    const char *name;
    gf_fluid_exact_problem problem;
    int n0;             /* coarsest grid; then 2 n0, 4 n0 */
    double c_dt;        /* dt = c_dt h^2 */
    double t_end, re;
    double p_lo, p_hi;  /* accepted order */
    double dt_tol;      /* accepted |e(dt/4)/e(dt) - 1| on the middle grid */
} order_case;

static double grid_h(const order_case *oc, int n)
{
    return (oc->problem == GF_EXACT_TAYLOR_GREEN ? 2.0 * M_PI : 1.0) / n;
}

static double run_error(const order_case *oc, int n, double dt_factor, gf_fluid_exact_result *r)
{
    gf_ctx ctx = {0};
    double h = grid_h(oc, n);
    gf_fluid_exact_case c = {.problem = oc->problem, .n = n, .dt = dt_factor * oc->c_dt * h * h, .t_end = oc->t_end, .re = oc->re};
    GF_CHECK_OK(gf_fluid_exact_run(&ctx, &c, r), &ctx);
    return r->err_rms;
}

static void check_order(const order_case *oc)
{
    double e[3], h[3];
    gf_fluid_exact_result r;
    printf("%s\n", oc->name);
    for (int q = 0; q < 3; ++q) {
        int n = oc->n0 << q;
        e[q] = run_error(oc, n, 1.0, &r);
        h[q] = r.h;
        printf("  n %3d  h %.4f  cell Re %.2f  %5ld steps  rms error %.4e  max error %.4e", n, r.h, r.cell_re,
               r.steps, r.err_rms, r.err_max);
        if (q > 0)
            printf("  order %.3f", gf_fluid_exact_order(e[q - 1], e[q], h[q - 1], h[q]));
        printf("\n");
    }
    for (int q = 1; q < 3; ++q) {
        double p = gf_fluid_exact_order(e[q - 1], e[q], h[q - 1], h[q]);
        GF_CHECK(p >= oc->p_lo && p <= oc->p_hi);
    }
    double e4 = run_error(oc, oc->n0 << 1, 0.25, &r);
    printf("  n %3d with dt/4: rms error %.4e (%+.1f %%: the spatial error dominates)\n", oc->n0 << 1, e4,
           100.0 * (e4 / e[1] - 1.0));
    GF_CHECK(fabs(e4 / e[1] - 1.0) < oc->dt_tol);
}

int main(void)
{
    const order_case poiseuille = {"Poiseuille start-up, t = 0.1 L^2/nu, dt = 0.1 h^2 (expected order 2)",
                                   GF_EXACT_POISEUILLE, 8, 0.1, 0.1, 0.0, 1.8, 2.2, 0.15};
    const order_case tgv = {"Taylor-Green, Re 10, t = 1/(U k), dt = 0.25 h^2 (expected order 1: upwind advection)",
                            GF_EXACT_TAYLOR_GREEN, 16, 0.25, 1.0, 10.0, 0.75, 1.25, 0.05};
    check_order(&poiseuille);
    check_order(&tgv);
    return gf_test_finish();
}
