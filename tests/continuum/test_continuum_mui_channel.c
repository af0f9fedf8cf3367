/*
 * Fully developed mu(I) channel (periodic along x, body force G, no gravity)
 * against the semi-analytic Poiseuille flow of Djouwe Meffeja 2012, §5.4,
 * eq. (5.18), which is the flow of the rate part (mu(I) - mu_s) P/|gdot| of the
 * law (gf_mui_oracles.h). Lambda = 20, constants 0.381/0.643/0.279.
 * Criteria: beta = 0.5: max |u - u_exact| / U_max over ny = 16, 32, 64,
 * observed order >= 1.8 and <= 1e-3 at ny = 64; beta = 0.65 (steep wall
 * layer): <= 1e-3 at ny = 128; beta = 0.02: U_max within 1e-3 of the Newtonian
 * limit beta Lambda I0/(8 dmu). The full law (yield stress mu_s P0) does not
 * flow at all in this channel: the wall stress G H/2 = beta^2 P0/2 < mu_s P0 for
 * every beta < beta_max; only the regularisation's creep (gdot_min) remains.
 * The thesis' approximation (4.8), eta lap(u), is run on the same channel and
 * its error printed (a figure of docs/continuum.md, not a criterion).
 * The 3-D code on the same channel (periodic z) reproduces the 2-D profile.
 * Bad input is refused: mu_2 <= mu_s, I0 <= 0, a grid too coarse for the walls.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "continuum/gf_mui_oracles.h"
#include "continuum_channel.h"
#include "gf_test.h"

/* max over cells of |u - u_exact| / U_max_exact, and the largest u. */
static double channel_error_form(int ny, double beta, gf_rheology rh, int laplacian_form, double *umax_out)
{
    gf_ctx ctx = {0};
    gf_mui_params law = gf_mui_thesis_maxima();
    double Lambda = 20.0;
    gf_continuum_params p = channel_mui(ny, beta, Lambda, law, rh);
    p.laplacian_form = laplacian_form;
    gf_continuum *s = NULL;
    GF_CHECK_OK(gf_continuum_create(&ctx, &p, &s), &ctx);
    if (!s)
        return NAN;
    double change = 0.0;
    GF_CHECK_OK(gf_continuum_run(s, 5000.0, 1e-13, &change), &ctx);
    GF_CHECK(change <= 1e-13);
    const gf_grid *g = gf_continuum_grid(s);
    const double *u = gf_continuum_velocity(s, 0);
    double Ue = beta * gf_poiseuille_umax(&law, beta, Lambda), worst = 0.0, umax = 0.0;
    for (int j = 0; j < ny; ++j) {
        double y = (j + 0.5) / ny, uh = u[gf_grid_face(g, 0, 1, j, 0)];
        worst = fmax(worst, fabs(uh - beta * gf_poiseuille_velocity(&law, beta, Lambda, y)));
        umax = fmax(umax, uh);
    }
    if (umax_out)
        *umax_out = umax;
    printf("beta = %.2f ny = %3d %s%s: max|u - u_exact|/U_max = %.3e, U_max %.6f (exact %.6f), t = %.0f\n", beta, ny,
           rh == GF_RHEOLOGY_MU_I ? "full law" : "rate part", laplacian_form ? ", eta lap(u) (4.8)" : "", worst / Ue, umax,
           Ue, gf_continuum_time(s));
    gf_continuum_destroy(&s);
    return worst / Ue;
}

static double channel_error(int ny, double beta, gf_rheology rh, double *umax_out)
{
    return channel_error_form(ny, beta, rh, 0, umax_out);
}

/* The same channel in 3-D (four periodic cells along z, w solved): the 3-D code must give the 2-D profile. */
static void three_d_matches_two_d(void)
{
    gf_ctx ctx = {0};
    gf_mui_params law = gf_mui_thesis_maxima();
    double u_2d[32] = {0}, worst = 0.0;
    for (int dim = 2; dim <= 3; ++dim) {
        gf_continuum_params p = channel_mui(32, 0.5, 20.0, law, GF_RHEOLOGY_MU_I_RATE_PART);
        if (dim == 3) {
            p.n[2] = 4;
            p.length_m[2] = p.length_m[0];
        }
        gf_continuum *s = NULL;
        GF_CHECK_OK(gf_continuum_create(&ctx, &p, &s), &ctx);
        if (!s)
            return;
        GF_CHECK_OK(gf_continuum_run(s, 5000.0, 1e-13, NULL), &ctx);
        const gf_grid *g = gf_continuum_grid(s);
        const double *u = gf_continuum_velocity(s, 0);
        for (int j = 0; j < 32; ++j) {
            double uh = u[gf_grid_face(g, 0, 1, j, g->n[2] - 1)];
            if (dim == 2)
                u_2d[j] = uh;
            else
                worst = fmax(worst, fabs(uh - u_2d[j]));
        }
        if (dim == 3) {
            const double *w = gf_continuum_velocity(s, 2);
            double wmax = 0.0;
            for (size_t q = 0; q < g->n_faces[2]; ++q)
                wmax = fmax(wmax, fabs(w[q]));
            GF_CHECK(wmax < 1e-12);
        }
        gf_continuum_destroy(&s);
    }
    printf("3-D against 2-D channel: max |u_3d - u_2d| = %.2e\n", worst);
    GF_CHECK(worst < 1e-10);
}

static void refusals(void)
{
    gf_ctx ctx = {0};
    gf_continuum *s = NULL;
    gf_continuum_params p = channel_mui(32, 0.5, 20.0, gf_mui_thesis_maxima(), GF_RHEOLOGY_MU_I);
    p.mui.law.mu_2 = p.mui.law.mu_s;
    GF_CHECK(gf_continuum_create(&ctx, &p, &s) == GF_ERR_CONFIG && !s);
    GF_CHECK(strstr(ctx.last_msg, "mu_2 must be > mu_s") != NULL);
    p = channel_mui(32, 0.5, 20.0, gf_mui_thesis_maxima(), GF_RHEOLOGY_MU_I);
    p.mui.law.I0 = -0.1;
    GF_CHECK(gf_continuum_create(&ctx, &p, &s) == GF_ERR_CONFIG && !s);
    GF_CHECK(strstr(ctx.last_msg, "I0 must be > 0") != NULL);
    p = channel_mui(6, 0.5, 20.0, gf_mui_thesis_maxima(), GF_RHEOLOGY_MU_I);
    GF_CHECK(gf_continuum_create(&ctx, &p, &s) == GF_ERR_CONFIG && !s);
    GF_CHECK(strstr(ctx.last_msg, "too coarse") != NULL);
    printf("refused: %s\n", ctx.last_msg);
}

int main(void)
{
    const int grids[3] = {16, 32, 64};
    double err[3];
    for (int k = 0; k < 3; ++k)
        err[k] = channel_error(grids[k], 0.5, GF_RHEOLOGY_MU_I_RATE_PART, NULL);
    for (int k = 1; k < 3; ++k) {
        double order = log(err[k - 1] / err[k]) / log(2.0);
        printf("observed order %d -> %d: %.3f\n", grids[k - 1], grids[k], order);
        GF_CHECK(order >= 1.8);
    }
    GF_CHECK(err[2] <= 1e-3);
    GF_CHECK(channel_error(128, 0.65, GF_RHEOLOGY_MU_I_RATE_PART, NULL) <= 1e-3);
    double umax = 0.0;
    gf_mui_params law = gf_mui_thesis_maxima();
    channel_error(64, 0.02, GF_RHEOLOGY_MU_I_RATE_PART, &umax);
    GF_CHECK_REL(umax / 0.02, gf_poiseuille_umax_newtonian(&law, 0.02, 20.0), 1e-3);
    channel_error(32, 0.5, GF_RHEOLOGY_MU_I, &umax);
    printf("full law, beta = 0.5: U_max = %.3e (creep of gdot_min = 1e-5 1/s over H = 1)\n", umax);
    GF_CHECK(umax < 1e-4 * 0.5 * gf_poiseuille_umax(&law, 0.5, 20.0));
    /* The thesis' approximation (4.8) on the same channel: reported, not a criterion (it is what
     * Djouwe Meffeja 2012, §4.5.2 asks about). */
    for (double beta = 0.02; beta < 0.7; beta += 0.21)
        channel_error_form(64, beta, GF_RHEOLOGY_MU_I_RATE_PART, 1, NULL);
    three_d_matches_two_d();
    refusals();
    return gf_test_finish();
}
