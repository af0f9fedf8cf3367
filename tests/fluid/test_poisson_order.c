/*
 * Poisson solvers of the projection step: manufactured solutions, second-order
 * convergence (halving h divides the max error by 4, accepted in [3.2, 4.8]).
 *
 *  - walls (Neumann) on every axis: phi = g(x) g(y) g(z), g(s) = cos(pi s) + s^2 (1-s)^2 / ... with zero
 *    normal derivative at s = 0, 1 — not an eigenfunction of the discrete operator;
 *  - periodic on every axis: phi = exp(sin 2 pi x) cos(2 pi y) + sin(2 pi z);
 *  - mixed (x periodic, y, z walls), the collapse/avalanche layout;
 *  - variable coefficient a = 1 + 0.5 sin(...) with the FFT-preconditioned CG:
 *    same order, and the iteration count stays flat as h halves (the
 *    preconditioner's point).
 * The solve cost per cell is printed for the report.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/gf_timer.h"
#include "fluid/gf_grid.h"
#include "fluid/gf_poisson.h"
#include "gf_test.h"

/* g(s) with g'(0) = g'(1) = 0 and its second derivative */
static double gw(double s) { return cos(M_PI * s) + 4.0 * s * s * (1 - s) * (1 - s); }
static double gw2(double s) { return -M_PI * M_PI * cos(M_PI * s) + 4.0 * (2 - 12 * s + 12 * s * s); }
static double gw1(double s) { return -M_PI * sin(M_PI * s) + 4.0 * (2 * s - 6 * s * s + 4 * s * s * s); }

typedef struct {
    int periodic[3];
    int variable;
} poisson_case;

static double exact(const poisson_case *pc, const double x[3], double *lap)
{
    double f[3], f1[3], f2[3];
    for (int d = 0; d < 3; ++d) {
        double s = x[d];
        if (pc->periodic[d]) {
            /* exp(sin 2 pi s) */
            double w = 2 * M_PI, e = exp(sin(w * s));
            f[d] = e;
            f1[d] = e * w * cos(w * s);
            f2[d] = e * (w * w * cos(w * s) * cos(w * s) - w * w * sin(w * s));
        } else {
            f[d] = gw(s);
            f1[d] = gw1(s);
            f2[d] = gw2(s);
        }
    }
    double phi = f[0] * f[1] * f[2];
    double grad[3] = {f1[0] * f[1] * f[2], f[0] * f1[1] * f[2], f[0] * f[1] * f1[2]};
    double l = f2[0] * f[1] * f[2] + f[0] * f2[1] * f[2] + f[0] * f[1] * f2[2];
    if (pc->variable) {
        /* div(a grad phi) = a lap phi + grad a . grad phi, a = 1 + 0.5 sin(2 pi x) sin(2 pi y) ... periodic-safe:
         * use a = 1 + 0.5 cos(2 pi x) cos(2 pi y) cos(2 pi z) (zero normal derivative at walls too) */
        double w = 2 * M_PI;
        double cx = cos(w * x[0]), cy = cos(w * x[1]), cz = cos(w * x[2]);
        double a = 1.0 + 0.5 * cx * cy * cz;
        double ga[3] = {-0.5 * w * sin(w * x[0]) * cy * cz, -0.5 * w * cx * sin(w * x[1]) * cz,
                        -0.5 * w * cx * cy * sin(w * x[2])};
        l = a * l + ga[0] * grad[0] + ga[1] * grad[1] + ga[2] * grad[2];
    }
    *lap = l;
    return phi;
}

static double coef_at(const double x[3])
{
    double w = 2 * M_PI;
    return 1.0 + 0.5 * cos(w * x[0]) * cos(w * x[1]) * cos(w * x[2]);
}

/* Max error (mean removed) on an n^3 grid of the unit cube. */
static double solve_error(const poisson_case *pc, int n, int *iters, double *sec_per_cell)
{
    gf_ctx ctx = {0};
    gf_grid g;
    int nn[3] = {n, n, n};
    double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    gf_grid_bc bc[3][2];
    for (int d = 0; d < 3; ++d)
        bc[d][0] = bc[d][1] = pc->periodic[d] ? GF_GRID_PERIODIC : GF_GRID_NO_SLIP;
    gf_grid_init(&ctx, &g, nn, lo, hi, bc);
    gf_poisson_plan *pl = NULL;
    GF_CHECK_OK(gf_poisson_plan_create(&ctx, &g, &pl), &ctx);
    size_t nc = g.n_cells;
    double *rhs = malloc(nc * sizeof(double)), *phi = calloc(nc, sizeof(double)), *ex = malloc(nc * sizeof(double));
    double *a[3];
    for (int d = 0; d < 3; ++d) {
        a[d] = malloc(g.n_faces[d] * sizeof(double));
        for (int k = 0; k < g.nf[d][2]; ++k)
            for (int j = 0; j < g.nf[d][1]; ++j)
                for (int i = 0; i < g.nf[d][0]; ++i) {
                    double x[3] = {(i + 0.5) * g.h_m[0], (j + 0.5) * g.h_m[1], (k + 0.5) * g.h_m[2]};
                    int idx[3] = {i, j, k};
                    x[d] = idx[d] * g.h_m[d];
                    a[d][gf_grid_face(&g, d, i, j, k)] = pc->variable ? coef_at(x) : 1.0;
                }
    }
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                double x[3] = {(i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n}, l;
                size_t c = gf_grid_cell(&g, i, j, k);
                ex[c] = exact(pc, x, &l);
                rhs[c] = l;
            }
    double t0 = gf_wtime();
    gf_solve_stats st = {0};
    if (pc->variable) {
        const double *const ac[3] = {a[0], a[1], a[2]};
        GF_CHECK_OK(gf_poisson_solve_var(pl, ac, rhs, phi, 1e-12, 500, &st), &ctx);
    } else {
        gf_poisson_solve_const(pl, rhs, phi);
    }
    *sec_per_cell = (gf_wtime() - t0) / (double)nc;
    *iters = st.iterations;
    double mp = 0, me = 0;
    for (size_t c = 0; c < nc; ++c) {
        mp += phi[c];
        me += ex[c];
    }
    mp /= nc;
    me /= nc;
    double err = 0;
    for (size_t c = 0; c < nc; ++c)
        err = fmax(err, fabs((phi[c] - mp) - (ex[c] - me)));
    for (int d = 0; d < 3; ++d)
        free(a[d]);
    free(rhs);
    free(phi);
    free(ex);
    gf_poisson_plan_destroy(&pl);
    return err;
}

static void check_order(const char *name, poisson_case pc)
{
    int it1, it2;
    double c1, c2;
    double e1 = solve_error(&pc, 16, &it1, &c1);
    double e2 = solve_error(&pc, 32, &it2, &c2);
    double ratio = e1 / e2;
    printf("%-28s err(h=1/16) %.3e  err(h=1/32) %.3e  ratio %.2f  CG its %d -> %d  cost %.2e s/cell (32^3)\n",
           name, e1, e2, ratio, it1, it2, c2);
    GF_CHECK(ratio >= 3.2 && ratio <= 4.8);  /* second order: 4 */
    if (pc.variable)
        GF_CHECK(it2 <= it1 + 5);  /* FFT preconditioner: h-independent iteration count */
}

int main(void)
{
    check_order("walls, constant coeff", (poisson_case){{0, 0, 0}, 0});
    check_order("periodic, constant coeff", (poisson_case){{1, 1, 1}, 0});
    check_order("x periodic + walls", (poisson_case){{1, 0, 0}, 0});
    check_order("walls, variable coeff (PCG)", (poisson_case){{0, 0, 0}, 1});
    check_order("periodic, variable (PCG)", (poisson_case){{1, 1, 1}, 1});
    return gf_test_finish();
}
