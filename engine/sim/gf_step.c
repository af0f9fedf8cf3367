/*
 * The step loop: velocity Verlet (Verlet 1967; Swope et al. 1982) in
 * kick-drift-kick form, the DEM step of Djouwe Meffeja 2012 §2.4 and
 * Izard 2014 §2.1.3. The reference step (reference_step) is the method as
 * written, one operation after the other:
 *
 *   kick(dt/2)   v(t + dt/2) = v(t) + (F(t)/m + g) dt/2     (and the spins)
 *   drift(dt)    x(t + dt)   = x(t) + v(t + dt/2) dt        (and the predicted v*)
 *   neighbours   rebuild the Verlet list when a grain moved more than skin/2
 *   forces       contacts, lubrication, walls at x(t + dt) (gf_forces.c),
 *                then the fluid's held forces (coupling)
 *   kick(dt/2)   v(t + dt) = v(t + dt/2) + (F(t + dt)/m + g) dt/2
 *
 * The fused step (fused_step), the default, does the same operations on each
 * grain in the same order, so the results are bitwise the reference's
 * (tests/engine/test_reference_step.c): the closing half-kick is deferred and
 * done with the next step's opening kick and drift in one pass, and when the
 * next step follows at once that pass runs at the end of the force region,
 * each thread on its own chunk (gf_forces.c); the force pass scans the near
 * list (gf_near_list.c). gf_sim_tuning.reference_step picks the reference.
 *
 * Immersed (the scene needs GF_NEED_FLUID and spec.fluid.model names a
 * coupling tier): every M = floor(dt_fluid_max/dt) DEM steps, one fluid step
 * with the grains frozen (gf_coupling_fluid_step), and every DEM step adds
 * the held fluid force after the contacts (Izard 2014 §2.3.1 sub-cycling).
 * The preparation inside a scene's build() runs dry (the coupling is created
 * after build).
 *
 * Where the loop stands between two operations is one gf_step_state
 * (gf_sim_internal.h), whose transitions are all in this file except the
 * fused pass's own result (gf_forces.c).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "coupling/gf_coupling.h"
#include "gf_sim_internal.h"
#include "integrate/gf_integrate.h"

#define GF_FINITE_CHECK_EVERY 1000 /* steps between finite-value guards */

void gf_sim_choose_substeps(gf_sim *s)
{
    /* M = floor(dt_fluid_max / dt) from the current state: the stable fluid
     * step shrinks when grains speed up (CFL, drag relaxation) */
    double m = floor(gf_coupling_dt_max_s(s->coupling, s->p) / s->dt_s);
    s->n_substeps = m < 1.0 ? 1 : (m > 1e6 ? 1000000 : (int)m);
}

static gf_drift_d2 kick_range(gf_sim *s, size_t i0, size_t i1, void *h)
{
    gf_integrate_factors k = gf_sim_integrate_factors(s);
    gf_integrate_kick(s->p, i0, i1, *(const double *)h, s->gravity_m_s2, &k);
    return (gf_drift_d2){0.0, 0.0};
}

static void kick(gf_sim *s, double h)
{
    gf_sim_grain_passes(s, kick_range, &h);
}

/* Applies the previous step's closing half-kick if it was deferred: before
 * anything outside the step reads the velocities (fluid step, sleep update,
 * finite check, the caller of gf_sim_advance). */
static void flush_kick(gf_sim *s)
{
    if (s->stepper.phase != GF_STEP_KICK_OWED)
        return;
    kick(s, 0.5 * s->dt_s);
    s->stepper.phase = GF_STEP_AT_T;
}

/* The previous step's deferred closing half-kick, this step's opening
 * half-kick and its drift, in one parallel region: all three act on each
 * grain alone (with the force F(t) of the last evaluation), so with the same
 * split of grains no barrier is needed between them, and a step pays two
 * thread wake-ups instead of four (with OMP_WAIT_POLICY=passive each region
 * costs one). The two half-kicks stay two additions: bitwise the results of
 * the undeferred sequence. Returns the largest squared displacements since
 * the last neighbour build and the last near-list build. */
static gf_drift_d2 kick_drift_range(gf_sim *s, size_t i0, size_t i1, void *n_kicks)
{
    return gf_sim_kick_drift_range(s, i0, i1, *(const int *)n_kicks);
}

static gf_drift_d2 kick_drift(gf_sim *s)
{
    const int n_kicks = s->stepper.phase == GF_STEP_KICK_OWED ? 2 : 1;
    const gf_drift_d2 d2 = gf_sim_grain_passes(s, kick_drift_range, (void *)&n_kicks);
    s->stepper.phase = GF_STEP_MOVED;
    s->stepper.n_moved = s->p->n_local; /* gf_integrate_kick_drift zeroes what it read */
    return d2;
}

/* Run-time guards, so that a run stops with the limit named instead of
 * finishing with garbage (the checks at creation assume impacts of order
 * sqrt(gD); a fast impact can break them):
 *  - a grain moving more than half the Verlet skin in one step (the list was
 *    valid for skin/2 at the last step) may cross a partner unseen;
 *  - an overlap beyond GF_MAX_OVERLAP_OVER_D leaves the soft-sphere regime
 *    (the contact model assumes delta << D);
 *  - the Hertz secant stiffness grows as (delta/delta_ref)^(1/2), so the
 *    t_c/5 bound shrinks by its square root at large overlaps. */
#define GF_MAX_OVERLAP_OVER_D 0.1
static gf_status check_run_limits(gf_sim *s, double d2_since_build)
{
    const double D = s->spec.grains.diameter_m, t_c = gf_run_spec_t_contact_s(&s->spec);
    if (d2_since_build > s->nb.skin_m * s->nb.skin_m)
        return GF_FAIL(s->ctx, GF_ERR_NUMERIC,
                       "a grain moved %.3g D since the last neighbour-list build at t = %g s (limit: the skin, "
                       "%.3g D): speed x dt too large for contact detection (lower contact.dt_over_tc)",
                       sqrt(d2_since_build) / D, s->t_s, s->nb.skin_m / D);
    if (s->max_overlap_m > GF_MAX_OVERLAP_OVER_D * D)
        return GF_FAIL(s->ctx, GF_ERR_NUMERIC,
                       "overlap %.3g D at t = %g s exceeds the soft-sphere limit %.2g D: contacts too soft for the "
                       "impact speed (lower contact.t_contact_nd)",
                       s->max_overlap_m / D, s->t_s, GF_MAX_OVERLAP_OVER_D);
    if (s->law->frequency_factor) {
        const double f = fmax(1.0, s->law->frequency_factor(&s->cp, s->max_overlap_m));
        if (s->dt_s > t_c / (5.0 * f))
            return GF_FAIL(s->ctx, GF_ERR_NUMERIC,
                           "dt = %.3g s exceeds the stability limit t_c/5 of the current %s stiffness at t = %g s "
                           "(overlap %.3g D stiffens the contact %.2gx): lower contact.dt_over_tc",
                           s->dt_s, s->law->name, s->t_s, s->max_overlap_m / D, f * f);
    }
    return GF_OK;
}

/* A coupling call's failure, said with what failed, when, and the
 * coupling's own message. */
static gf_status coupling_failed(gf_sim *s, gf_status st, const char *doing)
{
    if (st == GF_OK)
        return GF_OK;
    char what[sizeof s->ctx->last_msg];
    snprintf(what, sizeof what, "%s", s->ctx->last_code == st ? s->ctx->last_msg : gf_status_str(st));
    return GF_FAIL(s->ctx, st, "coupling: %s failed at t = %g s: %s", doing, s->t_s, what);
}

/* The fluid's held forces (drag, buoyancy, ...) added to the contact forces
 * of the store in one serial pass. */
static gf_status add_fluid_forces(gf_sim *s)
{
    gf_timer_start(&s->timers, GF_T_COUPLING);
    gf_status st = gf_coupling_add_forces(s->coupling, s->p);
    gf_timer_stop(&s->timers, GF_T_COUPLING);
    return coupling_failed(s, st, "adding fluid forces");
}

/* x(t + dt) = x(t) + v(t + dt/2) dt and the predicted velocities, every
 * grain; returns the largest squared displacement since the last neighbour
 * build. The forces stay F(t) until the force pass clears them all. */
static gf_drift_d2 drift_range(gf_sim *s, size_t i0, size_t i1, void *unused)
{
    const double *const ref[3] = {s->nb.x_ref, s->nb.y_ref, s->nb.z_ref};
    double *const vp[3] = {s->nb.vx_pred, s->nb.vy_pred, s->nb.vz_pred};
    gf_integrate_factors k = gf_sim_integrate_factors(s);
    return (gf_drift_d2){gf_integrate_drift(s->p, i0, i1, s->dt_s, s->gravity_m_s2, ref, vp, &k), 0.0};
}

static double drift(gf_sim *s)
{
    const gf_drift_d2 d2 = gf_sim_grain_passes(s, drift_range, NULL);
    s->stepper.phase = GF_STEP_MOVED;
    s->stepper.n_moved = 0; /* nothing zeroed */
    return d2.build;
}

/* One step of the method as written: kick, drift, neighbour upkeep, forces,
 * kick; every force pass over the whole neighbour list. */
static gf_status reference_step(gf_sim *s)
{
    const double h = 0.5 * s->dt_s;
    gf_timer_start(&s->timers, GF_T_INTEGRATE);
    kick(s, h);
    const double moved = drift(s);
    gf_timer_stop(&s->timers, GF_T_INTEGRATE);
    if (moved > 0.25 * s->nb.skin_m * s->nb.skin_m || s->nb.need_build) { /* a grain moved more than skin/2 */
        gf_timer_start(&s->timers, GF_T_NEIGHBOUR);
        gf_status st = gf_sim_rebuild(s);
        gf_timer_stop(&s->timers, GF_T_NEIGHBOUR);
        GF_TRY(st);
    }
    gf_timer_start(&s->timers, GF_T_FORCE);
    gf_status st = gf_sim_compute_forces(s);
    gf_timer_stop(&s->timers, GF_T_FORCE);
    GF_TRY(st);
    GF_TRY(check_run_limits(s, moved));
    if (s->coupling)
        GF_TRY(add_fluid_forces(s));
    gf_timer_start(&s->timers, GF_T_INTEGRATE);
    kick(s, h);
    gf_timer_stop(&s->timers, GF_T_INTEGRATE);
    s->step++;
    s->t_s += s->dt_s;
    if (s->spec.contact.sleep_speed_nd > 0.0 && s->step % GF_SLEEP_EVERY == 0)
        GF_TRY(gf_sim_sleep_update(s));
    return GF_OK;
}

/* One step. next_follows: the caller runs the next step straight after this
 * one, with nothing reading or changing the grains in between; then, unless
 * a fluid step or a sleep update comes between the two steps (or the fluid's
 * held forces no longer follow the store's order), the held fluid forces,
 * this step's closing kick and the next step's kick-drift are done by each
 * thread on its chunk at the end of this step's force region
 * (gf_forces.c), once its contact forces are complete: one parallel
 * region per step instead of two, and no serial pass for the fluid forces.
 * The operations on each grain are the same, in the same order. */
static gf_status fused_step(gf_sim *s, int next_follows)
{
    gf_step_state *st_ = &s->stepper;
    gf_drift_d2 moved;
    if (st_->fused) { /* by the previous step's force region */
        moved = st_->fused_d2;
        st_->fused = 0;
    } else {
        gf_timer_start(&s->timers, GF_T_INTEGRATE);
        moved = kick_drift(s);
        gf_timer_stop(&s->timers, GF_T_INTEGRATE);
    }
    const double d2 = moved.build;
    if (d2 > 0.25 * s->nb.skin_m * s->nb.skin_m || s->nb.need_build) { /* a grain moved more than skin/2 */
        gf_timer_start(&s->timers, GF_T_NEIGHBOUR);
        gf_status st = gf_sim_rebuild(s);
        gf_timer_stop(&s->timers, GF_T_NEIGHBOUR);
        GF_TRY(st);
    }
    gf_near_list_check(&s->nb.near, moved.near, (s->skips & GF_SKIP_TANGENTIAL) != 0);
    const int sleep_after = s->spec.contact.sleep_speed_nd > 0.0 && (s->step + 1) % GF_SLEEP_EVERY == 0;
    const int fluid_after = s->coupling && (s->step + 1 >= s->next_fluid_step ||
                                            !gf_coupling_forces_in_order(s->coupling, s->p));
    st_->fuse = next_follows && !sleep_after && !fluid_after;
    gf_timer_start(&s->timers, GF_T_FORCE);
    gf_status st = gf_sim_compute_forces(s);
    gf_timer_stop(&s->timers, GF_T_FORCE);
    st_->fuse = 0;
    s->nb.near.use = 0;
    if (st_->fused) { /* the timers keep the drift apart (as the first thread saw it) */
        s->timers.elapsed_s[GF_T_FORCE] -= st_->fused_s;
        s->timers.elapsed_s[GF_T_INTEGRATE] += st_->fused_s;
    }
    GF_TRY(st);
    GF_TRY(check_run_limits(s, d2));
    if (s->coupling && !st_->fused) /* else added with the drift */
        GF_TRY(add_fluid_forces(s));
    if (!st_->fused) /* v(t+dt) = v(t+dt/2) + F(t+dt) dt/2 m: with the next step's kick_drift */
        st_->phase = GF_STEP_KICK_OWED;
    s->step++;
    s->t_s += s->dt_s;
    if (s->spec.contact.sleep_speed_nd > 0.0 && s->step % GF_SLEEP_EVERY == 0) {
        flush_kick(s);
        GF_TRY(gf_sim_sleep_update(s));
    }
    return GF_OK;
}

static gf_status fluid_step(gf_sim *s)
{
    gf_timer_start(&s->timers, GF_T_FLUID);
    gf_sim_choose_substeps(s);
    s->next_fluid_step = s->step + s->n_substeps;
    gf_status st = gf_coupling_fluid_step(s->coupling, s->p, s->dt_s * s->n_substeps);
    gf_timer_stop(&s->timers, GF_T_FLUID);
    return coupling_failed(s, st, "fluid step");
}

gf_status gf_sim_advance(gf_sim *s, long n_steps)
{
    gf_particles *p = s->p;
    if (s->in_build || s->stepper.phase != GF_STEP_AT_T || s->nb.nl->n != p->n_local) {
        /* grains were added or moved by a builder: fresh list and F(t) */
        GF_TRY(gf_sim_rebuild(s));
        GF_TRY(gf_sim_compute_forces(s));
    }
    gf_timer_start(&s->timers, GF_T_TOTAL);
    gf_status st = GF_OK;
    for (long k = 0; k < n_steps && st == GF_OK; ++k) {
        const int interrupted = s->opt.interrupt && *s->opt.interrupt;
        if (interrupted && !s->stepper.fused) { /* else the step under way is finished first */
            st = s->in_build ? GF_FAIL(s->ctx, GF_ERR_INTERRUPTED,
                                       "run interrupted while scene %s prepared its grains (nothing to checkpoint yet)",
                                       s->spec.scene)
                             : GF_FAIL(s->ctx, GF_ERR_INTERRUPTED, "run interrupted at t = %g s (step %ld)", s->t_s,
                                       s->step);
            break;
        }
        if (s->coupling && s->step >= s->next_fluid_step) {
            gf_timer_start(&s->timers, GF_T_INTEGRATE);
            flush_kick(s);
            gf_timer_stop(&s->timers, GF_T_INTEGRATE);
            st = fluid_step(s);
        }
        if (st == GF_OK) {
            const int next_follows = k + 1 < n_steps && !interrupted && (s->step + 1) % GF_FINITE_CHECK_EVERY != 0;
            st = s->opt.tuning.reference_step ? reference_step(s) : fused_step(s, next_follows);
        }
        if (st == GF_OK && s->step % GF_FINITE_CHECK_EVERY == 0)
            flush_kick(s);
        if (st == GF_OK && s->step % GF_FINITE_CHECK_EVERY == 0 && gf_particles_check_finite(s->ctx, p) != GF_OK) {
            char what[sizeof s->ctx->last_msg];
            snprintf(what, sizeof what, "%s", s->ctx->last_msg);
            st = GF_FAIL(s->ctx, GF_ERR_NUMERIC,
                         "%s at t = %g s (step %ld): the run is unstable (dt too large for the contact stiffness or "
                         "the fluid coupling?)",
                         what, s->t_s, s->step);
        }
    }
    gf_timer_start(&s->timers, GF_T_INTEGRATE);
    flush_kick(s); /* the caller sees v(t) */
    gf_timer_stop(&s->timers, GF_T_INTEGRATE);
    gf_timer_stop(&s->timers, GF_T_TOTAL);
    return st;
}
