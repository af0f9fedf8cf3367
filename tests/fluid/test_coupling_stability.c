/*
 * Numerical stability of the coupled step.
 *  1. A fluid step past the advective stability limit (CFL number > 1 for the
 *     explicit upwind advection) is refused with GF_ERR_NUMERIC and a message
 *     naming the limit and the admissible step; the fluid state stays finite.
 *  2. A step that lets grains jump more than a cell is refused the same way.
 *  3. Stiff drag adapts instead of failing: a small-St grain (particle
 *     response time m/K = 1e-3 of the DEM substep, x = K dt_s/m = 1000)
 *     integrated with ONE explicit substep per fluid step still reaches its
 *     Stokes terminal velocity (exponential drag update, gf_coupling_add_forces):
 *     within 3 %, never NaN. An explicit drag update would diverge at x > 2.
 *  4. gf_coupling_dt_max_s is positive and finite at rest (the step loop
 *     sizes its substep count from it before anything moves).
 */
#include <string.h>

#include "fluid_test_util.h"
#include "gf_test.h"

static void make(coupled_loop *L, gf_ctx *ctx, double D, double rp, double rf, double mu, int n)
{
    gf_run_spec spec;
    spec_fluid(&spec, D, rp, rf, mu, "tenneti", 2.5);
    gf_coupling_setup su = {.gravity_m_s2 = {0, 0, -9.81}};
    memset(L, 0, sizeof *L);
    L->g[2] = -9.81;
    L->substeps = 1;
    L->dt_f_max = 1.0;
    for (int d = 0; d < 3; ++d) {
        su.hi_m[d] = L->hi[d] = n * 2.5 * D;
        su.bc[d][0] = su.bc[d][1] = GF_BC_PERIODIC;
        L->periodic[d] = 1;
    }
    GF_CHECK_OK(gf_coupling_create(ctx, &spec, &su, &L->c), ctx);
    GF_CHECK_OK(gf_particles_create(ctx, 4, &L->p), ctx);
    GF_CHECK_OK(gf_particles_add(ctx, L->p, 0.4 * su.hi_m[0], 0.6 * su.hi_m[1], 0.5 * su.hi_m[2], D / 2, rp, 0, NULL),
                ctx);
}

static int fields_finite(const gf_coupling *c)
{
    int n[3];
    double lo[3], h[3];
    const gf_var_info *vars;
    const double *const *f;
    int nv = gf_coupling_fields(c, n, lo, h, &vars, &f);
    for (int v = 0; v < nv; ++v)
        for (long i = 0; i < (long)n[0] * n[1] * n[2]; ++i)
            if (!isfinite(f[v][i]))
                return 0;
    return 1;
}

int main(void)
{
    gf_ctx ctx = {0};
    coupled_loop L;
    /* a sphere settling at Re ~ 20 (Izard 2014 §2.2.3): fast enough for the CFL to bind */
    double D = 1e-3, rf = 1000, rp = 4000, mu = sqrt(rf * 3000 * 9.81 * 1e-9 / 800.0);
    make(&L, &ctx, D, rp, rf, mu, 16);
    double dt0 = gf_coupling_dt_max_s(L.c, L.p);
    printf("dt_max at rest: %.3g s\n", dt0);
    GF_CHECK(dt0 > 0.0 && isfinite(dt0));
    for (int s = 0; s < 30; ++s)
        GF_CHECK_OK(loop_step(&L), &ctx);
    double dtm = gf_coupling_dt_max_s(L.c, L.p);
    gf_status st = gf_coupling_fluid_step(L.c, L.p, 50.0 * dtm);
    printf("step of 50 dt_max (%.3g s): %s: %s\n", 50 * dtm, gf_status_str(st), ctx.last_msg);
    GF_CHECK(st == GF_ERR_NUMERIC);
    GF_CHECK(strstr(ctx.last_msg, "CFL") != NULL || strstr(ctx.last_msg, "cells") != NULL);
    GF_CHECK(fields_finite(L.c));
    /* grains jumping cells: a fast grain in a fluid at rest */
    gf_coupling_destroy(&L.c);
    gf_particles_destroy(&L.p);
    make(&L, &ctx, D, rp, rf, mu, 16);
    L.p->vz_m_s[0] = -10.0;
    gf_ctx_clear(&ctx);
    st = gf_coupling_fluid_step(L.c, L.p, 0.01);
    printf("grain at 10 m/s, dt 0.01 s: %s: %s\n", gf_status_str(st), ctx.last_msg);
    GF_CHECK(st == GF_ERR_NUMERIC && strstr(ctx.last_msg, "cells") != NULL);
    gf_coupling_destroy(&L.c);
    gf_particles_destroy(&L.p);

    /* stiff drag: tiny grain in a viscous fluid, one substep per fluid step */
    double d2 = 1e-4, mu2 = 1.0, rp2 = 2500;
    make(&L, &ctx, d2, rp2, rf, mu2, 16);
    double m = L.p->mass_kg[0], K = 3 * M_PI * mu2 * d2;
    double tau = m / K;
    L.dt_f_max = 1000 * tau;
    for (int s = 0; s < 60; ++s) {
        st = loop_step(&L);
        if (st != GF_OK) {
            GF_CHECK_OK(st, &ctx);
            break;
        }
    }
    double uf[3];
    gf_coupling_mean_fluid_velocity(L.c, uf);
    double w = uf[2] - L.p->vz_m_s[0];
    double ust = (rp2 - rf) * 9.81 * d2 * d2 / (18 * mu2);
    double c = M_PI * d2 * d2 * d2 / 6 / pow(16 * 2.5 * d2, 3);
    double uref = ust * (1 - 1.7601 * cbrt(c) + c);
    printf("stiff drag: dt_f = %.3g s = %.0f tau_p, slip %.5g m/s vs Stokes-Hasimoto %.5g (%+.2f %%)\n", L.dt_f_max,
           L.dt_f_max / tau, w, uref, 100 * (w / uref - 1));
    GF_CHECK(isfinite(w));
    GF_CHECK_REL(w, uref, 0.03);
    gf_coupling_destroy(&L.c);
    gf_particles_destroy(&L.p);
    return gf_test_finish();
}
