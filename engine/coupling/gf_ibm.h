/*
 * gf_ibm: the immersed boundary of the resolved tier, grain by grain on the
 * MAC grid: the smoothed solid fraction, the grain-to-face maps, the direct
 * forcing and the force and torque it exerts on each grain.
 *
 * Solid fraction of grain i (centre x_i, radius R_i) at a point x (Yuki,
 * Takeuchi & Kajishima, J. Fluid Sci. Tech. 2, 2007, with the coefficients
 * 1.3 times theirs of Izard 2014 §2.2.2, eq. (2.26), and §3.1.2.1):
 *     alpha_i(x) = 1/2 - 1/2 tanh( (|x - x_i| - R_i) / (lambda phi Delta) ),
 *     lambda = |n_x| + |n_y| + |n_z|,  phi = 0.065 (1 - lambda^2) + 0.39,
 *     Delta = sqrt(2) dx,  n = (x - x_i)/|x - x_i|.
 * The thesis prints 0.039 for the last constant; 0.39 is the value that keeps
 * phi > 0 for every normal and gives the transition of "about three cells"
 * the same section describes (lambda phi lies between 0.39 and 0.46).
 * alpha_i is evaluated at every velocity face (per component), not at the
 * pressure points, so that the forcing of each component sees the body where
 * that component lives.
 *
 * Direct forcing (Uhlmann, J. Comput. Phys. 209, 2005; Izard 2014 §2.2.2,
 * eqs. (2.30)-(2.31)): with u~ the velocity predicted without the solids,
 *     f = alpha (U - u~) / dt,   alpha = min(1, sum_i alpha_i),
 *     U = sum_i alpha_i (v_i + w_i x r_i) / sum_i alpha_i.
 * Force and torque on grain i (Izard 2014 eqs. (2.32)-(2.33), after Uhlmann
 * 2005 and Bigot et al. 2014: the momentum of the fluid inside the grain is
 * taken as rigid and its rate of change folded into the factor, whence the
 * singularity at rho_p = rho):
 *     F_i = -(rho rho_p / (rho_p - rho)) sum_faces alpha_i (U_i - u~)/dt dV,
 *     T_i = -(rho rho_p / (rho_p - rho)) sum_faces r_i x alpha_i (U_i - u~)/dt dV,
 * the sums over each grain's own alpha_i. The fluid carries the pressure in
 * excess of the hydrostatic one, so F_i includes the buoyancy: at terminal
 * velocity F_i = -m_i g.
 *
 * Maps. gf_ibm_build lists, per grain and per velocity component, the faces
 * within GF_IBM_SHELL_WIDTHS profile widths outside R_i (alpha_i above ~1e-6),
 * with alpha_i and r_i (minimum image on periodic axes). Face indices are those of the grid the map is built on:
 * a later domain split builds the same map on each rank's grid (its cells
 * plus a halo of GF_IBM_REACH_CELLS) from the grains that overlap it, and
 * sums the per-grain force over ranks; nothing here assumes the whole domain.
 *
 * Retraction (beyond Izard's method). A diffuse boundary makes the grain
 * hydrodynamically larger than R by a fraction of a cell, an error of first
 * order in dx on the drag. Breugem (J. Comput. Phys. 231, 2012, §2-3) moves
 * the forcing points of his sphere inward by 0.3 dx for it. Here the same
 * idea shifts the tanh profile: alpha_i is evaluated at |x - x_i| - (R_i - c dx),
 * c = retraction_cells (fluid.ibm_retraction_dx); the force formula keeps
 * the grain's true mass and radius.
 *
 * Threads. The maps are built grain by grain, a grain's three components on
 * one thread, the grains spread over all threads (each grain's entries live
 * in its own buffers, so no order depends on the split). The forcing sums
 * every face array in grain order, one component per thread (at most three);
 * the per-face forcing and each grain's integrals (its own entries, in map
 * order) are split freely. So the force, the torque and the forcing field are
 * bitwise the same on 1 or N threads.
 *
 * Reuse. A grain's entries depend only on its centre, its profile radius and
 * the grid: a grain whose centre and radius are bitwise those of the last
 * build (glued grains, grains at rest) keeps its entries, the same bytes a
 * rebuild would give.
 */
#ifndef GF_IBM_H
#define GF_IBM_H

#include <stddef.h>
#include <stdint.h>

#include "core/gf_status.h"
#include "fluid/gf_grid.h"
#include "particles/gf_particles.h"

/* alpha below this is left out of the maps: |x - x_i| - R_i > 7 lambda phi Delta. */
#define GF_IBM_SHELL_WIDTHS 7.0
/* Reach of a grain's map beyond its radius, in cells: 7 x 0.46 x sqrt(2) = 4.6. */
#define GF_IBM_REACH_CELLS 4.6

/* Maps hold faces of grids up to this many cells per axis (the unwrapped indices are 16-bit). */
#define GF_IBM_MAX_CELLS 30000

/* 24 bytes: the forcing streams every entry twice a step. The face's offset from the grain's centre (minimum
 * image) is recomputed from the unwrapped indices q, the same expression that selected the face. */
typedef struct gf_ibm_entry {
    double alpha;
    uint32_t face;      /* index in the component's face array */
    int16_t q[3];       /* face indices before the periodic wrap */
} gf_ibm_entry;

/* One grain's entries, per velocity component, in face order (k, then j, then i). */
typedef struct gf_ibm_grain {
    double key[4];      /* centre and profile radius the entries were built for (NaN: not built) */
    gf_ibm_entry *e[3];
    size_t n_e[3], cap_e[3];
} gf_ibm_grain;

typedef struct gf_ibm_map {
    int n_threads;      /* OpenMP threads of the build and the forcing (0 or 1: one); the values do not depend on it */
    double retraction_cells; /* the profile is centred on R - retraction_cells dx (0: on R, Izard's profile) */
    size_t n_grains, cap_grains;
    gf_ibm_grain *grain;    /* grain i's entries (slots past n_grains keep their buffers for reuse) */
    gf_grid built_on;       /* the grid of the entries (a different grid rebuilds every grain) */
    size_t n_rebuilt;       /* grains the last gf_ibm_build recomputed (the others had not moved) */
} gf_ibm_map;

/* Solid fraction at signed distance s_m = |x - x_i| - R_i, normal n (unit), grid step dx_m. */
double gf_ibm_alpha(double s_m, const double n[3], double dx_m);

/* (Re)builds the maps of all local grains on grid g (uniform cells assumed: dx = h[0]). */
gf_status gf_ibm_build(gf_ctx *ctx, gf_ibm_map *m, const gf_grid *g, const gf_particles *p);
void gf_ibm_free(gf_ibm_map *m);

/* Direct forcing and its integrals. u_pred: the predicted face velocities u~.
 * force_out: face arrays, receives alpha (U - u~)/dt (m/s^2; zero away from grains).
 * F_N, T_Nm: n_local x 3, receive each grain's force and torque (factor above, rho_p from mass and radius).
 * alpha_sum: face scratch arrays (sum_i alpha_i), aU: face scratch (sum alpha_i U_i). */
void gf_ibm_force(const gf_ibm_map *m, const gf_grid *g, const gf_particles *p, const double *const u_pred[3],
                  double dt_s, double rho_f, double *const force_out[3], double *const alpha_sum[3],
                  double *const aU[3], double *F_N, double *T_Nm);

/* sum_i alpha_i per face (alpha_sum: face arrays), grains in order, one component per thread. */
void gf_ibm_fraction(const gf_ibm_map *m, const gf_grid *g, double *const alpha_sum[3]);
/* Each grain's fluid momentum int alpha_i u dV (P, kg/m3 omitted: m^4/s) and angular momentum about its centre
 * int alpha_i r x u dV (L), n_local x 3 each, over its own entries (the internal momentum of gf_ibm_markers.h). */
void gf_ibm_momentum(const gf_ibm_map *m, const gf_grid *g, const gf_particles *p, const double *const u[3],
                     double *P, double *L);
/* Face index m of component a along axis d mapped into the grid (wrapped on periodic axes), -1 when it is not
 * an unknown (outside the grid, or a wall's normal face). */
int gf_ibm_face_index(const gf_grid *g, int a, int d, int m);

/* alpha = min(1, sum_i alpha_i) at cell centres (mean of the six faces), for fields.nc; on n_threads threads. */
void gf_ibm_cell_fraction(const gf_grid *g, const double *const alpha_sum[3], int n_threads, double *alpha_cell);

#endif
