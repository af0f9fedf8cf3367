/* Second-order Navier-Stokes substeps of the resolved tier (AB2/CN, RK3/CN); schemes and sources in
 * gf_fluid_ns2.h. */
#include "fluid/gf_fluid_ns2.h"

#include <math.h>
#include <string.h>

static const gf_ns2_substep ab2_substeps[1] = {{1.5, -0.5, 0.5}};
static const gf_ns2_substep rk3_substeps[3] = {
    {8.0 / 15.0, 0.0, 4.0 / 15.0}, {5.0 / 12.0, -17.0 / 60.0, 1.0 / 15.0}, {3.0 / 4.0, -5.0 / 12.0, 1.0 / 6.0}};

int gf_fluid_ns2_substeps(gf_ns2_scheme scheme, const gf_ns2_substep **out)
{
    *out = scheme == GF_NS2_RK3 ? rk3_substeps : ab2_substeps;
    return scheme == GF_NS2_RK3 ? 3 : 1;
}

/* The index of name in the NULL-terminated list, -1 when absent. */
static int name_index(const char *name, const char *const *list)
{
    for (int i = 0; list[i]; ++i)
        if (strcmp(name, list[i]) == 0)
            return i;
    return -1;
}

const char *const gf_ns2_scheme_names[] = {"ab2", "rk3", NULL};
const char *const gf_ns2_advection_names[] = {"advective", "divergence", NULL};

int gf_fluid_ns2_advection_from_name(const char *name, gf_ns2_advection *out)
{
    int i = name_index(name, gf_ns2_advection_names);
    if (i >= 0)
        *out = (gf_ns2_advection)i;
    return i >= 0 ? 0 : -1;
}

int gf_fluid_ns2_scheme_from_name(const char *name, gf_ns2_scheme *out)
{
    int i = name_index(name, gf_ns2_scheme_names);
    if (i >= 0)
        *out = (gf_ns2_scheme)i;
    return i >= 0 ? 0 : -1;
}

int gf_fluid_ns2_uses_previous(gf_ns2_scheme scheme, int k, int first_step)
{
    return k > 0 || (scheme == GF_NS2_AB2 && !first_step);
}

void gf_fluid_ns2_rotate(double *A[3], double *A_old[3])
{
    for (int a = 0; a < 3; ++a) {
        double *t = A_old[a];
        A_old[a] = A[a];
        A[a] = t;
    }
}

/* The step's OpenMP threads: those its FFT plans were set for (gf_poisson_plan_set_threads), 1 by default.
 * Every loop below writes each face or cell from its own inputs alone, or takes a max: the values do not
 * depend on the thread count (nor do the slab FFTs'; gf_poisson.h). */
static int step_threads(const gf_fluid *f) { return gf_poisson_plan_threads(f->poisson); }

/* 1 when face (i,j,k) of component a has all its stencil neighbours inside the arrays, no boundary rule
 * needed: the fast path of the loops below (the generic gf_grid calls handle the rest, the same values). */
static int interior_face(const gf_grid *g, int a, int i, int j, int k)
{
    const int idx[3] = {i, j, k};
    for (int d = 0; d < 3; ++d) {
        if (d == a ? (idx[d] < 1 || idx[d] > g->n[d] - 1) : (idx[d] < 1 || idx[d] > g->n[d] - 2))
            return 0;
    }
    return 1;
}

static double advection_generic(const gf_grid *g, const double *const uu[3], int a, size_t fi, int i, int j, int k)
{
    const double *u = uu[a];
    double adv = 0.0;
    for (int d = 0; d < 3; ++d) {
        if (g->n[d] == 1 && g->periodic[d])
            continue;
        double vd = d == a ? u[fi] : gf_fluid_advecting_velocity(g, uu, a, d, i, j, k);
        double up = gf_grid_face_neighbour(g, u, a, i, j, k, d, +1);
        double dn = gf_grid_face_neighbour(g, u, a, i, j, k, d, -1);
        adv += vd * (up - dn) / (2.0 * g->h_m[d]);
    }
    return adv;
}

/* Interior face: strides of the face arrays instead of the boundary-aware neighbour calls. */
static double advection_interior(const gf_grid *g, const double *const uu[3], int a, size_t fi, int i, int j, int k)
{
    const double *u = uu[a];
    const size_t s[3] = {1, (size_t)g->nf[a][0], (size_t)g->nf[a][0] * (size_t)g->nf[a][1]};
    double adv = 0.0;
    for (int d = 0; d < 3; ++d) {
        double vd = u[fi];
        if (d != a) { /* component d at this face: the four d-faces around it (cells m-1, m along a) */
            const size_t sd[3] = {1, (size_t)g->nf[d][0], (size_t)g->nf[d][0] * (size_t)g->nf[d][1]};
            size_t q = gf_grid_face(g, d, i, j, k);
            vd = 0.25 * (uu[d][q] + uu[d][q + sd[d]] + uu[d][q - sd[a]] + uu[d][q - sd[a] + sd[d]]);
        }
        adv += vd * (u[fi + s[d]] - u[fi - s[d]]) / (2.0 * g->h_m[d]);
    }
    return adv;
}

/* Component d averaged along a to the edge of the a-face's control volume on its low (up 0) or high (up 1)
 * side along d: the advecting velocity of the divergence form. Wall faces hold 0. */
static double edge_velocity(const gf_grid *g, const double *ud, int a, int d, int i, int j, int k, int up)
{
    const int idx[3] = {i, j, k};
    int c0 = gf_grid_wrap(g, a, idx[a] - 1), c1 = gf_grid_wrap(g, a, idx[a]);
    c0 = c0 < 0 ? c1 : c0, c1 = c1 < 0 ? c0 : c1;
    int q0[3] = {i, j, k}, q1[3] = {i, j, k};
    q0[a] = c0, q1[a] = c1, q0[d] += up, q1[d] += up;
    return 0.5 * (ud[gf_grid_face(g, d, q0[0], q0[1], q0[2])] + ud[gf_grid_face(g, d, q1[0], q1[1], q1[2])]);
}

/* Divergence form, sum_d d(u_d u_a)/dx_d with second-order interpolations (Harlow & Welch, Phys. Fluids 8,
 * 1965; Morinishi et al., J. Comput. Phys. 143, 1998, "Div.-2"): conserves the kinetic energy of a
 * divergence-free field up to the time scheme (the advective form does not, and pumps energy into the grid
 * scale at high cell Reynolds numbers). */
static double divergence_generic(const gf_grid *g, const double *const uu[3], int a, size_t fi, int i, int j, int k)
{
    const double *u = uu[a];
    double adv = 0.0;
    for (int d = 0; d < 3; ++d) {
        if (g->n[d] == 1 && g->periodic[d])
            continue;
        double at = 0.5 * (u[fi] + gf_grid_face_neighbour(g, u, a, i, j, k, d, +1));
        double ab = 0.5 * (u[fi] + gf_grid_face_neighbour(g, u, a, i, j, k, d, -1));
        double vt = d == a ? at : edge_velocity(g, uu[d], a, d, i, j, k, 1);
        double vb = d == a ? ab : edge_velocity(g, uu[d], a, d, i, j, k, 0);
        adv += (vt * at - vb * ab) / g->h_m[d];
    }
    return adv;
}

static double divergence_interior(const gf_grid *g, const double *const uu[3], int a, size_t fi, int i, int j,
                                  int k)
{
    const double *u = uu[a];
    const size_t s[3] = {1, (size_t)g->nf[a][0], (size_t)g->nf[a][0] * (size_t)g->nf[a][1]};
    double adv = 0.0;
    for (int d = 0; d < 3; ++d) {
        double at = 0.5 * (u[fi] + u[fi + s[d]]), ab = 0.5 * (u[fi] + u[fi - s[d]]), vt = at, vb = ab;
        if (d != a) { /* component d at the high and low edges: two d-faces each (cells m-1, m along a) */
            const size_t sd[3] = {1, (size_t)g->nf[d][0], (size_t)g->nf[d][0] * (size_t)g->nf[d][1]};
            size_t q = gf_grid_face(g, d, i, j, k);
            vb = 0.5 * (uu[d][q] + uu[d][q - sd[a]]);
            vt = 0.5 * (uu[d][q + sd[d]] + uu[d][q - sd[a] + sd[d]]);
        }
        adv += (vt * at - vb * ab) / g->h_m[d];
    }
    return adv;
}

void gf_fluid_ns2_advection(const gf_fluid *f, gf_ns2_advection form, double *const A[3])
{
    const gf_grid *g = &f->grid;
    const double *const uu[3] = {f->u[0], f->u[1], f->u[2]};
    const int nt = step_threads(f);
    const int div = form == GF_NS2_DIVERGENCE;
    for (int a = 0; a < 3; ++a) {
        memset(A[a], 0, g->n_faces[a] * sizeof(double));
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static)
        GF_GRID_FOR_FREE_FACES(g, a, fi, i, j, k)
        {
            int in = interior_face(g, a, i, j, k);
            A[a][fi] = div ? -(in ? divergence_interior(g, uu, a, fi, i, j, k) : divergence_generic(g, uu, a, fi, i, j, k))
                           : -(in ? advection_interior(g, uu, a, fi, i, j, k) : advection_generic(g, uu, a, fi, i, j, k));
        }
        gf_grid_sync_periodic(g, a, A[a]);
    }
}

static double laplacian(const gf_grid *g, const double *u, int a, size_t fi, int i, int j, int k)
{
    if (!interior_face(g, a, i, j, k))
        return gf_grid_face_laplacian(g, u, a, i, j, k);
    const size_t s[3] = {1, (size_t)g->nf[a][0], (size_t)g->nf[a][0] * (size_t)g->nf[a][1]};
    double l = 0.0;
    for (int d = 0; d < 3; ++d)
        l += (u[fi + s[d]] - 2.0 * u[fi] + u[fi - s[d]]) / (g->h_m[d] * g->h_m[d]);
    return l;
}

static double pressure_gradient(const gf_grid *g, const double *p, int a, int i, int j, int k)
{
    int idx[3] = {i, j, k}, lo[3] = {i, j, k}, hi[3] = {i, j, k};
    lo[a] = gf_grid_wrap(g, a, idx[a] - 1);
    hi[a] = gf_grid_wrap(g, a, idx[a]);
    return (p[gf_grid_cell(g, hi[0], hi[1], hi[2])] - p[gf_grid_cell(g, lo[0], lo[1], lo[2])]) / g->h_m[a];
}

void gf_fluid_ns2_rates(const gf_fluid *f, const gf_ns2_substep *s, const double *const A[3],
                        const double *const A_old[3], double *const r[3])
{
    const gf_grid *g = &f->grid;
    /* 2 alpha is 1 for AB2: w nu and w grad p are then nu and grad p, the same bits */
    const double rho = f->rho_kg_m3, w = 2.0 * s->alpha, w_nu = w * (f->mu_Pa_s / rho), ga = s->gamma, ze = s->zeta;
    const int nt = step_threads(f);
    for (int a = 0; a < 3; ++a) {
        memset(r[a], 0, g->n_faces[a] * sizeof(double));
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static)
        GF_GRID_FOR_FREE_FACES(g, a, fi, i, j, k)
        {
            double adv = ga * A[a][fi] + ze * A_old[a][fi];
            r[a][fi] = adv + w_nu * laplacian(g, f->u[a], a, fi, i, j, k) -
                       w * pressure_gradient(g, f->p_Pa, a, i, j, k) / rho;
        }
        gf_grid_sync_periodic(g, a, r[a]);
    }
}

void gf_fluid_ns2_add_acceleration(const gf_fluid *f, const double b_m_s2[3], double *const r[3])
{
    const gf_grid *g = &f->grid;
    const int nt = step_threads(f);
    for (int a = 0; a < 3; ++a) {
        if (b_m_s2[a] == 0.0)
            continue;
        const double b = b_m_s2[a];
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static)
        GF_GRID_FOR_FREE_FACES(g, a, fi, i, j, k)
        r[a][fi] += b;
        gf_grid_sync_periodic(g, a, r[a]);
    }
}

void gf_fluid_ns2_predict(const gf_fluid *f, const double *const r[3], double dt_s, double *const u_pred[3])
{
    const gf_grid *g = &f->grid;
    const int nt = step_threads(f);
    for (int a = 0; a < 3; ++a) {
        const long n = (long)g->n_faces[a];
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static)
        for (long q = 0; q < n; ++q)
            u_pred[a][q] = f->u[a][q] + dt_s * r[a][q];
    }
}

gf_status gf_fluid_ns2_viscous(gf_ctx *ctx, gf_fluid *f, const gf_ns2_substep *s, const double *const r[3],
                               const double *const force[3], double dt_s)
{
    const gf_grid *g = &f->grid;
    double nu = f->mu_Pa_s / f->rho_kg_m3;
    const int nt = step_threads(f);
    for (int a = 0; a < 3; ++a) {
        double *w = f->work[a];
        const double *fa = force ? force[a] : NULL;
        const long n = (long)g->n_faces[a];
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static)
        for (long q = 0; q < n; ++q)
            w[q] = dt_s * (r[a][q] + (fa ? fa[q] : 0.0));
        /* wall faces stay 0: r and force are 0 there */
        gf_helmholtz_solve(f->visc[a], s->alpha * dt_s * nu, w);
        int finite = 1;
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static) reduction(&& : finite)
        for (long q = 0; q < n; ++q) {
            w[q] += f->u[a][q];
            finite = finite && isfinite(w[q]);
        }
        if (!finite)
            return GF_FAIL(ctx, GF_ERR_NUMERIC, "resolved fluid step: non-finite velocity (component %d)", a);
    }
    return GF_OK;
}

/* div u at every cell, times scale (gf_grid_cell_divergence), by z-slabs on nt threads. */
static void scaled_divergence(const gf_grid *g, const double *const u[3], double scale, int nt, double *div)
{
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static)
    for (int k = 0; k < g->n[2]; ++k)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i)
                div[gf_grid_cell(g, i, j, k)] = gf_grid_cell_divergence(g, u, NULL, i, j, k) * scale;
}

gf_status gf_fluid_ns2_project(gf_ctx *ctx, gf_fluid *f, double dt_s)
{
    const gf_grid *g = &f->grid;
    const int nt = step_threads(f);
    const long n_cells = (long)g->n_cells;
    double rho = f->rho_kg_m3;
    double *rhs = f->tmp[0], *phi = f->tmp[1];
    const double *const w[3] = {f->work[0], f->work[1], f->work[2]};
    scaled_divergence(g, w, rho / dt_s, nt, rhs);
    gf_poisson_solve_const(f->poisson, rhs, phi);
    int finite = 1;
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static) reduction(&& : finite)
    for (long c = 0; c < n_cells; ++c) {
        finite = finite && isfinite(phi[c]);
        f->p_Pa[c] += phi[c];
    }
    if (!finite)
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "resolved fluid step: non-finite pressure (check the fluid step against "
                       "its advective limit)");
    for (int a = 0; a < 3; ++a) {
        memcpy(f->u[a], f->work[a], g->n_faces[a] * sizeof(double));
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static)
        GF_GRID_FOR_FREE_FACES(g, a, fi, i, j, k)
        f->u[a][fi] -= dt_s / rho * pressure_gradient(g, phi, a, i, j, k);
        gf_grid_sync_periodic(g, a, f->u[a]);
    }
    const double *const uu[3] = {f->u[0], f->u[1], f->u[2]};
    scaled_divergence(g, uu, dt_s, nt, rhs);
    double res = 0.0; /* a max: the same on any number of threads */
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static) reduction(max : res)
    for (long c = 0; c < n_cells; ++c)
        res = fabs(rhs[c]) > res ? fabs(rhs[c]) : res;
    f->last_mass_residual = res;
    return GF_OK;
}
