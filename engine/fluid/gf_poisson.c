/* FFT and FFT-preconditioned CG Poisson solvers; see gf_poisson.h for the method. */
#include "fluid/gf_poisson.h"

#include <fftw3.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/gf_timer.h"

/*
 * A 3-D in-place r2r transform pair (row-major dims: z, y, x), in one of two forms:
 *   whole: FFTW's own 3-D plans (serial), what the plans are created with: the unresolved tier's bits;
 *   slabs: the same transform as a 2-D (y, x) plan applied to each z-plane, then a 1-D plan along z applied
 *          to each y-row of columns, every call on a piece of the same shape: the pieces go to OpenMP threads
 *          and each line is transformed by the same plan whatever the thread count, so the result is bitwise
 *          the same on 1 or N threads. FFTW's own threaded plans (libfftw3_omp) split differently per
 *          thread count and, measured on the shared 2-core machine, spent most of the time switching
 *          threads (one parallel region per batch of lines).
 * FFTW_ESTIMATE throughout: the plan depends only on the sizes and kinds, so a run is bitwise reproducible
 * (FFTW_MEASURE times candidate algorithms, which differ in their rounding). FFTW_UNALIGNED on the slab
 * plans: they run on sub-arrays whose alignment differs from the planned one.
 */
typedef struct transform3 {
    int dims[3];
    fftw_r2r_kind kind[2][3];       /* [0] forward, [1] backward */
    fftw_plan whole[2];
    fftw_plan plane[2], line[2];
    int slabs, n_threads;
} transform3;

static void transform3_free_plans(transform3 *t)
{
    for (int w = 0; w < 2; ++w) {
        if (t->whole[w])
            fftw_destroy_plan(t->whole[w]);
        if (t->plane[w])
            fftw_destroy_plan(t->plane[w]);
        if (t->line[w])
            fftw_destroy_plan(t->line[w]);
        t->whole[w] = t->plane[w] = t->line[w] = NULL;
    }
}

/* (Re)plans t on work: whole (slabs = 0) or by slabs on n_threads threads. 0 when FFTW cannot plan. */
static int transform3_plan(transform3 *t, double *work, int slabs, int n_threads)
{
    transform3_free_plans(t);
    t->slabs = slabs;
    t->n_threads = n_threads > 1 ? n_threads : 1;
    const int nz = t->dims[0], ny = t->dims[1], nx = t->dims[2], plane_n[2] = {ny, nx};
    for (int w = 0; w < 2; ++w) {
        if (!slabs) {
            t->whole[w] = fftw_plan_r2r(3, t->dims, work, work, t->kind[w], FFTW_ESTIMATE);
            if (!t->whole[w])
                return 0;
            continue;
        }
        const unsigned flags = FFTW_ESTIMATE | FFTW_UNALIGNED;
        t->plane[w] = fftw_plan_many_r2r(2, plane_n, 1, work, NULL, 1, 0, work, NULL, 1, 0, t->kind[w] + 1, flags);
        t->line[w] = fftw_plan_many_r2r(1, &t->dims[0], nx, work, NULL, nx * ny, 1, work, NULL, nx * ny, 1,
                                        t->kind[w], flags);
        if (!t->plane[w] || (nz > 1 && !t->line[w]))
            return 0;
    }
    return 1;
}

/* The forward (backward = 0) or backward transform of work in place. */
static void transform3_execute(const transform3 *t, double *work, int backward)
{
    if (!t->slabs) {
        fftw_execute(t->whole[backward]);
        return;
    }
    const int nz = t->dims[0], ny = t->dims[1], nx = t->dims[2], nt = t->n_threads;
    const size_t plane = (size_t)nx * ny;
    /* new-array execution of one plan from several threads at once is thread-safe (FFTW manual §5.4) */
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static)
    for (int k = 0; k < nz; ++k)
        fftw_execute_r2r(t->plane[backward], work + k * plane, work + k * plane);
    if (nz > 1) {
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static)
        for (int j = 0; j < ny; ++j)
            fftw_execute_r2r(t->line[backward], work + (size_t)j * nx, work + (size_t)j * nx);
    }
}

/* What the Poisson and the Helmholtz solvers diagonalise with: the transform pair on its work array, the
 * eigenvalues of the 1-D second difference per mode and axis, and the scaling of FFTW's unnormalised
 * forward + backward pair. */
typedef struct spectral3 {
    transform3 tr;
    double *work;
    double *eig[3];
    double norm;
} spectral3;

/* The work array for len[0] len[1] len[2] values and the whole 3-D plans of kinds kf, kb (given x, y, z; FFTW
 * is row-major, so z goes first). Errors: out of memory, FFTW cannot plan (what names the solver). */
static gf_status spectral3_plan(gf_ctx *ctx, spectral3 *s, const int len[3], const fftw_r2r_kind kf[3],
                                const fftw_r2r_kind kb[3], const char *what)
{
    s->work = fftw_malloc((size_t)len[0] * len[1] * len[2] * sizeof(double));
    if (!s->work)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "%s: out of memory for %dx%dx%d values", what, len[0], len[1], len[2]);
    for (int d = 0; d < 3; ++d) {
        s->tr.dims[d] = len[2 - d];
        s->tr.kind[0][d] = kf[2 - d], s->tr.kind[1][d] = kb[2 - d];
    }
    if (!transform3_plan(&s->tr, s->work, 0, 1))
        return GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "%s: FFTW could not plan a %dx%dx%d transform", what, len[0], len[1],
                       len[2]);
    return GF_OK;
}

static void spectral3_free(spectral3 *s)
{
    transform3_free_plans(&s->tr);
    fftw_free(s->work);
    for (int d = 0; d < 3; ++d)
        free(s->eig[d]);
}

struct gf_poisson_plan {
    const gf_grid *g;
    spectral3 sp;
    double *r, *z, *p, *q;  /* CG vectors */
};

gf_status gf_poisson_plan_create(gf_ctx *ctx, const gf_grid *g, gf_poisson_plan **out)
{
    *out = NULL;
    gf_poisson_plan *pl = calloc(1, sizeof *pl);
    if (!pl)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "poisson plan: out of memory");
    pl->g = g;
    size_t n = g->n_cells;
    pl->r = malloc(n * sizeof(double));
    pl->z = malloc(n * sizeof(double));
    pl->p = malloc(n * sizeof(double));
    pl->q = malloc(n * sizeof(double));
    pl->sp.norm = 1.0;
    fftw_r2r_kind kf[3], kb[3];
    int ok = pl->r && pl->z && pl->p && pl->q;
    for (int d = 0; d < 3 && ok; ++d) {
        int nd = g->n[d];
        double h2 = g->h_m[d] * g->h_m[d];
        pl->sp.eig[d] = malloc((size_t)nd * sizeof(double));
        if (!pl->sp.eig[d]) {
            ok = 0;
            break;
        }
        for (int m = 0; m < nd; ++m) {
            if (g->periodic[d]) {
                int fr = m <= nd / 2 ? m : nd - m;  /* half-complex: index m holds frequency fr */
                pl->sp.eig[d][m] = (2.0 * cos(2.0 * M_PI * fr / nd) - 2.0) / h2;
            } else {
                pl->sp.eig[d][m] = (2.0 * cos(M_PI * m / nd) - 2.0) / h2;
            }
        }
        kf[d] = g->periodic[d] ? FFTW_R2HC : FFTW_REDFT10;
        kb[d] = g->periodic[d] ? FFTW_HC2R : FFTW_REDFT01;
        pl->sp.norm *= g->periodic[d] ? nd : 2.0 * nd;
    }
    gf_status st = ok ? spectral3_plan(ctx, &pl->sp, g->n, kf, kb, "poisson plan")
                      : GF_FAIL(ctx, GF_ERR_NOMEM, "poisson plan: out of memory for %zu cells", n);
    if (st != GF_OK) {
        gf_poisson_plan_destroy(&pl);
        return st;
    }
    *out = pl;
    return GF_OK;
}

void gf_poisson_plan_destroy(gf_poisson_plan **plan)
{
    if (!plan || !*plan)
        return;
    gf_poisson_plan *pl = *plan;
    spectral3_free(&pl->sp);
    free(pl->r);
    free(pl->z);
    free(pl->p);
    free(pl->q);
    free(pl);
    *plan = NULL;
}

gf_status gf_poisson_plan_set_threads(gf_ctx *ctx, gf_poisson_plan *pl, int n_threads)
{
    if (!transform3_plan(&pl->sp.tr, pl->sp.work, 1, n_threads))
        return GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "poisson plan: FFTW could not plan the slab transforms");
    return GF_OK;
}

int gf_poisson_plan_threads(const gf_poisson_plan *pl) { return pl ? pl->sp.tr.n_threads : 1; }

void gf_poisson_solve_const(gf_poisson_plan *pl, const double *rhs, double *phi)
{
    const gf_grid *g = pl->g;
    const int nt = pl->sp.tr.n_threads;
    memcpy(pl->sp.work, rhs, g->n_cells * sizeof(double));
    transform3_execute(&pl->sp.tr, pl->sp.work, 0);
    /* pointwise: the same values on any number of threads */
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static)
    for (int k = 0; k < g->n[2]; ++k)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i) {
                size_t c = gf_grid_cell(g, i, j, k);
                double lam = pl->sp.eig[0][i] + pl->sp.eig[1][j] + pl->sp.eig[2][k];
                pl->sp.work[c] = (i == 0 && j == 0 && k == 0) ? 0.0 : pl->sp.work[c] / (lam * pl->sp.norm);
            }
    transform3_execute(&pl->sp.tr, pl->sp.work, 1);
    memcpy(phi, pl->sp.work, g->n_cells * sizeof(double));
}

/* The neighbour index of cell index m along axis d in direction dir (0: -1,
 * 1: +1), wrapped on a periodic axis; -1 across a wall (zero flux). */
static int stencil_neighbour(const gf_grid *g, int d, int m, int dir)
{
    if (!g->periodic[d] && (dir ? m == g->n[d] - 1 : m == 0))
        return -1;
    return gf_grid_wrap(g, d, m + (dir ? 1 : -1));
}

/* y = div(a grad x) on the cells, one row along x at a time: the y and z
 * neighbour rows and face rows are found once per row, the x neighbours
 * wrap only at the row's ends. The terms are summed in the same order for
 * every cell (x-, x+, y-, y+, z-, z+), each a_f (x_nb - x_c)/h^2. */
void gf_poisson_apply_var(const gf_grid *g, const double *const a[3], const double *x, double *y)
{
    const int n0 = g->n[0];
    double ih2[3];
    for (int d = 0; d < 3; ++d)
        ih2[d] = 1.0 / (g->h_m[d] * g->h_m[d]);
    const int xm0 = stencil_neighbour(g, 0, 0, 0), xp_last = stencil_neighbour(g, 0, n0 - 1, 1);
    for (int k = 0; k < g->n[2]; ++k)
        for (int j = 0; j < g->n[1]; ++j) {
            const double *xr = x + gf_grid_cell(g, 0, j, k);
            const double *ax = a[0] + gf_grid_face(g, 0, 0, j, k);
            int nb[4] = {stencil_neighbour(g, 1, j, 0), stencil_neighbour(g, 1, j, 1), stencil_neighbour(g, 2, k, 0),
                         stencil_neighbour(g, 2, k, 1)};
            const double *xn[4], *an[4];
            for (int q = 0; q < 4; ++q) {
                int d = 1 + q / 2, dir = q % 2, jj = d == 1 ? nb[q] : j, kk = d == 2 ? nb[q] : k;
                int fj = d == 1 ? j + dir : j, fk = d == 2 ? k + dir : k;
                xn[q] = nb[q] < 0 ? NULL : x + gf_grid_cell(g, 0, jj, kk);
                an[q] = a[d] + gf_grid_face(g, d, 0, fj, fk);
            }
            double *yr = y + gf_grid_cell(g, 0, j, k);
            for (int i = 0; i < n0; ++i) {
                const double xc = xr[i];
                double s = 0.0;
                int im = i > 0 ? i - 1 : xm0, ip = i < n0 - 1 ? i + 1 : xp_last;
                if (im >= 0)
                    s += ax[i] * (xr[im] - xc) * ih2[0];
                if (ip >= 0)
                    s += ax[i + 1] * (xr[ip] - xc) * ih2[0];
                for (int q = 0; q < 4; ++q)
                    if (xn[q])
                        s += an[q][i] * (xn[q][i] - xc) * ih2[1 + q / 2];
                yr[i] = s;
            }
        }
}

static double dot(const double *a, const double *b, size_t n)
{
    double s = 0.0;
    for (size_t i = 0; i < n; ++i)
        s += a[i] * b[i];
    return s;
}

static void remove_mean(double *x, size_t n)
{
    double m = 0.0;
    for (size_t i = 0; i < n; ++i)
        m += x[i];
    m /= (double)n;
    for (size_t i = 0; i < n; ++i)
        x[i] -= m;
}

/* Mean face coefficient over the free (non-wall) faces: the preconditioner's constant. */
static double mean_coefficient(const gf_grid *g, const double *const a[3])
{
    double s = 0.0;
    size_t cnt = 0;
    for (int d = 0; d < 3; ++d)
        GF_GRID_FOR_FREE_FACES(g, d, fi, i, j, k) {
            s += a[d][fi];
            ++cnt;
        }
    return cnt ? s / (double)cnt : 1.0;
}

gf_status gf_poisson_solve_var(gf_poisson_plan *pl, const double *const a[3], const double *rhs, double *phi,
                               double rtol, int max_iter, gf_solve_stats *stats)
{
    const gf_grid *g = pl->g;
    size_t n = g->n_cells;
    double t0 = gf_wtime();
    double abar = mean_coefficient(g, a);
    double *r = pl->r, *z = pl->z, *p = pl->p, *q = pl->q;
    /* Solve B x = b with B = -div(a grad .), b = -rhs (mean-free): SPD on the mean-free subspace. */
    remove_mean(phi, n);
    gf_poisson_apply_var(g, a, phi, q);
    for (size_t c = 0; c < n; ++c)
        r[c] = -rhs[c];
    remove_mean(r, n);
    double bnorm = sqrt(dot(r, r, n));
    for (size_t c = 0; c < n; ++c)
        r[c] += q[c];  /* r = b - B phi = b + A phi */
    double rnorm = sqrt(dot(r, r, n));
    gf_solve_stats st = {0, rnorm, rnorm, 0.0};
    double tol = rtol * (bnorm > 0.0 ? bnorm : 1.0);
    double rz_old = 0.0;
    int it = 0;
    while (rnorm > tol && it < max_iter) {
        /* z = M^-1 r with M = -abar L */
        for (size_t c = 0; c < n; ++c)
            z[c] = -r[c] / abar;
        gf_poisson_solve_const(pl, z, z);
        double rz = dot(r, z, n);
        if (it == 0) {
            memcpy(p, z, n * sizeof(double));
        } else {
            double beta = rz / rz_old;
            for (size_t c = 0; c < n; ++c)
                p[c] = z[c] + beta * p[c];
        }
        rz_old = rz;
        gf_poisson_apply_var(g, a, p, q);
        double pq = -dot(p, q, n);  /* p.Bp */
        if (!(pq > 0.0))
            break;
        double alpha = rz / pq;
        for (size_t c = 0; c < n; ++c) {
            phi[c] += alpha * p[c];
            r[c] += alpha * q[c];  /* r -= alpha B p */
        }
        rnorm = sqrt(dot(r, r, n));
        ++it;
    }
    st.iterations = it;
    st.residual_final = rnorm;
    st.seconds = gf_wtime() - t0;
    if (stats)
        *stats = st;
    if (!isfinite(rnorm))
        return GF_FAIL(NULL, GF_ERR_NUMERIC, "poisson: non-finite residual");
    if (rnorm > tol)
        return GF_ERR_NOT_CONVERGED;
    return GF_OK;
}

/* --- Helmholtz (implicit viscosity) ------------------------------------------------------------ */

struct gf_helmholtz_plan {
    const gf_grid *g;
    int a;
    int len[3], off[3];   /* unknowns per axis and first face index */
    size_t n;
    spectral3 sp;
};

gf_status gf_helmholtz_plan_create(gf_ctx *ctx, const gf_grid *g, int a, gf_helmholtz_plan **out)
{
    *out = NULL;
    gf_helmholtz_plan *pl = calloc(1, sizeof *pl);
    if (!pl)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "helmholtz plan: out of memory");
    pl->g = g;
    pl->a = a;
    pl->sp.tr.n_threads = 1;
    pl->sp.norm = 1.0;
    pl->n = 1;
    fftw_r2r_kind kf[3], kb[3];
    for (int d = 0; d < 3; ++d) {
        int n = g->n[d];
        double h2 = g->h_m[d] * g->h_m[d];
        int len = n, off = 0;
        int walls = !g->periodic[d];
        if (d == a && walls) {
            len = n - 1;
            off = 1;
        }
        pl->len[d] = len;
        pl->off[d] = off;
        pl->n *= (size_t)(len > 0 ? len : 0);
        if (len <= 0)
            break;
        pl->sp.eig[d] = malloc((size_t)len * sizeof(double));
        if (!pl->sp.eig[d]) {
            gf_helmholtz_plan_destroy(&pl);
            return GF_FAIL(ctx, GF_ERR_NOMEM, "helmholtz plan: out of memory");
        }
        double shift = 0.0;  /* eigenvalue (2 cos(pi (m + shift)/N) - 2)/h^2 */
        int N = n;
        if (!walls) {
            kf[d] = FFTW_R2HC;
            kb[d] = FFTW_HC2R;
            pl->sp.norm *= n;
        } else if (d == a) {
            kf[d] = kb[d] = FFTW_RODFT00;
            shift = 1.0;
            pl->sp.norm *= 2.0 * n;
        } else {
            int ns_lo = g->bc[d][0] != GF_GRID_FREE_SLIP, ns_hi = g->bc[d][1] != GF_GRID_FREE_SLIP;
            if (ns_lo && ns_hi) {
                kf[d] = FFTW_RODFT10;
                kb[d] = FFTW_RODFT01;
                shift = 1.0;
            } else if (!ns_lo && !ns_hi) {
                kf[d] = FFTW_REDFT10;
                kb[d] = FFTW_REDFT01;
            } else {
                kf[d] = kb[d] = ns_lo ? FFTW_RODFT11 : FFTW_REDFT11;
                shift = 0.5;
            }
            pl->sp.norm *= 2.0 * n;
        }
        for (int m = 0; m < len; ++m) {
            double fr = m + shift;
            if (!walls) {
                fr = m <= n / 2 ? m : n - m;
                pl->sp.eig[d][m] = (2.0 * cos(2.0 * M_PI * fr / N) - 2.0) / h2;
            } else {
                pl->sp.eig[d][m] = (2.0 * cos(M_PI * fr / N) - 2.0) / h2;
            }
        }
    }
    char what[48];
    snprintf(what, sizeof what, "helmholtz plan of component %d", a);
    gf_status st = pl->n > 0 ? spectral3_plan(ctx, &pl->sp, pl->len, kf, kb, what) : GF_OK;
    if (st != GF_OK) {
        gf_helmholtz_plan_destroy(&pl);
        return st;
    }
    *out = pl;
    return GF_OK;
}

void gf_helmholtz_plan_destroy(gf_helmholtz_plan **plan)
{
    if (!plan || !*plan)
        return;
    gf_helmholtz_plan *pl = *plan;
    spectral3_free(&pl->sp);
    free(pl);
    *plan = NULL;
}

gf_status gf_helmholtz_plan_set_threads(gf_ctx *ctx, gf_helmholtz_plan *pl, int n_threads)
{
    if (pl->n == 0) {
        pl->sp.tr.n_threads = n_threads > 1 ? n_threads : 1;
        return GF_OK;
    }
    if (!transform3_plan(&pl->sp.tr, pl->sp.work, 1, n_threads))
        return GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "helmholtz plan: FFTW could not plan the slab transforms of "
                       "component %d", pl->a);
    return GF_OK;
}

/* The unknowns of plan pl, row by row, to and from the transform's work array (to_work: 1 gathers u). */
static void helmholtz_copy(const gf_helmholtz_plan *pl, double *u, int to_work)
{
    const gf_grid *g = pl->g;
#pragma omp parallel for num_threads(pl->sp.tr.n_threads) if (pl->sp.tr.n_threads > 1) schedule(static)
    for (int k = 0; k < pl->len[2]; ++k)
        for (int j = 0; j < pl->len[1]; ++j) {
            double *w = pl->sp.work + ((size_t)k * pl->len[1] + j) * pl->len[0];
            double *row = u + gf_grid_face(g, pl->a, pl->off[0], j + pl->off[1], k + pl->off[2]);
            if (to_work)
                memcpy(w, row, (size_t)pl->len[0] * sizeof(double));
            else
                memcpy(row, w, (size_t)pl->len[0] * sizeof(double));
        }
}

void gf_helmholtz_solve(gf_helmholtz_plan *pl, double c, double *u)
{
    if (pl->n == 0)
        return;
    helmholtz_copy(pl, u, 1);
    transform3_execute(&pl->sp.tr, pl->sp.work, 0);
#pragma omp parallel for num_threads(pl->sp.tr.n_threads) if (pl->sp.tr.n_threads > 1) schedule(static)
    for (int k = 0; k < pl->len[2]; ++k)
        for (int j = 0; j < pl->len[1]; ++j) {
            double *w = pl->sp.work + ((size_t)k * pl->len[1] + j) * pl->len[0];
            for (int i = 0; i < pl->len[0]; ++i)
                w[i] /= pl->sp.norm * (1.0 - c * (pl->sp.eig[0][i] + pl->sp.eig[1][j] + pl->sp.eig[2][k]));
        }
    transform3_execute(&pl->sp.tr, pl->sp.work, 1);
    helmholtz_copy(pl, u, 0);
    gf_grid_sync_periodic(pl->g, pl->a, u);
}
