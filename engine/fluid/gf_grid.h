/*
 * gf_grid: the staggered (MAC) Cartesian grid of the fluid solvers
 * (Harlow & Welch, Phys. Fluids 8, 1965). Scalars (pressure, fluid fraction)
 * live at cell centres; the velocity component a lives on the faces normal to
 * axis a. One grid code serves the unresolved tier (cells of a few D) and the
 * resolved tier (D/10).
 *
 * Storage. Cell (i,j,k) is i + n0 (j + n1 k) (x fastest). Component a is an
 * array of (n0 + [a==0]) (n1 + [a==1]) (n2 + [a==2]) faces: face m along a sits
 * at lo + m h. On a wall axis faces 0 and n are the walls (normal velocity 0,
 * never updated); on a periodic axis face n duplicates face 0 (kept equal by
 * gf_grid_sync_periodic), so every stencil can read face m+1 without a wrap.
 *
 * Boundary conditions of the tangential components use a ghost value across
 * the wall: u_ghost = -u (no-slip, the wall sits half a cell away) or
 * u_ghost = +u (free-slip, zero shear). All operators below are the standard
 * second-order MAC stencils; with these ghosts the Laplacian is symmetric,
 * so CG applies to the implicit viscous step.
 */
#ifndef GF_GRID_H
#define GF_GRID_H

#include <stddef.h>

#include "core/gf_status.h"

typedef enum gf_grid_bc { GF_GRID_PERIODIC = 0, GF_GRID_NO_SLIP, GF_GRID_FREE_SLIP } gf_grid_bc;

typedef struct gf_grid {
    int n[3];                 /* cells per axis */
    double h_m[3], lo_m[3];   /* cell edge and low corner */
    gf_grid_bc bc[3][2];      /* [axis][side]; periodic on both sides or neither */
    int periodic[3];
    size_t n_cells;
    int nf[3][3];             /* nf[a][d]: size of the face array of component a along axis d */
    size_t n_faces[3];
} gf_grid;

/* Fills *g for n cells over [lo, hi]. Errors: n < 1, hi <= lo, mixed periodic sides. */
gf_status gf_grid_init(gf_ctx *ctx, gf_grid *g, const int n[3], const double lo_m[3], const double hi_m[3],
                       const gf_grid_bc bc[3][2]);

static inline size_t gf_grid_cell(const gf_grid *g, int i, int j, int k)
{
    return (size_t)i + (size_t)g->n[0] * ((size_t)j + (size_t)g->n[1] * (size_t)k);
}
static inline size_t gf_grid_face(const gf_grid *g, int a, int i, int j, int k)
{
    return (size_t)i + (size_t)g->nf[a][0] * ((size_t)j + (size_t)g->nf[a][1] * (size_t)k);
}
/* 1 when face index m of component a is an unknown (not a wall, not the periodic duplicate). */
static inline int gf_grid_face_free(const gf_grid *g, int a, int m)
{
    return g->periodic[a] ? (m < g->n[a]) : (m >= 1 && m <= g->n[a] - 1);
}
/* Visits every free face of component a (gf_grid_face_free), x fastest: declares its face index fi and
 * (i, j, k) for the statement that follows. Plain nested loops: an OpenMP `parallel for` placed before it
 * shares the outer one. */
#define GF_GRID_FOR_FREE_FACES(g, a, fi, i, j, k)                                            \
    for (int k = 0; k < (g)->nf[a][2]; ++k)                                                  \
        for (int j = 0; j < (g)->nf[a][1]; ++j)                                              \
            for (int i = 0; i < (g)->nf[a][0]; ++i)                                          \
                for (size_t fi = gf_grid_face(g, a, i, j, k), once_ = 1; once_; once_ = 0) \
                    if (gf_grid_face_free(g, a, (a) == 0 ? i : (a) == 1 ? j : k))
/* Wraps a cell index on a periodic axis; on a wall axis returns -1 outside [0, n). */
static inline int gf_grid_wrap(const gf_grid *g, int d, int m)
{
    int n = g->n[d];
    if (m >= 0 && m < n)
        return m;
    if (!g->periodic[d])
        return -1;
    m %= n;
    return m < 0 ? m + n : m;
}

/* The faces of component a on one plane m along a (the two other axes' face counts multiplied), and the
 * n-th of them, n < gf_grid_plane_faces, x fastest: returns its face index and fills its (i,j,k). */
size_t gf_grid_plane_faces(const gf_grid *g, int a);
size_t gf_grid_plane_face(const gf_grid *g, int a, int m, size_t n, int idx[3]);
/* Copies face 0 onto face n of every periodic axis of component a. */
void gf_grid_sync_periodic(const gf_grid *g, int a, double *u);
/* Value of component a at the neighbour of face (i,j,k) one step along d (dir = +-1), with the BCs. */
double gf_grid_face_neighbour(const gf_grid *g, const double *u, int a, int i, int j, int k, int d, int dir);
/* Discrete Laplacian of component a at face (i,j,k) (1/s * m/s units of u / m^2). */
double gf_grid_face_laplacian(const gf_grid *g, const double *u, int a, int i, int j, int k);
/* Cell-centred component a (average of the two faces). */
void gf_grid_cell_velocity(const gf_grid *g, int a, const double *u, double *uc);
/* Face value of a cell field (arithmetic mean of the two cells; the wall cell itself on a wall face). */
double gf_grid_face_from_cells(const gf_grid *g, const double *c, int a, int i, int j, int k);
/* div(coef u) at every cell: coef is a cell field averaged to faces, NULL for 1. */
void gf_grid_divergence(const gf_grid *g, const double *const u[3], const double *coef, double *div);
/* The same at one cell (x, y, z faces summed in that order). */
double gf_grid_cell_divergence(const gf_grid *g, const double *const u[3], const double *coef, int i, int j, int k);

#endif
