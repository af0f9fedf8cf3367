/*
 * The viscous rheology of the fast tier's immersed bed against Boyer,
 * Guazzelli & Pouliquen, PRL 107, 188301 (2011), measured on an inclined
 * layer: a steady flow down a rough periodic incline carries the stress
 * ratio mu = tan(theta) at every depth (the fluid far above is at rest, the
 * grains keep their full buoyancy), so each angle gives one point of mu
 * against the measured viscous number I_v = eta_f |du/dy| / P.
 *
 * Set-up: the avalanche scene of the regime map (Izard 2014 §4.1.2.2, case d:
 * 5 D x 20 D x 5 D, bed 8 D, D = 5 mm +- 10 %, rho_p 2500, mu_c 0.25,
 * eps 0.87, lubrication eta_e/R = 2e-4, cells of 2 D) with the fluid of its
 * viscous point St = 0.05, r = 2.58 (rho_f 626 kg/m3, eta_f 1.22 Pa s,
 * fixed for all angles). Run to 60 sqrt(D/g), then profiles on slabs of 1 D
 * averaged every 2 sqrt(D/g) up to 160; bulk = slabs from 2 D above the
 * base to 2 D below the surface; P(y) = (rho_p - rho_f) g cos(theta) times
 * the measured solid fraction integrated from the surface; du/dy central.
 *
 * Reference: Boyer et al. (2011), eq. (5) and (4), with their values
 *   mu(I_v) = mu1 + (mu2 - mu1)/(1 + I0/I_v) + I_v + (5/2) phi_m sqrt(I_v),
 *   mu1 = 0.32, mu2 = 0.7, I0 = 0.005, phi_m = 0.585,
 * the contact part (the first two terms) printed as well. Tolerance: the
 * bulk I_v (geometric mean over the bulk slabs) within a factor 2 of
 * Boyer's I_v at mu = tan(theta) — a factor 2 on the flow rate, the
 * regime map's tolerance on T — at each angle.
 *
 * argv[1]: drag closure (default mean_slip); argv[2..]: angles in degrees
 * (default 22.5 25 27.5).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/gf_boyer.h"
#include "core/gf_groups.h"
#include "gf_sim.h"
#include "gf_test.h"
#include "scenes/gf_measure.h"

enum { NS = 24 };

static void measure(const char *drag, double theta_deg)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    gf_run_spec_defaults(&spec);
    snprintf(spec.scene, sizeof spec.scene, "avalanche");
    spec.seed = 1;
    spec.grains.diameter_m = 5e-3;
    spec.grains.polydispersity = 0.10;
    spec.grains.density_kg_m3 = 2500.0;
    spec.contact.restitution = 0.87;
    spec.contact.friction = 0.25;
    spec.output.particles = spec.output.fields = spec.output.probes = spec.output.diagnostics = 0;
    snprintf(spec.fluid.model, sizeof spec.fluid.model, "unresolved");
    snprintf(spec.fluid.drag, sizeof spec.fluid.drag, "%s", drag);
    spec.fluid.roughness_over_R = 2e-4;
    double g = spec.gravity_m_s2, D = spec.grains.diameter_m, th = theta_deg * M_PI / 180.0;
    GF_CHECK_OK(gf_groups_invert(&ctx, 0.05, 2.58, D, 2500.0, g * sin(25.0 * M_PI / 180.0),
                                 &spec.fluid.density_kg_m3, &spec.fluid.viscosity_Pa_s),
                &ctx);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "incline_deg", theta_deg), &ctx);
    gf_sim *sim = NULL;
    gf_sim_options opt = {.n_threads = 1};
    GF_CHECK_OK(gf_sim_create(&ctx, &spec, &opt, &sim), &ctx);
    if (!sim)
        return;
    gf_measure_domain dom;
    gf_sim_box(sim, dom.lo_m, dom.hi_m, dom.periodic);
    double tg = sqrt(D / g), eta = spec.fluid.viscosity_Pa_s, drho = 2500.0 - spec.fluid.density_kg_m3;
    long chunk = (long)ceil(2.0 * tg / gf_sim_dt_s(sim));
    double phi_acc[NS] = {0}, u_acc[NS] = {0};
    int n_win = 0;
    for (int w = 0; w < 80; ++w) {
        GF_CHECK_OK(gf_sim_advance(sim, chunk), &ctx);
        if (w < 30)
            continue;  /* 60 sqrt(D/g) of start-up */
        double phi[NS], u[3 * NS];
        GF_CHECK_OK(gf_measure_profile_y(&ctx, gf_sim_particles(sim), &dom, 0.0, D, NS, phi, u), &ctx);
        for (int k = 0; k < NS; ++k)
            phi_acc[k] += phi[k], u_acc[k] += isnan(u[3 * k]) ? 0.0 : u[3 * k];
        ++n_win;
    }
    for (int k = 0; k < NS; ++k)
        phi_acc[k] /= n_win, u_acc[k] /= n_win;
    double top = gf_measure_bed_height_m(phi_acc, NS, 0.0, 1.0, 0.5);  /* in D */
    double P[NS], above = 0.0;
    for (int k = NS - 1; k >= 0; --k) {  /* P at slab centres: the grains above, buoyant weight */
        P[k] = drho * g * cos(th) * D * (above + 0.5 * phi_acc[k]);
        above += phi_acc[k];
    }
    double slog = 0.0, phib = 0.0;
    int nb = 0;
    printf("%s, theta %.1f deg: bed top %.1f D, surface u %.3g m/s\n", drag, theta_deg, top,
           u_acc[(int)top > 0 ? (int)top - 1 : 0]);
    for (int k = 2; k + 0.5 <= top - 2.0; ++k) {
        double gd = (u_acc[k + 1] - u_acc[k - 1]) / (2.0 * D);
        double iv = eta * fabs(gd) / P[k];
        printf("  slab %d: phi %.3f  u %.3g m/s  du/dy %.3g 1/s  P %.1f Pa  I_v %.3g\n", k, phi_acc[k], u_acc[k], gd,
               P[k], iv);
        if (iv > 0.0)
            slog += log(iv), phib += phi_acc[k], ++nb;
    }
    double iv_meas = nb ? exp(slog / nb) : 0.0;
    const gf_boyer_law *b = &GF_BOYER_2011;
    double mu = tan(th), iv_boyer = gf_boyer_Iv(b, mu, 0), iv_contact = gf_boyer_Iv(b, mu, 1);
    printf("%s, theta %.1f deg: mu = tan(theta) %.3f, bulk I_v %.3g (phi %.3f), Boyer I_v(mu) %.3g (contact part "
           "only %.3g), ratio measured/Boyer %.3g; Boyer mu(measured I_v) %.3f, phi(I_v) %.3f\n",
           drag, theta_deg, mu, iv_meas, nb ? phib / nb : NAN, iv_boyer, iv_contact, iv_meas / iv_boyer,
           gf_boyer_mu(b, iv_meas, 0), gf_boyer_phi(b, iv_boyer));
    GF_CHECK(nb >= 2);
    GF_CHECK(iv_meas > 0.5 * iv_boyer && iv_meas < 2.0 * iv_boyer);
    gf_sim_destroy(&sim);
}

int main(int argc, char **argv)
{
    const char *drag = argc > 1 ? argv[1] : "mean_slip";
    if (argc > 2)
        for (int a = 2; a < argc; ++a)
            measure(drag, atof(argv[a]));
    else
        for (int a = 0; a < 3; ++a)
            measure(drag, 22.5 + 2.5 * a);
    return gf_test_finish();
}
