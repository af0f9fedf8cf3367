/*
 * gf_continuum: incompressible flow of a continuum with a mu(I) (or
 * Newtonian) viscosity on the MAC grid of the fluid module, by the projection
 * scheme of Djouwe Meffeja 2012, §4.4 (after Seibold 2008, "A compact and fast
 * Matlab code solving the incompressible Navier-Stokes equations on
 * rectangular domains"):
 *   1. explicit advection, conservative form, central fluxes blended with
 *      donor cell by gamma = min(1.2 dt max_b max|u_b|/h_b, 1), plus body forces;
 *   2. implicit (backward Euler) viscous step with the viscosity of u^n;
 *   3. projection: L phi = (rho/dt) div u**, u^{n+1} = u** - (dt/rho) grad phi.
 * Departures from the thesis, on purpose:
 *   - the projection is incremental (the predictor carries -grad p^n and
 *     p^{n+1} = p^n + phi), so a steady state is the discrete steady flow
 *     whatever dt: the thesis' full-pressure projection leaves an O(dt) wall
 *     slip (dt/rho) dp/dx in a channel;
 *   - the viscous step solves the stress divergence div(eta (grad u + grad u^T))
 *     exactly (the form of §4.3.1, one coupled sparse system for all
 *     components), not the approximation eta lap(u) of its eq. (4.8), whose
 *     plug-like channel profiles the thesis itself questions (§4.5.2);
 *   - |gdot| = sqrt(gdot_ij gdot_ij / 2) with all strain components (the
 *     thesis' code keeps the off-diagonal part at the corners only).
 * Boundaries per side (ibid. §4.4.2): no-slip walls (optionally moving
 * tangentially), a parabolic inflow (normal velocity prescribed, tangential
 * zero, zero-flux pressure), an outflow (zero normal gradient of velocity and
 * p = 0 on the face, the thesis' code), or periodic.
 * 2-D is the 3-D code with one periodic cell along z and no z velocity.
 * Two phases (two_phase = 1, after Lagree, Staron & Popinet, JFM 686, 2011):
 * the main phase (mu(I)) and a light Newtonian one (air) mix cell by cell by
 * the volume fraction c, advected by THINC in direction-split sweeps
 * (Xiao, Honma & Kono 2005; Weymouth & Yue 2010; gf_continuum_vof.c), with
 * rho = c rho + (1 - c) rho_2 and eta = c eta + (1 - c) eta_2; the projection
 * is then variable-coefficient, div(grad(phi)/rho) = div u / dt, solved by
 * LU as well (it needs an outflow side to fix the pressure).
 * Units SI. The rheology's pressure is P = pressure_ref_Pa + p, p the
 * projection pressure (zero on an outflow face).
 */
#ifndef GF_CONTINUUM_H
#define GF_CONTINUUM_H

#include "continuum/gf_mui.h"
#include "core/gf_status.h"
#include "fluid/gf_grid.h"

typedef enum gf_continuum_side {
    GF_SIDE_WALL = 0,
    GF_SIDE_PERIODIC,
    GF_SIDE_INFLOW,
    GF_SIDE_OUTFLOW
} gf_continuum_side;

typedef enum gf_rheology { GF_RHEOLOGY_NEWTONIAN = 0, GF_RHEOLOGY_MU_I, GF_RHEOLOGY_MU_I_RATE_PART } gf_rheology;

typedef struct gf_continuum_params {
    int n[3];                       /* cells per axis; n[2] = 1 for 2-D */
    double length_m[3];
    gf_continuum_side side[3][2];   /* [axis][low, high]; axis 2 is periodic in 2-D */
    double wall_velocity_m_s[3][2][3]; /* [axis][side][component] tangential speed of a moving wall */
    double inflow_umax_m_s;         /* inflow profile: umax times 4 s (1 - s) over each wall-bounded axis */
    double density_kg_m3;           /* bulk density of the continuum (phi rho_s for grains) */
    double body_accel_m_s2[3];      /* gravity plus any driving force per unit mass */
    gf_rheology rheology;
    double viscosity_Pa_s;          /* Newtonian */
    gf_mui_material mui;            /* mu(I) and its rate part */
    double pressure_ref_Pa;         /* added to the projection pressure in the mu(I) law */
    double dt_s;
    int min_cells_across;           /* refuse coarser wall-to-wall grids; 0: 8 */
    int two_phase;                  /* 1: a second, Newtonian phase fills the cells in proportion 1 - c,
                                       c the volume fraction of the main phase (a free surface by VOF) */
    double density2_kg_m3, viscosity2_Pa_s; /* the second phase (air) */
    int laplacian_form;             /* 1: eta lap(u) per component, the thesis' approximation (4.8), with
                                       eta averaged from the edges to the face; 0: the stress divergence */
} gf_continuum_params;

typedef struct gf_continuum gf_continuum;

/* GF_ERR_CONFIG with `where` first on anything the solver cannot run. */
gf_status gf_continuum_params_check(gf_ctx *ctx, const gf_continuum_params *p, const char *where);
/* Returns owned solver; fluid at rest, boundary values set. ctx is borrowed for its lifetime. */
gf_status gf_continuum_create(gf_ctx *ctx, const gf_continuum_params *p, gf_continuum **out);
void gf_continuum_destroy(gf_continuum **s);
/* Sets the pressure of the fluid at rest under the body force: one projection of
 * u* = dt g from rest, the velocity left at rest. A mu(I) material has no strength
 * where P <= 0, so without it the first step would be inviscid. Call before the
 * first step (after setting the volume fraction under two phases). */
gf_status gf_continuum_init_pressure(gf_continuum *s);
/* One step of dt_s. */
gf_status gf_continuum_step(gf_continuum *s);
/* Steps until t_end_s or until max|u^{n+1} - u^n| <= steady_tol_m_s (0: never); *change_m_s gets the last change. */
gf_status gf_continuum_run(gf_continuum *s, double t_end_s, double steady_tol_m_s, double *change_m_s);

const gf_grid *gf_continuum_grid(const gf_continuum *s);
/* Face array of component a (gf_grid layout; boundary faces hold the boundary values). Borrowed. */
const double *gf_continuum_velocity(const gf_continuum *s, int a);
/* Projection pressure at cell centres (Pa). Borrowed. */
const double *gf_continuum_pressure(const gf_continuum *s);
/* Volume fraction c of the main phase at cell centres (1 everywhere unless two_phase); writable
 * before the first step to set the initial shape. Borrowed. */
double *gf_continuum_fraction(gf_continuum *s);
/* Effective viscosity at cell centres (Pa s) of the last step. Borrowed. */
const double *gf_continuum_viscosity(const gf_continuum *s);
double gf_continuum_time(const gf_continuum *s);
/* max |div u| h / max|u| over cells (a check of the projection). */
double gf_continuum_divergence_norm(const gf_continuum *s);

#endif
