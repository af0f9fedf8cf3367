/*
 * gf_fluid_exact: two exact solutions of the incompressible Navier-Stokes
 * equations, and a driver that runs the complete fluid step of gf_fluid
 * (advection, implicit viscous step, projection; eps = 1, no drag) on them
 * and returns the velocity error. Used for the convergence order in cell
 * size (tests/fluid/test_fluid_order.c, the accuracy benchmark's
 * fluid_cell_order case, docs/notes/benchmarks.md).
 *
 *  POISEUILLE  start-up of plane Poiseuille flow: fluid at rest at t = 0
 *              between no-slip walls y = 0 and y = L, driven by a uniform
 *              body force G along x (periodic in x and z). Exact solution
 *              (separation of variables, e.g. Pozrikidis, Introduction to
 *              Theoretical and Computational Fluid Dynamics, 2nd ed., §6.13):
 *                u(y,t) = G/(2 nu) y (L - y)
 *                         - sum_{m odd} 4 G L^2/(nu pi^3 m^3) sin(m pi y/L) exp(-m^2 pi^2 nu t/L^2).
 *              Advection and pressure vanish: it tests the viscous step and
 *              the no-slip walls (ghost -u, wall half a cell from the
 *              nearest x-face row). Units: L = nu = 1, G = 8 (u_max = 1);
 *              time in L^2/nu.
 *  TAYLOR_GREEN decaying Taylor-Green vortex in the periodic box [0, 2 pi]^2
 *              (one periodic cell along z), k = 1 (Taylor & Green, Proc. R.
 *              Soc. A 158, 1937):
 *                u =  U sin x cos y F,  v = -U cos x sin y F,  F = exp(-2 nu k^2 t),
 *                p = (rho U^2/4)(cos 2x + cos 2y) F^2.
 *              The nonlinear term is a gradient, balanced by the pressure:
 *              it tests advection + projection + viscous step together.
 *              Units: U = k = rho = 1, nu = 1/Re; time in 1/(U k).
 *              The sampled field is exactly divergence-free on the MAC grid;
 *              the run starts from the exact u and p.
 * Error: root mean square over every velocity unknown (faces) of
 * u_h - u_exact at t_end, divided by the exact velocity scale at t_end
 * (u_max of the steady profile for POISEUILLE, U F(t_end) for TAYLOR_GREEN);
 * the largest face error with the same scale too.
 */
#ifndef GF_FLUID_EXACT_H
#define GF_FLUID_EXACT_H

#include "core/gf_status.h"
#include "fluid/gf_fluid_ns2.h"

typedef enum gf_fluid_exact_problem { GF_EXACT_POISEUILLE = 0, GF_EXACT_TAYLOR_GREEN } gf_fluid_exact_problem;

typedef struct gf_fluid_exact_case {
    gf_fluid_exact_problem problem;
    int n;            /* cells along each varying axis: across the channel / along x and y of the box */
    double dt;        /* fluid step (the problem's time unit); rounded down so that t_end is a whole number of steps */
    double t_end;     /* the problem's time unit */
    double re;        /* TAYLOR_GREEN: Reynolds number U/(nu k); ignored otherwise */
    gf_ns2_scheme scheme; /* gf_fluid_exact_run_ns2: the resolved tier's time scheme (0: AB2) */
    gf_ns2_advection advection; /* gf_fluid_exact_run_ns2: its advection form (0: advective) */
    double noise;     /* TAYLOR_GREEN: a fixed pseudo-random velocity of this amplitude added at t = 0 (its
                         divergence removed by the first projection), to excite every grid mode; 0: none */
} gf_fluid_exact_case;

typedef struct gf_fluid_exact_result {
    double err_rms, err_max;  /* relative velocity errors at t_end (see above) */
    double h;                 /* cell edge (problem units) */
    double cell_re;           /* TAYLOR_GREEN: U h / nu; 0 otherwise */
    long steps;
    double energy_ratio;      /* kinetic energy at t_end over the exact one (the discrete one at t = 0 times F^2
                                 for TAYLOR_GREEN, times 1 for POISEUILLE: meaningful for TAYLOR_GREEN only) */
} gf_fluid_exact_result;

/* Runs the case. Errors: n < 2, dt or t_end <= 0, a failed fluid step. */
gf_status gf_fluid_exact_run(gf_ctx *ctx, const gf_fluid_exact_case *c, gf_fluid_exact_result *out);
/* The same with the resolved tier's step (gf_fluid_ns2.h; c->scheme: AB2 or RK3 with Crank-Nicolson), no
 * forcing; TAYLOR_GREEN only (that step has no body force). */
gf_status gf_fluid_exact_run_ns2(gf_ctx *ctx, const gf_fluid_exact_case *c, gf_fluid_exact_result *out);

/* Order between two grids: ln(e_coarse / e_fine) / ln(h_coarse / h_fine). */
double gf_fluid_exact_order(double e_coarse, double e_fine, double h_coarse, double h_fine);

#endif
