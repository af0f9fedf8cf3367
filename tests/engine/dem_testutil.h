/*
 * Helpers shared by the engine tests: build a sim of a scene with a few
 * overrides, and the contact-point relative velocity of a pair.
 */
#ifndef DEM_TESTUTIL_H
#define DEM_TESTUTIL_H

#include <math.h>
#include <stdio.h>
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

#endif
