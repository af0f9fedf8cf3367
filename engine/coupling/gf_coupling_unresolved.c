/*
 * Unresolved CFD-DEM coupling: the "unresolved" tier behind gf_coupling.h.
 *
 * Fluid equations: the locally averaged Navier–Stokes equations of Anderson
 * & Jackson (I&EC Fundam. 6, 1967) in the form called "model A" by
 * Gidaspow (1994) and "set II" by Zhou, Kuang, Chu & Yu (JFM 661, 2010),
 * pressure shared by both phases:
 *   d(eps)/dt + div(eps u) = 0
 *   d(eps rho u)/dt + div(eps rho u u) = -eps grad p + div(eps tau) + eps rho g - f_d
 * with eps the fluid fraction and f_d = sum_i K_i (u_f(x_i) - v_i) delta_i the
 * drag density, delta_i the smoothing kernel of gf_average. The force on
 * grain i is
 *   F_i = K_i (u_f(x_i) - v_i) - V_i grad p(x_i)
 * and p contains the hydrostatic part: p = p_h + p', p_h = rho g.x, so a grain
 * at rest in a fluid at rest feels exactly -rho V_i g (Archimedes), added
 * analytically, while the grid carries only the excess pore pressure p' the
 * gauges report. The reaction of -V grad p on the fluid is already inside
 * the -eps grad p term (the phi grad p share), so the only explicit exchange
 * term in the fluid equation is -f_d: fluid + grains conserve momentum (up to
 * the sub-cycling lag, see fix_mixture_momentum).
 * In p' form the fluid equation has no gravity: the step of gf_fluid.h with
 * beta = sum_i K_i delta_i / V_cell and the implicit drag inside the projection.
 *
 * Periodic gravity axis (homogeneous suspensions). p' must then be periodic,
 * so the weight in excess of buoyancy of free grains is carried by a mean
 * pressure gradient -<grad p'> = G = -phi_mean (rho_p - rho_f) g applied to
 * both phases (eps G on the fluid, V_i G on grain i), which keeps the mixture's
 * momentum constant, as the bottom of a settling tank would (Capecelatro &
 * Desjardins 2013). When glued grains exist (a rough bed carries the weight,
 * e.g. an avalanche on a periodic incline) G = 0: the fluid then stays at rest
 * far from the grains and each grain keeps the full buoyancy -rho V g, which
 * is the "physical tank" form, not Izard 2014 (4.6), which may drop the
 * downslope buoyancy.
 *
 * Drag closures: gf_drag.h (the mean-slip ones also gf_coupling_mean_slip.c). Two choices made here:
 *  1. The closure's phi excludes the grain's own kernel-smoothed volume: a lone
 *     grain must see phi = 0 (otherwise Beetstra's sqrt(phi) and Tenneti's
 *     phi^{1/3} terms add 5-13 % to an isolated sphere's drag for a kernel of
 *     125 D^3). In a suspension with ~100 grains per kernel this changes phi
 *     by ~1 %.
 *  2. Self-induced velocity. A grain's own reaction force, spread over the
 *     kernel, moves the fluid at its centre by u_self = -G0 F_d, with
 *     G0 ~ 1/(6 pi^{3/2} eta sigma), the Stokes flow of a Gaussian force of
 *     width sigma averaged with the same Gaussian (Maxey & Patel, IJMF 27,
 *     2001, force-coupling method). With sigma = 2.5 D this is 11-13 % of the
 *     Stokes velocity. The undisturbed velocity is recovered as u_f + s_i G0 F_d
 *     (Balachandar, Liu & Lakhote, JCP 376, 2019; Evrard, Denner & van Wachem,
 *     JCP 2020 use the same idea), i.e. K_eff = K / (1 - s_i K G0), where s_i
 *     is the grain's own share of the kernel-averaged solid fraction at its
 *     centre: 1 for a lone grain, ~1/N in a suspension whose smoothed force
 *     density is uniform and whose averaged velocity is already the
 *     closure's mean (homogeneous suspensions need no correction). K G0 s is
 *     capped at 0.5. G0 is measured on this grid (calibrate_self_mobility:
 *     the discrete Stokes value; within 1 % of the continuum one at
 *     sigma = h, but not for other kernel/cell ratios) and reduced
 *     at finite kernel Reynolds number rho W sigma/eta by the Oseen factor of
 *     oseen_factor_exact (the disturbance is swept downstream).
 *
 * Time stepping (Izard 2014 §2.3.1 sub-cycling): per fluid step
 * the grains are frozen, eps^{n+1} and K_i are built from them, the fluid
 * advances with the drag implicit (gf_project.c), then the fluid velocity at
 * each grain and grad p' are held for the M DEM substeps. The drag in
 * gf_coupling_add_forces uses the grain's CURRENT velocity v and the force
 * already accumulated on it (contacts, lubrication: gf_sim calls it after
 * them) plus gravity, F_tot = F_already + m g + F_other (pressure, buoyancy):
 *   m dv/dt = K (u_f - v) + F_tot  has the exact solution over dt_s
 *   v' = v_eq + (v - v_eq) e^{-x},  v_eq = u_f + F_tot/K,  x = K dt_s / m,
 * and the force that makes one explicit step (the velocity-Verlet kick pair of
 * gf_sim, or symplectic Euler) land on it is
 *   F_add = phi1 K (u_f - v) + phi1 F_other + (phi1 - 1)(F_already + m g),
 *   phi1(x) = (1 - e^{-x}) / x  (-> the plain explicit drag when x << 1).
 * This is unconditionally stable AND gives the exact terminal slip F_tot/K for
 * any particle response time m/K, so small-St grains do not force small DEM
 * steps (dt_s is gf_run_spec_dt_s(spec), or gf_coupling_set_dem_step). The
 * coupled lag scheme
 * (fluid implicit towards the grains, grains exponentially towards the
 * fluid) contracts the slip by e^{-dt/tau_p}/(1 + dt beta/(eps rho)) per
 * fluid step: no drag stability limit. gf_coupling_dt_max_s returns the
 * advective CFL limit (fluid and grains, margin spec.fluid.cfl; the grains'
 * velocity scale min(Stokes settling, sqrt(drho/rho_p g D)) stands in for
 * their speed before they move) and the viscous accuracy bound h^2/nu (the
 * viscous step is implicit; beyond h^2/nu the kernel-scale flow would lag),
 * and, in packed regions only, the pore-pressure feedback bound 0.5 m/K
 * (pore_pressure_limit: the lagged dilation/pressure loop is unstable
 * beyond ~ m/K there); a
 * step past the advective STABILITY limit (CFL 1), or one that lets a grain
 * cross more than a cell, is refused with GF_ERR_NUMERIC naming the limit.
 *
 * Grid: cells of spec.fluid.cell_over_D D (rounded so that an integer number
 * fits each axis), kernel sigma = the largest cell edge (>= one cell, >= D).
 * Torques: the unresolved tier applies no fluid torque (rotational drag of
 * a sphere is O((D/h)^3) smaller in the averaged equations); lubrication
 * is computed in the DEM pair loop.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/gf_timer.h"
#include "coupling/gf_average.h"
#include "coupling/gf_coupling.h"
#include "coupling/gf_weight_balance.h"
#include "coupling/gf_coupling_diag.h"
#include "coupling/gf_coupling_tier.h"
#include "coupling/gf_coupling_unresolved.h"
#include "coupling/gf_drag.h"
#include "fluid/gf_fluid.h"

#define EPS_FLOOR 0.25  /* below any random packing's fluid fraction (0.36) after smoothing */
#define SELF_CAP 0.5
/* below this many grains the per-grain loops of the fluid step stay on one thread (thread start-up) */
#define PARALLEL_MIN_GRAINS 1000
#define OSEEN_LOG_RE0 (-3.0)
#define OSEEN_DLOG_RE (7.0 / (OSEEN_N - 1))

/* The tier's object behind the handle the tier row receives (gf_coupling base is its first member). */
static gf_unresolved *U(gf_coupling *c) { return (gf_unresolved *)c; }
static const gf_unresolved *CU(const gf_coupling *c) { return (const gf_unresolved *)c; }

static const gf_var_info field_vars[FLD_N] = {
    {"fluid_fraction", "1", "fluid volume fraction (kernel-averaged)", NULL},
    {"u_fluid", "m s-1", "fluid velocity along x (interstitial, cell-centred)", NULL},
    {"v_fluid", "m s-1", "fluid velocity along y (interstitial, cell-centred)", NULL},
    {"w_fluid", "m s-1", "fluid velocity along z (interstitial, cell-centred)", NULL},
    {"excess_pressure", "Pa", "fluid pressure minus hydrostatic", NULL},
};


/*
 * Self-mobility G0 of a kernel-spread force on this grid: the Stokes velocity,
 * interpolated with the same kernel, per unit force. The continuum value
 * 1/(6 pi^{3/2} eta sigma) (Maxey & Patel 2001) ignores the discretisation
 * (MAC Laplacian, cell-integrated kernel, face <-> cell averaging), so it is
 * measured: one backward-Euler step with dt -> infinity
 * on a periodic 24^3 grid of the same cells IS the discrete steady Stokes
 * solution; the periodic images are removed with Hasimoto's (JFM 5, 1959)
 * leading term, G0 = G0_periodic + 2.8373 / (6 pi eta L). Averaged over four
 * sub-cell positions of the force.
 */
/*
 * Finite-Reynolds-number reduction of the self-induced velocity. For a
 * force F spread and sampled with Gaussians (combined width sigma) in a
 * uniform stream W, the linearised (Oseen) velocity at the centre, along F, is
 *   u = F/(mu sigma) (1/(4 pi^2)) int_0^inf ds e^{-s^2} int_{-1}^{1} dc (1 - c^2) s^2/(s^2 + R^2 c^2),
 * R = rho W sigma / mu, Fourier variable s = k sigma, c = cos(k, W). The c
 * integral is 2a[(1 + a^2) atan(1/a) - a] with a = s/R (4/3 at R = 0: the
 * Stokes value 1/(6 pi^{3/2} mu sigma)). f(R) = u(R)/u(0) falls as ~1.3/R: at
 * the Re_p = 20 of Izard 2014 §2.2.3 the kernel Reynolds number is ~50 and the Stokes
 * correction would overestimate the drag by 30 %. Tabulated on a log grid.
 */
static double oseen_factor_exact(double R)
{
    const int ns = 400;
    const double smax = 6.0;
    double sum = 0.0;
    for (int q = 0; q < ns; ++q) {
        double s = (q + 0.5) * smax / ns;
        double inner;
        if (R < 1e-12) {
            inner = 4.0 / 3.0;
        } else {
            double a = s / R;
            inner = a > 1e3 ? 4.0 / 3.0 - 0.8 / (a * a) /* series: 4/3 - 4/(5 a^2) */
                            : 2.0 * a * ((1.0 + a * a) * atan(1.0 / a) - a);
        }
        sum += exp(-s * s) * inner * smax / ns;
    }
    return sum / (4.0 / 3.0 * sqrt(M_PI) / 2.0);
}

static double oseen_factor(const gf_unresolved *c, double R)
{
    if (!(R > 0.0))
        return 1.0;
    double t = (log10(R) - OSEEN_LOG_RE0) / OSEEN_DLOG_RE;
    if (t <= 0.0)
        return c->oseen[0];
    if (t >= OSEEN_N - 1)
        return c->oseen[OSEEN_N - 1] * pow(10.0, OSEEN_LOG_RE0 + (OSEEN_N - 1) * OSEEN_DLOG_RE) / R;
    int j = (int)t;
    double w = t - j;
    return (1.0 - w) * c->oseen[j] + w * c->oseen[j + 1];
}

static gf_status calibrate_self_mobility(gf_ctx *ctx, gf_unresolved *c)
{
    for (int j = 0; j < OSEEN_N; ++j)
        c->oseen[j] = oseen_factor_exact(pow(10.0, OSEEN_LOG_RE0 + j * OSEEN_DLOG_RE));
    const gf_grid *g = &c->fluid->grid;
    enum { NCAL = 24 };
    gf_fluid_params fp = {.density_kg_m3 = c->rho_f, .viscosity_Pa_s = c->mu, .n_cells = {NCAL, NCAL, NCAL}};
    for (int d = 0; d < 3; ++d) {
        fp.lo_m[d] = 0.0;
        fp.hi_m[d] = NCAL * g->h_m[d];
        fp.bc[d][0] = fp.bc[d][1] = GF_GRID_PERIODIC;
    }
    gf_fluid *f = NULL;
    GF_TRY(gf_fluid_create(ctx, &fp, &f));
    const gf_grid *gc = &f->grid;
    double vc = gc->h_m[0] * gc->h_m[1] * gc->h_m[2];
    double dt = 1e8 * gc->h_m[2] * gc->h_m[2] * c->rho_f / c->mu;
    static const double offs[4][3] = {{0.5, 0.5, 0.5}, {0.0, 0.0, 0.0}, {0.25, 0.7, 0.1}, {0.9, 0.35, 0.6}};
    double sum = 0.0;
    gf_status st = GF_OK;
    double *uc = f->tmp[3];
    for (int o = 0; o < 4 && st == GF_OK; ++o) {
        double x[3];
        for (int d = 0; d < 3; ++d)
            x[d] = (NCAL / 2 + offs[o][d]) * gc->h_m[d];
        gf_kernel k;
        gf_average_kernel(gc, c->sigma_m, x, &k);
        for (int a = 0; a < 3; ++a) {
            memset(f->u[a], 0, gc->n_faces[a] * sizeof(double));
            memset(f->body[a], 0, gc->n_cells * sizeof(double));
        }
        memset(f->p_Pa, 0, gc->n_cells * sizeof(double));
        gf_average_spread(gc, &k, 1.0 / c->rho_f, f->body[2]);  /* unit force, per unit fluid mass */
        double mean = 1.0 / (c->rho_f * vc * (double)gc->n_cells);
        for (size_t cc = 0; cc < gc->n_cells; ++cc)
            f->body[2][cc] -= mean;  /* periodic box: the mean force is balanced by a mean pressure gradient */
        gf_fluid_advect(f, dt);
        st = gf_fluid_viscous(ctx, f, dt);
        if (st == GF_OK)
            st = gf_fluid_project(ctx, f, dt);
        gf_grid_cell_velocity(gc, 2, f->u[2], uc);
        sum += gf_average_interpolate(gc, &k, uc);
    }
    gf_fluid_destroy(&f);
    GF_TRY(st);
    double L = cbrt(NCAL * g->h_m[0] * NCAL * g->h_m[1] * NCAL * g->h_m[2]);
    c->self_mobility = sum / 4.0 + 2.8373 / (6.0 * M_PI * c->mu * L);
    c->sigma_eff_m = 1.0 / (6.0 * pow(M_PI, 1.5) * c->mu * c->self_mobility);
    return GF_OK;
}

/* Pressure reference: the face opposite to gravity on a non-periodic gravity axis (the free-surface side). */
static void pressure_reference_axis(gf_unresolved *c)
{
    const gf_grid *g = &c->fluid->grid;
    const double *gv = c->setup.gravity_m_s2;
    c->ref_axis = -1;
    int ga = 0;
    for (int d = 1; d < 3; ++d)
        if (fabs(gv[d]) > fabs(gv[ga]))
            ga = d;
    if (gv[ga] != 0.0 && !g->periodic[ga]) {
        c->ref_axis = ga;
        c->ref_side = gv[ga] < 0.0 ? 1 : 0;
    }
}

static gf_status unresolved_set_gravity(gf_coupling *base, const double g[3])
{
    gf_unresolved *c = U(base);
    for (int d = 0; d < 3; ++d)
        if (!isfinite(g[d]))
            return GF_FAIL(c->ctx, GF_ERR_ARG, "coupling: gravity component %d is not finite", d);
    for (int d = 0; d < 3; ++d)
        c->setup.gravity_m_s2[d] = g[d];
    pressure_reference_axis(c);
    return GF_OK;
}

/* --- set-up --------------------------------------------------------------------------------- */

static gf_grid_bc map_bc(gf_fluid_bc b)
{
    return b == GF_BC_PERIODIC ? GF_GRID_PERIODIC : b == GF_BC_FREE_SLIP ? GF_GRID_FREE_SLIP : GF_GRID_NO_SLIP;
}

static void unresolved_destroy(gf_coupling *base);

static gf_status unresolved_create(gf_ctx *ctx, const gf_run_spec *spec, const gf_coupling_setup *setup,
                                   gf_coupling **out)
{
    *out = NULL;
    const gf_fluid_spec *fs = &spec->fluid;
    if (!(fs->density_kg_m3 > 0.0) || !(fs->viscosity_Pa_s > 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid: density (%g kg/m3) and viscosity (%g Pa s) must be > 0 for an "
                       "immersed run", fs->density_kg_m3, fs->viscosity_Pa_s);
    if (!(fs->cell_over_D >= 1.0) || fs->cell_over_D > 20.0)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid.cell_over_D = %g: the unresolved tier needs cells of 1-20 D "
                       "(a cell must hold a few grains; 1.5-3 is usual)", fs->cell_over_D);
    if (!(fs->cfl > 0.0 && fs->cfl <= 1.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid.cfl = %g must be in (0, 1]", fs->cfl);
    const gf_drag_info *law;
    GF_TRY(gf_drag_find(ctx, fs->drag, &law));
    double D = spec->grains.diameter_m;
    if (!(D > 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "grains.diameter_m = %g must be > 0", D);

    gf_unresolved *c = calloc(1, sizeof *c);
    if (!c)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "coupling: out of memory");
    c->ctx = ctx;
    c->spec = *spec;
    c->setup = *setup;
    c->law = law;
    c->rho_f = fs->density_kg_m3;
    c->mu = fs->viscosity_Pa_s;
    c->first_step = 1;
    c->n_threads = 1;
    c->dt_dem_s = gf_run_spec_dt_s(spec);

    gf_fluid_params fp = {.density_kg_m3 = c->rho_f, .viscosity_Pa_s = c->mu};
    double hmax = 0.0;
    for (int d = 0; d < 3; ++d) {
        double L = setup->hi_m[d] - setup->lo_m[d];
        int n = (int)lround(L / (fs->cell_over_D * D));
        fp.n_cells[d] = n < 1 ? 1 : n;
        fp.lo_m[d] = setup->lo_m[d];
        fp.hi_m[d] = setup->hi_m[d];
        fp.bc[d][0] = map_bc(setup->bc[d][0]);
        fp.bc[d][1] = map_bc(setup->bc[d][1]);
        double h = L / fp.n_cells[d];
        if (fp.n_cells[d] > 1 || !(fp.bc[d][0] == GF_GRID_PERIODIC))
            hmax = h > hmax ? h : hmax;
    }
    if ((double)fp.n_cells[0] * fp.n_cells[1] * fp.n_cells[2] > 2e7) {
        free(c);
        return GF_FAIL(ctx, GF_ERR_CAPACITY, "fluid grid %dx%dx%d is too large for the unresolved tier", fp.n_cells[0],
                       fp.n_cells[1], fp.n_cells[2]);
    }
    gf_status st = gf_fluid_create(ctx, &fp, &c->fluid);
    if (st != GF_OK) {
        free(c);
        return st;
    }
    const gf_grid *g = &c->fluid->grid;
    c->sigma_m = fmax(hmax > 0.0 ? hmax : fs->cell_over_D * D, D);
    st = calibrate_self_mobility(ctx, c);
    if (st != GF_OK) {
        unresolved_destroy(&c->base);
        return st;
    }

    pressure_reference_axis(c);
    int ok = 1;
    for (int a = 0; a < 3; ++a) {
        ok &= (c->uc[a] = calloc(g->n_cells, sizeof(double))) != NULL;
        ok &= (c->gp[a] = calloc(g->n_cells, sizeof(double))) != NULL;
    }
    for (int v = 0; v < FLD_N; ++v)
        ok &= (c->fields[v] = calloc(g->n_cells, sizeof(double))) != NULL;
    /* a cell's lanes are one cache line: 64-byte aligned */
    ok &= (c->lanes = aligned_alloc(64, g->n_cells * GF_AVERAGE_LANES * sizeof(double))) != NULL;
    if (!ok) {
        unresolved_destroy(&c->base);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "coupling: out of memory for %zu cells", g->n_cells);
    }
    for (size_t i = 0; i < g->n_cells; ++i)
        c->fields[FLD_EPS][i] = 1.0;
    for (int d = 0; d < 3; ++d) {
        c->stats.n_cells[d] = g->n[d];
        c->stats.cell_m[d] = g->h_m[d];
    }
    c->stats.kernel_sigma_m = c->sigma_m;
    c->stats.self_mobility_s_kg = c->self_mobility;
    gf_log(ctx, GF_LOG_INFO, "coupling: unresolved, %dx%dx%d cells of %.3g x %.3g x %.3g m, kernel sigma %.3g m, drag %s",
           g->n[0], g->n[1], g->n[2], g->h_m[0], g->h_m[1], g->h_m[2], c->sigma_m, law->name);
    *out = &c->base;
    return GF_OK;
}

static void unresolved_set_threads(gf_coupling *base, int n_threads)
{
    gf_unresolved *c = U(base);
    c->n_threads = n_threads > 1 ? n_threads : 1;
}

static void unresolved_destroy(gf_coupling *base)
{
    gf_unresolved *c = U(base);
    gf_fluid_destroy(&c->fluid);
    for (int a = 0; a < 3; ++a) {
        free(c->uc[a]);
        free(c->gp[a]);
    }
    for (int v = 0; v < FLD_N; ++v)
        free(c->fields[v]);
    free(c->lanes);
    free(c->kern);
    free(c->held);
    free(c->mean_v);
    free(c);
}

gf_status gf_unresolved_reserve(gf_unresolved *c, size_t n)
{
    if (n <= c->cap)
        return GF_OK;
    size_t cap = n + n / 2 + 16;
    gf_kernel *k = realloc(c->kern, cap * sizeof *k);
    if (!k)
        return GF_FAIL(c->ctx, GF_ERR_NOMEM, "coupling: out of memory for %zu grains", n);
    c->kern = k;
    held_grain *h = realloc(c->held, cap * sizeof *h);
    if (!h)
        return GF_FAIL(c->ctx, GF_ERR_NOMEM, "coupling: out of memory for %zu grains", n);
    c->held = h;
    c->cap = cap;
    return GF_OK;
}

/* --- stability -------------------------------------------------------------------------------- */

static double grain_speed_max(const gf_particles *p)
{
    double m = 0.0;
    for (size_t i = 0; i < p->n_local; ++i) {
        double v = fmax(fabs(p->vx_m_s[i]), fmax(fabs(p->vy_m_s[i]), fabs(p->vz_m_s[i])));
        m = v > m ? v : m;
    }
    return m;
}

/* sum_d |u_d|max / h_d over the fluid faces: dt times this is the upwind CFL number */
static double advective_rate(const gf_unresolved *c)
{
    const gf_grid *g = &c->fluid->grid;
    double s = 0.0;
    for (int a = 0; a < 3; ++a) {
        double m = 0.0;
        for (size_t i = 0; i < g->n_faces[a]; ++i)
            m = fmax(m, fabs(c->fluid->u[a][i]));
        s += m / g->h_m[a];
    }
    return s;
}

static double min_cell(const gf_unresolved *c)
{
    const gf_grid *g = &c->fluid->grid;
    double h = 1e300;
    for (int d = 0; d < 3; ++d)
        if (g->n[d] > 1 || !g->periodic[d])
            h = fmin(h, g->h_m[d]);
    return h < 1e300 ? h : g->h_m[0];
}

/*
 * Pore-pressure feedback limit (the drag-relaxation limit of packed
 * regions). In a packed region (phi > PHI_PACKED) the grains' motion and the
 * pore pressure are tied: dilation sucks fluid in and the suction slows the
 * dilation (Iverson 2000; Rondon 2011). The fluid sees the grains' dilation
 * one fluid step late; when the grains respond to the held pressure within
 * the step (response time tau_p = m/K shorter than the step), the loop
 * "dilation -> suction -> compaction -> over-pressure" has a gain ~ phi/eps > 1
 * and the pore pressure oscillates step to step (measured in the dense
 * column at dt_f = 2 tau_p: +-0.9 drho g H0 under a column at rest). Hence
 * dt_f <= 0.5 tau_p over grains in packed regions, the practice of
 * CFDEM-type codes (coupling interval below the particle relaxation time);
 * with it the same column shows a smooth suction of -0.03..-0.1 drho g H0.
 * Dilute grains (suspensions, single spheres) do not constrain the step:
 * there the exponential drag update keeps them stable at any step.
 */
#define PHI_PACKED 0.5
#ifndef PORE_PRESSURE_TAU_FACTOR
#define PORE_PRESSURE_TAU_FACTOR 0.5
#endif
static double grain_volume(const gf_particles *p, size_t i)
{
    double r = p->radius_m[i];
    return 4.0 / 3.0 * M_PI * r * r * r;
}

static double pore_pressure_limit(const gf_unresolved *c, const gf_particles *p)
{
    const gf_grid *g = &c->fluid->grid;
    double tau = 1e30;
    int held = c->n_held == p->n_local && c->n_held > 0 && !c->first_step;
    double vc = g->h_m[0] * g->h_m[1] * g->h_m[2];
    double *bins = NULL;
    if (!held) {  /* before the first fluid step: solid fraction binned by grain centre */
        bins = calloc(g->n_cells, sizeof(double));
        if (!bins)
            return tau;
        for (size_t i = 0; i < p->n_local; ++i) {
            int q[3];
            double x[3] = {p->x_m[i], p->y_m[i], p->z_m[i]};
            for (int d = 0; d < 3; ++d) {
                q[d] = (int)floor((x[d] - g->lo_m[d]) / g->h_m[d]);
                q[d] = q[d] < 0 ? 0 : q[d] >= g->n[d] ? g->n[d] - 1 : q[d];
            }
            bins[gf_grid_cell(g, q[0], q[1], q[2])] += grain_volume(p, i) / vc;
        }
    }
    for (size_t i = 0; i < p->n_local; ++i) {
        if (p->flags[i] & GF_P_GLUED)
            continue;
        double phi, K;
        if (held) {
            phi = 1.0 - c->held[i].eps;
            K = c->held[i].K_kg_s;
        } else {
            int q[3];
            double x[3] = {p->x_m[i], p->y_m[i], p->z_m[i]};
            for (int d = 0; d < 3; ++d) {
                q[d] = (int)floor((x[d] - g->lo_m[d]) / g->h_m[d]);
                q[d] = q[d] < 0 ? 0 : q[d] >= g->n[d] ? g->n[d] - 1 : q[d];
            }
            phi = fmin(bins[gf_grid_cell(g, q[0], q[1], q[2])], 0.64);
            K = phi > PHI_PACKED ? gf_drag_coefficient(c->law, 2.0 * p->radius_m[i], 1.0 - phi, 0.0, c->rho_f, c->mu)
                                 : 0.0;
        }
        if (phi > PHI_PACKED && K > 0.0)
            tau = fmin(tau, p->mass_kg[i] / K);
    }
    free(bins);
    return PORE_PRESSURE_TAU_FACTOR * tau;
}

static double unresolved_dt_max_s(const gf_coupling *base, const gf_particles *p)
{
    const gf_unresolved *c = CU(base);
    double cfl = c->spec.fluid.cfl, h = min_cell(c);
    double rate = advective_rate(c);
    double dt = rate > 0.0 ? cfl / rate : 1e30;
    double vmax = p ? grain_speed_max(p) : 0.0;
    if (vmax > 0.0)
        dt = fmin(dt, cfl * h / vmax);  /* grains move at most cfl cells per step: eps^{n+1} - eps^n stays smooth */
    double nu = c->mu / c->rho_f;
    dt = fmin(dt, h * h / nu);          /* accuracy of the implicit viscous step at the kernel scale */
    /* before anything moves: the grains' own velocity scale, min(Stokes settling, free fall over D),
     * so the step a loop sizes at t = 0 (gf_sim fixes its substep count there) stays within the CFL */
    double gmag = sqrt(c->setup.gravity_m_s2[0] * c->setup.gravity_m_s2[0] +
                       c->setup.gravity_m_s2[1] * c->setup.gravity_m_s2[1] +
                       c->setup.gravity_m_s2[2] * c->setup.gravity_m_s2[2]);
    double D = c->spec.grains.diameter_m, rp = c->spec.grains.density_kg_m3;
    if (gmag > 0.0 && rp > c->rho_f) {
        double us = (rp - c->rho_f) * gmag * D * D / (18.0 * c->mu);
        double uff = sqrt((rp - c->rho_f) / rp * gmag * D);
        dt = fmin(dt, cfl * h / fmin(us, uff));
    }
    if (p)
        dt = fmin(dt, pore_pressure_limit(c, p));
    return dt;
}

/* --- fluid step --------------------------------------------------------------------------------- */

static int has_glued(const gf_particles *p)
{
    for (size_t i = 0; i < p->n_local; ++i)
        if (p->flags[i] & GF_P_GLUED)
            return 1;
    return 0;
}

/* eps^{n+1} from the grains; kernels cached per grain. */
static void build_fluid_fraction(gf_unresolved *c, const gf_particles *p)
{
    gf_fluid *f = c->fluid;
    const gf_grid *g = &f->grid;
    double *solid = f->tmp[3];
    memset(solid, 0, g->n_cells * sizeof(double));
    double vgr = 0.0;
    for (size_t i = 0; i < p->n_local; ++i) {
        double x[3] = {p->x_m[i], p->y_m[i], p->z_m[i]};
        gf_average_kernel(g, c->sigma_m, x, &c->kern[i]);
        double v = grain_volume(p, i);
        gf_average_spread(g, &c->kern[i], v, solid);
        vgr += v;
    }
    double vc = g->h_m[0] * g->h_m[1] * g->h_m[2], vgrid = 0.0;
    long clipped = 0;
    for (size_t cc = 0; cc < g->n_cells; ++cc) {
        vgrid += solid[cc] * vc;
        double e = 1.0 - solid[cc];
        if (e < EPS_FLOOR) {
            e = EPS_FLOOR;
            ++clipped;
        }
        f->eps[cc] = e;
    }
    c->stats.solid_volume_grid_m3 = vgrid;
    c->stats.solid_volume_grains_m3 = vgr;
    c->stats.eps_clipped_cells = clipped;
}

/* Weight balance (gf_weight_balance.h) or imposed mean gradient G (Pa/m) for this step. */
static void mean_pressure_gradient(gf_unresolved *c, const gf_particles *p)
{
    if (!c->user_gradp)
        gf_weight_balance_gradient(&c->fluid->grid, p, c->rho_f, c->setup.gravity_m_s2, c->mean_gradp);
}

/* Drag coefficient of grain i with the self-induced-velocity correction; slip from the measured u_f. */
static double grain_drag(const gf_unresolved *c, const gf_particles *p, size_t i, const double uf[3], double eps_closure,
                         double self_share)
{
    double D = 2.0 * p->radius_m[i];
    const double *vm = gf_mean_slip_velocity(c, i);  /* mean-slip closures: slip against <v> */
    double v[3] = {vm ? vm[0] : p->vx_m_s[i], vm ? vm[1] : p->vy_m_s[i], vm ? vm[2] : p->vz_m_s[i]};
    double w = sqrt((uf[0] - v[0]) * (uf[0] - v[0]) + (uf[1] - v[1]) * (uf[1] - v[1]) + (uf[2] - v[2]) * (uf[2] - v[2]));
    double K = 0.0, corr = 1.0;
    for (int it = 0; it < 4; ++it) {  /* fixed point on the undisturbed slip w corr */
        K = gf_drag_coefficient(c->law, D, eps_closure, w * corr, c->rho_f, c->mu);
        double g0 = c->self_mobility * oseen_factor(c, c->rho_f * w * corr * c->sigma_eff_m / c->mu);
        double x = fmin(self_share * K * g0, SELF_CAP);
        corr = 1.0 / (1.0 - x);
    }
    return K * corr;
}

static void cell_fields(gf_unresolved *c)
{
    gf_fluid *f = c->fluid;
    const gf_grid *g = &f->grid;
    for (int a = 0; a < 3; ++a)
        gf_grid_cell_velocity(g, a, f->u[a], c->uc[a]);
}

/* Cell-centred gradient of p' (central, from the face differences; zero across walls). */
static void pressure_gradient(gf_unresolved *c)
{
    gf_fluid *f = c->fluid;
    const gf_grid *g = &f->grid;
    for (int a = 0; a < 3; ++a)
        for (int k = 0; k < g->n[2]; ++k)
            for (int j = 0; j < g->n[1]; ++j)
                for (int i = 0; i < g->n[0]; ++i) {
                    int idx[3] = {i, j, k};
                    double s = 0.0;
                    for (int dir = -1; dir <= 1; dir += 2) {
                        int m = gf_grid_wrap(g, a, idx[a] + dir);
                        if (m < 0)
                            continue;  /* wall: zero normal gradient on that face */
                        int q[3] = {i, j, k};
                        q[a] = m;
                        double dp = f->p_Pa[gf_grid_cell(g, q[0], q[1], q[2])] - f->p_Pa[gf_grid_cell(g, i, j, k)];
                        s += dir * dp;  /* (p_hi - p) + (p - p_lo) */
                    }
                    c->gp[a][gf_grid_cell(g, i, j, k)] = 0.5 * s / g->h_m[a];
                }
}

/* Shift p' so that its mean over the reference layer (free-surface side) is 0. */
static void reference_pressure(gf_unresolved *c)
{
    gf_fluid *f = c->fluid;
    const gf_grid *g = &f->grid;
    double s = 0.0;
    size_t n = 0;
    for (int k = 0; k < g->n[2]; ++k)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i) {
                int idx[3] = {i, j, k};
                if (c->ref_axis >= 0 && idx[c->ref_axis] != (c->ref_side ? g->n[c->ref_axis] - 1 : 0))
                    continue;
                s += f->p_Pa[gf_grid_cell(g, i, j, k)];
                ++n;
            }
    double m = s / (double)n;
    for (size_t cc = 0; cc < g->n_cells; ++cc)
        f->p_Pa[cc] -= m;
}

/*
 * Fully periodic box with the weight balance: the mixture receives no net
 * external force, so its momentum rho_f sum eps u V + sum m v must stay at zero
 * (grains and fluid start at rest). The sub-cycled exchange is not exactly
 * equal and opposite within a fluid step (the grains relax against the held
 * u_f, the fluid against the grains' start-of-step velocity), so transients
 * leave a small uniform drift of the mixture; a uniform velocity is a
 * Galilean shift in a fully periodic box. The fluid is shifted by the
 * mixture's centre-of-mass velocity P/(M_f + M_g) (not P/M_f: the grains
 * follow the fluid through the drag, and with M_g > M_f, e.g. phi = 0.4,
 * that feedback would grow); the drift then decays within a step or two,
 * restoring the zero-momentum frame in which settling velocities are defined.
 */
static void fix_mixture_momentum(gf_unresolved *c, const gf_particles *p)
{
    gf_fluid *f = c->fluid;
    const gf_grid *g = &f->grid;
    if (c->user_gradp || has_glued(p) || !(g->periodic[0] && g->periodic[1] && g->periodic[2]))
        return;
    double vc = g->h_m[0] * g->h_m[1] * g->h_m[2], mass = 0.0;
    for (size_t cc = 0; cc < g->n_cells; ++cc)
        mass += c->rho_f * f->eps[cc] * vc;
    for (size_t i = 0; i < p->n_local; ++i)
        mass += p->mass_kg[i];
    for (int a = 0; a < 3; ++a) {
        double mom = 0.0;
        for (int k = 0; k < g->n[2]; ++k)
            for (int j = 0; j < g->n[1]; ++j)
                for (int i = 0; i < g->n[0]; ++i)
                    mom += c->rho_f * vc * f->u[a][gf_grid_face(g, a, i, j, k)] *
                           gf_grid_face_from_cells(g, f->eps, a, i, j, k);
        const double *v = a == 0 ? p->vx_m_s : a == 1 ? p->vy_m_s : p->vz_m_s;
        for (size_t i = 0; i < p->n_local; ++i)
            mom += p->mass_kg[i] * v[i];
        double du = mom / mass;
        for (size_t q = 0; q < g->n_faces[a]; ++q)
            f->u[a][q] -= du;
    }
}

static gf_status unresolved_fluid_step(gf_coupling *base, const gf_particles *p, double dt_s)
{
    gf_unresolved *c = U(base);
    gf_ctx *ctx = c->ctx;
    double t0 = gf_wtime();
    gf_fluid *f = c->fluid;
    const gf_grid *g = &f->grid;
    if (!(dt_s > 0.0) || !isfinite(dt_s))
        return GF_FAIL(ctx, GF_ERR_ARG, "fluid step: dt = %g s must be > 0", dt_s);
    /* stability: explicit upwind advection needs sum_d |u_d| dt / h_d <= 1, grains must not skip cells */
    double rate = advective_rate(c);
    if (rate * dt_s > 1.0)
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "fluid step dt = %.3g s exceeds the advective CFL stability limit %.3g s "
                       "(CFL number %.2f > 1); take dt <= gf_coupling_dt_max_s = %.3g s", dt_s, 1.0 / rate,
                       rate * dt_s, unresolved_dt_max_s(base, p));
    double vmax = grain_speed_max(p), h = min_cell(c);
    if (vmax * dt_s > h)
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "fluid step dt = %.3g s lets grains move %.2f cells (|v|max = %.3g m/s, "
                       "limit 1 cell); take dt <= gf_coupling_dt_max_s = %.3g s", dt_s, vmax * dt_s / h, vmax,
                       unresolved_dt_max_s(base, p));
    GF_TRY(gf_unresolved_reserve(c, p->n_local));

    /* 1. fluid fraction from the grains as they are now */
    memcpy(f->eps_old, f->eps, g->n_cells * sizeof(double));
    build_fluid_fraction(c, p);
    if (c->first_step)
        memcpy(f->eps_old, f->eps, g->n_cells * sizeof(double));
    mean_pressure_gradient(c, p);
    GF_TRY(gf_mean_slip_prepare(c, p));

    /* 2. drag coefficients at the current state, spread to beta and beta v */
    cell_fields(c);
    double vc = g->h_m[0] * g->h_m[1] * g->h_m[2];
    const long n_grains = (long)p->n_local;
    const double *const at_grain[4] = {c->uc[0], c->uc[1], c->uc[2], f->eps};
    gf_average_interleave(g->n_cells, at_grain, 4, c->lanes);
#pragma omp parallel for num_threads(c->n_threads) if (c->n_threads > 1 && n_grains >= PARALLEL_MIN_GRAINS) \
    schedule(static)
    for (long i = 0; i < n_grains; ++i) {
        const gf_kernel *k = &c->kern[i];
        double v[GF_AVERAGE_LANES];
        gf_average_interpolate_lanes(g, k, c->lanes, v);
        double uf[3] = {v[0], v[1], v[2]};
        double eps_i = v[3];
        double vi = grain_volume(p, (size_t)i);
        double own = vi * gf_average_self_overlap(k) / vc;  /* own contribution to 1 - eps at the centre */
        double phi_i = 1.0 - eps_i;
        double share = phi_i > own ? own / phi_i : 1.0;
        held_grain *hg = &c->held[i];
        hg->id = p->id[i];
        hg->K_kg_s = grain_drag(c, p, (size_t)i, uf, fmin(1.0, eps_i + own), share);
        if (c->law->fluctuation)
            hg->K_kg_s = gf_mean_slip_hold(c, p, (size_t)i, hg->K_kg_s, fmin(1.0, eps_i + own), dt_s);
        hg->eps = eps_i;
        hg->mass_kg = p->mass_kg[i];
        hg->phi1_x = NAN;
    }
    memset(c->lanes, 0, g->n_cells * GF_AVERAGE_LANES * sizeof(double));
    for (size_t i = 0; i < p->n_local; ++i) {  /* sums over grains: in grain order */
        double value[GF_AVERAGE_LANES];
        gf_mean_slip_exchange(c, p, i, c->held[i].K_kg_s, value);
        gf_average_spread_lanes(g, &c->kern[i], value, c->lanes);
    }
    double *const beta_fields[4] = {f->beta, f->beta_v[0], f->beta_v[1], f->beta_v[2]};
    gf_average_deinterleave(g->n_cells, c->lanes, 4, beta_fields);
    c->n_held = p->n_local;
    c->held_epoch = p->order_epoch, c->held_epoch_known = 1;

    /* 3. fluid: body force = mean pressure gradient only (gravity is in p_h) */
    for (int a = 0; a < 3; ++a)
        for (size_t cc = 0; cc < g->n_cells; ++cc)
            f->body[a][cc] = c->mean_gradp[a] / c->rho_f;
    gf_fluid_advect(f, dt_s);
    GF_TRY(gf_fluid_viscous(ctx, f, dt_s));
    GF_TRY(gf_fluid_project(ctx, f, dt_s));
    reference_pressure(c);
    fix_mixture_momentum(c, p);
    if (gf_fluid_nonfinite(f))
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "fluid state became non-finite after a step of %.3g s (CFL number %.2f, "
                       "dt_max %.3g s)", dt_s, rate * dt_s, unresolved_dt_max_s(base, p));

    /* 4. held fluid velocity and non-drag forces at each grain */
    cell_fields(c);
    pressure_gradient(c);
    const double *const at_grain_after[6] = {c->uc[0], c->uc[1], c->uc[2], c->gp[0], c->gp[1], c->gp[2]};
    gf_average_interleave(g->n_cells, at_grain_after, 6, c->lanes);
#pragma omp parallel for num_threads(c->n_threads) if (c->n_threads > 1 && n_grains >= PARALLEL_MIN_GRAINS) \
    schedule(static)
    for (long i = 0; i < n_grains; ++i) {
        const gf_kernel *k = &c->kern[i];
        held_grain *hg = &c->held[i];
        double vi = grain_volume(p, (size_t)i);
        double v[GF_AVERAGE_LANES];
        gf_average_interpolate_lanes(g, k, c->lanes, v);
        for (int a = 0; a < 3; ++a) {
            hg->uf[a] = v[a];
            double gpa = v[3 + a];
            /* -V grad p' - V rho_f g (hydrostatic part) + V G (mean gradient) */
            hg->f_other_N[a] = vi * (-gpa - c->rho_f * c->setup.gravity_m_s2[a] + c->mean_gradp[a]);
        }
        if (c->law->fluctuation)
            gf_mean_slip_target(c, p, (size_t)i, hg->uf, hg->uf);
    }

    /* 5. output fields and bookkeeping */
    for (size_t cc = 0; cc < g->n_cells; ++cc) {
        c->fields[FLD_EPS][cc] = f->eps[cc];
        c->fields[FLD_U][cc] = c->uc[0][cc];
        c->fields[FLD_V][cc] = c->uc[1][cc];
        c->fields[FLD_W][cc] = c->uc[2][cc];
        c->fields[FLD_P][cc] = f->p_Pa[cc];
    }
    c->first_step = 0;
    c->stats.n_steps++;
    c->stats.poisson_s += f->last_solve.seconds;
    c->stats.poisson_iterations += f->last_solve.iterations;
    c->stats.last_mass_residual = f->last_mass_residual;
    for (int a = 0; a < 3; ++a)
        c->stats.mean_gradp_Pa_m[a] = c->mean_gradp[a];
    c->stats.fluid_s += gf_wtime() - t0;
    return GF_OK;
}

/* --- forces on the grains ------------------------------------------------------------------------- */

static int cmp_id(const void *a, const void *b)
{
    int64_t x = ((const held_grain *)a)->id, y = ((const held_grain *)b)->id;
    return (x > y) - (x < y);
}

/* The held fluid force on grain i (hg: its held values), added to p->f:
 * exact exponential relaxation over one DEM step under the total force (see
 * the opening comment), F_add = phi1 K (u - v) + phi1 F_fluid,other + (phi1 - 1)(F_already + m g). */
static void add_held_force(const gf_unresolved *c, held_grain *hg, gf_particles *p, size_t i)
{
    if (p->flags[i] & GF_P_GLUED)
        return;
    double m = p->mass_kg[i];
    double x = hg->K_kg_s * c->dt_dem_s / m;
    if (x != hg->phi1_x) {
        hg->phi1 = x > 1e-8 ? -expm1(-x) / x : 1.0 - 0.5 * x;
        hg->phi1_x = x;
    }
    const double phi1 = hg->phi1;
    double K = hg->K_kg_s * phi1;
    double *f[3] = {&p->fx_N[i], &p->fy_N[i], &p->fz_N[i]};
    double v[3] = {p->vx_m_s[i], p->vy_m_s[i], p->vz_m_s[i]};
    for (int a = 0; a < 3; ++a)
        *f[a] += K * (hg->uf[a] - v[a]) + phi1 * hg->f_other_N[a] + (phi1 - 1.0) * (*f[a] + m * c->setup.gravity_m_s2[a]);
}

static int unresolved_forces_in_order(const gf_coupling *base, const gf_particles *p)
{
    const gf_unresolved *c = CU(base);
    return c->first_step ||
           (c->held_epoch_known && c->held_epoch == p->order_epoch && c->n_held == p->n_local);
}

static void unresolved_add_forces_range(gf_coupling *base, gf_particles *p, size_t i0, size_t i1)
{
    gf_unresolved *c = U(base);
    if (c->first_step)
        return;
    for (size_t i = i0; i < i1; ++i)
        add_held_force(c, &c->held[i], p, i);
}

static gf_status unresolved_add_forces(gf_coupling *base, gf_particles *p)
{
    gf_unresolved *c = U(base);
    if (c->first_step)
        return GF_OK;  /* no fluid step yet: the fluid is at rest and hydrostatic, nothing held */
    int reordered = p->n_local != c->n_held;
    for (size_t i = 0; i < p->n_local && !reordered; ++i)
        reordered = p->id[i] != c->held[i].id;
    if (reordered)  /* the DEM sorted or removed grains since the fluid step: look up by id */
        qsort(c->held, c->n_held, sizeof *c->held, cmp_id);
    for (size_t i = 0; i < p->n_local; ++i) {
        held_grain *hg = &c->held[i];
        if (reordered) {
            held_grain key = {.id = p->id[i]};
            hg = bsearch(&key, c->held, c->n_held, sizeof key, cmp_id);
            if (!hg)
                continue;  /* a grain added since the last fluid step feels the fluid from the next one */
        }
        add_held_force(c, hg, p, i);
    }
    if (!reordered) {
        c->held_epoch = p->order_epoch, c->held_epoch_known = 1;
    } else {  /* restore index order for the next substep when the store order is stable */
        size_t n = p->n_local < c->n_held ? p->n_local : c->n_held;
        int same_set = p->n_local == c->n_held;
        if (same_set) {
            held_grain *tmp = malloc(n * sizeof *tmp);
            if (tmp) {
                int all_found = 1;
                for (size_t i = 0; i < n; ++i) {
                    held_grain key = {.id = p->id[i]};
                    held_grain *hg = bsearch(&key, c->held, c->n_held, sizeof key, cmp_id);
                    tmp[i] = hg ? *hg : (held_grain){.id = -1};
                    all_found &= hg != NULL;
                }
                memcpy(c->held, tmp, n * sizeof *tmp);
                free(tmp);
                if (all_found)
                    c->held_epoch = p->order_epoch, c->held_epoch_known = 1;
            }
        }
    }
    return GF_OK;
}

/* --- probes and outputs ----------------------------------------------------------------------------- */

static double unresolved_excess_pressure_Pa(const gf_coupling *base, const double x_m[3])
{
    const gf_unresolved *c = CU(base);
    const gf_grid *g = &c->fluid->grid;
    int i0[3];
    double t[3];
    for (int d = 0; d < 3; ++d) {
        double s = (x_m[d] - g->lo_m[d]) / g->h_m[d] - 0.5;  /* cell-centre coordinates */
        if (g->n[d] == 1) {
            i0[d] = 0;
            t[d] = 0.0;
            continue;
        }
        if (s < 0.0)
            s = 0.0;
        if (s > g->n[d] - 1)
            s = g->n[d] - 1;
        i0[d] = (int)floor(s);
        if (i0[d] > g->n[d] - 2)
            i0[d] = g->n[d] - 2;
        t[d] = s - i0[d];
    }
    double v = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        int q[3];
        double w = 1.0;
        for (int d = 0; d < 3; ++d) {
            int b = (corner >> d) & 1;
            q[d] = g->n[d] == 1 ? 0 : i0[d] + b;
            w *= g->n[d] == 1 ? (b ? 0.0 : 1.0) : (b ? t[d] : 1.0 - t[d]);
        }
        if (w != 0.0)
            v += w * c->fluid->p_Pa[gf_grid_cell(g, q[0], q[1], q[2])];
    }
    return v;
}

static int unresolved_fields(const gf_coupling *base, int n_cells[3], double lo_m[3], double cell_m[3],
                             const gf_var_info **vars, const double *const **fields)
{
    const gf_unresolved *c = CU(base);
    const gf_grid *g = &c->fluid->grid;
    for (int d = 0; d < 3; ++d) {
        n_cells[d] = g->n[d];
        lo_m[d] = g->lo_m[d];
        cell_m[d] = g->h_m[d];
    }
    *vars = field_vars;
    *fields = (const double *const *)c->fields;
    return FLD_N;
}

static double unresolved_fluid_flow_rate(const gf_coupling *base)
{
    const gf_unresolved *c = CU(base);
    const gf_grid *g = &c->fluid->grid;
    double s = 0.0, vc = g->h_m[0] * g->h_m[1] * g->h_m[2];
    for (size_t cc = 0; cc < g->n_cells; ++cc)
        s += c->fluid->eps[cc] * c->fields[FLD_U][cc] * vc;
    return s / (g->h_m[0] * g->n[0]);
}

static double unresolved_fluid_mass_kg(const gf_coupling *base)
{
    const gf_unresolved *c = CU(base);
    const gf_grid *g = &c->fluid->grid;
    double s = 0.0;
    for (size_t cc = 0; cc < g->n_cells; ++cc)
        s += c->fluid->eps[cc];
    return c->rho_f * s * g->h_m[0] * g->h_m[1] * g->h_m[2];
}

/* --- the tier row (gf_coupling_tier.h): the calls above behind the table --------------------------- */

/* The unresolved tier is the cheapest that carries a fluid: `fluid: auto` takes it whenever the
 * regime needs one (gf_tier.h says when). */
static int unresolved_auto_fits(const gf_tier_query *q, char *why, size_t n)
{
    (void)q;
    snprintf(why, n, "unresolved: averaged fluid on cells of a few D, the cheapest tier with pore pressure");
    return 1;
}

/*
 * Cost (gf_coupling_tier.cost): the fluid's CPU per grain and DEM step, measured on the immersed
 * collapse of configs/demo.yaml (a = 1, Phi_i = 0.6, R0 = 10 D: 404 grains; R0 = 16 D: 960 grains;
 * cells of 2 D) as the excess of the immersed run's CPU over the dry one's between end_time 12 and
 * 2 sqrt(D/g): 1.17e-7 and 1.28e-7 s per grain-step in all, 3.2e-8 and 3.8e-8 of it the DEM's.
 * Re-measure: docs/campaigns.md, "What a campaign costs".
 */
#define UNRESOLVED_COST_S_PER_GRAIN_STEP 8.8e-8

static void unresolved_cost(const gf_run_spec *spec, const gf_tier_cost_query *q, gf_tier_cost *out)
{
    out->cells = NAN;
    out->fluid_steps = NAN;
    out->cpu_s = q->n_grains * ceil(q->fluid_time_s / gf_run_spec_dt_s(spec)) * UNRESOLVED_COST_S_PER_GRAIN_STEP;
}

const gf_coupling_tier gf_coupling_tier_unresolved = {
    .name = "unresolved",
    .summary = "locally averaged Navier-Stokes on cells of a few D, drag closure, pore pressure",
    .create = unresolved_create,
    .destroy = unresolved_destroy,
    .auto_fits = unresolved_auto_fits,
    .set_threads = unresolved_set_threads,
    .dt_max_s = unresolved_dt_max_s,
    .fluid_step = unresolved_fluid_step,
    .add_forces = unresolved_add_forces,
    .forces_in_order = unresolved_forces_in_order,
    .add_forces_range = unresolved_add_forces_range,
    .excess_pressure_Pa = unresolved_excess_pressure_Pa,
    .fields = unresolved_fields,
    .set_gravity = unresolved_set_gravity,
    .save = gf_unresolved_save,
    .load = gf_unresolved_load,
    .fluid_flow_rate = unresolved_fluid_flow_rate,
    .fluid_mass_kg = unresolved_fluid_mass_kg,
    .cost = unresolved_cost,
};

/* --- diagnostics of this tier through the public handle (gf_coupling_diag.h) --------------------- */

static gf_unresolved *diag_of(const gf_coupling *c)
{
    return c && c->tier == &gf_coupling_tier_unresolved ? (gf_unresolved *)c : NULL;
}

void gf_coupling_get_stats(const gf_coupling *c, gf_coupling_stats *s)
{
    const gf_unresolved *u = diag_of(c);
    if (u)
        *s = u->stats;
    else
        memset(s, 0, sizeof *s);
}

void gf_coupling_set_mean_pressure_gradient(gf_coupling *c, const double G_Pa_m[3])
{
    gf_unresolved *u = diag_of(c);
    if (!u)
        return;
    u->user_gradp = 1;
    for (int d = 0; d < 3; ++d)
        u->mean_gradp[d] = G_Pa_m[d];
}

void gf_coupling_set_dem_step(gf_coupling *c, double dt_s)
{
    gf_unresolved *u = diag_of(c);
    if (u && dt_s > 0.0)
        u->dt_dem_s = dt_s;
}

int gf_coupling_grain_state(const gf_coupling *c, size_t i, double *K_kg_s, double uf_m_s[3], double *eps)
{
    const gf_unresolved *u = diag_of(c);
    if (!u || i >= u->n_held)
        return 0;
    *K_kg_s = u->held[i].K_kg_s;
    for (int a = 0; a < 3; ++a)
        uf_m_s[a] = u->held[i].uf[a];
    *eps = u->held[i].eps;
    return 1;
}

void gf_coupling_mean_fluid_velocity(const gf_coupling *c, double u_m_s[3])
{
    const gf_unresolved *u = diag_of(c);
    if (!u) {
        u_m_s[0] = u_m_s[1] = u_m_s[2] = NAN;
        return;
    }
    const gf_grid *g = &u->fluid->grid;
    double se = 0.0;
    u_m_s[0] = u_m_s[1] = u_m_s[2] = 0.0;
    for (size_t cc = 0; cc < g->n_cells; ++cc) {
        se += u->fluid->eps[cc];
        for (int a = 0; a < 3; ++a)
            u_m_s[a] += u->fluid->eps[cc] * u->fields[FLD_U + a][cc];
    }
    for (int a = 0; a < 3; ++a)
        u_m_s[a] /= se;
}
