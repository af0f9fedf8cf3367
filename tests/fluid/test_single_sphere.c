/*
 * Single sphere settling in a large periodic box, unresolved coupling
 * (cells of 2.5 D, kernel sigma = 2.5 D), drag closure tenneti (its isolated
 * limit is Schiller–Naumann, C_D = 24/Re (1 + 0.15 Re^0.687)).
 *
 *  stokes: Re_t ~ 0.01. Reference: Stokes U = drho g D^2/(18 eta) corrected
 *          for the periodic images of the box (Hasimoto, JFM 5, 1959, simple
 *          cubic array): U/U_St = 1 - 1.7601 c^{1/3} + c, c = V_p/V_box, a
 *          1.4 % effect at 100 D spacing. Tolerance 3 % (issue #4).
 *  sn20:   Ar = 800, rho_p/rho_f = 4 (Izard 2014 §2.2.3, its validation case),
 *          Re_t = 20.3; Schiller–Naumann reference, tolerance 3 % (issue #4),
 *          box 24 x 24 x 160 cells so the sphere never meets its own wake.
 * Measured: the slip v - <u_f> once steady. The self-induced-velocity
 * correction of gf_coupling_unresolved.c is what makes 3 % reachable: without
 * it the sphere's own disturbance of the cell velocity biases the drag by
 * ~14 % (printed for the report).
 */
#include <stdlib.h>
#include <string.h>

#include "fluid_test_util.h"
#include "gf_test.h"

typedef struct sphere_case {
    const char *name;
    double D, rho_p, rho_f, mu;
    int n[3];
    double t_end_s, dt_f_max;
} sphere_case;

static double run_case(const sphere_case *sc, double *re_out, double *drift)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    spec_fluid(&spec, sc->D, sc->rho_p, sc->rho_f, sc->mu, "tenneti", 2.5);
    double h = 2.5 * sc->D;
    gf_coupling_setup su = {.gravity_m_s2 = {0, 0, -9.81}};
    coupled_loop L = {.g = {0, 0, -9.81}, .substeps = 20, .dt_f_max = sc->dt_f_max};
    for (int d = 0; d < 3; ++d) {
        su.lo_m[d] = L.lo[d] = 0.0;
        su.hi_m[d] = L.hi[d] = sc->n[d] * h;
        su.bc[d][0] = su.bc[d][1] = GF_BC_PERIODIC;
        L.periodic[d] = 1;
    }
    GF_CHECK_OK(gf_coupling_create(&ctx, &spec, &su, &L.c), &ctx);
    GF_CHECK_OK(gf_particles_create(&ctx, 4, &L.p), &ctx);
    if (!L.c || !L.p)
        return NAN;
    /* off-centre start so the sphere crosses cells (no grid-aligned luck) */
    GF_CHECK_OK(gf_particles_add(&ctx, L.p, 0.43 * su.hi_m[0], 0.57 * su.hi_m[1], 0.9 * su.hi_m[2], sc->D / 2,
                                 sc->rho_p, 0, NULL), &ctx);
    double w_prev = 0.0, w = 0.0, t_prev = 0.0;
    while (L.t < sc->t_end_s) {
        gf_status st = loop_step(&L);
        if (st != GF_OK) {
            GF_CHECK_OK(st, &ctx);
            break;
        }
        double uf[3];
        gf_coupling_mean_fluid_velocity(L.c, uf);
        w = uf[2] - L.p->vz_m_s[0];  /* settling slip, positive downwards */
        if (L.t < 0.8 * sc->t_end_s) {
            w_prev = w;
            t_prev = L.t;
        }
    }
    *drift = (w - w_prev) / w;
    (void)t_prev;
    *re_out = sc->rho_f * w * sc->D / sc->mu;
    gf_coupling_stats st;
    gf_coupling_get_stats(L.c, &st);
    {
        double K, uf[3], eps, um[3];
        gf_coupling_grain_state(L.c, 0, &K, uf, &eps);
        gf_coupling_mean_fluid_velocity(L.c, um);
        double Fd = K * (uf[2] - L.p->vz_m_s[0]);  /* drag on the grain, z */
        double mp = L.p->mass_kg[0], vp = M_PI * pow(sc->D, 3) / 6;
        printf("%s: force balance: drag %.4g N, weight - buoyancy %.4g N; K %.4g kg/s = %.3f x 3 pi eta D\n", sc->name, Fd, (mp - sc->rho_f * vp) * 9.81, K,
               K / (3 * M_PI * sc->mu * sc->D));
        printf("%s: self-induced velocity at the grain %.4g m/s = %.3f of the slip; measured G0 %.4g s/kg, model G0 %.4g\n",
               sc->name, uf[2] - um[2], (uf[2] - um[2]) / w, (uf[2] - um[2]) / (-Fd), st.self_mobility_s_kg);
    }
    printf("%s: %ld fluid steps, %dx%dx%d cells, fluid %.2f s (Poisson %.2f s, %.1f CG its/step)\n", sc->name,
           st.n_steps, st.n_cells[0], st.n_cells[1], st.n_cells[2], st.fluid_s, st.poisson_s,
           (double)st.poisson_iterations / st.n_steps);
    gf_coupling_destroy(&L.c);
    gf_particles_destroy(&L.p);
    return w;
}

int main(int argc, char **argv)
{
    const char *which = argc > 1 ? argv[1] : "stokes";
    if (strcmp(which, "stokes") == 0 || strcmp(which, "all") == 0) {
        /* Re_t = 0.01: D = 1 mm, rho_p 2500, rho_f 1000, eta from Re = rho U D/eta */
        double D = 1e-3, rp = 2500, rf = 1000, g = 9.81;
        double mu = sqrt(rf * (rp - rf) * g * D * D * D / (18.0 * 0.01));
        sphere_case sc = {"stokes", D, rp, rf, mu, {32, 32, 32}, 0.0, 0.0};
        double U = (rp - rf) * g * D * D / (18 * mu);
        double c = M_PI * D * D * D / 6 / pow(32 * 2.5 * D, 3);
        double Uref = U * (1 - 1.7601 * cbrt(c) + c);
        double nu = mu / rf, hh = 2.5 * D;
        sc.t_end_s = 100 * hh * hh / nu;  /* 400 kernel diffusion times */
        sc.dt_f_max = 2 * hh * hh / nu;
        double re, drift;
        double w = run_case(&sc, &re, &drift);
        printf("stokes: Re_t %.4f  U %.5g m/s  U_Stokes %.5g  U_ref(Hasimoto) %.5g  error %+.2f %% (drift last 20%%: %+.2f %%)\n",
               re, w, U, Uref, 100 * (w / Uref - 1), 100 * drift);
        GF_CHECK_REL(w, Uref, 0.03);
        GF_CHECK(re < 0.1);
    }
    if (strcmp(which, "sn20") == 0 || strcmp(which, "all") == 0) {
        double D = 1e-3, rf = 1000, rp = 4000, g = 9.81;
        double mu = sqrt(rf * (rp - rf) * g * D * D * D / 800.0);  /* Ar = 800 */
        double Usn = schiller_naumann_terminal(D, rp, rf, mu, g);
        sphere_case sc = {"sn20", D, rp, rf, mu, {20, 20, 140}, 0.0, 0.0};
        sc.t_end_s = 0.8 * 140 * 2.5 * D / Usn;  /* fall 80 % of the box: no wake re-entry */
        sc.dt_f_max = 1.0;
        double re, drift;
        double w = run_case(&sc, &re, &drift);
        printf("sn20: Re_t %.2f  U %.5g m/s  U_SN %.5g (u/sqrt(gD) %.3f vs %.3f)  error %+.2f %% (drift last 20%%: %+.2f %%)\n",
               re, w, Usn, w / sqrt(g * D), Usn / sqrt(g * D), 100 * (w / Usn - 1), 100 * drift);
        GF_CHECK_REL(w, Usn, 0.03);
    }
    return gf_test_finish();
}
