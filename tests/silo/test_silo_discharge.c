/*
 * Silo discharge, the fast checks (scene silo; Djouwe Meffeja 2012 ch. 3).
 *
 * A small silo, 10 d x 10 d x 20 d, square orifice 5 d x 5 d, fill 10 d,
 * the thesis' contact set (§3.3: e_n = 0.885, mu = mu_wall = 0.5,
 * k_t = 2 k_n / 7) at Silbert et al. (2001)'s stiffness (t_n = 4.97e-3 sqrt(d/g)),
 * d = 0.5 mm, discharged with reinjection for 16 sqrt(d/g) after 4 of transient:
 *  - reinjection keeps every grain: the store's count is unchanged and every
 *    grain but those waiting for a free site is mobile and inside the box;
 *  - mass balance at the orifice: the count of grains that left (the scene's
 *    counter) against the kinematic flux through the slab -d <= y <= 0 under
 *    the orifice, (1/d) sum (-v_y) over the grains in it, sampled every 100
 *    steps (an independent reading of the same Q): within 10 %;
 *  - Q against Beverloo, Leniger & van de Velde (1961), W = C rho_b sqrt(g)
 *    (D - k d)^(5/2) with C = 0.58, k = 1.5 (their glass-bead values) and rho_b the
 *    settled column's bulk density (its interior phi), D the hydraulic diameter
 *    (thesis §3.4.2): within 25 % (the literature's C spans 0.55-0.65 and
 *    k 1.3-1.6, +-12 % at D = 5 d, and a 10 d fill sits below saturation,
 *    Q/Q0 = 0.83 with the thesis' H0 = 5.7 d);
 *  - inconsistent parameters are refused at load with the key's
 *    file:line:column (orifice wider than the floor, narrower than 2 d, a
 *    fill above the reinjection height).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "campaign/gf_campaign.h"
#include "gf_sim.h"
#include "gf_test.h"
#include "scenes/gf_scene.h"
#include "scenes/gf_silo_thesis.h"

static void silo_spec(gf_run_spec *s)
{
    gf_silo_thesis_spec(s);
    gf_run_spec_set_param(NULL, s, "width_x_over_d", 10);
    gf_run_spec_set_param(NULL, s, "width_z_over_d", 10);
    gf_run_spec_set_param(NULL, s, "height_over_d", 20);
    gf_run_spec_set_param(NULL, s, "orifice_x_over_d", 5);
    gf_run_spec_set_param(NULL, s, "orifice_z_over_d", 5);
    gf_run_spec_set_param(NULL, s, "fill_height_over_d", 10);
    gf_run_spec_set_param(NULL, s, "reinject_height_over_d", 17);
    gf_run_spec_set_param(NULL, s, "settle_time_nd", 3);
}

/* (1/d) sum of -v_y over the mobile grains in -d <= y < 0 under the orifice: the number flux. */
static double slab_flux(gf_sim *sim, double d)
{
    const gf_particles *p = gf_sim_particles(sim);
    double q = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        if (!(p->flags[i] & GF_P_GLUED) && p->y_m[i] < 0.0 && p->y_m[i] >= -d)
            q -= p->vy_m_s[i];
    return q / d;
}

static void test_discharge(void)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    silo_spec(&spec);
    gf_sim *sim = NULL;
    gf_sim_options opt = {.n_threads = 1};
    GF_CHECK_OK(gf_sim_create(&ctx, &spec, &opt, &sim), &ctx);
    if (!sim)
        return;
    const gf_scene_desc *desc = gf_scene_find("silo");
    const double d = spec.grains.diameter_m, tg = sqrt(d / spec.gravity_m_s2);
    gf_particles *p = gf_sim_particles(sim);
    const size_t n0 = p->n_local;
    double phi_measured = NAN, phi_local = NAN, v[5];
    GF_CHECK_OK(desc->initial_packing(sim, &phi_measured, &phi_local), &ctx);
    const long every = GF_SCENE_MAINTAIN_EVERY;
    const long transient = (long)ceil(4.0 * tg / gf_sim_dt_s(sim) / every);
    const long window = (long)ceil(16.0 * tg / gf_sim_dt_s(sim) / every);
    double flux_sum = 0.0, out0 = 0.0, t0 = 0.0;
    for (long k = 0; k < transient + window; ++k) {
        gf_status st = gf_sim_advance(sim, every);
        if (st == GF_OK)
            st = desc->maintain(sim);
        GF_CHECK_OK(st, &ctx);
        if (st != GF_OK)
            break;
        if (k + 1 == transient) {
            GF_CHECK_OK(desc->diagnose(sim, v), &ctx);
            out0 = v[0], t0 = gf_sim_time_s(sim);
        } else if (k + 1 > transient) {
            flux_sum += slab_flux(sim, d);
        }
    }
    GF_CHECK_OK(desc->diagnose(sim, v), &ctx);
    const double T = gf_sim_time_s(sim) - t0, Q = (v[0] - out0) / T, Q_kin = flux_sum / (double)window;
    size_t held = 0, outside = 0;
    for (size_t i = 0; i < p->n_local; ++i) {
        held += (p->flags[i] & GF_P_GLUED) != 0;
        outside += p->y_m[i] < -6.0 * d || p->y_m[i] > 20.0 * d || p->x_m[i] < 0.0 || p->x_m[i] > 10.0 * d ||
                   p->z_m[i] < 0.0 || p->z_m[i] > 10.0 * d;
    }
    /* Beverloo et al. 1961 with the column's bulk density (its interior packing: the global estimate also
     * counts the looser layer along the walls and the trimmed top), in grains per second */
    const double Dh = 5.0, Q_bev = 0.58 * phi_local * (6.0 / M_PI) * pow(Dh - 1.5, 2.5) / tg;
    printf("silo 10x10x20 d, 5 d orifice: %zu grains, phi %.3f (interior %.3f); Q = %.4g grains/s = %.3f sqrt(g/d) "
           "over %.1f sqrt(d/g) (%.0f grains), kinematic flux %.4g /s (%.2f %%), Beverloo (C 0.58, k 1.5) %.4g /s "
           "(ratio %.3f); phi_out %.3f; %zu waiting\n",
           n0, phi_measured, phi_local, Q, Q * tg, T / tg, v[0] - out0, Q_kin, 100.0 * (Q_kin / Q - 1.0), Q_bev,
           Q / Q_bev, v[3], held);
    GF_CHECK(p->n_local == n0);
    GF_CHECK(outside == 0);
    GF_CHECK(held < 5);
    GF_CHECK(v[0] - out0 > 100.0);
    GF_CHECK_REL(Q_kin, Q, 0.10);
    GF_CHECK_REL(Q, Q_bev, 0.25);
    gf_sim_destroy(&sim);
}

/* The scene's refusals, located at the key by the campaign loader. */
static void refused(const char *scene_lines, const char *where, const char *what)
{
    char text[1024];
    snprintf(text, sizeof text,
             "scene:\n  name: silo\n%s"
             "grains: {diameter_m: 0.5e-3, density_kg_m3: 2500}\n",
             scene_lines);
    gf_ctx ctx = {0};
    gf_campaign *c = NULL;
    gf_status st = gf_campaign_load_string(&ctx, "silo.yaml", text, strlen(text), NULL, 0, &c);
    gf_test_check(st == GF_ERR_CONFIG && strstr(ctx.last_msg, where) && strstr(ctx.last_msg, what), __FILE__,
                  __LINE__, "expected '%s ... %s', got (%d) %s", where, what, (int)st, ctx.last_msg);
    gf_campaign_destroy(&c);
}

static void test_bad_input(void)
{
    refused("  width_x_over_d: 20\n  orifice_x_over_d: 19\n", "silo.yaml:4:21:", "larger than the floor");
    refused("  orifice_z_over_d: 1.5\n", "silo.yaml:3:21:", "out of range");
    refused("  height_over_d: 30\n  reinject_height_over_d: 26\n  fill_height_over_d: 25\n", "silo.yaml:5:23:",
            "does not fit the box");
}

int main(void)
{
    test_bad_input();
    test_discharge();
    return gf_test_finish();
}
