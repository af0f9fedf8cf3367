/*
 * Tangential sub-model shared by the normal laws: a vector spring on the
 * accumulated tangential displacement delta_t with a Coulomb cap
 * (Cundall & Strack, Geotechnique 1979; Silbert et al., PRE 64, 2001;
 * Izard 2014 (2.5), (3.14)-(3.15) with rotation included, which the printed (3.15) omits).
 *
 * Per step, with n the current unit normal and u_t the tangential part of
 * the relative surface velocity:
 *   1. rotate delta_t back onto the tangent plane, keeping its length (the
 *      contact frame turns with the pair; dropping the normal part without
 *      restoring the length would leak stored elastic energy);
 *   2. delta_t += u_t dt;
 *   3. F_t = -k_t delta_t; if |F_t| > mu |F_n|, F_t <- mu |F_n| F_t/|F_t| and
 *      delta_t = -F_t/k_t (the spring stays at the slip threshold).
 * u_t is the half-step (kick-drift-kick) velocity, so delta_t is the exact
 * time integral of the surface slip velocity on the mid-point rule.
 */
#include "contact/gf_contact.h"
#include "contact/gf_contact_kernels.h"

void gf_contact_tangential(const gf_contact_geom *g, double k_t, double f_n, double dt_s, double *h,
                           double f_t[3])
{
    gf_contact_tangential_inline(g, k_t, f_n, dt_s, h, f_t);
}
