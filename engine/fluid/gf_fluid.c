/* Allocation and checks of the fluid state; the steps are in gf_advect.c, gf_viscous.c, gf_project.c. */
#include "fluid/gf_fluid.h"

#include <math.h>
#include <stdlib.h>

gf_status gf_fluid_create(gf_ctx *ctx, const gf_fluid_params *prm, gf_fluid **out)
{
    *out = NULL;
    if (!(prm->density_kg_m3 > 0.0) || !(prm->viscosity_Pa_s > 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid: density (%g kg/m3) and viscosity (%g Pa s) must be > 0",
                       prm->density_kg_m3, prm->viscosity_Pa_s);
    gf_fluid *f = calloc(1, sizeof *f);
    if (!f)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "fluid: out of memory");
    gf_status st = gf_grid_init(ctx, &f->grid, prm->n_cells, prm->lo_m, prm->hi_m, prm->bc);
    if (st != GF_OK) {
        free(f);
        return st;
    }
    const gf_grid *g = &f->grid;
    f->rho_kg_m3 = prm->density_kg_m3;
    f->mu_Pa_s = prm->viscosity_Pa_s;
    f->poisson_rtol = prm->poisson_rtol > 0.0 ? prm->poisson_rtol : 1e-10;
    int ok = 1;
    size_t nc = g->n_cells;
    for (int a = 0; a < 3; ++a) {
        ok &= (f->u[a] = calloc(g->n_faces[a], sizeof(double))) != NULL;
        ok &= (f->work[a] = calloc(g->n_faces[a], sizeof(double))) != NULL;
        ok &= (f->flux[a] = calloc(g->n_faces[a], sizeof(double))) != NULL;
        ok &= (f->a_face[a] = calloc(g->n_faces[a], sizeof(double))) != NULL;
        ok &= (f->beta_v[a] = calloc(nc, sizeof(double))) != NULL;
        ok &= (f->body[a] = calloc(nc, sizeof(double))) != NULL;
    }
    size_t nmax = nc;  /* scratch serves cell and face arrays alike */
    for (int a = 0; a < 3; ++a)
        nmax = g->n_faces[a] > nmax ? g->n_faces[a] : nmax;
    for (int t = 0; t < 4; ++t)
        ok &= (f->tmp[t] = calloc(nmax, sizeof(double))) != NULL;
    ok &= (f->p_Pa = calloc(nc, sizeof(double))) != NULL;
    ok &= (f->eps = calloc(nc, sizeof(double))) != NULL;
    ok &= (f->eps_old = calloc(nc, sizeof(double))) != NULL;
    ok &= (f->beta = calloc(nc, sizeof(double))) != NULL;
    if (!ok) {
        gf_fluid_destroy(&f);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "fluid: out of memory for %zu cells", nc);
    }
    for (size_t c = 0; c < nc; ++c)
        f->eps[c] = f->eps_old[c] = 1.0;
    st = gf_poisson_plan_create(ctx, &f->grid, &f->poisson);
    for (int a = 0; a < 3 && st == GF_OK; ++a)
        st = gf_helmholtz_plan_create(ctx, &f->grid, a, &f->visc[a]);
    if (st != GF_OK) {
        gf_fluid_destroy(&f);
        return st;
    }
    *out = f;
    return GF_OK;
}

void gf_fluid_destroy(gf_fluid **pf)
{
    if (!pf || !*pf)
        return;
    gf_fluid *f = *pf;
    gf_poisson_plan_destroy(&f->poisson);
    for (int a = 0; a < 3; ++a)
        gf_helmholtz_plan_destroy(&f->visc[a]);
    for (int a = 0; a < 3; ++a) {
        free(f->u[a]);
        free(f->work[a]);
        free(f->flux[a]);
        free(f->a_face[a]);
        free(f->beta_v[a]);
        free(f->body[a]);
    }
    for (int t = 0; t < 4; ++t)
        free(f->tmp[t]);
    free(f->p_Pa);
    free(f->eps);
    free(f->eps_old);
    free(f->beta);
    free(f);
    *pf = NULL;
}

double gf_fluid_max_speed(const gf_fluid *f)
{
    double m = 0.0;
    for (int a = 0; a < 3; ++a)
        for (size_t i = 0; i < f->grid.n_faces[a]; ++i)
            if (fabs(f->u[a][i]) > m)
                m = fabs(f->u[a][i]);
    return m;
}

int gf_fluid_nonfinite(const gf_fluid *f)
{
    for (int a = 0; a < 3; ++a)
        for (size_t i = 0; i < f->grid.n_faces[a]; ++i)
            if (!isfinite(f->u[a][i]))
                return 1;
    for (size_t c = 0; c < f->grid.n_cells; ++c)
        if (!isfinite(f->p_Pa[c]))
            return 1;
    return 0;
}
