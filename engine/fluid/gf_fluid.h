/*
 * gf_fluid: state and steps of the incompressible MAC solver used by the
 * coupling tiers. The unresolved tier solves the locally averaged equations
 * (Anderson & Jackson, I&EC Fundam. 6, 1967) in the form set out in
 * coupling/gf_coupling_unresolved.c; with eps = 1 and no drag they reduce to
 * the plain Navier-Stokes equations the resolved tier needs.
 *
 * One fluid step, an incremental pressure-correction scheme (van Kan, SIAM
 * J. Sci. Stat. Comput. 7, 1986) in which every explicit term, the viscous
 * term and the drag are written for the INCREMENT delta = u** - u^n, so that a
 * steady state satisfies the steady equations exactly whatever dt (a
 * non-incremental split leaves an O(dt) error dt f where the drag force f is
 * concentrated, which doubled a settling grain's self-induced velocity):
 *   1. explicit rates (gf_advect.c):  r = -(u.grad)u + b
 *   2. (gf_viscous.c)  (1 - dt nu L) delta = dt [ r + nu L u^n - grad p^n / rho + B (vbar - u^n) ],
 *        u** = u^n + delta,   B = beta / (eps rho), beta vbar = sum_i K_i v_i delta_i
 *   3. implicit drag correction + projection (gf_project.c):
 *        u^{n+1} = (u** + dt B u^n - (dt/rho) grad phi) / (1 + dt B),  p^{n+1} = p^n + phi,
 *        with div(eps u^{n+1}) = -(eps^{n+1} - eps^n)/dt, i.e.
 *        div( eps/(1 + dt B) grad phi ) = (rho/dt) [ div(eps (u** + dt B u^n)/(1 + dt B)) + (eps^{n+1} - eps^n)/dt ].
 *      Step 3 turns the explicit drag of step 2 into backward Euler:
 *      u^{n+1} - u^n = dt B (vbar - u^{n+1}) + ..., stable for any dt B.
 * p is the pressure in excess of the hydrostatic one (the caller removes rho_f g from the body force).
 *
 * The struct is plain so the coupling can read the fields; only gf_fluid_*
 * functions write them. All arrays are owned by the struct.
 */
#ifndef GF_FLUID_H
#define GF_FLUID_H

#include "core/gf_status.h"
#include "fluid/gf_grid.h"
#include "fluid/gf_poisson.h"

typedef struct gf_fluid_params {
    int n_cells[3];
    double lo_m[3], hi_m[3];
    gf_grid_bc bc[3][2];
    double density_kg_m3, viscosity_Pa_s;
    double poisson_rtol;          /* CG relative tolerance, 0: 1e-10 */
} gf_fluid_params;

typedef struct gf_fluid {
    gf_grid grid;
    double rho_kg_m3, mu_Pa_s;
    double *u[3];                 /* face velocities, m/s */
    double *p_Pa;                 /* cell-centred excess pressure */
    double *eps, *eps_old;        /* cell fluid fraction now / at the previous step */
    double *beta;                 /* cell drag coefficient, kg m^-3 s^-1 (force density per slip) */
    double *beta_v[3];            /* beta times the grains' velocity, cell-centred */
    double *body[3];              /* extra body force per unit fluid mass at cells, m/s^2 */
    double *work[3];              /* u** after gf_fluid_viscous */
    double *flux[3];              /* eps-weighted provisional flux of the projection */
    double *tmp[4];               /* scratch (max of cell and face counts) */
    double *a_face[3];            /* Poisson coefficient */
    gf_poisson_plan *poisson;
    gf_helmholtz_plan *visc[3];
    double poisson_rtol;
    gf_solve_stats last_solve;
    double last_mass_residual;    /* max |div(eps u) + d eps/dt| dt after the last projection */
} gf_fluid;

gf_status gf_fluid_create(gf_ctx *ctx, const gf_fluid_params *prm, gf_fluid **out);
void gf_fluid_destroy(gf_fluid **f);

/* Step 1: work = dt (-(u.grad)u + body), first-order upwind (gf_advect.c). */
void gf_fluid_advect(gf_fluid *f, double dt_s);
/* Step 2: adds the viscous, pressure and drag rates to work, solves the backward-Euler
 * Helmholtz problem for the increment (FFT), leaves u** in work (gf_viscous.c). */
gf_status gf_fluid_viscous(gf_ctx *ctx, gf_fluid *f, double dt_s);
/* Step 3: implicit drag + projection (gf_project.c): u = u^{n+1}, p += phi. Uses eps, eps_old, beta, beta_v. */
gf_status gf_fluid_project(gf_ctx *ctx, gf_fluid *f, double dt_s);
/* Component b of the velocity at the face (i,j,k) of component a: the mean of the four b-faces around it. */
double gf_fluid_advecting_velocity(const gf_grid *g, const double *const u[3], int a, int b, int i, int j, int k);
/* Largest |u| component over the faces, m/s. */
double gf_fluid_max_speed(const gf_fluid *f);
/* 0 when every velocity and pressure is finite. */
int gf_fluid_nonfinite(const gf_fluid *f);

#endif
