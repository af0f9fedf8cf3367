/*
 * Two phases in the continuum solver: a mu(I) material and a light Newtonian
 * phase (air), mixed cell by cell by the volume fraction c of the former, as
 * Lagree, Staron & Popinet (JFM 686, 2011) ran the granular column collapse
 * with a VOF free surface; see gf_continuum.h.
 *
 *  - face density: the mean of the two cells' c rho + (1 - c) rho_2;
 *  - projection: div(grad(phi)/rho) = div(u**)/dt on the cells (zero flux
 *    across walls and inflows, phi = 0 on outflow faces), assembled and
 *    solved by LU every step (rho moves with c), u = u** - dt grad(phi)/rho;
 *  - c is advected by the divergence-free u^{n+1}: gf_continuum_vof.c.
 */
#include "continuum/gf_continuum_internal.h"

static double density_of(const gf_continuum *s, double c)
{
    return c * s->p.density_kg_m3 + (1.0 - c) * s->p.density2_kg_m3;
}

void gf_continuum_face_density(gf_continuum *s)
{
    const gf_grid *g = &s->g;
    for (int a = 0; a < s->n_comp; ++a)
        for (int k = 0; k < g->nf[a][2]; ++k)
            for (int j = 0; j < g->nf[a][1]; ++j)
                for (int i = 0; i < g->nf[a][0]; ++i) {
                    int hi[3] = {i, j, k}, lo[3] = {i, j, k};
                    lo[a] -= 1;
                    double c = 0.5 * (s->c_cell[gf_continuum_cell_clamped(s, hi)] +
                                      s->c_cell[gf_continuum_cell_clamped(s, lo)]);
                    s->rho_face[a][gf_grid_face(g, a, i, j, k)] = density_of(s, c);
                }
}

static double face_rho(const gf_continuum *s, int a, const int face_idx[3])
{
    return s->rho_face[a][gf_grid_face(&s->g, a, face_idx[0], face_idx[1], face_idx[2])];
}

static void assemble_pressure(gf_continuum *s)
{
    const gf_grid *g = &s->g;
    gf_cont_lu_clear(s->lu_p);
    for (int k = 0; k < g->n[2]; ++k)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i) {
                int row = (int)gf_grid_cell(g, i, j, k);
                double diag = 0.0;
                for (int a = 0; a < s->n_comp; ++a)
                    for (int side = 0; side < 2; ++side) {
                        int f[3] = {i, j, k}, nb[3] = {i, j, k};
                        f[a] += side;          /* the face: idx[a] (low) or idx[a] + 1 (high) */
                        nb[a] += side ? 1 : -1;
                        double coef = 1.0 / (face_rho(s, a, f) * g->h_m[a] * g->h_m[a]);
                        if (g->periodic[a] || (nb[a] >= 0 && nb[a] < g->n[a])) {
                            diag -= coef;
                            gf_cont_lu_add(s->lu_p, row, (int)gf_continuum_cell_clamped(s, nb), coef);
                        } else if (s->p.side[a][side] == GF_SIDE_OUTFLOW) {
                            diag -= 2.0 * coef;  /* phi = 0 on the face: ghost -phi */
                        }
                    }
                gf_cont_lu_add(s->lu_p, row, row, diag);
            }
}

gf_status gf_continuum_project_variable(gf_continuum *s, double dt)
{
    const gf_grid *g = &s->g;
    for (int k = 0; k < g->n[2]; ++k)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i)
                s->div_cell[gf_grid_cell(g, i, j, k)] = gf_continuum_cell_divergence(s, i, j, k) / dt;
    assemble_pressure(s);
    GF_TRY(gf_cont_lu_factor(s->ctx, s->lu_p));
    GF_TRY(gf_cont_lu_solve(s->ctx, s->lu_p, s->div_cell, s->c_new)); /* c_new: scratch for phi */
    gf_continuum_correct_velocity(s, s->c_new, dt);
    for (size_t c = 0; c < g->n_cells; ++c)
        s->p_cell[c] += s->c_new[c];
    for (int a = 0; a < s->n_comp; ++a)
        gf_grid_sync_periodic(g, a, s->u[a]);
    return GF_OK;
}
