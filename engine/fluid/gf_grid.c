/* MAC grid set-up and the shared stencils; see gf_grid.h. */
#include "fluid/gf_grid.h"

#include <math.h>
#include <string.h>

gf_status gf_grid_init(gf_ctx *ctx, gf_grid *g, const int n[3], const double lo_m[3], const double hi_m[3],
                       const gf_grid_bc bc[3][2])
{
    memset(g, 0, sizeof *g);
    g->n_cells = 1;
    for (int d = 0; d < 3; ++d) {
        if (n[d] < 1)
            return GF_FAIL(ctx, GF_ERR_ARG, "fluid grid: axis %d has %d cells (need >= 1)", d, n[d]);
        if (!(hi_m[d] > lo_m[d]))
            return GF_FAIL(ctx, GF_ERR_ARG, "fluid grid: axis %d has hi %g <= lo %g", d, hi_m[d], lo_m[d]);
        if ((bc[d][0] == GF_GRID_PERIODIC) != (bc[d][1] == GF_GRID_PERIODIC))
            return GF_FAIL(ctx, GF_ERR_ARG, "fluid grid: axis %d is periodic on one side only", d);
        g->n[d] = n[d];
        g->lo_m[d] = lo_m[d];
        g->h_m[d] = (hi_m[d] - lo_m[d]) / n[d];
        g->bc[d][0] = bc[d][0];
        g->bc[d][1] = bc[d][1];
        g->periodic[d] = bc[d][0] == GF_GRID_PERIODIC;
        g->n_cells *= (size_t)n[d];
    }
    for (int a = 0; a < 3; ++a) {
        g->n_faces[a] = 1;
        for (int d = 0; d < 3; ++d) {
            g->nf[a][d] = n[d] + (a == d);
            g->n_faces[a] *= (size_t)g->nf[a][d];
        }
    }
    return GF_OK;
}

size_t gf_grid_plane_faces(const gf_grid *g, int a)
{
    return g->n_faces[a] / (size_t)g->nf[a][a];
}

size_t gf_grid_plane_face(const gf_grid *g, int a, int m, size_t n, int idx[3])
{
    int d1 = a == 0 ? 1 : 0, d2 = a == 2 ? 1 : 2;  /* the other two axes, the lower one fastest */
    idx[a] = m;
    idx[d1] = (int)(n % (size_t)g->nf[a][d1]);
    idx[d2] = (int)(n / (size_t)g->nf[a][d1]);
    return gf_grid_face(g, a, idx[0], idx[1], idx[2]);
}

void gf_grid_sync_periodic(const gf_grid *g, int a, double *u)
{
    if (!g->periodic[a])
        return;
    for (size_t n = 0; n < gf_grid_plane_faces(g, a); ++n) {
        int idx[3];
        size_t first = gf_grid_plane_face(g, a, 0, n, idx);
        u[gf_grid_plane_face(g, a, g->n[a], n, idx)] = u[first];
    }
}

double gf_grid_face_neighbour(const gf_grid *g, const double *u, int a, int i, int j, int k, int d, int dir)
{
    int idx[3] = {i, j, k};
    double here = u[gf_grid_face(g, a, i, j, k)];
    int m = idx[d] + dir;
    if (d == a) {
        /* along the normal: faces 0 and n are walls (u = 0) or periodic images */
        int n = g->n[d];
        if (g->periodic[d]) {
            m %= n;
            if (m < 0)
                m += n;
        } else if (m <= 0 || m >= n) {
            return 0.0;
        }
        idx[d] = m;
        return u[gf_grid_face(g, a, idx[0], idx[1], idx[2])];
    }
    if (m >= 0 && m < g->n[d]) {
        idx[d] = m;
        return u[gf_grid_face(g, a, idx[0], idx[1], idx[2])];
    }
    if (g->periodic[d]) {
        idx[d] = gf_grid_wrap(g, d, m);
        return u[gf_grid_face(g, a, idx[0], idx[1], idx[2])];
    }
    /* tangential component across a wall: mirror ghost */
    gf_grid_bc bc = g->bc[d][m < 0 ? 0 : 1];
    return bc == GF_GRID_FREE_SLIP ? here : -here;
}

double gf_grid_face_laplacian(const gf_grid *g, const double *u, int a, int i, int j, int k)
{
    double here = u[gf_grid_face(g, a, i, j, k)], lap = 0.0;
    for (int d = 0; d < 3; ++d) {
        double lo = gf_grid_face_neighbour(g, u, a, i, j, k, d, -1);
        double hi = gf_grid_face_neighbour(g, u, a, i, j, k, d, +1);
        lap += (lo - 2.0 * here + hi) / (g->h_m[d] * g->h_m[d]);
    }
    return lap;
}

void gf_grid_cell_velocity(const gf_grid *g, int a, const double *u, double *uc)
{
    for (int k = 0; k < g->n[2]; ++k)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i) {
                int hi[3] = {i, j, k};
                hi[a] += 1;
                uc[gf_grid_cell(g, i, j, k)] =
                    0.5 * (u[gf_grid_face(g, a, i, j, k)] + u[gf_grid_face(g, a, hi[0], hi[1], hi[2])]);
            }
}

double gf_grid_face_from_cells(const gf_grid *g, const double *c, int a, int i, int j, int k)
{
    int idx[3] = {i, j, k};
    int m = idx[a], n = g->n[a];
    int lo = m - 1, hi = m;
    if (g->periodic[a]) {
        lo = gf_grid_wrap(g, a, lo);
        hi = gf_grid_wrap(g, a, hi);
    } else {
        if (lo < 0)
            lo = 0;
        if (hi > n - 1)
            hi = n - 1;
    }
    int il[3] = {i, j, k}, ih[3] = {i, j, k};
    il[a] = lo;
    ih[a] = hi;
    return 0.5 * (c[gf_grid_cell(g, il[0], il[1], il[2])] + c[gf_grid_cell(g, ih[0], ih[1], ih[2])]);
}

double gf_grid_cell_divergence(const gf_grid *g, const double *const u[3], const double *coef, int i, int j, int k)
{
    double s = 0.0;
    for (int a = 0; a < 3; ++a) {
        int hi[3] = {i, j, k};
        hi[a] += 1;
        double ul = u[a][gf_grid_face(g, a, i, j, k)];
        double uh = u[a][gf_grid_face(g, a, hi[0], hi[1], hi[2])];
        if (coef) {
            ul *= gf_grid_face_from_cells(g, coef, a, i, j, k);
            uh *= gf_grid_face_from_cells(g, coef, a, hi[0], hi[1], hi[2]);
        }
        s += (uh - ul) / g->h_m[a];
    }
    return s;
}

void gf_grid_divergence(const gf_grid *g, const double *const u[3], const double *coef, double *div)
{
    for (int k = 0; k < g->n[2]; ++k)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i)
                div[gf_grid_cell(g, i, j, k)] = gf_grid_cell_divergence(g, u, coef, i, j, k);
}
