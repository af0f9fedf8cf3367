/*
 * The container of a scene: its box under gravity and its plane walls, the
 * set-up every build() opens with. The scenes describe their walls as a
 * table (point, inward normal, friction) so that a wall's row number is its
 * id, the handle a scene later opens a gate or cuts an orifice with.
 */
#ifndef GF_SCENE_BOX_H
#define GF_SCENE_BOX_H

#include "gf_sim.h"

/* One plane wall: a point on it (m), its normal pointing into the box (any
 * length but zero) and its Coulomb friction coefficient. */
typedef struct gf_scene_plane {
    double point_m[3];
    double normal[3];
    double friction;
} gf_scene_plane;

/* Sets the box lo..hi (m), periodic along the axes flagged in periodic, with
 * gravity of magnitude g_m_s2 pointing to -y. Errors: gf_sim_set_box's and
 * gf_sim_set_gravity's. */
gf_status gf_scene_box_under_gravity(gf_sim *sim, const double lo[3], const double hi[3], const int periodic[3],
                                     double g_m_s2);

/* Adds the n walls of planes in order, as the sim's first walls, so that
 * planes[k] is wall k; GF_ERR_ARG when a wall was added before (the ids
 * would not be the rows). */
gf_status gf_scene_add_planes(gf_sim *sim, int n, const gf_scene_plane *planes);

#endif
