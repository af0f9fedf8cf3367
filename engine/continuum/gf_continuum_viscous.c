/*
 * The mu(I) viscosity field and the implicit viscous step of the continuum
 * solver; see gf_continuum.h.
 *
 * Strain: gdot_ab = du_a/dx_b + du_b/dx_a lives on the edges (corners in
 * 2-D) for a != b and at the cell centres for a = b (2 du_a/dx_a), as the
 * MAC grid places them; |gdot|^2 = gdot_ij gdot_ij / 2 (Djouwe Meffeja 2012,
 * §4.3.1) takes the missing components from the four neighbours' average.
 * The viscosity is that of u^n, frozen over the step (the thesis' lagging).
 *
 * Viscous step: (rho/dt) u - div(eta (grad u + grad u^T)) = (rho/dt) u*, the
 * stress divergence in conservation form on the MAC stencil (tau_aa at the
 * cells either side of a face, tau_ab on the edges), all components in one
 * sparse system solved by LU.
 */
#include <math.h>

#include "continuum/gf_continuum_internal.h"

static size_t edge_index(const gf_continuum *s, int k, const int idx[3])
{
    int m[3];
    for (int d = 0; d < 3; ++d) {
        int n = s->ne[k][d];
        m[d] = idx[d];
        if (d == k && s->p.side[d][0] == GF_SIDE_PERIODIC)
            m[d] = ((m[d] % n) + n) % n;
        if (m[d] < 0)
            m[d] = 0;
        if (m[d] >= n)
            m[d] = n - 1;
    }
    return (size_t)m[0] + (size_t)s->ne[k][0] * ((size_t)m[1] + (size_t)s->ne[k][1] * m[2]);
}

static double val(const gf_continuum *s, int a, int i, int j, int k)
{
    int idx[3] = {i, j, k};
    return gf_continuum_value(s, a, idx);
}

static void other_axes(int k, int *a, int *b)
{
    *a = k == 0 ? 1 : 0;
    *b = k == 2 ? 1 : 2;
}

/* gdot_ab on the edge normal to axis k at idx (face indices along a and b). */
static double edge_shear(const gf_continuum *s, int k, const int idx[3])
{
    int a, b;
    other_axes(k, &a, &b);
    int ea[3] = {0, 0, 0}, eb[3] = {0, 0, 0};
    ea[a] = 1;
    eb[b] = 1;
    double dua_db = (val(s, a, idx[0], idx[1], idx[2]) - val(s, a, idx[0] - eb[0], idx[1] - eb[1], idx[2] - eb[2])) /
                    s->g.h_m[b];
    double dub_da = (val(s, b, idx[0], idx[1], idx[2]) - val(s, b, idx[0] - ea[0], idx[1] - ea[1], idx[2] - ea[2])) /
                    s->g.h_m[a];
    return dua_db + dub_da;
}

static double pressure_at_cell(const gf_continuum *s, const int idx[3])
{
    return s->p.pressure_ref_Pa + s->p_cell[gf_continuum_cell_clamped(s, idx)];
}

static double viscosity(const gf_continuum *s, double gdot2, double pressure, double c)
{
    double eta = s->p.rheology == GF_RHEOLOGY_NEWTONIAN ? s->p.viscosity_Pa_s
                                                        : gf_mui_viscosity(&s->p.mui, sqrt(gdot2), pressure);
    return s->p.two_phase ? c * eta + (1.0 - c) * s->p.viscosity2_Pa_s : eta;
}

static int n_pairs(const gf_continuum *s)
{
    return s->n_comp == 3 ? 3 : 1;  /* 2-D: the edges normal to z only */
}

/* The normal axis of the kk-th edge family. */
static int edge_family(const gf_continuum *s, int kk)
{
    return s->n_comp == 3 ? kk : 2;
}

/* A value on the edge normal to axis k at idx. */
typedef double edge_value_fn(const gf_continuum *s, int k, const int idx[3]);

/* out[k][edge] = value(edge) for every edge of every family, x fastest. */
static void fill_edges(const gf_continuum *s, double *const out[3], edge_value_fn *value)
{
    for (int kk = 0; kk < n_pairs(s); ++kk) {
        int k = edge_family(s, kk);
        const int *n = s->ne[k];
        for (size_t q = 0; q < s->n_edges[k]; ++q) {
            int idx[3] = {(int)(q % n[0]), (int)(q / n[0] % n[1]), (int)(q / ((size_t)n[0] * n[1]))};
            out[k][q] = value(s, k, idx);
        }
    }
}

/* Cell: diagonal part and, per edge family, the square of the four-edge average. */
static void cell_strains(gf_continuum *s, double *offsq[3])
{
    const gf_grid *g = &s->g;
    for (int k2 = 0; k2 < g->n[2]; ++k2)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i) {
                size_t c = gf_grid_cell(g, i, j, k2);
                int idx[3] = {i, j, k2};
                double diag = 0.0;
                for (int a = 0; a < s->n_comp; ++a) {
                    int hi[3] = {i, j, k2};
                    hi[a] += 1;
                    double daa = (gf_continuum_value(s, a, hi) - gf_continuum_value(s, a, idx)) / g->h_m[a];
                    diag += 2.0 * daa * daa;
                }
                s->diag_cell[c] = diag;
                double total = diag;
                for (int kk = 0; kk < n_pairs(s); ++kk) {
                    int a, b, k = edge_family(s, kk);
                    other_axes(k, &a, &b);
                    double avg = 0.0;
                    for (int da = 0; da < 2; ++da)
                        for (int db = 0; db < 2; ++db) {
                            int e[3] = {i, j, k2};
                            e[a] += da;
                            e[b] += db;
                            avg += 0.25 * s->e_edge[k][edge_index(s, k, e)];
                        }
                    offsq[k][c] = avg * avg;
                    total += avg * avg;
                }
                s->strain_cell[c] = total;
            }
}

/* eta on the edge normal to k at idx: its own gdot_ab, the rest of |gdot|^2, the pressure and c from the
 * four cells around it. */
static double edge_viscosity(const gf_continuum *s, int k, const int idx[3])
{
    int a, b;
    other_axes(k, &a, &b);
    double rest = 0.0, pres = 0.0, frac = 0.0;
    for (int da = -1; da < 1; ++da)
        for (int db = -1; db < 1; ++db) {
            int cidx[3] = {idx[0], idx[1], idx[2]};
            cidx[a] += da;
            cidx[b] += db;
            size_t c = gf_continuum_cell_clamped(s, cidx);
            rest += 0.25 * (s->strain_cell[c] - s->offsq_cell[k][c]);
            pres += 0.25 * (s->p.pressure_ref_Pa + s->p_cell[c]);
            frac += 0.25 * s->c_cell[c];
        }
    double e = s->e_edge[k][edge_index(s, k, idx)];
    return viscosity(s, e * e + rest, pres, frac);
}

void gf_continuum_update_viscosity(gf_continuum *s)
{
    const gf_grid *g = &s->g;
    if (s->p.rheology == GF_RHEOLOGY_NEWTONIAN && !s->p.two_phase) {
        for (size_t c = 0; c < g->n_cells; ++c)
            s->eta_cell[c] = s->p.viscosity_Pa_s;
        for (int k = 0; k < 3; ++k)
            for (size_t q = 0; q < s->n_edges[k]; ++q)
                s->eta_edge[k][q] = s->p.viscosity_Pa_s;
        return;
    }
    fill_edges(s, s->e_edge, edge_shear);
    cell_strains(s, s->offsq_cell);
    for (int k2 = 0; k2 < g->n[2]; ++k2)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i) {
                int idx[3] = {i, j, k2};
                size_t c = gf_grid_cell(g, i, j, k2);
                s->eta_cell[c] = viscosity(s, s->strain_cell[c], pressure_at_cell(s, idx), s->c_cell[c]);
            }
    fill_edges(s, s->eta_edge, edge_viscosity);
}

/* Adds coef * u_comp(idx) to row: the matrix for an unknown face, the right-hand side otherwise. */
static void add_face(gf_continuum *s, int row, int comp, const int idx[3], double coef)
{
    gf_face_ref r = gf_continuum_resolve(s, comp, idx);
    int col = s->unknown[comp][r.face];
    if (col >= 0) {
        gf_cont_lu_add(s->lu, row, col, coef * r.scale);
        s->rhs[row] -= coef * r.constant;
    } else {
        s->rhs[row] -= coef * (r.scale * s->u[comp][r.face] + r.constant);
    }
}

static void shift(int out[3], const int idx[3], int axis, int by)
{
    out[0] = idx[0], out[1] = idx[1], out[2] = idx[2];
    out[axis] += by;
}

/* The thesis' approximation (4.8): eta (sum_b d2u_a/dx_b^2), eta at the face from its edges. */
static void assemble_row_laplacian(gf_continuum *s, int a, const int idx[3], int row, double rho_dt)
{
    const double *h = s->g.h_m;
    int t[3];
    double eta = 0.0;
    int n_edges = 0;
    for (int b = 0; b < s->n_comp; ++b) {
        if (b == a)
            continue;
        int k = 3 - a - b;
        for (int side = 0; side < 2; ++side) {
            shift(t, idx, b, side);
            eta += s->eta_edge[k][edge_index(s, k, t)];
            ++n_edges;
        }
    }
    eta /= n_edges;
    add_face(s, row, a, idx, rho_dt);
    for (int b = 0; b < s->n_comp; ++b) {
        double c = eta / (h[b] * h[b]);
        shift(t, idx, b, 1);
        add_face(s, row, a, t, -c);
        add_face(s, row, a, idx, 2.0 * c);
        shift(t, idx, b, -1);
        add_face(s, row, a, t, -c);
    }
}

static void assemble_row(gf_continuum *s, int a, const int idx[3], int row, double rho_dt)
{
    if (s->p.laplacian_form) {
        assemble_row_laplacian(s, a, idx, row, rho_dt);
        return;
    }
    const double *h = s->g.h_m;
    int t[3], t2[3];
    add_face(s, row, a, idx, rho_dt);
    /* normal stress 2 eta du_a/dx_a at the cells either side */
    shift(t, idx, a, 0);
    double eta_hi = s->eta_cell[gf_continuum_cell_clamped(s, t)];
    shift(t, idx, a, -1);
    double eta_lo = s->eta_cell[gf_continuum_cell_clamped(s, t)];
    double chi = 2.0 * eta_hi / (h[a] * h[a]), clo = 2.0 * eta_lo / (h[a] * h[a]);
    shift(t, idx, a, 1);
    add_face(s, row, a, t, -chi);
    add_face(s, row, a, idx, chi + clo);
    shift(t, idx, a, -1);
    add_face(s, row, a, t, -clo);
    /* shear stress eta (du_a/dx_b + du_b/dx_a) on the edges either side along b */
    for (int b = 0; b < s->n_comp; ++b) {
        if (b == a)
            continue;
        int k = 3 - a - b;
        for (int side = 0; side < 2; ++side) {
            int e[3];
            shift(e, idx, b, side);  /* edge: b-face index idx[b] + side */
            double eta = s->eta_edge[k][edge_index(s, k, e)];
            double sgn = side ? -1.0 : 1.0;  /* -(tau_hi - tau_lo)/h_b */
            double cbb = sgn * eta / (h[b] * h[b]), cab = sgn * eta / (h[a] * h[b]);
            /* du_a/dx_b on the edge: (u_a(idx + side e_b) - u_a(idx + (side - 1) e_b))/h_b */
            shift(t, idx, b, side);
            add_face(s, row, a, t, cbb);
            shift(t, idx, b, side - 1);
            add_face(s, row, a, t, -cbb);
            /* du_b/dx_a on the edge: (u_b(e) - u_b(e - e_a))/h_a */
            add_face(s, row, b, e, cab);
            shift(t2, e, a, -1);
            add_face(s, row, b, t2, -cab);
        }
    }
}

gf_status gf_continuum_viscous(gf_continuum *s, double dt)
{
    const gf_grid *g = &s->g;
    double rho_dt = s->p.density_kg_m3 / dt;
    int newtonian = s->p.rheology == GF_RHEOLOGY_NEWTONIAN && !s->p.two_phase; /* constant matrix */
    gf_cont_lu_clear(s->lu);
    for (int row = 0; row < s->n_unknowns; ++row) {
        const gf_unknown_face *f = &s->unknown_face[row];
        double rho_dt_q = s->rho_face[f->a] ? s->rho_face[f->a][f->q] / dt : rho_dt;
        s->rhs[row] = rho_dt_q * s->u[f->a][f->q];
        assemble_row(s, f->a, f->idx, row, rho_dt_q);
    }
    if (!newtonian || !s->factored) {
        GF_TRY(gf_cont_lu_factor(s->ctx, s->lu));
        s->factored = 1;
    }
    GF_TRY(gf_cont_lu_solve(s->ctx, s->lu, s->rhs, s->x));
    for (int row = 0; row < s->n_unknowns; ++row)
        s->u[s->unknown_face[row].a][s->unknown_face[row].q] = s->x[row];
    for (int a = 0; a < s->n_comp; ++a)
        gf_grid_sync_periodic(g, a, s->u[a]);
    return GF_OK;
}

double gf_continuum_pressure_gradient(const gf_continuum *s, const double *p, int a, const int idx[3])
{
    const gf_grid *g = &s->g;
    int hi[3] = {idx[0], idx[1], idx[2]}, lo[3] = {idx[0], idx[1], idx[2]};
    lo[a] -= 1;
    /* across an outflow face the pressure is zero on the face: ghost -p */
    double p_hi = p[gf_continuum_cell_clamped(s, hi)], p_lo = p[gf_continuum_cell_clamped(s, lo)];
    if (!g->periodic[a] && hi[a] >= g->n[a])
        p_hi = -p_hi;
    if (!g->periodic[a] && lo[a] < 0)
        p_lo = -p_lo;
    return (p_hi - p_lo) / g->h_m[a];
}

double gf_continuum_max_speed(const gf_continuum *s, int a)
{
    double vmax = 0.0;
    for (size_t q = 0; q < s->g.n_faces[a]; ++q)
        vmax = fmax(vmax, fabs(s->u[a][q]));
    return vmax;
}

double gf_continuum_cell_divergence(const gf_continuum *s, int i, int j, int k)
{
    const gf_grid *g = &s->g;
    double div = 0.0;
    for (int a = 0; a < s->n_comp; ++a) {
        int hi[3] = {i, j, k};
        hi[a] += 1;
        div += (s->u[a][gf_grid_face(g, a, hi[0], hi[1], hi[2])] - s->u[a][gf_grid_face(g, a, i, j, k)]) / g->h_m[a];
    }
    return div;
}

void gf_continuum_correct_velocity(gf_continuum *s, const double *phi, double dt)
{
    for (int r = 0; r < s->n_unknowns; ++r) {
        const gf_unknown_face *f = &s->unknown_face[r];
        s->u[f->a][f->q] -= dt / gf_continuum_rho(s, f->a, f->q) * gf_continuum_pressure_gradient(s, phi, f->a, f->idx);
    }
}

/*
 * Incremental projection (Goda 1979; van Kan 1986): the predictor carries
 * -grad p^n, the Poisson equation gives the increment phi, p^{n+1} = p^n + phi.
 * The thesis' scheme (Seibold 2008) projects with the whole pressure; its
 * steady state then keeps a tangential slip (dt/rho) dp/dx on the walls, an
 * O(dt) = O(h) error of the channel profile at a fixed Courant number.
 */
void gf_continuum_project(gf_continuum *s, double dt)
{
    const gf_grid *g = &s->g;
    double rho = s->p.density_kg_m3;
    for (int k = 0; k < g->n[2]; ++k)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i)
                s->div_cell[gf_grid_cell(g, i, j, k)] = rho / dt * gf_continuum_cell_divergence(s, i, j, k);
    gf_cont_poisson_solve(s->poisson, s->div_cell, s->div_cell);  /* div_cell: the increment phi */
    gf_continuum_correct_velocity(s, s->div_cell, dt);
    for (size_t c = 0; c < g->n_cells; ++c)
        s->p_cell[c] += s->div_cell[c];
    for (int a = 0; a < s->n_comp; ++a)
        gf_grid_sync_periodic(g, a, s->u[a]);
}
