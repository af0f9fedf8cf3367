/*
 * Time integration: velocity Verlet in kick-drift-kick form (Verlet 1967;
 * Swope et al., J. Chem. Phys. 1982), for translation and rotation:
 *     v(t+dt/2) = v(t) + (F(t)/m + g) dt/2,    w(t+dt/2) = w(t) + T(t)/I dt/2
 *     x(t+dt)   = x(t) + v(t+dt/2) dt
 *     F(t+dt)   = contacts(x(t+dt), v(t+dt/2))          <- velocity-dependent forces
 *     v(t+dt)   = v(t+dt/2) + (F(t+dt)/m + g) dt/2
 * Symplectic and second order for conservative forces (an elastic, frictionless
 * gas conserves energy to O(dt^2) without drift). Velocity-dependent forces
 * (Djouwe Meffeja 2012 §2.4.5 does not say which velocity is used):
 *   - the normal dashpot and the lubrication force use the PREDICTED velocity
 *     v*(t+dt) = v(t+dt/2) + (F(t)/m + g) dt/2, an O(dt^2) estimate of
 *     v(t+dt) computed in the drift from the forces of the previous step.
 *     With the half-step velocity instead (the LAMMPS convention) the
 *     dissipation lags by dt/2, a first-order error: +1.1 % on the clipped
 *     restitution for eps = 0.5 at t_c/dt = 50, against the 1 % target;
 *   - the tangential spring increment delta_t += u_t dt uses the half-step
 *     surface velocity: the mid-point rule for the integral of the slip.
 * Spheres: the angular velocity needs no orientation (torque-free rotation of
 * a sphere is trivial). Glued grains (GF_P_GLUED) and sleeping grains
 * (GF_P_SLEEPING) are skipped: they never move.
 */
#ifndef GF_INTEGRATE_H
#define GF_INTEGRATE_H

#include <stddef.h>

#include "particles/gf_particles.h"

/* Per-grain factors that make the loops branch-free: inverse mass and
 * inverse inertia (0 for glued or sleeping grains) and mobility (1 or 0). */
typedef struct gf_integrate_factors {
    const double *inv_mass, *inv_inertia, *mobile;
} gf_integrate_factors;

/* Fills the factors of grains [0, n) from the flags, masses and inertias. */
void gf_integrate_factors_fill(const gf_particles *p, size_t n, double *inv_mass, double *inv_inertia, double *mobile);

/* v += (F/m + g) dt_half, w += T/I dt_half, for mobile grains in [i0, i1);
 * k->inv_inertia NULL: translation only (a run without torques). */
void gf_integrate_kick(gf_particles *p, size_t i0, size_t i1, double dt_half_s, const double g_m_s2[3],
                       const gf_integrate_factors *k);
/* The step's opening sequence in one pass over the grains [i0, i1):
 * n_kicks (1 or 2) half-kicks of dt/2 as gf_integrate_kick does them (the
 * previous step's deferred closing kick, then this step's opening one),
 * then x += v dt for mobile grains and the predicted velocities
 * v* = v + (F/m + g) dt/2 (F still the previous step's force) into vp[3].
 * Per grain, the operations and their order are those of the separate
 * passes, so the results are bitwise theirs; the store is read once instead
 * of two or three times. The forces and torques of [i0, i1) are zeroed
 * once read: the next force evaluation accumulates into them, and zeroing
 * them here, by the thread that integrates them, spares it a pass over the
 * store (on two threads, one that moved every chunk's force lines to the
 * core clearing them). Returns the largest squared displacements from the
 * positions of the last neighbour build (ref->build) and of the last
 * near-list build (ref->near, engine/sim/gf_near_list.c), m^2. */
typedef struct gf_drift_refs {
    const double *build[3]; /* positions at the last neighbour-list build */
    const double *near[3];  /* positions at the last near-list build (may be build) */
} gf_drift_refs;
typedef struct gf_drift_d2 {
    double build, near;     /* largest squared displacement since each build, m^2 */
} gf_drift_d2;
gf_drift_d2 gf_integrate_kick_drift(gf_particles *p, size_t i0, size_t i1, int n_kicks, double dt_s,
                                    const double g_m_s2[3], const gf_drift_refs *ref, double *const vp[3],
                                    const gf_integrate_factors *k);

/* The drift alone, for the reference step (engine/sim/gf_step.c): x += v dt
 * for mobile grains in [i0, i1) and the predicted velocities
 * v* = v + (F/m + g) dt/2 into vp[3], with the expressions of
 * gf_integrate_kick_drift (so a kick then a drift give its bits). The forces
 * are left as they are. Returns the largest squared displacement from
 * ref[3], the positions of the last neighbour build, m^2. */
double gf_integrate_drift(gf_particles *p, size_t i0, size_t i1, double dt_s, const double g_m_s2[3],
                          const double *const ref[3], double *const vp[3], const gf_integrate_factors *k);

#endif
