/*
 * Buoyancy on a periodic incline (Izard 2014 (4.5)-(4.6): the seed's modified
 * gravity (4.6) may drop the downslope buoyancy). Set-up as an avalanche:
 * x downslope and periodic, y normal to the bed (no-slip floor with glued
 * grains, free-slip top), z periodic, gravity tilted by theta = 25 deg. The
 * form kept here is the physical tank: the fluid body force is NOT modified;
 * its weight, downslope part included, is balanced by the hydrostatic
 * pressure p_h = rho_f g.x, so a quiescent fluid stays at rest, and every
 * grain feels the full buoyancy -rho_f V g, downslope component included.
 * The coupling is created with vertical gravity and tilted with
 * gf_coupling_set_gravity, the path of the avalanche scene's start().
 * Checks, with grains held at rest in the quiescent fluid:
 *   - the fluid force on each grain is -rho_f V g in all three components
 *     (relative 1e-9): the seed's (4.6) would leave the downslope component
 *     at 0 (grains keep their full weight m g sin(theta) downslope);
 *   - the fluid stays at rest (|u| < 1e-12 m/s) and the excess pressure is
 *     zero (|p'| < 1e-9 Pa): no spurious downslope flow from the tilt.
 * (A settling sphere is not a clean check here: in a periodic layer the
 * grain's downslope drag sets the whole layer flowing, a real effect of the
 * periodic incline that a closed tank does not have.)
 */
#include "core/gf_rng.h"
#include "fluid_test_util.h"
#include "gf_test.h"

int main(void)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    double D = 5e-3, rp = 2500, rf = 1000, mu = 0.05, g = 9.81, th = 25.0 * M_PI / 180.0;
    spec_fluid(&spec, D, rp, rf, mu, "di_felice", 2.0);
    /* created with vertical gravity, tilted afterwards as the avalanche scene's start() does */
    gf_coupling_setup su = {.lo_m = {0, 0, 0}, .hi_m = {10 * D, 20 * D, 6 * D}, .gravity_m_s2 = {0, -g, 0}};
    su.bc[0][0] = su.bc[0][1] = su.bc[2][0] = su.bc[2][1] = GF_BC_PERIODIC;
    su.bc[1][0] = GF_BC_NO_SLIP;
    su.bc[1][1] = GF_BC_FREE_SLIP;
    coupled_loop L = {.g = {g * sin(th), -g * cos(th), 0}, .substeps = 10, .dt_f_max = 1e-3, .fixed = 1,
                      .periodic = {1, 0, 1}};
    for (int d = 0; d < 3; ++d) {
        L.lo[d] = su.lo_m[d];
        L.hi[d] = su.hi_m[d];
    }
    GF_CHECK_OK(gf_coupling_create(&ctx, &spec, &su, &L.c), &ctx);
    GF_CHECK_OK(gf_particles_create(&ctx, 256, &L.p), &ctx);
    GF_CHECK_OK(gf_coupling_set_gravity(L.c, L.g), &ctx);
    gf_rng rng;
    gf_rng_seed(&rng, 9);
    for (int i = 0; i < 10; ++i)  /* rough bed */
        for (int k = 0; k < 6; ++k)
            gf_particles_add(&ctx, L.p, (i + 0.5) * D, 0.0, (k + 0.5) * D, D / 2, rp, GF_P_GLUED, NULL);
    for (int n = 0; n < 60; ++n)  /* a loose layer of grains at rest */
        gf_particles_add(&ctx, L.p, gf_rng_range(&rng, 0, 10 * D), gf_rng_range(&rng, D, 6 * D),
                         gf_rng_range(&rng, 0, 6 * D), D / 2, rp, 0, NULL);
    for (int s = 0; s < 5; ++s)
        GF_CHECK_OK(loop_step(&L), &ctx);
    /* fluid force on the resting grains: add_forces into cleared accumulators */
    gf_particles_clear_forces(L.p);
    gf_coupling_set_dem_step(L.c, 1e-15);  /* phi1 -> 1: the physical force, not the exponential-step one */
    GF_CHECK_OK(gf_coupling_add_forces(L.c, L.p), &ctx);
    double worst = 0.0, fx = 0.0;
    for (size_t i = 0; i < L.p->n_local; ++i) {
        if (L.p->flags[i] & GF_P_GLUED)
            continue;
        double r = L.p->radius_m[i], V = 4.0 / 3.0 * M_PI * r * r * r;
        double want[3] = {-rf * V * L.g[0], -rf * V * L.g[1], 0.0};
        double got[3] = {L.p->fx_N[i], L.p->fy_N[i], L.p->fz_N[i]};
        for (int a = 0; a < 3; ++a)
            worst = fmax(worst, fabs(got[a] - want[a]) / (rf * V * g));
        fx = got[0] / (rf * V * g * sin(th));
    }
    int n[3];
    double lo[3], h[3];
    const gf_var_info *vars;
    const double *const *f;
    int nv = gf_coupling_fields(L.c, n, lo, h, &vars, &f);
    double umax = 0.0, pmax = 0.0;
    for (int v = 0; v < nv; ++v)
        for (long i = 0; i < (long)n[0] * n[1] * n[2]; ++i) {
            if (v >= 1 && v <= 3)
                umax = fmax(umax, fabs(f[v][i]));
            if (v == 4)
                pmax = fmax(pmax, fabs(f[v][i]));
        }
    printf("incline 25 deg: max |F - (-rho_f V g)| / (rho_f V g) = %.2e, downslope force / (rho_f V g sin theta) = "
           "%.6f (seed (4.6): 0); fluid max |u| %.2e m/s, max |p'| %.2e Pa\n", worst, fx, umax, pmax);
    GF_CHECK(worst < 1e-9);
    GF_CHECK(umax < 1e-12);
    GF_CHECK(pmax < 1e-9);
    gf_coupling_destroy(&L.c);
    gf_particles_destroy(&L.p);
    return gf_test_finish();
}
