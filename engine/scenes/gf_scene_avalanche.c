/*
 * Granular avalanche on a rough incline, periodic in x and z: the dry chute
 * flow of Izard 2014 §2.1.3.3 (mu(I), Bagnold profile) and, immersed, the
 * avalanches of chapter 4 (§4.1.2.2; Courrech du Pont et al. PRL 2003 for
 * the regimes).
 *
 * Axes: x downslope, y normal to the bed, z spanwise. The domain is
 * L x H x W (5D x 20D x 5D in Izard 2014 §4.1.2.2), periodic in
 * x and z, with glued grains centred on y = 0 ("half-grains", Izard 2014 §4.1.2.2; placed
 * at random by gf_packing_rough_base, so the base roughness does not depend
 * on L and W) over a plane floor, and a plane lid at y = H (the fluid's free-slip top). The bed
 * (height h_bed, 7-8 D in the thesis) is prepared at theta = 0 by gf_packing
 * at the requested packing fraction, re-equilibrated with the run's
 * contacts, and at t = 0 start() tilts gravity to
 *     g = |g| (sin theta, -cos theta, 0)                       (§4.1.2.2).
 * The unresolved tier gives each grain the full buoyancy -rho_f V g (a grain
 * in a tank). Izard 2014 (4.5)-(4.6) take the downslope gravity off the fluid, so
 * that it stays at rest far from the bed, and add rho_f/(rho_p - rho_f) g sin(theta)
 * to the grains' acceleration "to keep the buoyancy unchanged"; with F_h the
 * surface force of that fluid, whose pressure has no downslope gradient,
 * this drives a grain downslope with rho_p V g sin(theta) rho_p/(rho_p - rho_f)
 * instead of the tank's (rho_p - rho_f) V g sin(theta); without the added term
 * it would be rho_p V g sin(theta) (no downslope buoyancy).
 * slope_gravity_exponent n scales the downslope gravity by
 * (rho_p/(rho_p - rho_f))^n, so that the grains' net downslope weight is the
 * tank's (n = 0, default), the one without downslope buoyancy (n = 1) or that
 * of (4.6) as printed (n = 2), the normal weight unchanged. Exact for the
 * unresolved tier, whose fluid carries only the excess pressure and whose
 * buoyancy follows the gravity set here; not checked with the resolved tier. Izard's free-fall and inertial points
 * of Table 4.2 are matched far better with n = 2 (docs/fast-tier.md). Dry
 * runs: no effect.
 *
 * The rough base: glued grains centred on y = 0 placed at random (default),
 * on a square lattice (base_spacing_over_D > 0), or none (rough_base = 0);
 * the thesis does not say how its half-grains are arranged, and a touching
 * lattice lets the bed slide on it (docs/fast-tier.md).
 *
 * Diagnostics (docs/output.md, thesis (4.7)-(4.11)):
 *   grain_flow_rate   Q_g = (1/L) sum_i V_i u_i (m3/s), the discrete form of
 *                     (1/L) int alpha U dV;
 *   bed_height        the height where the slab solid fraction (slabs of D/2)
 *                     falls to half its plateau (gf_measure_bed_height_m);
 *   bed_packing_fraction  phi of the mobile grains between y = D/2 and
 *                     h_bed - D/2 (thesis (4.7): the glued layer and the free
 *                     surface excluded);
 *   fluid_flow_rate   Q_f = (1/L) int eps u dV, the fluid's flux through a cross
 *                     section, as the run's coupling tier measures it (the
 *                     fluid outside the grains); 0 in dry runs.
 */
#include <math.h>
#include <string.h>

#include "coupling/gf_coupling.h"
#include "particles/gf_packing.h"
#include "scenes/gf_measure.h"
#include "scenes/gf_scene.h"
#include "scenes/gf_scene_box.h"
#include "scenes/gf_scene_deposit.h"
#include "scenes/gf_scene_settle.h"

static const gf_param_info avalanche_params[] = {
    {"length_over_D", "1", 5.0, 2.0, 1000.0, "periodic length L / D"},
    {"width_over_D", "1", 5.0, 2.0, 1000.0, "periodic width W / D"},
    {"height_over_D", "1", 20.0, 4.0, 1000.0, "domain height H / D (lid)"},
    {"bed_height_over_D", "1", 8.0, 2.0, 500.0, "initial bed height / D"},
    {"incline_deg", "degree", 25.0, 0.0, 60.0, "incline angle theta, applied at t = 0"},
    {"phi_target", "1", 0.60, 0.50, 0.645, "bed packing fraction requested (the campaign's phi_initial wins)"},
    {"phi_tolerance", "1", 0.005, 0.001, 0.05, "accepted |Phi - phi_target| of the preparation (thin beds: more)"},
    {"settle_time_nd", "1", 5.0, 0.0, 1e4, "re-equilibration at theta = 0 before t = 0, sqrt(D/g)"},
    {"rough_base", "1", 1.0, 0.0, 1.0, "1: glued half-grains on the floor; 0: plain frictional floor"},
    {"base_spacing_over_D", "1", 0.0, 0.0, 10.0, "0: glued grains at random; > 0: square lattice of ~ this / D"},
    {"slope_gravity_exponent", "1", 0.0, 0.0, 2.0, "downslope weight x (rho_p/Delta rho)^n: 0 tank, 2 Izard (4.6)"},
};

static const gf_var_info avalanche_diag[] = {
    {"grain_flow_rate", "m3 s-1", "grain volume flow rate Q_g = (1/L) sum V_i u_i", NULL},
    {"fluid_flow_rate", "m3 s-1", "fluid volume flow rate Q_f", NULL},
    {"bed_packing_fraction", "1", "bed solid fraction between D/2 and h - D/2", NULL},
    {"bed_height", "m", "bed height (half-plateau solid fraction)", NULL},
};

static int is_immersed(const gf_run_spec *s)
{
    return s->fluid.viscosity_Pa_s > 0.0 && strcmp(s->fluid.model, "none") != 0;
}

/* Glued half-grains centred on y = 0 on a square lattice whose spacing, near spacing_m, divides L and W,
 * radii drawn from psd (neighbours may overlap: glued pairs do not interact). */
static gf_status lattice_base(gf_ctx *ctx, gf_particles *out, const gf_psd *psd, double rho, double L, double W,
                              double spacing_m, uint64_t seed)
{
    int nx = (int)lround(L / spacing_m), nz = (int)lround(W / spacing_m);
    nx = nx < 1 ? 1 : nx, nz = nz < 1 ? 1 : nz;
    gf_rng rng;
    gf_rng_seed(&rng, seed ^ 0x9e3779b97f4a7c15ull);
    for (int i = 0; i < nx; ++i)
        for (int k = 0; k < nz; ++k)
            GF_TRY(gf_particles_add(ctx, out, (i + 0.5) * L / nx, 0.0, (k + 0.5) * W / nz,
                                    gf_psd_draw_radius_m(psd, &rng), rho, GF_P_GLUED, NULL));
    return GF_OK;
}

/* The periodic cell L x H x W, the lid at H. */
static void avalanche_fluid_box(const gf_run_spec *spec, double size_m[3])
{
    const double D = spec->grains.diameter_m;
    size_m[0] = gf_run_spec_param(spec, "length_over_D", 5.0) * D;
    size_m[1] = gf_run_spec_param(spec, "height_over_D", 20.0) * D;
    size_m[2] = gf_run_spec_param(spec, "width_over_D", 5.0) * D;
}

static gf_status avalanche_build(gf_sim *sim, const gf_run_spec *spec)
{
    gf_ctx *ctx = gf_sim_ctx(sim);
    gf_particles *p = gf_sim_particles(sim);
    double D = spec->grains.diameter_m, rho = spec->grains.density_kg_m3;
    double hi[3];
    avalanche_fluid_box(spec, hi);
    const double L = hi[0], H = hi[1], W = hi[2];
    double h_bed = gf_run_spec_param(spec, "bed_height_over_D", 8.0) * D;
    double phi = isnan(spec->phi_initial) ? gf_run_spec_param(spec, "phi_target", 0.6) : spec->phi_initial;
    if (h_bed + 2.0 * D > H)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "avalanche: bed_height_over_D + 2 must not exceed height_over_D");
    const double lo[3] = {0, 0, 0};
    GF_TRY(gf_scene_box_under_gravity(sim, lo, hi, (const int[3]){1, 0, 1}, spec->gravity_m_s2));
    const double mu = spec->contact.wall_friction;
    const gf_scene_plane floor_and_lid[] = {{{0, 0, 0}, {0, 1, 0}, mu}, {{0, H, 0}, {0, -1, 0}, mu}};
    GF_TRY(gf_scene_add_planes(sim, 2, floor_and_lid));
    gf_psd psd = {0.5 * D, spec->grains.polydispersity};
    gf_particles *base = NULL;
    GF_TRY(gf_particles_create(ctx, 256, &base));
    const double spacing = gf_run_spec_param(spec, "base_spacing_over_D", 0.0) * D;
    const int rough = gf_run_spec_param(spec, "rough_base", 1.0) >= 0.5;
    gf_status st = GF_OK;
    if (rough && spacing > 0.0)
        st = lattice_base(ctx, base, &psd, rho, L, W, spacing, spec->seed);
    else if (rough)
        st = gf_packing_rough_base(ctx, base, &psd, rho, 0.0, 0.0, L, 0.0, W, (const int[2]){1, 1}, spec->seed);
    for (size_t i = 0; st == GF_OK && i < base->n_local; ++i)
        st = gf_particles_add(ctx, p, base->x_m[i], base->y_m[i], base->z_m[i], base->radius_m[i], rho, GF_P_GLUED,
                              NULL);
    gf_packing_spec ps = {.lo_m = {0, 0, 0}, .hi_m = {L, h_bed, W}, .periodic = {1, 0, 1}, .phi_target = phi,
                          .psd = psd, .density_kg_m3 = rho, .gravity_m_s2 = spec->gravity_m_s2, .obstacles = base,
                          .seed = spec->seed, .tolerance = gf_run_spec_param(spec, "phi_tolerance", 0.005)};
    gf_packing_result pr;
    if (st == GF_OK)
        st = gf_scene_deposit(sim, &ps, &pr);
    gf_particles_destroy(&base);
    GF_TRY(st);
    GF_TRY(gf_scene_settle(sim, spec, gf_run_spec_param(spec, "settle_time_nd", 5.0)));
    gf_sim_reset_clock(sim);
    /* fluid: free-slip lid, no-slip floor (default), periodic x and z (Izard §4.1.2.2) */
    return gf_sim_set_fluid_bc(sim, 1, 1, GF_BC_FREE_SLIP);
}

static gf_status avalanche_start(gf_sim *sim)
{
    const gf_run_spec *s = gf_sim_spec(sim);
    double th = gf_run_spec_param(s, "incline_deg", 25.0) * M_PI / 180.0;
    double g[3] = {s->gravity_m_s2 * sin(th), -s->gravity_m_s2 * cos(th), 0.0};
    const double rho_p = s->grains.density_kg_m3, rho_f = s->fluid.density_kg_m3;
    if (is_immersed(s) && rho_f > 0.0 && rho_f < rho_p) /* the coupling gives each grain -rho_f V g: see the header */
        g[0] *= pow(rho_p / (rho_p - rho_f), gf_run_spec_param(s, "slope_gravity_exponent", 0.0));
    return gf_sim_set_gravity(sim, g);
}

/* Q_f of the coupling tier; NaN before the coupling exists (the initial packing's measure). */
static double fluid_flow_rate(gf_sim *sim)
{
    struct gf_coupling *c = gf_sim_coupling(sim);
    return c ? gf_coupling_fluid_flow_rate(c) : NAN;
}

static gf_status avalanche_diagnose(gf_sim *sim, double *v)
{
    const gf_run_spec *s = gf_sim_spec(sim);
    const gf_particles *p = gf_sim_particles(sim);
    gf_measure_domain d;
    gf_sim_box(sim, d.lo_m, d.hi_m, d.periodic);
    double D = s->grains.diameter_m;
    enum { MAX_SLABS = 4096 };
    double phi[MAX_SLABS];
    int n = (int)ceil((d.hi_m[1] - d.lo_m[1]) / (0.5 * D));
    if (n > MAX_SLABS)
        n = MAX_SLABS;
    GF_TRY(gf_measure_profile_y(gf_sim_ctx(sim), p, &d, 0.0, 0.5 * D, n, phi, NULL));
    double h = gf_measure_bed_height_m(phi, n, 0.0, 0.5 * D, 0.5), phi_bed = NAN;
    if (h > 1.5 * D)
        GF_TRY(gf_measure_profile_y(gf_sim_ctx(sim), p, &d, 0.5 * D, h - D, 1, &phi_bed, NULL));
    v[0] = gf_measure_grain_flow_rate(p, &d);
    v[1] = is_immersed(s) ? fluid_flow_rate(sim) : 0.0;
    v[2] = phi_bed;
    v[3] = h;
    return GF_OK;
}

static gf_status avalanche_initial_packing(gf_sim *sim, double *phi_measured, double *phi_local)
{
    double v[4];
    GF_TRY(avalanche_diagnose(sim, v));
    *phi_measured = v[2];
    *phi_local = v[2];
    return GF_OK;
}

/* phi L W h_bed over the mean grain volume, and the rough base's glued grains, about 0.45 per D^2
 * (gf_packing_rough_base: random placement until 500 misses in a row). */
static double avalanche_grain_count(const gf_run_spec *spec)
{
    double L = gf_run_spec_param(spec, "length_over_D", 5.0), W = gf_run_spec_param(spec, "width_over_D", 5.0);
    double h = gf_run_spec_param(spec, "bed_height_over_D", 8.0);
    double phi = isnan(spec->phi_initial) ? gf_run_spec_param(spec, "phi_target", 0.6) : spec->phi_initial;
    return phi * L * W * h / (M_PI / 6.0) + 0.45 * L * W;
}

const gf_scene_desc gf_scene_avalanche = {
    .name = "avalanche",
    .caption = "granular avalanche on a rough periodic incline (Izard 2014 §2.1.3.3, ch. 4)",
    .needs = GF_NEED_CONTACTS | GF_NEED_FLUID | GF_NEED_PACKING,
    GF_SCENE_PARAMS(avalanche_params),
    .default_end_time_nd = 200.0,
    .build = avalanche_build,
    .start = avalanche_start,
    GF_SCENE_DIAG(avalanche_diag),
    .diagnose = avalanche_diagnose,
    .done = NULL,
    .initial_packing = avalanche_initial_packing,
    .grain_count = avalanche_grain_count,
    .fluid_box = avalanche_fluid_box,
};
