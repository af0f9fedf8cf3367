/*
 * The resolved tier ("resolved"): Navier-Stokes over the whole domain,
 * inside the grains too, on a MAC grid of D/dx = spec.fluid.d_over_dx cells
 * per diameter, with immersed-boundary direct forcing on every grain (Uhlmann,
 * J. Comput. Phys. 209, 2005; Izard 2014 §2.2 and §3.1.2.1, the method of the
 * JADIM/GraDyM coupling of Izard, Bonometti & Lacaze, J. Fluid Mech. 747, 2014).
 *
 * One fluid step of dt with the grains frozen (Izard 2014 §2.3.1):
 *   1. grain-to-face maps and solid fractions alpha_i (coupling/gf_ibm.h);
 *   then for each substep of the time scheme (fluid.time_scheme: ab2, one; rk3, three;
 *   fluid/gf_fluid_ns2.h, with fluid.advection's form, divergence by default):
 *   2. rates and the predictor u~;
 *   3. forcing f = alpha (U - u~)/dt, and each grain's force and torque from
 *      the forcing integral, F_i = -(rho rho_p/(rho_p - rho)) int alpha_i (U_i - u~)/dt,
 *      summed over the substeps (fluid.ibm_forcing: smoothed); or the forcing
 *      at surface markers, F_i = -rho sum_l F_l dV_l summed over the substeps,
 *      plus, once a step, the inner fluid's momentum rate (following the
 *      moving grain: the last step's closing value is kept) and the buoyancy
 *      (fluid.ibm_forcing: markers, coupling/gf_ibm_markers.h);
 *   4. Crank-Nicolson viscous step with f, projection (FFT Poisson);
 * then the DEM runs its substeps with F_i and T_i held (gf_coupling_add_forces),
 * contacts and lubrication recomputed at every substep. The fluid carries the
 * pressure in excess of the hydrostatic one, so F_i contains the buoyancy and
 * the step loop adds m g as for a dry grain.
 *
 * Limits (checked by gf_resolved_check before a run and at every step):
 *   - D/dx >= 6: below, the shell of alpha (about three cells) is as thick as
 *     the grain's radius and the grain is no longer resolved (the thesis uses
 *     10-40, §3.1.3.1, Table 3.2);
 *   - rho_p/rho >= 1.7: the force formula is singular at rho_p = rho and the
 *     thesis' lowest ratio is 1.7 (§3.1.3.1);
 *   - advective: sum_d |u_d| dt/h <= 1 (AB2 on central advection diverges
 *     beyond; gf_coupling_dt_max_s keeps spec.fluid.cfl);
 *   - viscous: nu dt/dx^2 <= 1, the predictor's explicit viscous term (the
 *     one the forcing sees) spreads at most a cell per step; the thesis'
 *     settling run sits at 0.98 (dt sqrt(g/D) = 0.04, D/dx = 20, Ar = 800).
 *     The step aims at spec.fluid.diffusion_number of it (0.5 by default):
 *     with the smoothed forcing the answers depend on the step, because each
 *     forcing moves the shell a fraction alpha towards the grain
 *     (docs/notes/resolved-settling.md, docs/notes/resolved-multigrain.md).
 *
 * A periodic axis along which gravity acts has no bottom to carry the grains'
 * excess weight: without more, the weight would accelerate the whole fluid.
 * The tier then adds the mean pressure gradient of a settling tank, a uniform
 * body force per unit volume on the fluid at every velocity face (inside the
 * grains too), on the periodic axes d,
 *   G_d = -(sum_i (m_i - rho V_i) / V_box) g_d,
 * and 0 while any grain is glued (the glued grains and the walls carry the
 * weight: the avalanche keeps its tank), as for periodic sedimentation in
 * Uhlmann (2005) and Uhlmann & Doychev (J. Fluid Mech. 752, 2014);
 * the unresolved tier applies the same G (Capecelatro & Desjardins 2013).
 * G leaves the grain's force formula as it is. With the full stress sigma
 * (pressure p = p' + P, P linear, -grad P + rho g = G) the grain obeys
 *   m dU/dt = oint sigma.n + m g = oint sigma'.n + V (G - rho g) + m g,
 * and the fluid inside it, which the fluid step carries with G and f,
 *   rho V dU/dt = oint sigma'.n + G V + rho int f_i    (rigid inner fluid);
 * subtracting, (m - rho V) dU/dt = -rho int f_i + (m - rho V) g: G V, the
 * mean gradient's push on the grain, is paid by the forcing integral (the
 * forcing removes G from the inner fluid), and F_i above is unchanged. Summed
 * over the box (periodic: the advection, viscous and pressure terms have no
 * net integral up to the non-conservative advection's truncation), the mixture
 * momentum rho int_box u + sum_i (m_i - rho V_i) U_i then stays constant
 * (tests/resolved/resolved_suspension.c: to 2e-4 of the weight impulse).
 * G is recomputed from the grains at every fluid step: no state of its own.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/gf_timer.h"
#include "coupling/gf_coupling_restart.h"
#include "coupling/gf_coupling_tier.h"
#include "coupling/gf_ibm.h"
#include "coupling/gf_ibm_markers.h"
#include "coupling/gf_weight_balance.h"
#include "fluid/gf_fluid.h"
#include "fluid/gf_fluid_ns2.h"

#define RESOLVED_MIN_D_OVER_DX 6.0
#define RESOLVED_DEFAULT_D_OVER_DX 16.0
#define RESOLVED_MIN_DENSITY_RATIO 1.7
#define RESOLVED_VISCOUS_LIMIT 1.0   /* nu dt / dx^2 */

enum { RF_ALPHA, RF_U, RF_V, RF_W, RF_P, RF_N };

static const gf_var_info resolved_vars[RF_N] = {
    {"solid_fraction", "1", "solid volume fraction alpha of the immersed boundary (cell-centred)", NULL},
    {"u_fluid", "m s-1", "fluid velocity along x (cell-centred, grains included)", NULL},
    {"v_fluid", "m s-1", "fluid velocity along y (cell-centred, grains included)", NULL},
    {"w_fluid", "m s-1", "fluid velocity along z (cell-centred, grains included)", NULL},
    {"excess_pressure", "Pa", "fluid pressure minus hydrostatic", NULL},
};

typedef struct gf_resolved {
    gf_coupling base;  /* first member: the tier row */
    gf_ctx *ctx;
    gf_run_spec spec;
    gf_coupling_setup setup;
    gf_fluid *fluid;
    gf_ibm_map map;
    gf_ibm_forcing forcing;  /* spec.fluid.ibm_forcing */
    gf_ibm_markers markers;  /* its state when it is GF_IBM_MARKERS */
    double *A[3], *A_old[3], *r[3], *u_pred[3], *force[3], *alpha_sum[3], *aU[3];
    double *fields[RF_N];
    int first_step;
    gf_ns2_scheme scheme;  /* spec.fluid.time_scheme */
    gf_ns2_advection advection;
    /* what the last fluid step left for the substeps, per grain */
    int64_t *held_id;
    double *held_F, *held_T;
    double *sub_F, *sub_T;   /* a later substep's force and torque, before they are added to held_F, held_T */
    double *P0, *L0, *P1, *L1; /* markers: each grain's internal momentum and angular momentum, before and after */
    double *P_last, *L_last;   /* markers: P1, L1 of the last fluid step, in held_id's order */
    int last_known;            /* P_last, L_last hold the last step's (0: the first step, or an older checkpoint) */
    int contact_correction;    /* spec.fluid.ibm_contact_correction, with the smoothed forcing (contact_correction_*) */
    double *U_last, *W_last;   /* contact correction: each grain's velocity and spin at the last fluid step (held_id's order) */
    double *corr_F, *corr_T;   /* contact correction: this step's, in the grains' present order */
    double *corr_F_last, *corr_T_last; /* contact correction: the last step's (held_id's order) */
    double dt_last;            /* contact correction: the last fluid step, s (0: none yet) */
    size_t n_held, cap_held;
    uint64_t held_epoch;
    int held_epoch_known;
    long n_steps;
    double fluid_s;
    int n_threads;     /* of the fluid step: stencils, FFTs, immersed boundary (resolved_set_threads) */
} gf_resolved;

static gf_resolved *R_(gf_coupling *c) { return (gf_resolved *)c; }
static const gf_resolved *CR(const gf_coupling *c) { return (const gf_resolved *)c; }

static double d_over_dx(const gf_run_spec *spec)
{
    return spec->fluid.d_over_dx > 0.0 ? spec->fluid.d_over_dx : RESOLVED_DEFAULT_D_OVER_DX;
}

/* --- checks -------------------------------------------------------------------------------------- */

/* The time scheme, the advection form (fluid/gf_fluid_ns2.h) and the forcing (coupling/gf_ibm_markers.h) named
 * in the spec. */
static gf_status numerics(gf_ctx *ctx, const gf_fluid_spec *fs, gf_ns2_scheme *scheme, gf_ns2_advection *form,
                          gf_ibm_forcing *forcing)
{
    if (gf_ibm_forcing_from_name(fs->ibm_forcing, forcing) != 0)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid.ibm_forcing = \"%s\": the resolved tier has the \"smoothed\" and "
                       "\"markers\" forcings", fs->ibm_forcing);
    if (gf_fluid_ns2_scheme_from_name(fs->time_scheme, scheme) != 0)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid.time_scheme = \"%s\": the resolved tier runs \"ab2\" or \"rk3\"",
                       fs->time_scheme);
    if (gf_fluid_ns2_advection_from_name(fs->advection, form) != 0)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid.advection = \"%s\": the resolved tier has the \"advective\" and "
                       "\"divergence\" forms", fs->advection);
    return GF_OK;
}

static gf_status resolved_check(gf_ctx *ctx, const gf_run_spec *spec)
{
    const gf_fluid_spec *fs = &spec->fluid;
    double n = d_over_dx(spec);
    if (!(fs->density_kg_m3 > 0.0) || !(fs->viscosity_Pa_s > 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid: density (%g kg/m3) and viscosity (%g Pa s) must be > 0 for the "
                       "resolved tier", fs->density_kg_m3, fs->viscosity_Pa_s);
    if (!(n >= RESOLVED_MIN_D_OVER_DX) || n > 64.0)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid.d_over_dx = %g: the resolved tier needs D/dx >= %g (the solid "
                       "fraction's shell is ~3 cells; Izard 2014 uses 10-40) and at most 64", n, RESOLVED_MIN_D_OVER_DX);
    double r = spec->grains.density_kg_m3 / fs->density_kg_m3;
    if (!(r >= RESOLVED_MIN_DENSITY_RATIO))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "grains.density_kg_m3 / fluid.density_kg_m3 = %.4g: the resolved tier's "
                       "force rho rho_p/(rho_p - rho) int f is singular at 1 and needs rho_p/rho >= %g (Izard 2014 "
                       "§3.1.3.1)", r, RESOLVED_MIN_DENSITY_RATIO);
    if (!(fs->ibm_retraction_dx >= 0.0 && fs->ibm_retraction_dx <= 1.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid.ibm_retraction_dx = %g must be in [0, 1] cells (Breugem 2012 "
                       "uses 0.3)", fs->ibm_retraction_dx);
    if (!(fs->cfl > 0.0 && fs->cfl <= 1.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid.cfl = %g must be in (0, 1]", fs->cfl);
    if (!(fs->diffusion_number > 0.0 && fs->diffusion_number <= RESOLVED_VISCOUS_LIMIT))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid.diffusion_number = %g must be in (0, %g] (nu dt/dx^2, the "
                       "resolved fluid step's viscous limit)", fs->diffusion_number, RESOLVED_VISCOUS_LIMIT);
    gf_ns2_scheme scheme;
    gf_ns2_advection form;
    gf_ibm_forcing forcing;
    GF_TRY(numerics(ctx, fs, &scheme, &form, &forcing));
    /* the fluid step is a whole number (>= 1) of DEM steps: a DEM step beyond the fluid's limits would
     * force a fluid step that breaks them */
    double D = spec->grains.diameter_m, h = D / n, nu = fs->viscosity_Pa_s / fs->density_kg_m3;
    double dt_dem = gf_run_spec_dt_s(spec);
    double dt_visc = RESOLVED_VISCOUS_LIMIT * h * h / nu;
    double dt_adv = spec->gravity_m_s2 > 0.0 ? h / sqrt(spec->gravity_m_s2 * D) : INFINITY;
    if (dt_dem > dt_visc)
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "contact.dt_over_tc: the DEM step %.3g s exceeds the resolved fluid "
                       "step's viscous limit nu dt/dx^2 <= %g, dt <= %.3g s at D/dx = %g (shorten t_c or dt/t_c, or "
                       "coarsen the grid)", dt_dem, RESOLVED_VISCOUS_LIMIT, dt_visc, n);
    if (dt_dem > dt_adv)
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "contact.dt_over_tc: the DEM step %.3g s exceeds the resolved fluid "
                       "step's advective limit sqrt(gD) dt/dx <= 1, dt <= %.3g s at D/dx = %g", dt_dem, dt_adv, n);
    return GF_OK;
}

/* The resolved tier is the accuracy reference, chosen by name: `fluid: auto` never picks it. */
static int resolved_auto_fits(const gf_tier_query *q, char *why, size_t n)
{
    (void)q;
    snprintf(why, n, "resolved: grain-resolved, cost ~ (D/dx)^3 cells per grain: chosen by name only");
    return 0;
}

/* --- set-up ---------------------------------------------------------------------------------------- */

static gf_grid_bc map_bc(gf_fluid_bc b)
{
    return b == GF_BC_PERIODIC ? GF_GRID_PERIODIC : b == GF_BC_FREE_SLIP ? GF_GRID_FREE_SLIP : GF_GRID_NO_SLIP;
}

static gf_status grid_params(gf_ctx *ctx, const gf_run_spec *spec, const gf_coupling_setup *setup,
                             gf_fluid_params *fp)
{
    double h = spec->grains.diameter_m / d_over_dx(spec);
    *fp = (gf_fluid_params){.density_kg_m3 = spec->fluid.density_kg_m3, .viscosity_Pa_s = spec->fluid.viscosity_Pa_s};
    for (int d = 0; d < 3; ++d) {
        double L = setup->hi_m[d] - setup->lo_m[d];
        long n = lround(L / h);
        if (n < 1 || fabs(L / n - h) > 0.01 * h)
            return GF_FAIL(ctx, GF_ERR_CONFIG, "resolved tier: box edge %d (%.6g m = %.4g D) is not a whole number of "
                           "cells D/%g", d, L, L / spec->grains.diameter_m, d_over_dx(spec));
        if (setup->bc[d][0] == GF_BC_PERIODIC && L < spec->grains.diameter_m + 2.0 * GF_IBM_REACH_CELLS * h) {
            /* a grain's forcing shell would meet its own image's; a finer grid thins the shell */
            double D = spec->grains.diameter_m, need = 2.0 * GF_IBM_REACH_CELLS * D / (L - D);
            if (L > D)
                return GF_FAIL(ctx, GF_ERR_CONFIG, "resolved tier: periodic box edge %d = %.4g D is shorter than a "
                               "grain and its forcing shell (D + %.3g dx); it needs fluid.d_over_dx >= %.3g",
                               d, L / D, 2.0 * GF_IBM_REACH_CELLS, need);
            return GF_FAIL(ctx, GF_ERR_CONFIG, "resolved tier: periodic box edge %d = %.4g D is shorter than a grain "
                           "and its forcing shell", d, L / D);
        }
        fp->n_cells[d] = (int)n;
        fp->lo_m[d] = setup->lo_m[d];
        fp->hi_m[d] = setup->hi_m[d];
        fp->bc[d][0] = map_bc(setup->bc[d][0]);
        fp->bc[d][1] = map_bc(setup->bc[d][1]);
    }
    if ((double)fp->n_cells[0] * fp->n_cells[1] * fp->n_cells[2] > 1.2e8)
        return GF_FAIL(ctx, GF_ERR_CAPACITY, "resolved tier: grid %dx%dx%d is too large for one process",
                       fp->n_cells[0], fp->n_cells[1], fp->n_cells[2]);
    return GF_OK;
}

static void resolved_destroy(gf_coupling *cc)
{
    gf_resolved *c = R_(cc);
    if (!c)
        return;
    gf_fluid_destroy(&c->fluid);
    gf_ibm_free(&c->map);
    gf_ibm_markers_free(&c->markers);
    for (int a = 0; a < 3; ++a) {
        free(c->A[a]), free(c->A_old[a]), free(c->r[a]), free(c->u_pred[a]);
        free(c->force[a]), free(c->alpha_sum[a]), free(c->aU[a]);
    }
    for (int v = 0; v < RF_N; ++v)
        free(c->fields[v]);
    free(c->held_id), free(c->held_F), free(c->held_T), free(c->sub_F), free(c->sub_T);
    free(c->P0), free(c->L0), free(c->P1), free(c->L1), free(c->P_last), free(c->L_last);
    free(c->U_last), free(c->W_last), free(c->corr_F), free(c->corr_T), free(c->corr_F_last), free(c->corr_T_last);
    free(c);
}

static gf_status resolved_create(gf_ctx *ctx, const gf_run_spec *spec, const gf_coupling_setup *setup,
                                 gf_coupling **out)
{
    *out = NULL;
    gf_fluid_params fp;
    gf_ns2_scheme scheme;
    gf_ns2_advection form;
    gf_ibm_forcing forcing;
    GF_TRY(numerics(ctx, &spec->fluid, &scheme, &form, &forcing));
    GF_TRY(grid_params(ctx, spec, setup, &fp));
    gf_resolved *c = calloc(1, sizeof *c);
    if (!c)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "resolved tier: out of memory");
    c->ctx = ctx;
    c->spec = *spec;
    c->setup = *setup;
    c->first_step = 1;
    c->n_threads = 1;
    c->scheme = scheme, c->advection = form;
    c->forcing = forcing;
    c->contact_correction = forcing == GF_IBM_SMOOTHED && spec->fluid.ibm_contact_correction;
    /* markers: the retraction moves the markers; the fraction (internal momentum, fields) stays on R */
    c->map.retraction_cells = forcing == GF_IBM_MARKERS ? 0.0 : spec->fluid.ibm_retraction_dx;
    c->markers.retraction_cells = spec->fluid.ibm_retraction_dx;
    gf_status st = gf_fluid_create(ctx, &fp, &c->fluid);
    if (st != GF_OK) {
        free(c);
        return st;
    }
    const gf_grid *g = &c->fluid->grid;
    int ok = 1;
    for (int a = 0; a < 3; ++a) {
        size_t n = g->n_faces[a];
        ok &= (c->A[a] = calloc(n, sizeof(double))) != NULL;
        ok &= (c->A_old[a] = calloc(n, sizeof(double))) != NULL;
        ok &= (c->r[a] = calloc(n, sizeof(double))) != NULL;
        ok &= (c->u_pred[a] = calloc(n, sizeof(double))) != NULL;
        ok &= (c->force[a] = calloc(n, sizeof(double))) != NULL;
        ok &= (c->alpha_sum[a] = calloc(n, sizeof(double))) != NULL;
        ok &= (c->aU[a] = calloc(n, sizeof(double))) != NULL;
    }
    for (int v = 0; v < RF_N; ++v)
        ok &= (c->fields[v] = calloc(g->n_cells, sizeof(double))) != NULL;
    if (!ok) {
        resolved_destroy(&c->base);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "resolved tier: out of memory for %zu cells", g->n_cells);
    }
    gf_log(ctx, GF_LOG_INFO, "coupling: resolved, %dx%dx%d cells of %.3g m (D/dx = %g)", g->n[0], g->n[1], g->n[2],
           g->h_m[0], d_over_dx(spec));
    *out = &c->base;
    return GF_OK;
}

/* --- limits ---------------------------------------------------------------------------------------- */

/* sum_d max|u_d| / h_d over the faces and the grains. A max: the same on any number of threads (written
 * as a comparison, not fmax, so that it vectorises: both skip a NaN the same way). */
static double advective_rate(const gf_resolved *c, const gf_particles *p)
{
    const gf_grid *g = &c->fluid->grid;
    const int nt = c->n_threads;
    double s = 0.0;
    for (int a = 0; a < 3; ++a) {
        double m = 0.0;
        const double *u = c->fluid->u[a];
        const long n = (long)g->n_faces[a];
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static) reduction(max : m)
        for (long q = 0; q < n; ++q)
            m = fabs(u[q]) > m ? fabs(u[q]) : m;
        if (p) {
            const double *v = a == 0 ? p->vx_m_s : a == 1 ? p->vy_m_s : p->vz_m_s;
            for (size_t i = 0; i < p->n_local; ++i)
                m = fmax(m, fabs(v[i]));
        }
        s += m / g->h_m[a];
    }
    return s;
}

/* The fluid step the spec's limits allow at an advective rate (sum_d |u_d|/h, 1/s): the CFL bound, and
 * diffusion_number of the viscous one, whichever is shorter. */
static double step_bound_s(const gf_run_spec *spec, double h, double nu, double rate)
{
    return fmin(spec->fluid.cfl / fmax(rate, 1e-300), spec->fluid.diffusion_number * h * h / nu);
}

static double resolved_dt_max_s(const gf_coupling *cc, const gf_particles *p)
{
    const gf_resolved *c = CR(cc);
    const gf_grid *g = &c->fluid->grid;
    double h = g->h_m[0], nu = c->fluid->mu_Pa_s / c->fluid->rho_kg_m3;
    double rate = advective_rate(c, p);
    /* before anything moves: the grains' free-fall speed over D, so the step sized at t = 0 holds */
    double gm = sqrt(c->setup.gravity_m_s2[0] * c->setup.gravity_m_s2[0] +
                     c->setup.gravity_m_s2[1] * c->setup.gravity_m_s2[1] +
                     c->setup.gravity_m_s2[2] * c->setup.gravity_m_s2[2]);
    double D = c->spec.grains.diameter_m;
    double rate0 = gm > 0.0 ? sqrt(gm * D) / h : 0.0;
    return step_bound_s(&c->spec, h, nu, fmax(rate, rate0));
}

static gf_status check_step(const gf_resolved *c, const gf_particles *p, double dt_s)
{
    const gf_grid *g = &c->fluid->grid;
    double h = g->h_m[0], nu = c->fluid->mu_Pa_s / c->fluid->rho_kg_m3;
    if (!(dt_s > 0.0) || !isfinite(dt_s))
        return GF_FAIL(c->ctx, GF_ERR_ARG, "resolved fluid step: dt = %g s must be > 0", dt_s);
    double rate = advective_rate(c, p);
    if (rate * dt_s > 1.0)
        return GF_FAIL(c->ctx, GF_ERR_NUMERIC, "resolved fluid step dt = %.3g s breaks the advective limit "
                       "sum |u| dt/dx = %.2f > 1 (take dt <= %.3g s)", dt_s, rate * dt_s, 1.0 / rate);
    if (nu * dt_s / (h * h) > RESOLVED_VISCOUS_LIMIT)
        return GF_FAIL(c->ctx, GF_ERR_NUMERIC, "resolved fluid step dt = %.3g s breaks the viscous limit "
                       "nu dt/dx^2 = %.2f > %g (take dt <= %.3g s)", dt_s, nu * dt_s / (h * h),
                       RESOLVED_VISCOUS_LIMIT, RESOLVED_VISCOUS_LIMIT * h * h / nu);
    return GF_OK;
}

/* --- fluid step -------------------------------------------------------------------------------------- */

/* *a grown to n doubles; 0 when out of memory (*a then keeps its old buffer). */
static int grow(double **a, size_t n)
{
    double *q = realloc(*a, n * sizeof *q);
    if (q)
        *a = q;
    return q != NULL;
}

static gf_status reserve_held(gf_resolved *c, size_t n)
{
    if (n <= c->cap_held)
        return GF_OK;
    size_t cap = n + n / 2 + 8;
    int64_t *id = realloc(c->held_id, cap * sizeof *id);
    if (id)
        c->held_id = id;
    int ok = id != NULL;
    ok &= grow(&c->held_F, 3 * cap);
    ok &= grow(&c->held_T, 3 * cap);
    ok &= grow(&c->sub_F, 3 * cap);
    ok &= grow(&c->sub_T, 3 * cap);
    ok &= grow(&c->P0, 3 * cap) && grow(&c->L0, 3 * cap) && grow(&c->P1, 3 * cap) && grow(&c->L1, 3 * cap);
    ok &= grow(&c->P_last, 3 * cap) && grow(&c->L_last, 3 * cap);
    ok &= grow(&c->U_last, 3 * cap) && grow(&c->W_last, 3 * cap) && grow(&c->corr_F, 3 * cap) && grow(&c->corr_T, 3 * cap);
    ok &= grow(&c->corr_F_last, 3 * cap) && grow(&c->corr_T_last, 3 * cap);
    if (!ok)
        return GF_FAIL(c->ctx, GF_ERR_NOMEM, "resolved tier: out of memory for %zu grains", n);
    c->cap_held = cap;
    return GF_OK;
}

static void output_fields(gf_resolved *c)
{
    gf_fluid *f = c->fluid;
    const gf_grid *g = &f->grid;
    const double *const as[3] = {c->alpha_sum[0], c->alpha_sum[1], c->alpha_sum[2]};
    gf_ibm_cell_fraction(g, as, c->n_threads, c->fields[RF_ALPHA]);
    for (int a = 0; a < 3; ++a)
        gf_grid_cell_velocity(g, a, f->u[a], c->fields[RF_U + a]);
    memcpy(c->fields[RF_P], f->p_Pa, g->n_cells * sizeof(double));
}

/* G/rho (m/s^2): the weight balance of gf_weight_balance.h as a body acceleration of the fluid. */
static void mean_pressure_gradient(const gf_resolved *c, const gf_particles *p, double b_m_s2[3])
{
    double rho = c->fluid->rho_kg_m3;
    gf_weight_balance_gradient(&c->fluid->grid, p, rho, c->setup.gravity_m_s2, b_m_s2);
    for (int d = 0; d < 3; ++d)
        b_m_s2[d] /= rho;
}

/* One substep of the scheme (fluid/gf_fluid_ns2.h) with the grains frozen: rates, predictor, forcing (this
 * substep's force and torque on each grain into F, T), Crank-Nicolson, projection over 2 alpha dt; A^{k-1}
 * then becomes A^{k-2}. use_old: A_old holds A^{k-2} (else the Euler start, A_old = A). */
static gf_status fluid_substep(gf_resolved *c, const gf_particles *p, const gf_ns2_substep *s, int use_old,
                               const double b[3], double dt_s, double *F, double *T)
{
    gf_fluid *f = c->fluid;
    gf_fluid_ns2_advection(f, c->advection, c->A);
    const double *const A[3] = {c->A[0], c->A[1], c->A[2]};
    const double *const A_old[3] = {c->A_old[0], c->A_old[1], c->A_old[2]};
    gf_fluid_ns2_rates(f, s, A, use_old ? A_old : A, c->r);
    const double w = 2.0 * s->alpha, bw[3] = {w * b[0], w * b[1], w * b[2]};
    gf_fluid_ns2_add_acceleration(f, bw, c->r);
    const double *const r[3] = {c->r[0], c->r[1], c->r[2]};
    gf_fluid_ns2_predict(f, r, dt_s, c->u_pred);
    const double *const up[3] = {c->u_pred[0], c->u_pred[1], c->u_pred[2]};
    if (c->forcing == GF_IBM_MARKERS)
        GF_TRY(gf_ibm_markers_force(c->ctx, &c->markers, &f->grid, p, up, dt_s, f->rho_kg_m3, c->aU, c->force, F, T));
    else
        gf_ibm_force(&c->map, &f->grid, p, up, dt_s, f->rho_kg_m3, c->force, c->alpha_sum, c->aU, F, T);
    const double *const force[3] = {c->force[0], c->force[1], c->force[2]};
    GF_TRY(gf_fluid_ns2_viscous(c->ctx, f, s, r, force, dt_s));
    GF_TRY(gf_fluid_ns2_project(c->ctx, f, w * dt_s));
    gf_fluid_ns2_rotate(c->A, c->A_old);
    return GF_OK;
}

/* 1 when the store is in the order of the last fluid step's grains (held_id). */
static int held_in_order(const gf_resolved *c, const gf_particles *p)
{
    return c->held_epoch_known && c->held_epoch == p->order_epoch && c->n_held == p->n_local;
}

/* Index of grain i among the last fluid step's grains (held_id): i while the order holds, else matched by id
 * (few grains: a linear search); n_held when it was not there. */
static size_t held_slot(const gf_resolved *c, const gf_particles *p, size_t i)
{
    if (held_in_order(c, p))
        return i;
    size_t h = 0;
    while (h < c->n_held && c->held_id[h] != p->id[i])
        ++h;
    return h;
}

/* Markers (coupling/gf_ibm_markers.h): the fraction for the fields, and each grain's internal momentum at the
 * start of the step: over the volume it occupied during the last step, int alpha_i(x - x_i^{n-1}) u^n dV, the
 * last step's closing value, so that the rate follows the moving grain (Breugem 2012); over its present volume
 * at the first step. */
static void begin_internal_momentum(gf_resolved *c, const gf_particles *p)
{
    const gf_grid *g = &c->fluid->grid;
    gf_ibm_fraction(&c->map, g, c->alpha_sum);
    const double *const u[3] = {c->fluid->u[0], c->fluid->u[1], c->fluid->u[2]};
    gf_ibm_momentum(&c->map, g, p, u, c->P0, c->L0);
    for (size_t i = 0; c->last_known && i < p->n_local; ++i) {
        size_t h = held_slot(c, p, i);
        for (int d = 0; h < c->n_held && d < 3; ++d)
            c->P0[3 * i + d] = c->P_last[3 * h + d], c->L0[3 * i + d] = c->L_last[3 * h + d];
    }
}

/* The rest of the markers' force and torque: rho d/dt int_{V_i(t)} u dV - rho V_i g, and rho d/dt int r x u dV,
 * the rates over the step; the closing values kept for the next step. */
static void add_internal_momentum(gf_resolved *c, const gf_particles *p, double dt_s)
{
    const gf_grid *g = &c->fluid->grid;
    const double rho = c->fluid->rho_kg_m3, *grav = c->setup.gravity_m_s2;
    const double *const u[3] = {c->fluid->u[0], c->fluid->u[1], c->fluid->u[2]};
    gf_ibm_momentum(&c->map, g, p, u, c->P1, c->L1);
    for (size_t i = 0; i < p->n_local; ++i) {
        double R = p->radius_m[i], V = 4.0 / 3.0 * M_PI * R * R * R;
        for (int d = 0; d < 3; ++d) {
            c->held_F[3 * i + d] += rho * (c->P1[3 * i + d] - c->P0[3 * i + d]) / dt_s - rho * V * grav[d];
            c->held_T[3 * i + d] += rho * (c->L1[3 * i + d] - c->L0[3 * i + d]) / dt_s;
        }
    }
    memcpy(c->P_last, c->P1, 3 * p->n_local * sizeof(double));
    memcpy(c->L_last, c->L1, 3 * p->n_local * sizeof(double));
    c->last_known = 1;
}

/* The contact correction (fluid.ibm_contact_correction, smoothed forcing). Izard's force (2.32),
 * F = -(rho rho_p/(rho_p - rho)) int f, takes the fictitious inner fluid's momentum rate out of the forcing
 * integral by assuming that every acceleration of the grain is hydrodynamic. The inner fluid follows the grain
 * whatever accelerates it, so a contact or lubrication force N costs the forcing the inner fluid's share too,
 * and the formula scales that share up with the rest: over more than one fluid step the grain obeys
 *   m dU/dt = F' + (m - rho V) g + ((rho_p - rho)/rho_p) N          (F' the true surface force)
 * (Uhlmann's (2005) rigid inner fluid, rho V dU/dt = F' + rho int f), and a grain at rest on a wall presses on
 * it with its dry weight m g (tests/resolved/test_resolved_rest.c). The correction X added to the held force
 * restores m dU/dt = F' + (m - rho V) g + N once X = (rho/(rho_p - rho)) N. It is taken from the last fluid
 * step, where the grain's momentum balance gives the part of its acceleration that the formula did not
 * supply, R = m dU/dt - F_Izard - m g = N + X_last, as
 *   X = (rho/rho_p) R = (rho/rho_p) (N + X_last),
 * whose fixed point is that X, reached geometrically at the ratio rho/rho_p. Written with X_last inside, a
 * grain resting in contact (N = -(F_Izard + X_last + m g)) gets X = -(rho/rho_p)(F_Izard + m g) with no
 * feedback from the last X: X = (rho/(rho_p - rho)) N applied at once oscillates undamped at rho_p/rho = 2
 * and diverges below. Over a collision the X's add up to (rho/(rho_p - rho)) J, the inner fluid's catch-up
 * of the impulse J that the formula charges to the grain. With no contact, R = X_last and X decays to 0: free
 * grains are unchanged. The torque likewise, with I. The markers' force (Kempe & Froehlich 2012: the inner
 * momentum's measured rate) needs no correction. */
static void contact_correction_begin(gf_resolved *c, const gf_particles *p)
{
    const double rho = c->fluid->rho_kg_m3, *g = c->setup.gravity_m_s2;
    for (size_t i = 0; i < p->n_local; ++i) {
        double *cf = c->corr_F + 3 * i, *ct = c->corr_T + 3 * i;
        cf[0] = cf[1] = cf[2] = ct[0] = ct[1] = ct[2] = 0.0;
        size_t h = c->dt_last > 0.0 ? held_slot(c, p, i) : c->n_held;
        if (h >= c->n_held || (p->flags[i] & GF_P_GLUED))
            continue;
        const double R = p->radius_m[i], m = p->mass_kg[i], I = p->inertia_kg_m2[i];
        const double k = rho * 4.0 / 3.0 * M_PI * R * R * R / m; /* rho / rho_p */
        const double v[3] = {p->vx_m_s[i], p->vy_m_s[i], p->vz_m_s[i]};
        const double w[3] = {p->wx_rad_s[i], p->wy_rad_s[i], p->wz_rad_s[i]};
        for (int d = 0; d < 3; ++d) {
            const double F_izard = c->held_F[3 * h + d] - c->corr_F_last[3 * h + d];
            const double T_izard = c->held_T[3 * h + d] - c->corr_T_last[3 * h + d];
            cf[d] = k * (m * (v[d] - c->U_last[3 * h + d]) / c->dt_last - F_izard - m * g[d]);
            ct[d] = k * (I * (w[d] - c->W_last[3 * h + d]) / c->dt_last - T_izard);
        }
    }
}

/* Adds this step's correction to the held force and torque; keeps it and the grains' velocities for the next. */
static void contact_correction_end(gf_resolved *c, const gf_particles *p, double dt_s)
{
    for (size_t i = 0; i < p->n_local; ++i) {
        const double v[3] = {p->vx_m_s[i], p->vy_m_s[i], p->vz_m_s[i]};
        const double w[3] = {p->wx_rad_s[i], p->wy_rad_s[i], p->wz_rad_s[i]};
        for (int d = 0; d < 3; ++d) {
            c->held_F[3 * i + d] += c->corr_F[3 * i + d], c->held_T[3 * i + d] += c->corr_T[3 * i + d];
            c->U_last[3 * i + d] = v[d], c->W_last[3 * i + d] = w[d];
        }
    }
    memcpy(c->corr_F_last, c->corr_F, 3 * p->n_local * sizeof(double));
    memcpy(c->corr_T_last, c->corr_T, 3 * p->n_local * sizeof(double));
    c->dt_last = dt_s;
}

/* The step's substeps; the grains' held force and torque are the sum of the substeps' (each substep forces
 * the fluid by dt f_k: the step's impulse on the fluid is dt sum_k int f_k). */
static gf_status resolved_fluid_step(gf_coupling *cc, const gf_particles *p, double dt_s)
{
    gf_resolved *c = R_(cc);
    double t0 = gf_wtime();
    gf_fluid *f = c->fluid;
    GF_TRY(check_step(c, p, dt_s));
    GF_TRY(gf_ibm_build(c->ctx, &c->map, &f->grid, p));
    GF_TRY(reserve_held(c, p->n_local));
    double b[3];
    mean_pressure_gradient(c, p, b);
    if (c->forcing == GF_IBM_MARKERS)
        begin_internal_momentum(c, p);
    if (c->contact_correction)
        contact_correction_begin(c, p);
    const gf_ns2_substep *sub;
    int n_sub = gf_fluid_ns2_substeps(c->scheme, &sub);
    for (int k = 0; k < n_sub; ++k) {
        int use_old = gf_fluid_ns2_uses_previous(c->scheme, k, c->first_step);
        GF_TRY(fluid_substep(c, p, &sub[k], use_old, b, dt_s, k == 0 ? c->held_F : c->sub_F,
                             k == 0 ? c->held_T : c->sub_T));
        for (size_t q = 0; k > 0 && q < 3 * p->n_local; ++q)
            c->held_F[q] += c->sub_F[q], c->held_T[q] += c->sub_T[q];
    }
    if (c->forcing == GF_IBM_MARKERS)
        add_internal_momentum(c, p, dt_s);
    if (c->contact_correction)
        contact_correction_end(c, p, dt_s);
    for (size_t i = 0; i < p->n_local; ++i)
        c->held_id[i] = p->id[i];
    c->n_held = p->n_local;
    c->held_epoch = p->order_epoch, c->held_epoch_known = 1;
    c->first_step = 0;
    output_fields(c);
    if (gf_fluid_nonfinite(f))
        return GF_FAIL(c->ctx, GF_ERR_NUMERIC, "resolved fluid step: non-finite velocity or pressure");
    c->n_steps++;
    c->fluid_s += gf_wtime() - t0;
    return GF_OK;
}

/* --- forces on the grains ------------------------------------------------------------------------------- */

static void add_held(const gf_resolved *c, size_t h, gf_particles *p, size_t i)
{
    if (p->flags[i] & GF_P_GLUED)
        return;
    p->fx_N[i] += c->held_F[3 * h], p->fy_N[i] += c->held_F[3 * h + 1], p->fz_N[i] += c->held_F[3 * h + 2];
    p->tx_N_m[i] += c->held_T[3 * h], p->ty_N_m[i] += c->held_T[3 * h + 1], p->tz_N_m[i] += c->held_T[3 * h + 2];
}

static int resolved_forces_in_order(const gf_coupling *cc, const gf_particles *p)
{
    const gf_resolved *c = CR(cc);
    return c->first_step || held_in_order(c, p);
}

static void resolved_add_forces_range(gf_coupling *cc, gf_particles *p, size_t i0, size_t i1)
{
    gf_resolved *c = R_(cc);
    if (c->first_step)
        return;
    for (size_t i = i0; i < i1; ++i)
        add_held(c, i, p, i);
}

static gf_status resolved_add_forces(gf_coupling *cc, gf_particles *p)
{
    gf_resolved *c = R_(cc);
    if (c->first_step)
        return GF_OK; /* no fluid step yet: the fluid is at rest, nothing held */
    if (resolved_forces_in_order(cc, p)) {
        resolved_add_forces_range(cc, p, 0, p->n_local);
        return GF_OK;
    }
    for (size_t i = 0; i < p->n_local; ++i) {
        size_t h = held_slot(c, p, i);
        if (h < c->n_held)
            add_held(c, h, p, i);
    }
    return GF_OK;
}

static int resolved_grain_force(const gf_coupling *cc, const gf_particles *p, size_t i, double f_N[3])
{
    const gf_resolved *c = CR(cc);
    if (c->first_step)
        return 0; /* before the first fluid step: nothing held */
    size_t h = held_slot(c, p, i);
    if (h >= c->n_held)
        return 0;
    for (int d = 0; d < 3; ++d)
        f_N[d] = c->held_F[3 * h + d];
    return 1;
}

/* --- outputs, probes, settings ----------------------------------------------------------------------------- */

static double resolved_excess_pressure(const gf_coupling *cc, const double x[3])
{
    const gf_resolved *c = CR(cc);
    const gf_grid *g = &c->fluid->grid;
    int q[3];
    for (int d = 0; d < 3; ++d) {
        int m = (int)floor((x[d] - g->lo_m[d]) / g->h_m[d]);
        q[d] = m < 0 ? 0 : (m >= g->n[d] ? g->n[d] - 1 : m);
    }
    return c->fluid->p_Pa[gf_grid_cell(g, q[0], q[1], q[2])];
}

static int resolved_fields(const gf_coupling *cc, int n[3], double lo[3], double h[3], const gf_var_info **vars,
                           const double *const **fields)
{
    const gf_resolved *c = CR(cc);
    const gf_grid *g = &c->fluid->grid;
    for (int d = 0; d < 3; ++d)
        n[d] = g->n[d], lo[d] = g->lo_m[d], h[d] = g->h_m[d];
    *vars = resolved_vars;
    *fields = (const double *const *)c->fields;
    return RF_N;
}

static gf_status resolved_set_gravity(gf_coupling *cc, const double g[3])
{
    gf_resolved *c = R_(cc);
    for (int d = 0; d < 3; ++d)
        if (!isfinite(g[d]))
            return GF_FAIL(c->ctx, GF_ERR_ARG, "coupling: gravity component %d is not finite", d);
    memcpy(c->setup.gravity_m_s2, g, 3 * sizeof(double));
    return GF_OK;
}

/* The fluid step on n_threads OpenMP threads (gf_sim calls it once, after create, with any count >= 1): the
 * stencils and the immersed boundary give the same bits on any number (each face alone, sums in grain order,
 * maxima), and so do the FFTs, planned by slabs for every count (gf_poisson_plan_set_threads): a run is
 * bitwise the same on 1 or N threads. */
static void resolved_set_threads(gf_coupling *cc, int n_threads)
{
    gf_resolved *c = R_(cc);
    int n = n_threads > 1 ? n_threads : 1;
    gf_status st = gf_poisson_plan_set_threads(c->ctx, c->fluid->poisson, n);
    for (int a = 0; a < 3 && st == GF_OK; ++a)
        st = gf_helmholtz_plan_set_threads(c->ctx, c->fluid->visc[a], n);
    if (st != GF_OK) { /* FFTW could not plan threaded: stay on one thread, all plans serial */
        gf_log(c->ctx, GF_LOG_WARN, "resolved tier: %s; the fluid step stays on one thread", c->ctx->last_msg);
        n = 1;
        gf_poisson_plan_set_threads(c->ctx, c->fluid->poisson, 1);
        for (int a = 0; a < 3; ++a)
            gf_helmholtz_plan_set_threads(c->ctx, c->fluid->visc[a], 1);
    }
    c->n_threads = n;
    c->map.n_threads = n;
    c->markers.n_threads = n;
}

static double resolved_fluid_mass(const gf_coupling *cc)
{
    const gf_resolved *c = CR(cc);
    const gf_grid *g = &c->fluid->grid;
    double s = 0.0;
    for (size_t q = 0; q < g->n_cells; ++q)
        s += 1.0 - c->fields[RF_ALPHA][q];
    return c->fluid->rho_kg_m3 * s * g->h_m[0] * g->h_m[1] * g->h_m[2];
}

static double resolved_flow_rate(const gf_coupling *cc)
{
    const gf_resolved *c = CR(cc);
    const gf_grid *g = &c->fluid->grid;
    double s = 0.0;
    for (size_t q = 0; q < g->n_cells; ++q)
        s += (1.0 - c->fields[RF_ALPHA][q]) * c->fields[RF_U][q];
    return s * g->h_m[0] * g->h_m[1] * g->h_m[2] / (g->h_m[0] * g->n[0]);
}

/* --- checkpoint --------------------------------------------------------------------------------------------- */

static const char *const face_names[3][2] = {{"resolved_u", "resolved_adv_u"},
                                             {"resolved_v", "resolved_adv_v"},
                                             {"resolved_w", "resolved_adv_w"}};

enum { GRID_ARRAYS = 3 * 2 + 1 + RF_N };

/* The grid state a fluid step reads from the previous one (face velocities, the previous step's advection
 * term, pressure) and the output fields, in the order they are written. */
static void grid_arrays(const gf_resolved *c, gf_restart_array list[GRID_ARRAYS])
{
    const gf_grid *g = &c->fluid->grid;
    int n = 0;
    for (int a = 0; a < 3; ++a) {
        list[n++] = (gf_restart_array){face_names[a][0], g->n_faces[a], c->fluid->u[a]};
        list[n++] = (gf_restart_array){face_names[a][1], g->n_faces[a], c->A_old[a]};
    }
    list[n++] = (gf_restart_array){"resolved_p", g->n_cells, c->fluid->p_Pa};
    for (int v = 0; v < RF_N; ++v)
        list[n++] = (gf_restart_array){resolved_vars[v].name, g->n_cells, c->fields[v]};
}

static gf_status resolved_save(const gf_coupling *cc, gf_restart *r)
{
    const gf_resolved *c = CR(cc);
    const gf_grid *g = &c->fluid->grid;
    int64_t counts[5] = {g->n[0], g->n[1], g->n[2], c->first_step, c->n_steps};
    gf_restart_array list[GRID_ARRAYS];
    grid_arrays(c, list);
    GF_TRY(gf_restart_put_i64(r, "resolved_counts", 5, counts));
    GF_TRY(gf_coupling_put_arrays(r, list, GRID_ARRAYS));
    GF_TRY(gf_restart_put_i64(r, "resolved_held_id", c->n_held, c->held_id));
    GF_TRY(gf_restart_put_f64(r, "resolved_held_F", 3 * c->n_held, c->held_F));
    if (c->forcing == GF_IBM_MARKERS && c->last_known) { /* the markers' last internal momenta (the smoothed
                                                             forcing's checkpoint stays as it was) */
        GF_TRY(gf_restart_put_f64(r, "resolved_last_P", 3 * c->n_held, c->P_last));
        GF_TRY(gf_restart_put_f64(r, "resolved_last_L", 3 * c->n_held, c->L_last));
    }
    if (c->contact_correction && c->dt_last > 0.0) { /* the velocities the next correction differences against */
        GF_TRY(gf_restart_put_f64(r, "resolved_last_U", 3 * c->n_held, c->U_last));
        GF_TRY(gf_restart_put_f64(r, "resolved_last_W", 3 * c->n_held, c->W_last));
        GF_TRY(gf_restart_put_f64(r, "resolved_dt_last", 1, &c->dt_last));
        GF_TRY(gf_restart_put_f64(r, "resolved_last_XF", 3 * c->n_held, c->corr_F_last));
        GF_TRY(gf_restart_put_f64(r, "resolved_last_XT", 3 * c->n_held, c->corr_T_last));
    }
    return gf_restart_put_f64(r, "resolved_held_T", 3 * c->n_held, c->held_T);
}

static gf_status resolved_load(gf_coupling *cc, gf_restart *r)
{
    gf_resolved *c = R_(cc);
    if (!gf_restart_has(r, "resolved_counts"))
        return GF_FAIL(c->ctx, GF_ERR_CONFIG, "restart: the checkpoint holds no resolved-tier fluid state (a dry run "
                       "or another tier wrote it)");
    int64_t counts[5];
    GF_TRY(gf_restart_get_i64(r, "resolved_counts", 5, counts));
    GF_TRY(gf_coupling_check_grid(c->ctx, counts, &c->fluid->grid));
    gf_restart_array list[GRID_ARRAYS];
    grid_arrays(c, list);
    GF_TRY(gf_coupling_get_arrays(r, list, GRID_ARRAYS));
    size_t n = 0;
    GF_TRY(gf_restart_len(r, "resolved_held_id", &n));
    GF_TRY(reserve_held(c, n));
    GF_TRY(gf_restart_get_i64(r, "resolved_held_id", n, c->held_id));
    GF_TRY(gf_restart_get_f64(r, "resolved_held_F", 3 * n, c->held_F));
    GF_TRY(gf_restart_get_f64(r, "resolved_held_T", 3 * n, c->held_T));
    c->last_known = c->forcing == GF_IBM_MARKERS && gf_restart_has(r, "resolved_last_P");
    if (c->last_known) {
        GF_TRY(gf_restart_get_f64(r, "resolved_last_P", 3 * n, c->P_last));
        GF_TRY(gf_restart_get_f64(r, "resolved_last_L", 3 * n, c->L_last));
    }
    c->dt_last = 0.0;
    if (c->contact_correction && gf_restart_has(r, "resolved_dt_last")) {
        GF_TRY(gf_restart_get_f64(r, "resolved_last_U", 3 * n, c->U_last));
        GF_TRY(gf_restart_get_f64(r, "resolved_last_W", 3 * n, c->W_last));
        GF_TRY(gf_restart_get_f64(r, "resolved_dt_last", 1, &c->dt_last));
        GF_TRY(gf_restart_get_f64(r, "resolved_last_XF", 3 * n, c->corr_F_last));
        GF_TRY(gf_restart_get_f64(r, "resolved_last_XT", 3 * n, c->corr_T_last));
    }
    c->n_held = n;
    c->held_epoch_known = 0; /* matched by id at the first substep */
    c->first_step = (int)counts[3];
    c->n_steps = (long)counts[4];
    return GF_OK;
}

/* --- cost (gf_coupling_tier.cost) --------------------------------------------------------------- */

/*
 * CPU of one fluid step on one core: c_cell per grid cell (stencils, Crank-Nicolson, the FFT
 * projection) and c_grain per cell of each grain's (D/dx)^3 (its maps, forcing and integrals;
 * docs/notes/resolved-multigrain.md, "Where the time goes"), times the time scheme's factor.
 * Measured on one thread (Release, no LTO, the other core busy) as the CPU between end_time 0.02
 * and 1.0 (0.5 for the collapses) sqrt(D/g), per fluid step:
 *   one sphere settling, D/dx 12, 96^3 cells:                  0.136 s  -> c_cell 1.54e-7 s
 *   avalanche, viscous point, D/dx 8, 40x160x40, 240 grains:   0.0773 s -> c_grain 3.1e-7 s
 *   collapse, D/dx 10, 500x300x20, ~338 grains:                0.555 s  -> c_grain 2.8e-7 s
 *   collapse, D/dx 8, 400x240x24, ~500 grains:                 0.506 s  (the model: 0.433, -14 %)
 * and rk3 2.3 times ab2 on the avalanche (the maps are built once a step, the rest three times).
 */
#define RESOLVED_COST_S_PER_CELL 1.54e-7
#define RESOLVED_COST_S_PER_GRAIN_CELL 3.0e-7
#define RESOLVED_COST_RK3_FACTOR 2.3

/* The fluid step as resolved_dt_max_s sizes it at rest (the viscous bound, or the advective one at the
 * free-fall speed sqrt(gD)), in whole DEM steps (gf_sim_choose_substeps); *advective when the advective
 * bound is the shorter: a flow faster than sqrt(gD) then shortens the step (the Table 4.2 inertial
 * avalanche: 0.037 sqrt(D/g) at rest, ~0.005 on average over 100 sqrt(D/g)). */
static double resolved_step_at_rest_s(const gf_run_spec *spec, int *advective)
{
    const double D = spec->grains.diameter_m, h = D / d_over_dx(spec);
    const double nu = spec->fluid.viscosity_Pa_s / spec->fluid.density_kg_m3, dt_dem = gf_run_spec_dt_s(spec);
    const double dt = step_bound_s(spec, h, nu, spec->gravity_m_s2 > 0.0 ? sqrt(spec->gravity_m_s2 * D) / h : 0.0);
    *advective = dt < spec->fluid.diffusion_number * h * h / nu;
    return fmax(floor(dt / dt_dem), 1.0) * dt_dem;
}

static void resolved_cost(const gf_run_spec *spec, const gf_tier_cost_query *q, gf_tier_cost *out)
{
    const double n = d_over_dx(spec), h = spec->grains.diameter_m / n;
    out->cells = round(q->box_m[0] / h) * round(q->box_m[1] / h) * round(q->box_m[2] / h); /* NaN: box unknown */
    out->fluid_steps = ceil(q->fluid_time_s / resolved_step_at_rest_s(spec, &out->at_least));
    gf_ns2_scheme scheme = GF_NS2_AB2;
    gf_fluid_ns2_scheme_from_name(spec->fluid.time_scheme, &scheme);
    const double per_step = RESOLVED_COST_S_PER_CELL * out->cells + RESOLVED_COST_S_PER_GRAIN_CELL * q->n_grains * n * n * n;
    out->cpu_s = out->fluid_steps * per_step * (scheme == GF_NS2_RK3 ? RESOLVED_COST_RK3_FACTOR : 1.0);
}

const gf_coupling_tier gf_coupling_tier_resolved = {
    .name = "resolved",
    .summary = "Navier-Stokes inside the grains too, immersed-boundary direct forcing at D/dx = 8-20",
    .create = resolved_create,
    .destroy = resolved_destroy,
    .check = resolved_check,
    .auto_fits = resolved_auto_fits,
    .dt_max_s = resolved_dt_max_s,
    .fluid_step = resolved_fluid_step,
    .add_forces = resolved_add_forces,
    .forces_in_order = resolved_forces_in_order,
    .add_forces_range = resolved_add_forces_range,
    .excess_pressure_Pa = resolved_excess_pressure,
    .fields = resolved_fields,
    .set_gravity = resolved_set_gravity,
    .set_threads = resolved_set_threads,
    .save = resolved_save,
    .load = resolved_load,
    .fluid_flow_rate = resolved_flow_rate,
    .fluid_mass_kg = resolved_fluid_mass,
    .grain_force = resolved_grain_force,
    .cost = resolved_cost,
};
