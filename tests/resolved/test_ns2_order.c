/*
 * The resolved tier's fluid step (fluid/gf_fluid_ns2.h: AB2 or RK3 for the
 * advection, Crank-Nicolson viscosity, incremental projection; the advective
 * or the divergence form) is second order in space and time: the decaying
 * Taylor-Green vortex (Taylor & Green, Proc. R. Soc. A 158, 1937) at Re = 100
 * to t = 1, with dt proportional to h (dt = 0.4 h, an advective CFL of 0.4),
 * on 16^2, 32^2 and 64^2 cells: the relative velocity error falls by 4 per
 * halving (order 2 +- 0.25 between each pair of grids), for each of the four
 * combinations.
 */
#include <math.h>
#include <stdio.h>

#include "fluid/gf_fluid_exact.h"
#include "gf_test.h"

static void check_order(gf_ns2_scheme scheme, gf_ns2_advection form)
{
    const int n[3] = {16, 32, 64};
    const char *label = scheme == GF_NS2_RK3 ? "RK3/CN" : "AB2/CN";
    const char *flabel = form == GF_NS2_DIVERGENCE ? "divergence" : "advective";
    double e[3], h[3];
    for (int k = 0; k < 3; ++k) {
        gf_ctx ctx = {0};
        double hk = 2.0 * M_PI / n[k];
        gf_fluid_exact_case c = {.problem = GF_EXACT_TAYLOR_GREEN, .n = n[k], .dt = 0.4 * hk, .t_end = 1.0,
                                 .re = 100.0, .scheme = scheme, .advection = form};
        gf_fluid_exact_result r;
        GF_CHECK_OK(gf_fluid_exact_run_ns2(&ctx, &c, &r), &ctx);
        e[k] = r.err_rms, h[k] = r.h;
        printf("Taylor-Green Re 100, %s, %s form: %d^2 cells, %ld steps: rms error %.4e, max %.4e\n", label, flabel,
               n[k], r.steps, r.err_rms, r.err_max);
    }
    for (int k = 0; k < 2; ++k) {
        double p = gf_fluid_exact_order(e[k], e[k + 1], h[k], h[k + 1]);
        printf("order %d -> %d: %.3f\n", n[k], n[k + 1], p);
        GF_CHECK_ABS(p, 2.0, 0.25);
    }
}

int main(void)
{
    for (int s = 0; s < 2; ++s)
        for (int a = 0; a < 2; ++a)
            check_order(s ? GF_NS2_RK3 : GF_NS2_AB2, a ? GF_NS2_DIVERGENCE : GF_NS2_ADVECTIVE);
    return gf_test_finish();
}
