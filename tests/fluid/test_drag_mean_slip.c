/*
 * The mean-slip closure (engine/coupling/gf_drag_mean_slip.c) separates the
 * drag on the mean slip of a suspension from the resistance to each grain's
 * motion about the local mean flow (Trulsson, Andreotti & Claudin, PRL 109,
 * 2012). Check of that split on a state with an exact answer: grains on a
 * simple cubic lattice at phi = 0.3, no gravity, no contacts, fluid at rest,
 * neighbouring grains moving at +V and -V along x (a three-dimensional
 * checkerboard, wavelength 2a ~ 2.4 D, so its kernel average is zero to
 * ~1e-6 with the kernel of 2 D). The local mean velocity and the mean slip
 * are then zero, the fluid stays at rest, and each grain's speed decays as
 *   V(t) = V0 exp(-K' t / m),  K' = 3 pi eta D (Stokes, Re' = 4e-3 here, the
 *   Schiller–Naumann factor 1.002 included in the prediction).
 * The per-grain closure di_felice drags the same motion with its dense-bed
 * coefficient K(eps = 0.7): the decay rate is K(eps)/m, 2.6 x Stokes here;
 * both rates are asserted within 2 %, the fluid's speed below 1e-3 V0.
 */
#include <stdlib.h>
#include <string.h>

#include "coupling/gf_drag.h"
#include "fluid_test_util.h"
#include "gf_test.h"

static double decay_rate(const char *drag, double D, double rp, double rf, double mu, double V0, double *ufluid)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    spec_fluid(&spec, D, rp, rf, mu, drag, 2.0);
    const double phi = 0.3;
    double a = D * cbrt(M_PI / (6 * phi));
    int n = 14;  /* even: the checkerboard is periodic */
    double Lb = n * a;
    coupled_loop L = {.g = {0, 0, 0}, .substeps = 5, .dt_f_max = 1.0};
    periodic_cube(&ctx, &spec, Lb, &L);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                size_t q = L.p->n_local;
                gf_particles_add(&ctx, L.p, (i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a, D / 2, rp, 0, NULL);
                L.p->vx_m_s[q] = (i + j + k) % 2 ? V0 : -V0;
            }
    double m = rp * M_PI * D * D * D / 6.0;
    double tau = m / (3 * M_PI * mu * D);
    L.dt_f_max = 0.05 * tau;
    double v1 = 0.0, t1 = 0.0;
    while (L.t < 0.5 * tau) {
        GF_CHECK_OK(loop_step(&L), &ctx);
        if (t1 == 0.0 && L.t >= 0.1 * tau) {  /* after the first fluid steps */
            t1 = L.t;
            for (size_t i = 0; i < L.p->n_local; ++i)
                v1 += fabs(L.p->vx_m_s[i]) / (double)L.p->n_local;
        }
    }
    double v2 = 0.0;
    for (size_t i = 0; i < L.p->n_local; ++i)
        v2 += fabs(L.p->vx_m_s[i]) / (double)L.p->n_local;
    double uf[3];
    gf_coupling_mean_fluid_velocity(L.c, uf);
    /* largest fluid speed: the cell field */
    int nc[3];
    double lo[3], h[3];
    const gf_var_info *vars;
    const double *const *fields;
    int nf = gf_coupling_fields(L.c, nc, lo, h, &vars, &fields);
    double umax = 0.0;
    for (int f = 1; f < nf && f <= 3; ++f)
        for (long c = 0; c < (long)nc[0] * nc[1] * nc[2]; ++c)
            umax = fmax(umax, fabs(fields[f][c]));
    *ufluid = umax;
    gf_coupling_destroy(&L.c);
    gf_particles_destroy(&L.p);
    return log(v1 / v2) / (L.t - t1) * m;  /* K in kg/s */
}

int main(void)
{
    double D = 1e-3, rp = 2500, rf = 1000, mu = 1e-2;
    double V0 = 4e-5;  /* Re' = rho V0 D / mu = 4e-3 */
    double stokes = 3 * M_PI * mu * D;
    double re = rf * V0 * D / mu;
    double uf;
    double k_new = decay_rate("mean_slip", D, rp, rf, mu, V0, &uf);
    double k_new_pred = stokes * (1 + 0.15 * pow(re, 0.687));
    printf("mean_slip: decay rate K' = %.4g kg/s = %.4f x Stokes (predicted %.4f, %+.2f %%), fluid |u|max %.2g V0\n",
           k_new, k_new / stokes, k_new_pred / stokes, 100 * (k_new / k_new_pred - 1), uf / V0);
    GF_CHECK_REL(k_new, k_new_pred, 0.02);
    GF_CHECK(uf < 1e-3 * V0);
    double k_old = decay_rate("di_felice", D, rp, rf, mu, V0, &uf);
    double k_old_pred = gf_drag_coefficient(gf_drag_lookup("di_felice"), D, 0.7, V0, rf, mu);
    printf("di_felice: decay rate K = %.4g kg/s = %.4f x Stokes (its K(eps 0.7) %.4f, %+.2f %%), fluid |u|max %.2g V0\n",
           k_old, k_old / stokes, k_old_pred / stokes, 100 * (k_old / k_old_pred - 1), uf / V0);
    GF_CHECK_REL(k_old, k_old_pred, 0.02);
    GF_CHECK(gf_drag_lookup("no_such_closure") == NULL);
    return gf_test_finish();
}
