/*
 * Sleeping grains: a grain of a deposit at rest stops being integrated until
 * something moves it again (issue #6, "skip what a scene doesn't need").
 * Opt-in by contact.sleep_speed_nd = eps > 0 (0, the default, never sets a
 * flag, so every result stays bitwise what it was without this file).
 *
 * Every GF_SLEEP_EVERY steps (t_c/5 at the default dt = t_c/50), with the
 * speed scale v_s = eps sqrt(g D):
 *   - an awake, non-glued grain is quiet when |u| <= v_s and |w| R <= v_s;
 *     it falls asleep (u = w = 0, GF_P_SLEEPING set) once it has been quiet
 *     at every check over a window of 0.1 sqrt(D/g), it overlaps at least one
 *     grain or an active wall, and no awake moving grain is within the wake
 *     reach below. The window rules out free flight: a grain accelerating at
 *     g stays below v_s for at most 2 v_s / g = 2 eps sqrt(D/g) <= 0.1
 *     sqrt(D/g) for eps <= 0.05 (the knob's upper bound), so a grain at the
 *     top of a hop is never taken for one at rest;
 *   - a sleeping grain wakes (flag cleared, it starts from rest) when an awake
 *     grain moving faster than v_s lies within a gap of 0.05 D of it (it was
 *     hit, or is about to be), or when it touches nothing any more (its
 *     support left: a grain in mid-air cannot be in equilibrium). A woken
 *     grain wakes its sleeping neighbours in turn as soon as it moves faster
 *     than v_s, so a disturbance propagates through a sleeping deposit one
 *     layer per check.
 * A sleeping grain is a fixed obstacle with its true mass in contacts with
 * awake grains (the dashpot uses the real m*), and pairs of grains that both
 * do not move (sleeping/sleeping, sleeping/glued) are skipped by the force
 * loop with their tangential history kept: that skip, together with fewer
 * neighbour-list rebuilds, is where the time is saved.
 *
 * Approximations, stated: a grain hit by a fast one acts as an immovable
 * obstacle for up to GF_SLEEP_EVERY steps (t_c/5) before it wakes; a woken
 * grain's first half kick uses the force stored while it slept, which lacks
 * its sleeping neighbours (an error of order g dt/2 in its velocity, one
 * half step); the slow creep of a grain loaded by sleeping neighbours only
 * is not seen (both sides are frozen). The quiet counters are not in the
 * restart file: a restarted run with sleep on restarts them at 0.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gf_sim_internal.h"

#define GF_SLEEP_WINDOW_ND 0.1  /* quiet time before sleep, sqrt(D/g) */
#define GF_WAKE_GAP_OVER_D 0.05 /* reach of a moving grain that wakes a sleeper */

enum { TOUCH = 1u, WAKE = 2u };

static int moving(const gf_particles *p, size_t i, double v_s2)
{
    double u2 = p->vx_m_s[i] * p->vx_m_s[i] + p->vy_m_s[i] * p->vy_m_s[i] + p->vz_m_s[i] * p->vz_m_s[i];
    double w2 = (p->wx_rad_s[i] * p->wx_rad_s[i] + p->wy_rad_s[i] * p->wy_rad_s[i] + p->wz_rad_s[i] * p->wz_rad_s[i]) *
                p->radius_m[i] * p->radius_m[i];
    return u2 > v_s2 || w2 > v_s2;
}

/* The integrator factors of grain i, as gf_integrate_factors_fill sets them. */
static void set_factors(gf_sim *s, size_t i, int moves)
{
    const gf_particles *p = s->p;
    s->nb.inv_mass[i] = moves ? 1.0 / p->mass_kg[i] : 0.0;
    s->nb.inv_inertia[i] = moves && !s->rotation_locked ? 1.0 / p->inertia_kg_m2[i] : 0.0;
    s->nb.mobile[i] = moves ? 1.0 : 0.0;
}

void gf_sim_sleep_wake_all(gf_sim *s)
{
    gf_particles *p = s->p;
    for (size_t i = 0; i < p->n_local; ++i)
        if ((p->flags[i] & GF_P_SLEEPING) && !(p->flags[i] & GF_P_GLUED)) {
            p->flags[i] &= (uint8_t)~GF_P_SLEEPING;
            if (s->nb.inv_mass && i < s->nb.ref_cap)
                set_factors(s, i, 1);
            s->n_wake_events++;
        }
    if (s->sleep_quiet_steps)
        memset(s->sleep_quiet_steps, 0, s->sleep_cap * sizeof *s->sleep_quiet_steps);
}

gf_status gf_sim_sleep_update(gf_sim *s)
{
    gf_particles *p = s->p;
    const size_t n = p->n_local;
    if (n == 0 || s->nb.nl->n != n)
        return GF_OK; /* the list is rebuilt before the next force evaluation */
    if (s->sleep_cap != n) { /* grains added or removed: counters restart */
        long *q = realloc(s->sleep_quiet_steps, n * sizeof *q);
        if (!q)
            return GF_FAIL(s->ctx, GF_ERR_NOMEM, "sim: cannot allocate sleep counters for %zu grains", n);
        memset(q, 0, n * sizeof *q);
        s->sleep_quiet_steps = q;
        s->sleep_cap = n;
    }
    uint8_t *mark = calloc(n, 1);
    if (!mark)
        return GF_FAIL(s->ctx, GF_ERR_NOMEM, "sim: cannot allocate sleep marks for %zu grains", n);
    const double D = s->spec.grains.diameter_m, g = s->spec.gravity_m_s2;
    const double v_s = s->spec.contact.sleep_speed_nd * sqrt(g * D), v_s2 = v_s * v_s;
    const double wake_gap = GF_WAKE_GAP_OVER_D * D;
    const long window = (long)ceil(GF_SLEEP_WINDOW_ND * sqrt(D / g) / s->dt_s);
    const gf_nlist *nl = s->nb.nl;
    const uint8_t glued = GF_P_GLUED, asleep = GF_P_SLEEPING;
    for (size_t i = 0; i < n; ++i)
        for (size_t k = nl->row_start[i]; k < nl->row_start[i + 1]; ++k) {
            size_t j = (size_t)nl->j[k];
            if (j >= n)
                continue;
            const double *sh = nl->shift_m[nl->image[k]];
            double d[3] = {p->x_m[i] - p->x_m[j] + sh[0], p->y_m[i] - p->y_m[j] + sh[1],
                           p->z_m[i] - p->z_m[j] + sh[2]};
            double gap = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - p->radius_m[i] - p->radius_m[j];
            if (gap > wake_gap)
                continue;
            if (gap < 0.0)
                mark[i] |= TOUCH, mark[j] |= TOUCH;
            /* an awake, non-glued grain that moves wakes (or keeps awake) the other */
            int mi = !(p->flags[i] & (glued | asleep)) && moving(p, i, v_s2);
            int mj = !(p->flags[j] & (glued | asleep)) && moving(p, j, v_s2);
            if (mi)
                mark[j] |= WAKE;
            if (mj)
                mark[i] |= WAKE;
        }
    for (int w = 0; w < s->n_walls; ++w) {
        if (!s->walls[w].active)
            continue;
        const double *nw = s->walls[w].normal, *q = s->walls[w].point_m;
        for (size_t i = 0; i < n; ++i) {
            double dist = (p->x_m[i] - q[0]) * nw[0] + (p->y_m[i] - q[1]) * nw[1] + (p->z_m[i] - q[2]) * nw[2];
            if (dist < p->radius_m[i])
                mark[i] |= TOUCH;
        }
    }
    long *quiet = s->sleep_quiet_steps;
    for (size_t i = 0; i < n; ++i) {
        if (p->flags[i] & glued)
            continue;
        if (p->flags[i] & asleep) {
            if ((mark[i] & WAKE) || !(mark[i] & TOUCH)) {
                p->flags[i] &= (uint8_t)~asleep;
                set_factors(s, i, 1);
                quiet[i] = 0;
                s->n_wake_events++;
            }
            continue;
        }
        if (moving(p, i, v_s2) || (mark[i] & WAKE)) {
            quiet[i] = 0;
            continue;
        }
        quiet[i] += GF_SLEEP_EVERY;
        if (quiet[i] >= window && (mark[i] & TOUCH)) {
            p->flags[i] |= asleep;
            p->vx_m_s[i] = p->vy_m_s[i] = p->vz_m_s[i] = 0.0;
            p->wx_rad_s[i] = p->wy_rad_s[i] = p->wz_rad_s[i] = 0.0;
            set_factors(s, i, 0);
            s->n_sleep_events++;
        }
    }
    free(mark);
    return GF_OK;
}
