/*
 * gf_fluid_ns2: the second-order Navier-Stokes step of the resolved tier on
 * the MAC grid of gf_fluid (eps = 1, no drag), with a forcing term supplied by
 * the caller (the immersed boundary, coupling/gf_ibm.h).
 *
 * Time scheme: Adams-Bashforth 2 for advection, Crank-Nicolson for the
 * viscous term, incremental pressure correction (Kim & Moin, J. Comput. Phys.
 * 59, 1985; van Kan 1986), second order in time for the velocity:
 *   r    = 3/2 A^n - 1/2 A^{n-1} + nu L u^n - grad p^n / rho        (A = -(u.grad)u)
 *   u~   = u^n + dt r                                             (predictor: forcing only)
 *   (1 - dt nu/2 L) delta = dt (r + f),   u* = u^n + delta          (CN; f = alpha (U - u~)/dt)
 *   L phi = (rho/dt) div u*,  u^{n+1} = u* - (dt/rho) grad phi,  p^{n+1} = p^n + phi.
 * Izard (2014, §2.2.1.2) uses the three-substep Runge-Kutta with Crank-Nicolson
 * of the same family; AB2/CN costs one Helmholtz and one Poisson solve per step
 * instead of three of each, for the same order, at the price of a smaller
 * stable advective CFL (AB2 on central advection: sum |u| dt/h <= ~0.5 with the
 * viscous damping of these cell Reynolds numbers; the tier keeps spec.fluid.cfl).
 * The first step, with no A^{n-1}, is Euler (A^{n-1} = A^n).
 *
 * Space: second-order central differences for the advection (non-conservative
 * form, advecting velocities averaged from the four neighbouring faces), the
 * MAC Laplacian and gradient of gf_grid; the Helmholtz and Poisson problems are
 * solved exactly by the transforms of gf_poisson (FFTW), two FFTs each.
 */
#ifndef GF_FLUID_NS2_H
#define GF_FLUID_NS2_H

#include "fluid/gf_fluid.h"

/* A = -(u.grad)u at every free face (0 elsewhere), m/s^2. */
void gf_fluid_ns2_advection(const gf_fluid *f, double *const A[3]);
/* r = 3/2 A - 1/2 A_old + nu L u - grad p / rho at free faces; A_old may be A (Euler start). */
void gf_fluid_ns2_rates(const gf_fluid *f, const double *const A[3], const double *const A_old[3], double *const r[3]);
/* r += b_a at every free face of each component a with b_a != 0: a uniform body acceleration (m/s^2), at the
 * faces inside the grains too (the resolved tier's mean pressure gradient over rho on a periodic gravity axis). */
void gf_fluid_ns2_add_acceleration(const gf_fluid *f, const double b_m_s2[3], double *const r[3]);
/* u~ = u + dt r. */
void gf_fluid_ns2_predict(const gf_fluid *f, const double *const r[3], double dt_s, double *const u_pred[3]);
/* Crank-Nicolson increment with the forcing: f->work = u*; force may be NULL. */
gf_status gf_fluid_ns2_viscous(gf_ctx *ctx, gf_fluid *f, const double *const r[3], const double *const force[3],
                               double dt_s);
/* Projection of f->work with the constant-coefficient FFT Poisson solve: f->u = u^{n+1}, f->p_Pa += phi;
 * f->last_mass_residual = max |div u^{n+1}| dt. */
gf_status gf_fluid_ns2_project(gf_ctx *ctx, gf_fluid *f, double dt_s);

#endif
