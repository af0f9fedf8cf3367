/*
 * gf_fluid_ns2: the second-order Navier-Stokes step of the resolved tier on
 * the MAC grid of gf_fluid (eps = 1, no drag), with a forcing term supplied by
 * the caller (the immersed boundary, coupling/gf_ibm.h).
 *
 * Time schemes. A step is one or more substeps k of the same form, explicit
 * advection with Crank-Nicolson viscosity and incremental pressure correction
 * (Kim & Moin, J. Comput. Phys. 59, 1985; van Kan 1986):
 *   r    = gamma_k A^{k-1} + zeta_k A^{k-2} + 2 alpha_k (nu L u^{k-1} - grad p^{k-1} / rho)   (A = -(u.grad)u)
 *   u~   = u^{k-1} + dt r                                         (predictor: forcing only)
 *   (1 - alpha_k dt nu L) delta = dt (r + f),   u* = u^{k-1} + delta   (f = alpha (U - u~)/dt)
 *   L phi = (rho/dt_k) div u*,  u^k = u* - (dt_k/rho) grad phi,  p^k = p^{k-1} + phi,   dt_k = 2 alpha_k dt.
 *  - "ab2": one substep, gamma 3/2, zeta -1/2, alpha 1/2 (Adams-Bashforth 2, A^{k-2} the previous step's);
 *    the first step, with no previous A, is Euler (A^{k-2} = A^{k-1}). One Helmholtz and one Poisson solve
 *    a step. AB2 amplifies the undamped modes of central advection (|G| ~ 1 + (lambda dt)^4/4 on the
 *    imaginary axis): stable only while the viscosity damps the grid scale, i.e. at small cell Reynolds
 *    numbers |u| dx/nu or small advective CFL.
 *  - "rk3": three substeps, gamma 8/15, 5/12, 3/4, zeta 0, -17/60, -5/12, alpha 4/15, 1/15, 1/6, the
 *    low-storage Runge-Kutta of Spalart, Moser & Rogers (J. Comput. Phys. 96, 1991, Appendix A) with
 *    Crank-Nicolson viscosity, as Rai & Moin (J. Comput. Phys. 96, 1991) and Izard (2014, §2.2.1.2) use.
 *    Its stability region holds the imaginary axis up to |lambda dt| = sqrt(3): central advection is
 *    damped, not amplified, up to sum |u| dt/h ~ 1.7, whatever the viscosity. Three solves of each a step,
 *    each substep forced (Uhlmann, J. Comput. Phys. 209, 2005, eq. 13).
 *
 * Space: second-order central differences for the advection (non-conservative
 * form, advecting velocities averaged from the four neighbouring faces), the
 * MAC Laplacian and gradient of gf_grid; the Helmholtz and Poisson problems are
 * solved exactly by the transforms of gf_poisson (FFTW), two FFTs each.
 */
#ifndef GF_FLUID_NS2_H
#define GF_FLUID_NS2_H

#include "fluid/gf_fluid.h"

typedef enum gf_ns2_scheme { GF_NS2_AB2, GF_NS2_RK3 } gf_ns2_scheme;

/* One substep's weights (above): gamma on A^{k-1}, zeta on A^{k-2}, alpha the Crank-Nicolson weight; the
 * substep advances time by 2 alpha dt. */
typedef struct gf_ns2_substep {
    double gamma, zeta, alpha;
} gf_ns2_substep;

/* The scheme's substeps: *out points at a static table; returns their number (1 or 3). */
int gf_fluid_ns2_substeps(gf_ns2_scheme scheme, const gf_ns2_substep **out);
/* The names of the schemes and of the advection forms, in their enums' order, NULL-terminated (the
 * configuration's allowed values). */
extern const char *const gf_ns2_scheme_names[];
extern const char *const gf_ns2_advection_names[];

/* Whether substep k of the scheme reads A^{k-2} (else A_old is taken as A: the first substep of RK3, and
 * the Euler start of AB2 at the run's first step). */
int gf_fluid_ns2_uses_previous(gf_ns2_scheme scheme, int k, int first_step);
/* A^{k-1} becomes A^{k-2}: the two sets of face arrays swap. */
void gf_fluid_ns2_rotate(double *A[3], double *A_old[3]);

/* "ab2" or "rk3" -> scheme; 0 when the name is known, -1 otherwise. */
int gf_fluid_ns2_scheme_from_name(const char *name, gf_ns2_scheme *out);

/* The advection operator's discrete form: (u.grad)u (advective, Kim & Moin's) or div(u u) (divergence,
 * energy-conserving; gf_fluid_ns2.c). Equal for a divergence-free field up to the truncation error. */
typedef enum gf_ns2_advection { GF_NS2_ADVECTIVE, GF_NS2_DIVERGENCE } gf_ns2_advection;

/* "advective" or "divergence" -> form; 0 when the name is known, -1 otherwise. */
int gf_fluid_ns2_advection_from_name(const char *name, gf_ns2_advection *out);

/* A = -(u.grad)u in the given form at every free face (0 elsewhere), m/s^2. */
void gf_fluid_ns2_advection(const gf_fluid *f, gf_ns2_advection form, double *const A[3]);
/* r = gamma A + zeta A_old + 2 alpha (nu L u - grad p / rho) at free faces; A_old may be A (Euler start). */
void gf_fluid_ns2_rates(const gf_fluid *f, const gf_ns2_substep *s, const double *const A[3],
                        const double *const A_old[3], double *const r[3]);
/* r += b_a at every free face of each component a with b_a != 0: a uniform body acceleration (m/s^2), at the
 * faces inside the grains too (the resolved tier's mean pressure gradient over rho on a periodic gravity axis). */
void gf_fluid_ns2_add_acceleration(const gf_fluid *f, const double b_m_s2[3], double *const r[3]);
/* u~ = u + dt r. */
void gf_fluid_ns2_predict(const gf_fluid *f, const double *const r[3], double dt_s, double *const u_pred[3]);
/* Crank-Nicolson increment (weight s->alpha) with the forcing: f->work = u*; force may be NULL. */
gf_status gf_fluid_ns2_viscous(gf_ctx *ctx, gf_fluid *f, const gf_ns2_substep *s, const double *const r[3],
                               const double *const force[3], double dt_s);
/* Projection of f->work over dt_s (a substep's 2 alpha dt) with the constant-coefficient FFT Poisson solve:
 * f->u = u^k, f->p_Pa += phi; f->last_mass_residual = max |div u^k| dt_s. */
gf_status gf_fluid_ns2_project(gf_ctx *ctx, gf_fluid *f, double dt_s);

#endif
