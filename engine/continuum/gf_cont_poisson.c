/* Poisson solve by real-to-real transforms, one kind per axis; see gf_cont_poisson.h. */
#include "continuum/gf_cont_poisson.h"

#include <fftw3.h>
#include <math.h>
#include <stdlib.h>

struct gf_cont_poisson {
    int n[3];
    size_t n_cells;
    double *work, *inv_eig;  /* inv_eig: 1/(sum of eigenvalues * normalisation), 0 for the null mode */
    fftw_plan fwd, bwd;
};

typedef struct axis_kind {
    fftw_r2r_kind fwd, bwd;
    double norm;  /* the forward-backward pair multiplies by norm */
} axis_kind;

static axis_kind kind_of(const gf_cont_poisson_side s[2], int n)
{
    if (s[0] == GF_POISSON_PERIODIC)
        return (axis_kind){FFTW_R2HC, FFTW_HC2R, n};
    if (s[0] == GF_POISSON_NEUMANN && s[1] == GF_POISSON_NEUMANN)
        return (axis_kind){FFTW_REDFT10, FFTW_REDFT01, 2.0 * n};
    if (s[0] == GF_POISSON_NEUMANN)
        return (axis_kind){FFTW_REDFT11, FFTW_REDFT11, 2.0 * n};
    if (s[1] == GF_POISSON_NEUMANN)
        return (axis_kind){FFTW_RODFT11, FFTW_RODFT11, 2.0 * n};
    return (axis_kind){FFTW_RODFT10, FFTW_RODFT01, 2.0 * n};
}

/* Eigenvalue of the 3-point Laplacian (times h^2) for transform index k. */
static double eigen_h2(const gf_cont_poisson_side s[2], int n, int k)
{
    double theta;
    if (s[0] == GF_POISSON_PERIODIC)
        theta = 2.0 * M_PI * (k <= n / 2 ? k : n - k) / n;
    else if (s[0] == GF_POISSON_NEUMANN && s[1] == GF_POISSON_NEUMANN)
        theta = M_PI * k / n;
    else if (s[0] != s[1])
        theta = M_PI * (k + 0.5) / n;
    else
        theta = M_PI * (k + 1.0) / n;
    return 2.0 * cos(theta) - 2.0;
}

gf_status gf_cont_poisson_create(gf_ctx *ctx, const int n[3], const double h_m[3],
                                 const gf_cont_poisson_side side[3][2], gf_cont_poisson **out)
{
    *out = NULL;
    for (int d = 0; d < 3; ++d)
        if (n[d] < 1 || !(h_m[d] > 0.0) || ((side[d][0] == GF_POISSON_PERIODIC) != (side[d][1] == GF_POISSON_PERIODIC)))
            return GF_FAIL(ctx, GF_ERR_ARG, "continuum poisson: bad axis %d (n = %d, h = %g)", d, n[d], h_m[d]);
    gf_cont_poisson *pl = calloc(1, sizeof *pl);
    if (!pl)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "continuum poisson: plan");
    pl->n_cells = (size_t)n[0] * n[1] * n[2];
    for (int d = 0; d < 3; ++d)
        pl->n[d] = n[d];
    pl->work = fftw_malloc(pl->n_cells * sizeof(double));
    pl->inv_eig = malloc(pl->n_cells * sizeof(double));
    if (!pl->work || !pl->inv_eig) {
        gf_cont_poisson_destroy(&pl);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "continuum poisson: %zu cells", pl ? pl->n_cells : 0);
    }
    axis_kind k[3];
    double norm = 1.0;
    for (int d = 0; d < 3; ++d) {
        k[d] = kind_of(side[d], n[d]);
        norm *= k[d].norm;
    }
    for (int kz = 0; kz < n[2]; ++kz)
        for (int ky = 0; ky < n[1]; ++ky)
            for (int kx = 0; kx < n[0]; ++kx) {
                double lam = eigen_h2(side[0], n[0], kx) / (h_m[0] * h_m[0]) +
                             eigen_h2(side[1], n[1], ky) / (h_m[1] * h_m[1]) +
                             eigen_h2(side[2], n[2], kz) / (h_m[2] * h_m[2]);
                size_t c = (size_t)kx + (size_t)n[0] * ((size_t)ky + (size_t)n[1] * kz);
                pl->inv_eig[c] = lam != 0.0 ? 1.0 / (lam * norm) : 0.0;
            }
    /* FFTW is row-major (last index fastest): the storage's x-fastest order is dims {nz, ny, nx}. */
    int dims[3] = {n[2], n[1], n[0]};
    fftw_r2r_kind kf[3] = {k[2].fwd, k[1].fwd, k[0].fwd}, kb[3] = {k[2].bwd, k[1].bwd, k[0].bwd};
    pl->fwd = fftw_plan_r2r(3, dims, pl->work, pl->work, kf, FFTW_ESTIMATE);
    pl->bwd = fftw_plan_r2r(3, dims, pl->work, pl->work, kb, FFTW_ESTIMATE);
    if (!pl->fwd || !pl->bwd) {
        gf_cont_poisson_destroy(&pl);
        return GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "continuum poisson: FFTW could not plan");
    }
    *out = pl;
    return GF_OK;
}

void gf_cont_poisson_destroy(gf_cont_poisson **plan)
{
    if (!plan || !*plan)
        return;
    gf_cont_poisson *pl = *plan;
    if (pl->fwd)
        fftw_destroy_plan(pl->fwd);
    if (pl->bwd)
        fftw_destroy_plan(pl->bwd);
    fftw_free(pl->work);
    free(pl->inv_eig);
    free(pl);
    *plan = NULL;
}

void gf_cont_poisson_solve(gf_cont_poisson *pl, const double *rhs, double *p)
{
    for (size_t c = 0; c < pl->n_cells; ++c)
        pl->work[c] = rhs[c];
    fftw_execute(pl->fwd);
    for (size_t c = 0; c < pl->n_cells; ++c)
        pl->work[c] *= pl->inv_eig[c];
    fftw_execute(pl->bwd);
    for (size_t c = 0; c < pl->n_cells; ++c)
        p[c] = pl->work[c];
}
