/*
 * The immersed boundary of the resolved tier (coupling/gf_ibm.h) on its own:
 *  - the smoothed solid fraction integrates to the sphere's volume, the
 *    error shrinking as dx^2 (the tanh shell of width ~0.6 dx adds a
 *    volume ~ pi^2 (w/2)^2 / R^2 V, the Fermi-function integral): error ratio
 *    between R = 4 dx and R = 8 dx within [3, 5];
 *  - with the fluid at rest (u~ = 0), a sphere translating at v feels
 *    F = -(rho rho_p/(rho_p - rho)) V v / dt and one spinning at w about z
 *    feels T_z = -(rho rho_p/(rho_p - rho)) (8 pi R^5 / 15) w / dt (Izard 2014
 *    eqs. (2.32)-(2.33) with the sphere's volume and the moment of its volume)
 *    times the shell's excess: the Fermi-function expansion of the tanh
 *    profile, int g(r) f(r) dr = int_0^R g + (pi^2 a^2/6) g'(R), gives the
 *    volume 1 + pi^2 a^2/R^2 and the moment int r^4 1 + (10/3) pi^2 a^2/R^2, so
 *    (F/F_ref - 1) = (V_alpha/V - 1) within 2 % and (T/T_ref - 1) = 10/3 of it
 *    within 10 %: signs (the force opposes the motion) and factors.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "coupling/gf_ibm.h"
#include "gf_test.h"

typedef struct result {
    double vol_ratio, F_ratio, T_ratio;
} result;

static result run(int R_cells)
{
    gf_ctx ctx = {0};
    const double h = 1e-3, R = R_cells * h, rho_f = 1000.0, rho_p = 2500.0, dt = 1e-3;
    int n = 2 * R_cells + 16;
    int nn[3] = {n, n, n};
    double lo[3] = {0, 0, 0}, hi[3] = {n * h, n * h, n * h};
    gf_grid_bc bc[3][2] = {{GF_GRID_FREE_SLIP, GF_GRID_FREE_SLIP},
                           {GF_GRID_FREE_SLIP, GF_GRID_FREE_SLIP},
                           {GF_GRID_FREE_SLIP, GF_GRID_FREE_SLIP}};
    gf_grid g;
    result r = {NAN, NAN, NAN};
    GF_CHECK_OK(gf_grid_init(&ctx, &g, nn, lo, hi, bc), &ctx);
    gf_particles *p = NULL;
    GF_CHECK_OK(gf_particles_create(&ctx, 4, &p), &ctx);
    /* off the grid's symmetry points, so no face pattern is special */
    GF_CHECK_OK(gf_particles_add(&ctx, p, 0.5 * n * h + 0.23 * h, 0.5 * n * h - 0.31 * h, 0.5 * n * h + 0.07 * h, R,
                                 rho_p, 0, NULL), &ctx);
    gf_ibm_map m = {0};
    GF_CHECK_OK(gf_ibm_build(&ctx, &m, &g, p), &ctx);
    double *up[3], *force[3], *as[3], *aU[3];
    for (int a = 0; a < 3; ++a) {
        up[a] = calloc(g.n_faces[a], sizeof(double));
        force[a] = calloc(g.n_faces[a], sizeof(double));
        as[a] = calloc(g.n_faces[a], sizeof(double));
        aU[a] = calloc(g.n_faces[a], sizeof(double));
    }
    double F[3], T[3], V = 4.0 / 3.0 * M_PI * R * R * R, factor = -rho_f * rho_p / (rho_p - rho_f) / dt;
    /* translation along x */
    p->vx_m_s[0] = 0.1;
    gf_ibm_force(&m, &g, p, (const double *const *)up, dt, rho_f, force, as, aU, F, T);
    double vol = 0.0;
    for (size_t q = 0; q < g.n_faces[0]; ++q)
        vol += as[0][q] * h * h * h;
    r.vol_ratio = vol / V;
    r.F_ratio = F[0] / (factor * V * 0.1);
    /* rotation about z */
    p->vx_m_s[0] = 0.0;
    p->wz_rad_s[0] = 10.0;
    gf_ibm_force(&m, &g, p, (const double *const *)up, dt, rho_f, force, as, aU, F, T);
    r.T_ratio = T[2] / (factor * 8.0 * M_PI * pow(R, 5) / 15.0 * 10.0);
    printf("R = %d dx: solid volume / V = %.5f, F / F_ref = %.4f, T_z / T_ref = %.4f (F_y %.2g, T_x %.2g)\n", R_cells,
           r.vol_ratio, r.F_ratio, r.T_ratio, F[1], T[0]);
    for (int a = 0; a < 3; ++a)
        free(up[a]), free(force[a]), free(as[a]), free(aU[a]);
    gf_ibm_free(&m);
    gf_particles_destroy(&p);
    return r;
}

int main(void)
{
    result c = run(4), f = run(8);
    double order_ratio = (c.vol_ratio - 1.0) / (f.vol_ratio - 1.0);
    printf("volume error ratio R = 4 dx / R = 8 dx: %.3f (second order: 4)\n", order_ratio);
    GF_CHECK(order_ratio > 3.0 && order_ratio < 5.0);
    const result *rs[2] = {&c, &f};
    for (int k = 0; k < 2; ++k) {
        double ev = rs[k]->vol_ratio - 1.0;
        printf("R = %d dx: (F/F_ref - 1)/(V_alpha/V - 1) = %.4f (1), (T/T_ref - 1)/(V_alpha/V - 1) = %.4f (10/3)\n",
               4 << k, (rs[k]->F_ratio - 1.0) / ev, (rs[k]->T_ratio - 1.0) / ev);
        GF_CHECK(rs[k]->F_ratio > 1.0 && rs[k]->T_ratio > 1.0); /* against the motion, as the excess says */
        GF_CHECK_REL((rs[k]->F_ratio - 1.0) / ev, 1.0, 0.02);
        GF_CHECK_REL((rs[k]->T_ratio - 1.0) / ev, 10.0 / 3.0, 0.10);
    }
    return gf_test_finish();
}
