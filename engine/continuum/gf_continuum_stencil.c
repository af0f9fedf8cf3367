/*
 * Boundary values and the explicit predictor (advection, body force, old
 * pressure gradient) of the continuum solver
 * (Djouwe Meffeja 2012, §4.4.1-4.4.2; Seibold 2008); see gf_continuum.h.
 *
 * Every stencil reads a face through gf_continuum_resolve, which folds an
 * index one cell outside the domain back inside with the side's ghost rule:
 *   tangential to a wall or an inflow: u_ghost = 2 u_wall - u (the value is
 *   prescribed on the boundary, half a cell away); across an outflow:
 *   u_ghost = u (zero normal gradient); periodic: wrap.
 */
#include <math.h>

#include "continuum/gf_continuum_internal.h"

static int wrap(int m, int n)
{
    m %= n;
    return m < 0 ? m + n : m;
}

gf_face_ref gf_continuum_resolve(const gf_continuum *s, int a, const int idx_in[3])
{
    const gf_grid *g = &s->g;
    int idx[3] = {idx_in[0], idx_in[1], idx_in[2]};
    double scale = 1.0, constant = 0.0;
    for (int d = 0; d < 3; ++d) {
        int n = g->n[d];
        if (s->p.side[d][0] == GF_SIDE_PERIODIC) {
            idx[d] = wrap(idx[d], n);
            continue;
        }
        if (d == a) { /* beyond an outflow face: zero gradient */
            idx[d] = idx[d] < 0 ? 0 : (idx[d] > n ? n : idx[d]);
            continue;
        }
        if (idx[d] >= 0 && idx[d] < n)
            continue;
        int side = idx[d] < 0 ? 0 : 1;
        idx[d] = side ? n - 1 : 0;
        if (s->p.side[d][side] != GF_SIDE_OUTFLOW) {
            constant += scale * 2.0 * s->p.wall_velocity_m_s[d][side][a];
            scale = -scale;
        }
    }
    return (gf_face_ref){gf_grid_face(g, a, idx[0], idx[1], idx[2]), scale, constant};
}

double gf_continuum_value(const gf_continuum *s, int a, const int idx[3])
{
    gf_face_ref r = gf_continuum_resolve(s, a, idx);
    return r.scale * s->u[a][r.face] + r.constant;
}

size_t gf_continuum_cell_clamped(const gf_continuum *s, const int idx_in[3])
{
    int idx[3];
    for (int d = 0; d < 3; ++d) {
        int n = s->g.n[d];
        idx[d] = s->p.side[d][0] == GF_SIDE_PERIODIC ? wrap(idx_in[d], n)
                                                     : (idx_in[d] < 0 ? 0 : (idx_in[d] >= n ? n - 1 : idx_in[d]));
    }
    return gf_grid_cell(&s->g, idx[0], idx[1], idx[2]);
}

static double at(const gf_continuum *s, int a, int i, int j, int k)
{
    int idx[3] = {i, j, k};
    return gf_continuum_value(s, a, idx);
}

/* Seibold's blended flux: average product minus gamma |transport| times half-difference (donor cell at gamma = 1). */
static double flux(double transported_avg, double transported_halfdiff, double transport_avg, double gamma)
{
    return transported_avg * transport_avg - gamma * fabs(transport_avg) * transported_halfdiff;
}

/* (div (u u_a)) at face idx of component a, conservative form. */
static double convection(const gf_continuum *s, int a, const int idx[3], double gamma)
{
    double sum = 0.0;
    for (int b = 0; b < s->n_comp; ++b) {
        int e[3] = {0, 0, 0};
        e[b] = 1;
        int i = idx[0], j = idx[1], k = idx[2];
        double up = at(s, a, i + e[0], j + e[1], k + e[2]), mid = at(s, a, i, j, k),
               dn = at(s, a, i - e[0], j - e[1], k - e[2]);
        double f_hi, f_lo;
        if (b == a) {
            f_hi = flux(0.5 * (up + mid), 0.5 * (up - mid), 0.5 * (up + mid), gamma);
            f_lo = flux(0.5 * (mid + dn), 0.5 * (mid - dn), 0.5 * (mid + dn), gamma);
        } else {
            /* u_b on the edge: the two b-faces either side of face idx along a */
            int ea[3] = {0, 0, 0};
            ea[a] = 1;
            double vb_hi = 0.5 * (at(s, b, i + e[0], j + e[1], k + e[2]) +
                                  at(s, b, i + e[0] - ea[0], j + e[1] - ea[1], k + e[2] - ea[2]));
            double vb_lo = 0.5 * (at(s, b, i, j, k) + at(s, b, i - ea[0], j - ea[1], k - ea[2]));
            f_hi = flux(0.5 * (up + mid), 0.5 * (up - mid), vb_hi, gamma);
            f_lo = flux(0.5 * (mid + dn), 0.5 * (mid - dn), vb_lo, gamma);
        }
        sum += (f_hi - f_lo) / s->g.h_m[b];
    }
    return sum;
}

void gf_continuum_advect(gf_continuum *s, double dt)
{
    const gf_grid *g = &s->g;
    double cfl = 0.0;
    for (int b = 0; b < s->n_comp; ++b)
        cfl = fmax(cfl, gf_continuum_max_speed(s, b) / g->h_m[b]);
    double gamma = fmin(1.2 * dt * cfl, 1.0);
    for (int a = 0; a < s->n_comp; ++a)
        for (size_t q = 0; q < g->n_faces[a]; ++q)
            s->u_old[a][q] = s->u[a][q];
    /* new values into u_old's twin: compute from the frozen copy by swapping pointers */
    for (int a = 0; a < s->n_comp; ++a) {
        double *tmp = s->u[a];
        s->u[a] = s->u_old[a];
        s->u_old[a] = tmp;
    }
    /* s->u now holds u^n (read by the stencils), s->u_old receives u* */
    for (int r = 0; r < s->n_unknowns; ++r) {
        const gf_unknown_face *f = &s->unknown_face[r];
        int a = f->a;
        s->u_old[a][f->q] = s->u[a][f->q] + dt * (s->p.body_accel_m_s2[a] - convection(s, a, f->idx, gamma) -
                                                   gf_continuum_pressure_gradient(s, s->p_cell, a, f->idx) /
                                                       gf_continuum_rho(s, a, f->q));
    }
    for (int a = 0; a < s->n_comp; ++a) {
        double *tmp = s->u[a];
        s->u[a] = s->u_old[a];
        s->u_old[a] = tmp;
    }
    /* s->u: u* on unknown faces, boundary values elsewhere; s->u_old: u^n */
}
