/* Exact solutions for the order of the fluid step in cell size; see gf_fluid_exact.h. */
#include "fluid/gf_fluid_exact.h"

#include <math.h>
#include <stdlib.h>

#include "core/gf_rng.h"

#include "fluid/gf_fluid.h"
#include "fluid/gf_fluid_ns2.h"

#define POIS_G 8.0 /* body force, L = nu = 1: u_max = G L^2/(8 nu) = 1 */

/* Start-up Poiseuille profile u(y, t) (gf_fluid_exact.h), L = nu = 1. */
static double poiseuille_u(double y, double t)
{
    double u = 0.5 * POIS_G * y * (1.0 - y);
    for (int m = 1; m < 400; m += 2) {
        double decay = exp(-m * m * M_PI * M_PI * t);
        if (decay < 1e-300)
            break;
        u -= 4.0 * POIS_G / (M_PI * M_PI * M_PI * m * m * m) * sin(m * M_PI * y) * decay;
    }
    return u;
}

/* Taylor-Green velocity component a at x (U = k = 1), amplitude F. */
static double taylor_green_u(int a, const double x[3], double F)
{
    if (a == 0)
        return sin(x[0]) * cos(x[1]) * F;
    if (a == 1)
        return -cos(x[0]) * sin(x[1]) * F;
    return 0.0;
}

static double nu_of(const gf_fluid_exact_case *c) { return c->problem == GF_EXACT_TAYLOR_GREEN ? 1.0 / c->re : 1.0; }

/* Exact velocity component a at x, time t. */
static double exact_u(const gf_fluid_exact_case *c, int a, const double x[3], double t)
{
    if (c->problem == GF_EXACT_TAYLOR_GREEN)
        return taylor_green_u(a, x, exp(-2.0 * nu_of(c) * t));
    return a == 0 ? poiseuille_u(x[1], t) : 0.0;
}

/* Position of face (i,j,k) of component a: on the face along a, at the cell centre across. */
static void face_position(const gf_grid *g, int a, int i, int j, int k, double x[3])
{
    int idx[3] = {i, j, k};
    for (int d = 0; d < 3; ++d)
        x[d] = g->lo_m[d] + (idx[d] + (d == a ? 0.0 : 0.5)) * g->h_m[d];
}

static gf_status create_fluid(gf_ctx *ctx, const gf_fluid_exact_case *c, gf_fluid **f)
{
    gf_fluid_params prm = {.density_kg_m3 = 1.0, .viscosity_Pa_s = nu_of(c)};
    double h = c->problem == GF_EXACT_TAYLOR_GREEN ? 2.0 * M_PI / c->n : 1.0 / c->n;
    /* POISEUILLE: 2 x n x 1 cells, walls across y; TAYLOR_GREEN: n x n x 1, all periodic */
    int n[3] = {c->problem == GF_EXACT_TAYLOR_GREEN ? c->n : 2, c->n, 1};
    for (int d = 0; d < 3; ++d) {
        prm.n_cells[d] = n[d];
        prm.lo_m[d] = 0.0;
        prm.hi_m[d] = n[d] * h;
        gf_grid_bc bc = (d == 1 && c->problem == GF_EXACT_POISEUILLE) ? GF_GRID_NO_SLIP : GF_GRID_PERIODIC;
        prm.bc[d][0] = prm.bc[d][1] = bc;
    }
    return gf_fluid_create(ctx, &prm, f);
}

/* Exact velocity at t = 0 on the faces, exact pressure at the cells, body force. */
static void initial_state(const gf_fluid_exact_case *c, gf_fluid *f)
{
    const gf_grid *g = &f->grid;
    gf_rng rng;
    gf_rng_seed(&rng, 1); /* the noise: the same sequence, in face order, on every run */
    for (int a = 0; a < 3; ++a)
        for (int k = 0; k < g->nf[a][2]; ++k)
            for (int j = 0; j < g->nf[a][1]; ++j)
                for (int i = 0; i < g->nf[a][0]; ++i) {
                    double x[3];
                    face_position(g, a, i, j, k, x);
                    size_t q = gf_grid_face(g, a, i, j, k);
                    f->u[a][q] = exact_u(c, a, x, 0.0) + (c->noise > 0.0 ? c->noise * gf_rng_range(&rng, -1.0, 1.0) : 0.0);
                }
    for (int k = 0; k < g->n[2]; ++k)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i) {
                size_t cc = gf_grid_cell(g, i, j, k);
                double x = (i + 0.5) * g->h_m[0], y = (j + 0.5) * g->h_m[1];
                int tg = c->problem == GF_EXACT_TAYLOR_GREEN;
                f->p_Pa[cc] = tg ? 0.25 * (cos(2.0 * x) + cos(2.0 * y)) : 0.0;
                f->body[0][cc] = tg ? 0.0 : POIS_G;
            }
}

/* RMS and max of u_h - u_exact over the velocity unknowns, divided by scale. */
static void velocity_error(const gf_fluid_exact_case *c, const gf_fluid *f, double t, double scale,
                           gf_fluid_exact_result *r)
{
    const gf_grid *g = &f->grid;
    double s2 = 0.0, mx = 0.0;
    long n = 0;
    for (int a = 0; a < 3; ++a)
        GF_GRID_FOR_FREE_FACES(g, a, fi, i, j, k) {
            double x[3];
            face_position(g, a, i, j, k, x);
            double e = f->u[a][fi] - exact_u(c, a, x, t);
            s2 += e * e, mx = fmax(mx, fabs(e)), ++n;
        }
    r->err_rms = sqrt(s2 / (double)n) / scale;
    r->err_max = mx / scale;
}

/* The resolved tier's step (gf_fluid_ns2.h) without forcing: c->scheme's substeps of rates, CN, projection. */
static gf_status run_ns2(gf_ctx *ctx, const gf_fluid_exact_case *c, gf_fluid *f, double dt, long steps)
{
    const gf_grid *g = &f->grid;
    double *A[3], *A_old[3], *r[3];
    int ok = 1;
    for (int a = 0; a < 3; ++a) {
        ok &= (A[a] = calloc(g->n_faces[a], sizeof(double))) != NULL;
        ok &= (A_old[a] = calloc(g->n_faces[a], sizeof(double))) != NULL;
        ok &= (r[a] = calloc(g->n_faces[a], sizeof(double))) != NULL;
    }
    gf_status st = ok ? GF_OK : GF_FAIL(ctx, GF_ERR_NOMEM, "fluid exact case: out of memory");
    const gf_ns2_substep *sub;
    int n_sub = gf_fluid_ns2_substeps(c->scheme, &sub);
    for (long s = 0; s < steps && st == GF_OK; ++s)
        for (int k = 0; k < n_sub && st == GF_OK; ++k) {
            int use_old = gf_fluid_ns2_uses_previous(c->scheme, k, s == 0);
            gf_fluid_ns2_advection(f, c->advection, A);
            gf_fluid_ns2_rates(f, &sub[k], (const double *const *)A, (const double *const *)(use_old ? A_old : A), r);
            st = gf_fluid_ns2_viscous(ctx, f, &sub[k], (const double *const *)r, NULL, dt);
            if (st == GF_OK)
                st = gf_fluid_ns2_project(ctx, f, 2.0 * sub[k].alpha * dt);
            gf_fluid_ns2_rotate(A, A_old);
        }
    for (int a = 0; a < 3; ++a)
        free(A[a]), free(A_old[a]), free(r[a]);
    return st;
}

/* Kinetic energy per unit density, sum over the free faces of u^2/2 times the cell volume. */
static double kinetic_energy(const gf_fluid *f)
{
    const gf_grid *g = &f->grid;
    double e = 0.0;
    for (int a = 0; a < 3; ++a)
        GF_GRID_FOR_FREE_FACES(g, a, fi, i, j, k)
        e += 0.5 * f->u[a][fi] * f->u[a][fi];
    return e * g->h_m[0] * g->h_m[1] * g->h_m[2];
}

static gf_status run_case(gf_ctx *ctx, const gf_fluid_exact_case *c, int ns2, gf_fluid_exact_result *out)
{
    if (c->n < 2 || !(c->dt > 0.0) || !(c->t_end > 0.0) || (c->problem == GF_EXACT_TAYLOR_GREEN && !(c->re > 0.0)))
        return GF_FAIL(ctx, GF_ERR_ARG, "fluid exact case: need n >= 2, dt > 0, t_end > 0, Re > 0 (n %d, dt %g, "
                       "t_end %g, Re %g)", c->n, c->dt, c->t_end, c->re);
    gf_fluid *f = NULL;
    GF_TRY(create_fluid(ctx, c, &f));
    initial_state(c, f);
    double ke0 = kinetic_energy(f);
    long steps = (long)ceil(c->t_end / c->dt - 1e-9);
    double dt = c->t_end / (double)steps;
    gf_status st = GF_OK;
    if (ns2 && c->problem == GF_EXACT_TAYLOR_GREEN)
        st = run_ns2(ctx, c, f, dt, steps);
    else if (ns2)
        st = GF_FAIL(ctx, GF_ERR_ARG, "fluid exact case: the resolved tier's step runs Taylor-Green only");
    for (long s = 0; s < steps && st == GF_OK && !ns2; ++s) {
        gf_fluid_advect(f, dt);                  /* work = dt (b - (u.grad)u) */
        st = gf_fluid_viscous(ctx, f, dt);       /* u** */
        if (st == GF_OK)
            st = gf_fluid_project(ctx, f, dt);   /* u^{n+1}, p^{n+1} */
    }
    if (st == GF_OK) {
        int tg = c->problem == GF_EXACT_TAYLOR_GREEN;
        double scale = tg ? exp(-2.0 * nu_of(c) * c->t_end) : 1.0;
        velocity_error(c, f, c->t_end, scale, out);
        out->h = f->grid.h_m[1];
        out->cell_re = tg ? out->h / nu_of(c) : 0.0;
        out->steps = steps;
        out->energy_ratio = ke0 > 0.0 ? kinetic_energy(f) / (ke0 * scale * scale) : 0.0;
    }
    gf_fluid_destroy(&f);
    return st;
}

gf_status gf_fluid_exact_run(gf_ctx *ctx, const gf_fluid_exact_case *c, gf_fluid_exact_result *out)
{
    return run_case(ctx, c, 0, out);
}

gf_status gf_fluid_exact_run_ns2(gf_ctx *ctx, const gf_fluid_exact_case *c, gf_fluid_exact_result *out)
{
    return run_case(ctx, c, 1, out);
}

double gf_fluid_exact_order(double e_coarse, double e_fine, double h_coarse, double h_fine)
{
    return log(e_coarse / e_fine) / log(h_coarse / h_fine);
}
