/*
 * Helpers shared by the engine tests: build a sim of a scene with a few
 * overrides, the contact-point relative velocity of a pair, and a snapshot of
 * the grain pairs that carry a tangential history.
 */
#ifndef DEM_TESTUTIL_H
#define DEM_TESTUTIL_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_sim.h"
#include "gf_test.h"
#include "gf_test_sim.h"
#include "scenes/gf_scene.h"

/* Relative surface velocity of grain a w.r.t. b at their contact point, along
 * the x-normal geometry of the binary_collision scene (a left of b): returns
 * the normal (x) and tangential (y) components of u_a - u_b + w_a x (R_a x^) - w_b x (-R_b x^). */
static inline void dem_contact_velocity(const gf_particles *p, size_t a, size_t b, double *un, double *ut)
{
    /* contact point is at +R_a x^ from a and -R_b x^ from b; (w x r)_y = w_z r_x */
    double ua_y = p->vy_m_s[a] + p->wz_rad_s[a] * p->radius_m[a];
    double ub_y = p->vy_m_s[b] - p->wz_rad_s[b] * p->radius_m[b];
    *un = p->vx_m_s[a] - p->vx_m_s[b];
    *ut = ua_y - ub_y;
}

/* A grain pair with a tangential history: global ids, branch vector (its image) and history. */
typedef struct dem_pair_h {
    int64_t a, b;
    double branch[3], h[3];
} dem_pair_h;

typedef struct dem_snapshot_into {
    const gf_particles *p;
    dem_pair_h *v;
    size_t m;
} dem_snapshot_into;

static inline int dem_add_pair(void *user, const gf_sim_contact *c)
{
    dem_snapshot_into *si = user;
    const double *h = c->history;
    if (c->wall >= 0 || (h[0] == 0.0 && h[1] == 0.0 && h[2] == 0.0))
        return 0;
    dem_pair_h *q = &si->v[si->m++];
    q->a = si->p->id[c->i], q->b = si->p->id[c->j];
    memcpy(q->branch, c->branch_m, sizeof q->branch);
    memcpy(q->h, h, sizeof q->h);
    return 0;
}

/* The grain pairs with a tangential history (gf_sim_foreach_contact), each image apart, into *out (free it). */
static inline size_t dem_snapshot(gf_ctx *ctx, gf_sim *s, dem_pair_h **out)
{
    dem_snapshot_into si = {gf_sim_particles(s), malloc((gf_sim_list_counters(s).pairs + 1) * sizeof(dem_pair_h)), 0};
    GF_CHECK_OK(gf_sim_foreach_contact(s, dem_add_pair, &si), ctx);
    *out = si.v;
    return si.m;
}

#endif
