/* The continuum solver's life cycle and step; see gf_continuum.h. */
#include "continuum/gf_continuum.h"

#include <math.h>
#include <stdlib.h>

#include "continuum/gf_continuum_internal.h"

static int bounded_by_wall(const gf_continuum_params *p, int d)
{
    return p->side[d][0] == GF_SIDE_WALL || p->side[d][1] == GF_SIDE_WALL;
}

gf_status gf_continuum_params_check(gf_ctx *ctx, const gf_continuum_params *p, const char *where)
{
    int has_inflow = 0, has_outflow = 0;
    for (int d = 0; d < 3; ++d) {
        if (p->n[d] < 1 || !(p->length_m[d] > 0.0))
            return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: axis %d needs n >= 1 and a length > 0 (got n = %d, L = %g m)", where,
                           d, p->n[d], p->length_m[d]);
        if ((p->side[d][0] == GF_SIDE_PERIODIC) != (p->side[d][1] == GF_SIDE_PERIODIC))
            return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: axis %d is periodic on one side only", where, d);
        for (int s = 0; s < 2; ++s) {
            has_inflow |= p->side[d][s] == GF_SIDE_INFLOW;
            has_outflow |= p->side[d][s] == GF_SIDE_OUTFLOW;
        }
    }
    if (p->n[2] == 1 && p->side[2][0] != GF_SIDE_PERIODIC)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: a 2-D run (one cell along z) must be periodic along z", where);
    if (has_inflow && !has_outflow)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: an inflow needs an outflow (incompressible)", where);
    int min_cells = p->min_cells_across > 0 ? p->min_cells_across : 8;
    for (int d = 0; d < 3; ++d)
        if (bounded_by_wall(p, d) && p->n[d] < min_cells)
            return GF_FAIL(ctx, GF_ERR_CONFIG,
                           "%s: %d cells across the walls of axis %d is too coarse to resolve the wall layer "
                           "(at least %d needed)",
                           where, p->n[d], d, min_cells);
    if (p->two_phase && !has_outflow)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: two phases need an outflow (open) side to fix the pressure", where);
    if (p->two_phase && !(p->density2_kg_m3 > 0.0 && p->viscosity2_Pa_s >= 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: the second phase needs a density > 0 and a viscosity >= 0 (got %g kg/m3, %g Pa s)",
                       where, p->density2_kg_m3, p->viscosity2_Pa_s);
    if (!(p->density_kg_m3 > 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: density must be > 0 (got %g kg/m3)", where, p->density_kg_m3);
    if (!(p->dt_s > 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: dt must be > 0 (got %g s)", where, p->dt_s);
    if (p->rheology == GF_RHEOLOGY_NEWTONIAN && !(p->viscosity_Pa_s > 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: viscosity must be > 0 (got %g Pa s)", where, p->viscosity_Pa_s);
    if (p->rheology != GF_RHEOLOGY_NEWTONIAN) {
        GF_TRY(gf_mui_material_check(ctx, &p->mui, where));
        if (!(p->pressure_ref_Pa >= 0.0))
            return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: reference pressure must be >= 0 (got %g Pa)", where,
                           p->pressure_ref_Pa);
    }
    return GF_OK;
}

/* Cell average of 4 s (1 - s) over [s0, s1] (the inflow through a face equals the parabola's). */
static double parabola_average(double s0, double s1)
{
    return 4.0 * ((s1 * s1 - s0 * s0) / 2.0 - (s1 * s1 * s1 - s0 * s0 * s0) / 3.0) / (s1 - s0);
}

static void set_inflow(gf_continuum *s, int a, int m)
{
    const gf_grid *g = &s->g;
    for (size_t n = 0; n < gf_grid_plane_faces(g, a); ++n) {
        int idx[3];
        size_t q = gf_grid_plane_face(g, a, m, n, idx);
        double v = s->p.inflow_umax_m_s;
        for (int d = 0; d < 3; ++d)
            if (d != a && bounded_by_wall(&s->p, d))
                v *= parabola_average((double)idx[d] / g->n[d], (double)(idx[d] + 1) / g->n[d]);
        s->u[a][q] = v;
    }
}

static gf_status map_unknowns(gf_continuum *s)
{
    const gf_grid *g = &s->g;
    int count = 0;
    s->unknown_face = malloc((g->n_faces[0] + g->n_faces[1] + g->n_faces[2]) * sizeof *s->unknown_face);
    if (!s->unknown_face)
        return GF_FAIL(s->ctx, GF_ERR_NOMEM, "continuum: unknown map");
    for (int a = 0; a < s->n_comp; ++a) {
        s->unknown[a] = malloc(g->n_faces[a] * sizeof(int));
        if (!s->unknown[a])
            return GF_FAIL(s->ctx, GF_ERR_NOMEM, "continuum: unknown map");
        for (int k = 0; k < g->nf[a][2]; ++k)
            for (int j = 0; j < g->nf[a][1]; ++j)
                for (int i = 0; i < g->nf[a][0]; ++i) {
                    int idx[3] = {i, j, k}, m = idx[a], n = g->n[a];
                    int free_face = g->periodic[a] ? m < n
                                                   : (m >= 1 && m <= n - 1) ||
                                                         (m == 0 && s->p.side[a][0] == GF_SIDE_OUTFLOW) ||
                                                         (m == n && s->p.side[a][1] == GF_SIDE_OUTFLOW);
                    size_t q = gf_grid_face(g, a, i, j, k);
                    s->unknown[a][q] = free_face ? count : -1;
                    if (free_face)
                        s->unknown_face[count++] = (gf_unknown_face){a, {i, j, k}, q};
                }
    }
    s->n_unknowns = count;
    return GF_OK;
}

static gf_status allocate(gf_continuum *s)
{
    const gf_grid *g = &s->g;
    for (int a = 0; a < s->n_comp; ++a) {
        s->u[a] = calloc(g->n_faces[a], sizeof(double));
        s->u_old[a] = calloc(g->n_faces[a], sizeof(double));
        if (!s->u[a] || !s->u_old[a])
            return GF_FAIL(s->ctx, GF_ERR_NOMEM, "continuum: velocity");
    }
    double **cell[] = {&s->p_cell, &s->div_cell, &s->eta_cell, &s->strain_cell, &s->diag_cell,
                       &s->offsq_cell[0], &s->offsq_cell[1], &s->offsq_cell[2], &s->c_cell, &s->c_new, &s->c_start};
    for (size_t f = 0; f < sizeof cell / sizeof cell[0]; ++f)
        if (!(*cell[f] = calloc(g->n_cells, sizeof(double))))
            return GF_FAIL(s->ctx, GF_ERR_NOMEM, "continuum: cell fields");
    for (int k = 0; k < 3; ++k) {
        s->n_edges[k] = 1;
        for (int d = 0; d < 3; ++d) {
            s->ne[k][d] = d == k ? g->n[d] : g->n[d] + 1;
            s->n_edges[k] *= (size_t)s->ne[k][d];
        }
        s->e_edge[k] = calloc(s->n_edges[k], sizeof(double));
        s->eta_edge[k] = calloc(s->n_edges[k], sizeof(double));
        if (!s->e_edge[k] || !s->eta_edge[k])
            return GF_FAIL(s->ctx, GF_ERR_NOMEM, "continuum: edge fields");
    }
    for (size_t c = 0; c < g->n_cells; ++c)
        s->c_cell[c] = 1.0;
    if (s->p.two_phase) {
        for (int a = 0; a < s->n_comp; ++a)
            if (!(s->rho_face[a] = calloc(g->n_faces[a], sizeof(double))))
                return GF_FAIL(s->ctx, GF_ERR_NOMEM, "continuum: face densities");
        GF_TRY(gf_cont_lu_create(s->ctx, (int)g->n_cells, (long)(2 * s->n_comp + 1) * (long)g->n_cells, &s->lu_p));
    }
    GF_TRY(map_unknowns(s));
    s->rhs = calloc(s->n_unknowns, sizeof(double));
    s->x = calloc(s->n_unknowns, sizeof(double));
    if (!s->rhs || !s->x)
        return GF_FAIL(s->ctx, GF_ERR_NOMEM, "continuum: %d unknowns", s->n_unknowns);
    /* at most 1 + 2 + 4 (n_comp - 1) * 2 stencil entries per row, duplicates summed by the LU */
    long per_row = 3 + 8L * (s->n_comp - 1) + 4;
    return gf_cont_lu_create(s->ctx, s->n_unknowns, per_row * s->n_unknowns, &s->lu);
}

static gf_status make_poisson(gf_continuum *s)
{
    gf_cont_poisson_side side[3][2];
    for (int d = 0; d < 3; ++d)
        for (int k = 0; k < 2; ++k)
            side[d][k] = s->p.side[d][k] == GF_SIDE_PERIODIC  ? GF_POISSON_PERIODIC
                         : s->p.side[d][k] == GF_SIDE_OUTFLOW ? GF_POISSON_DIRICHLET
                                                              : GF_POISSON_NEUMANN;
    return gf_cont_poisson_create(s->ctx, s->g.n, s->g.h_m, side, &s->poisson);
}

gf_status gf_continuum_create(gf_ctx *ctx, const gf_continuum_params *p, gf_continuum **out)
{
    *out = NULL;
    GF_TRY(gf_continuum_params_check(ctx, p, "continuum"));
    gf_continuum *s = calloc(1, sizeof *s);
    if (!s)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "continuum: solver");
    s->ctx = ctx;
    s->p = *p;
    s->n_comp = p->n[2] > 1 ? 3 : 2;
    gf_grid_bc bc[3][2];
    double lo[3] = {0, 0, 0};
    for (int d = 0; d < 3; ++d)
        for (int k = 0; k < 2; ++k)
            bc[d][k] = p->side[d][k] == GF_SIDE_PERIODIC ? GF_GRID_PERIODIC : GF_GRID_NO_SLIP;
    gf_status st = gf_grid_init(ctx, &s->g, p->n, lo, p->length_m, bc);
    if (st == GF_OK)
        st = allocate(s);
    if (st == GF_OK)
        st = make_poisson(s);
    if (st != GF_OK) {
        gf_continuum_destroy(&s);
        return st;
    }
    for (int a = 0; a < s->n_comp; ++a) {
        if (p->side[a][0] == GF_SIDE_INFLOW)
            set_inflow(s, a, 0);
        if (p->side[a][1] == GF_SIDE_INFLOW)
            set_inflow(s, a, s->g.n[a]);
    }
    *out = s;
    return GF_OK;
}

void gf_continuum_destroy(gf_continuum **ps)
{
    if (!ps || !*ps)
        return;
    gf_continuum *s = *ps;
    for (int a = 0; a < 3; ++a) {
        free(s->u[a]), free(s->u_old[a]), free(s->unknown[a]);
        free(s->e_edge[a]), free(s->eta_edge[a]), free(s->offsq_cell[a]);
        free(s->rho_face[a]);
    }
    free(s->p_cell), free(s->div_cell), free(s->eta_cell), free(s->strain_cell), free(s->diag_cell);
    free(s->rhs), free(s->x), free(s->c_cell), free(s->c_new), free(s->c_start), free(s->unknown_face);
    gf_cont_lu_destroy(&s->lu_p);
    gf_cont_poisson_destroy(&s->poisson);
    gf_cont_lu_destroy(&s->lu);
    free(s);
    *ps = NULL;
}

gf_status gf_continuum_step(gf_continuum *s)
{
    double dt = s->p.dt_s;
    if (s->p.two_phase)
        gf_continuum_face_density(s);
    if (s->p.rheology != GF_RHEOLOGY_NEWTONIAN || s->p.two_phase || s->steps == 0)
        gf_continuum_update_viscosity(s);
    gf_continuum_advect(s, dt);
    GF_TRY(gf_continuum_viscous(s, dt));
    if (s->p.two_phase) {
        GF_TRY(gf_continuum_project_variable(s, dt));
        gf_continuum_advect_fraction(s, dt);
    } else {
        gf_continuum_project(s, dt);
    }
    s->time_s += dt;
    ++s->steps;
    for (int a = 0; a < s->n_comp; ++a)
        for (size_t q = 0; q < s->g.n_faces[a]; ++q)
            if (!isfinite(s->u[a][q]))
                return GF_FAIL(s->ctx, GF_ERR_NUMERIC, "continuum: non-finite velocity at t = %g s (step %ld)",
                               s->time_s, s->steps);
    return GF_OK;
}

gf_status gf_continuum_init_pressure(gf_continuum *s)
{
    double dt = s->p.dt_s;
    for (int a = 0; a < s->n_comp; ++a)
        for (size_t q = 0; q < s->g.n_faces[a]; ++q) {
            s->u_old[a][q] = s->u[a][q];
            if (s->unknown[a][q] >= 0)
                s->u[a][q] += dt * s->p.body_accel_m_s2[a];
        }
    for (int a = 0; a < s->n_comp; ++a)
        gf_grid_sync_periodic(&s->g, a, s->u[a]);
    gf_status st = GF_OK;
    if (s->p.two_phase) {
        gf_continuum_face_density(s);
        st = gf_continuum_project_variable(s, dt);
    } else {
        gf_continuum_project(s, dt);
    }
    for (int a = 0; a < s->n_comp; ++a)
        for (size_t q = 0; q < s->g.n_faces[a]; ++q)
            s->u[a][q] = s->u_old[a][q];
    return st;
}

gf_status gf_continuum_run(gf_continuum *s, double t_end_s, double steady_tol_m_s, double *change_m_s)
{
    double change = INFINITY;
    while (s->time_s < t_end_s - 1e-9 * s->p.dt_s) {
        GF_TRY(gf_continuum_step(s));
        change = 0.0;
        for (int a = 0; a < s->n_comp; ++a)
            for (size_t q = 0; q < s->g.n_faces[a]; ++q)
                change = fmax(change, fabs(s->u[a][q] - s->u_old[a][q]));
        if (steady_tol_m_s > 0.0 && change <= steady_tol_m_s)
            break;
    }
    if (change_m_s)
        *change_m_s = change;
    return GF_OK;
}

const gf_grid *gf_continuum_grid(const gf_continuum *s)
{
    return &s->g;
}
const double *gf_continuum_velocity(const gf_continuum *s, int a)
{
    return a < s->n_comp ? s->u[a] : NULL;
}
const double *gf_continuum_pressure(const gf_continuum *s)
{
    return s->p_cell;
}
double *gf_continuum_fraction(gf_continuum *s)
{
    return s->c_cell;
}
const double *gf_continuum_viscosity(const gf_continuum *s)
{
    return s->eta_cell;
}
double gf_continuum_time(const gf_continuum *s)
{
    return s->time_s;
}

double gf_continuum_divergence_norm(const gf_continuum *s)
{
    const gf_grid *g = &s->g;
    double worst = 0.0, umax = 0.0;
    for (int a = 0; a < s->n_comp; ++a)
        umax = fmax(umax, gf_continuum_max_speed(s, a));
    for (int k = 0; k < g->n[2]; ++k)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i)
                worst = fmax(worst, fabs(gf_continuum_cell_divergence(s, i, j, k)) * g->h_m[0]);
    return umax > 0.0 ? worst / umax : worst;
}
