/*
 * Shared set-up of the channel tests: the Newtonian channel of Djouwe Meffeja
 * 2012, §4.5.1 (3H x H, parabolic inflow, outflow at p = 0) and the fully
 * developed mu(I) channel (periodic along x, driven by a body force).
 */
#ifndef CONTINUUM_CHANNEL_H
#define CONTINUUM_CHANNEL_H

#include <math.h>

#include "continuum/gf_continuum.h"

/* H = 1, U_max = 1, rho = 1, eta = 1/Re; dt = cfl h. */
static inline gf_continuum_params channel_newtonian(int ny, double Re, double cfl)
{
    gf_continuum_params p = {
        .n = {3 * ny, ny, 1},
        .length_m = {3.0, 1.0, 1.0},
        .side = {{GF_SIDE_INFLOW, GF_SIDE_OUTFLOW}, {GF_SIDE_WALL, GF_SIDE_WALL}, {GF_SIDE_PERIODIC, GF_SIDE_PERIODIC}},
        .inflow_umax_m_s = 1.0,
        .density_kg_m3 = 1.0,
        .rheology = GF_RHEOLOGY_NEWTONIAN,
        .viscosity_Pa_s = 1.0 / Re,
        .dt_s = cfl / ny,
    };
    return p;
}

/* Max over the outlet faces of |u - 4 y (1 - y)| (U_max = 1). */
static inline double outlet_error(const gf_continuum *s)
{
    const gf_grid *g = gf_continuum_grid(s);
    const double *u = gf_continuum_velocity(s, 0);
    double worst = 0.0;
    for (int j = 0; j < g->n[1]; ++j) {
        double y = (j + 0.5) * g->h_m[1];
        worst = fmax(worst, fabs(u[gf_grid_face(g, 0, g->n[0], j, 0)] - 4.0 * y * (1.0 - y)));
    }
    return worst;
}

#endif

/* Fully developed mu(I) channel: H = 1, Lambda = H/d, rho_s = P0 = 1, phi = 0.6, periodic along x
 * (nx cells), driven by G = beta^2 P0/H as a body force; velocity scale sqrt(G H/rho_s) = beta. */
static inline gf_continuum_params channel_mui(int ny, double beta, double Lambda, gf_mui_params law, gf_rheology rh)
{
    double phi = 0.6, rho = phi * 1.0, G = beta * beta;
    gf_continuum_params p = {
        .n = {4, ny, 1},
        .length_m = {4.0 / ny, 1.0, 1.0},
        .side = {{GF_SIDE_PERIODIC, GF_SIDE_PERIODIC}, {GF_SIDE_WALL, GF_SIDE_WALL}, {GF_SIDE_PERIODIC, GF_SIDE_PERIODIC}},
        .density_kg_m3 = rho,
        .body_accel_m_s2 = {G / rho, 0.0, 0.0},
        .rheology = rh,
        .mui = {.law = law, .diameter_m = 1.0 / Lambda, .grain_density_kg_m3 = 1.0, .gdot_min_1_s = 1e-5,
                .rate_part_only = rh == GF_RHEOLOGY_MU_I_RATE_PART},
        .pressure_ref_Pa = 1.0,
        .dt_s = 2.0,
    };
    return p;
}
