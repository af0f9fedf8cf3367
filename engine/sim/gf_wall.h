/*
 * A plane wall of the sim (gf_sim_add_wall), with an optional rectangular
 * orifice, and the distance from a grain centre to its solid part: shared by
 * the wall contacts (gf_wall_forces.c), the state check (gf_sim.c) and the
 * neighbour upkeep, which reads the walls without the sim (gf_neighbours.h).
 */
#ifndef GF_WALL_H
#define GF_WALL_H

#include <math.h>

#define GF_SIM_MAX_WALLS 16

typedef struct gf_wall {
    double point_m[3], normal[3];
    double friction;
    int active;
    double force_N[3];         /* on the wall, last force evaluation */
    /* A rectangular hole (a silo's orifice, gf_sim_set_wall_hole): the wall is
     * the plane less the open rectangle hole_lo..hole_hi on the two axes other
     * than hole_axis (the normal's). */
    int has_hole, hole_axis;
    double hole_lo[3], hole_hi[3];
} gf_wall;

/* Distance from a grain centre c to the solid part of wall w, and the unit
 * contact normal from the wall towards c in n. A plain wall: the signed
 * distance to its plane, n its normal. A wall with a hole: over the hole (the
 * centre's projection inside the rectangle) the nearest solid point is on the
 * rim, and the contact is with that edge (distance |c - q|, n along c - q), so
 * a grain leaving through the orifice rolls off its edge; a centre behind the
 * plane and outside the hole has gone through and is out of reach (INFINITY). */
static inline double gf_wall_distance(const gf_wall *w, const double c[3], double n[3])
{
    const double *nw = w->normal, *pw = w->point_m;
    double dist = (c[0] - pw[0]) * nw[0] + (c[1] - pw[1]) * nw[1] + (c[2] - pw[2]) * nw[2];
    n[0] = nw[0], n[1] = nw[1], n[2] = nw[2];
    if (!w->has_hole)
        return dist;
    int in = 1;
    double edge = INFINITY;
    int edge_axis = -1;
    double edge_at = 0.0;
    for (int a = 0; a < 3; ++a) {
        if (a == w->hole_axis)
            continue;
        if (c[a] <= w->hole_lo[a] || c[a] >= w->hole_hi[a])
            in = 0;
        double to_lo = c[a] - w->hole_lo[a], to_hi = w->hole_hi[a] - c[a];
        if (to_lo < edge)
            edge = to_lo, edge_axis = a, edge_at = w->hole_lo[a];
        if (to_hi < edge)
            edge = to_hi, edge_axis = a, edge_at = w->hole_hi[a];
    }
    if (!in)
        return dist > 0.0 ? dist : INFINITY;
    double q[3] = {c[0], c[1], c[2]}; /* the nearest rim point: on the plane, on the nearest edge */
    q[w->hole_axis] = pw[w->hole_axis];
    q[edge_axis] = edge_at;
    double r[3] = {c[0] - q[0], c[1] - q[1], c[2] - q[2]}, len = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    if (!(len > 0.0))
        return 0.0;
    n[0] = r[0] / len, n[1] = r[1] / len, n[2] = r[2] / len;
    return len;
}

#endif
