/*
 * Granular column collapse in a quasi-2D periodic slab (dry: Lajeunesse,
 * Monnier & Homsy PoF 2005, Lube et al. PRE 2005, Staron & Hinch JFM 2005;
 * immersed: Rondon, Pouliquen & Aussillous PoF 2011, Izard 2014 ch. 5).
 *
 * Axes: x streamwise (the collapse runs towards +x), y vertical, z
 * transverse and periodic with width W (2-5 D in the thesis, Table 5.1).
 * A column of length R0 and height H0 = a R0 rests against the back wall
 * x = 0 and is held by a gate wall at x = R0 that start() removes at t = 0
 * (Izard 2014 §5.2: the column collapses towards +x only).
 * The floor is a plane at y = 0, made rough (default) by glued grains
 * centred on it at random (gf_packing_rough_base; Izard §5.2 "fixed grains
 * on the floor for roughness"). The
 * column is prepared at the requested Phi_i by gf_packing (deposition with a
 * tuned preparation friction and rotations blocked, trimmed to H0), then
 * re-equilibrated with the run's own contacts and gravity for settle_time_nd,
 * dry, and the clock is reset. With settle_rotation_locked = 1 (the immersed
 * dense/loose comparison, configs/column_collapse_immersed.yaml) the
 * rotations stay blocked during that re-equilibration and are free from
 * t = 0; with 0 (default, the dry runs) they are free throughout. With free rotations the
 * re-equilibration would undo a loose preparation: at the run's mu_c = 0.25
 * (Izard §5.2) rolling grains hold no packing looser than ~0.59 (measured:
 * 0.563 prepared for a 0.56 request became 0.588 in 5 sqrt(D/g); free-rolling
 * deposits stay above ~0.59 even at mu = 1, gf_packing.h). A column looser
 * than that is therefore metastable from t = 0 and contracts once its grains
 * may roll, as a loose column does once disturbed (Rondon et al. 2011: the
 * contraction expels pore fluid, positive basal excess pressure);
 * validate_collapse's mode "held" measures how far it contracts behind a
 * closed gate. Even with the rotations blocked, a loose column compacts in
 * the re-equilibration: the run's contacts start with unloaded tangential
 * springs, stiffer than the preparation's and at mu_c below its mu_prep
 * (0.557 at t = 0 for a 0.55 request, 48 D, seed 1; 0.552 without the
 * re-equilibration or with the run at mu 0.4, 0.553 at the preparation's
 * t_c). relax_preparation = 1 has each deposit relax with the run's mu_c,
 * t_c and eps_max before the preparation measures it (gf_packing_spec.relax;
 * the preparation's linear law, an approximation for a Hertz run), so that
 * the bisection tunes the Phi the run starts from (0.550 there).
 *
 * The domain length follows the published run-out laws with a 30 % margin:
 *     (R_inf - R0)/R0 = lambda1 a (a small),  lambda2 a^(2/3) (a large),
 * taking the larger of 1.8 a and 2.3 a^(2/3) (Lajeunesse et al. 2005, the
 * longer of the published quasi-2D laws), plus 4 D.
 *
 * Diagnostics (docs/output.md): front_position, the farthest x of the
 * contiguous deposit whose solid height sum V_i/(dx W) is at least D/4 in
 * bins of dx = D (a single saltating grain in a bin carries 0.17 D at W = 3D
 * and does not count; gaps of one bin are tolerated); deposit_height, the
 * highest grain top among those bins; packing_fraction, the sampled solid
 * fraction of the initial column box [1.5D, R0 - 1.5D] x [1.5D, H0 - 1.5D];
 * deposit_extent_1D and _2D, the x where the material height first falls
 * below 1 D and 2 D (gf_measure_profile_extent, bins of D): the solid height
 * over the column's own packing, phi_col = sum V_i / (R0 H0 W) of the mobile
 * grains (conserved), the height a continuum at phi_col gives the same mass,
 * so that the continuum's deposit is compared with the same measure.
 * done(): after t > 2 T0 (T0 = sqrt(2 H0/g), the free-fall time of §5.3),
 * the mean kinetic energy per mobile grain is below rest_energy x m g D
 * (1e-4 by default: a grain at rest energy moves at ~0.014 sqrt(gD)).
 *
 * Fluid (immersed runs): free-slip top, no-slip floor and walls, periodic z
 * (Izard §5.2); basal gauges at x = 13/16 R0 (the thesis' x = 13 D for
 * R0 = 16 D, §5.5) and at x = R0/4, R0/2 under the column, y = 0.
 * The campaign's aspect_ratio_a and phi_initial groups, when set (not NaN),
 * take precedence over the scene parameters aspect_ratio and phi_target.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "coupling/gf_coupling.h"
#include "particles/gf_packing.h"
#include "scenes/gf_measure.h"
#include "scenes/gf_scene.h"
#include "scenes/gf_scene_box.h"
#include "scenes/gf_scene_deposit.h"
#include "scenes/gf_scene_settle.h"

/* Walls are added in this order, so their ids are these (gf_scene_add_planes checks). */
enum { WALL_FLOOR = 0, WALL_BACK, WALL_GATE, WALL_END, WALL_TOP };

static const gf_param_info column_params[] = {
    {"column_length_over_D", "1", 16.0, 4.0, 400.0, "column length R0 / D"},
    {"aspect_ratio", "1", 0.5, 0.1, 8.0, "a = H0 / R0 (the campaign's aspect_ratio_a wins when set)"},
    {"width_over_D", "1", 3.0, 1.0, 100.0, "transverse periodic width W / D"},
    {"rough_base", "1", 1.0, 0.0, 1.0, "1: glued grains centred on the floor; 0: plain frictional floor"},
    {"phi_target", "1", 0.60, 0.50, 0.645, "requested interior Phi_i (the campaign's phi_initial wins when set)"},
    {"phi_tolerance", "1", 0.005, 0.001, 0.05, "accepted |Phi - phi_target| of the preparation (small columns: more)"},
    {"domain_length_over_R0", "1", 0.0, 0.0, 100.0, "domain length / R0; 0: from the published run-out law"},
    {"settle_time_nd", "1", 5.0, 0.0, 1e4, "re-equilibration with the run's contacts before t = 0, sqrt(D/g)"},
    {"relax_preparation", "1", 0.0, 0.0, 1.0,
     "1: each deposit of the preparation relaxes with the run's contacts before its Phi is measured, so that "
     "the column keeps phi_target through the re-equilibration (with settle_rotation_locked)"},
    {"settle_rotation_locked", "1", 0.0, 0.0, 1.0,
     "1: rotations blocked during the re-equilibration, as in the preparation (keeps loose packings); 0: free"},
    {"rest_energy", "1", 1e-4, 0.0, 1.0, "done() when kinetic energy per grain < rest_energy m g D"},
    {"sediment_T_visq", "1", 0.0, 0.0, 1e6,
     "immersed: before t = 0 the column, stretched 1.6-fold about the floor, settles this long (in T_visq) "
     "through the fluid behind the gate, the loose column of Izard 2014 §5.5; 0: off"},
};

static const gf_var_info column_diag[] = {
    {"front_position", "m", "front position from the back wall", NULL},
    {"deposit_height", "m", "maximum height of the deposit", NULL},
    {"packing_fraction", "1", "solid fraction of the initial column region", NULL},
    {"deposit_extent_1D", "m", "x where the deposit's material height first falls below 1 D", NULL},
    {"deposit_extent_2D", "m", "x where the deposit's material height first falls below 2 D", NULL},
};

typedef struct column_geom {
    double D, R0, H0, W, L, top, a, phi;
    int rough;
} column_geom;

static void column_geom_of(const gf_run_spec *s, column_geom *g)
{
    g->D = s->grains.diameter_m;
    g->a = isnan(s->aspect_ratio_a) ? gf_run_spec_param(s, "aspect_ratio", 0.5) : s->aspect_ratio_a;
    g->phi = isnan(s->phi_initial) ? gf_run_spec_param(s, "phi_target", 0.6) : s->phi_initial;
    g->R0 = gf_run_spec_param(s, "column_length_over_D", 16.0) * g->D;
    g->H0 = g->a * g->R0;
    g->W = gf_run_spec_param(s, "width_over_D", 3.0) * g->D;
    g->rough = gf_run_spec_param(s, "rough_base", 1.0) > 0.5;
    double lr = gf_run_spec_param(s, "domain_length_over_R0", 0.0);
    if (lr > 0.0) {
        g->L = lr * g->R0;
    } else {
        double runout = fmax(1.8 * g->a, 2.3 * pow(g->a, 2.0 / 3.0));
        g->L = g->R0 * (1.0 + 1.3 * runout) + 4.0 * g->D;
    }
    int immersed = s->fluid.viscosity_Pa_s > 0.0 && strcmp(s->fluid.model, "none") != 0;
    /* dry: room above the column; immersed: Table 5.1's fluid heights (30, 46, 54 D for H0 = 8, 16, 24 D) */
    g->top = immersed ? 2.0 * g->H0 + 14.0 * g->D : g->H0 + 4.0 * g->D;
}

/* The run's box: L x the fluid's height x W. */
static void column_fluid_box(const gf_run_spec *spec, double size_m[3])
{
    column_geom g;
    column_geom_of(spec, &g);
    size_m[0] = g.L, size_m[1] = g.top, size_m[2] = g.W;
}

static double sphere_volume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }

static gf_status column_build(gf_sim *sim, const gf_run_spec *spec)
{
    gf_ctx *ctx = gf_sim_ctx(sim);
    gf_particles *p = gf_sim_particles(sim);
    column_geom g;
    column_geom_of(spec, &g);
    if (g.R0 >= g.L)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "column_collapse: domain_length_over_R0 must exceed 1");
    double lo[3] = {0, 0, 0}, hi[3];
    column_fluid_box(spec, hi);
    GF_TRY(gf_scene_box_under_gravity(sim, lo, hi, (const int[3]){0, 0, 1}, spec->gravity_m_s2));
    const double mu = spec->contact.wall_friction;
    const gf_scene_plane walls[] = {
        [WALL_FLOOR] = {{0, 0, 0}, {0, 1, 0}, mu},     [WALL_BACK] = {{0, 0, 0}, {1, 0, 0}, mu},
        [WALL_GATE] = {{g.R0, 0, 0}, {-1, 0, 0}, mu},  [WALL_END] = {{g.L, 0, 0}, {-1, 0, 0}, mu},
        [WALL_TOP] = {{0, g.top, 0}, {0, -1, 0}, mu},
    };
    GF_TRY(gf_scene_add_planes(sim, 5, walls));
    gf_psd psd = {0.5 * g.D, spec->grains.polydispersity};
    gf_particles *base = NULL;
    GF_TRY(gf_particles_create(ctx, 256, &base));
    gf_status st = GF_OK;
    if (g.rough)
        st = gf_packing_rough_base(ctx, base, &psd, spec->grains.density_kg_m3, 0.0, 0.0, g.L, 0.0, g.W,
                                   (const int[2]){0, 1}, spec->seed);
    /* all base grains go to the run; those under the column are the preparation's obstacles */
    gf_particles *under = NULL;
    if (st == GF_OK)
        st = gf_particles_create(ctx, 256, &under);
    for (size_t i = 0; st == GF_OK && i < base->n_local; ++i) {
        st = gf_particles_add(ctx, p, base->x_m[i], base->y_m[i], base->z_m[i], base->radius_m[i],
                              spec->grains.density_kg_m3, GF_P_GLUED, NULL);
        if (st == GF_OK && base->x_m[i] < g.R0 + g.D)
            st = gf_particles_add(ctx, under, base->x_m[i], base->y_m[i], base->z_m[i], base->radius_m[i],
                                  spec->grains.density_kg_m3, GF_P_GLUED, NULL);
    }
    gf_packing_spec ps = {.lo_m = {0, 0, 0}, .hi_m = {g.R0, g.H0, g.W}, .periodic = {0, 0, 1}, .walls_x = 1,
                          .phi_target = g.phi, .psd = psd, .density_kg_m3 = spec->grains.density_kg_m3,
                          .gravity_m_s2 = spec->gravity_m_s2, .obstacles = under, .seed = spec->seed,
                          .tolerance = gf_run_spec_param(spec, "phi_tolerance", 0.005)};
    if (gf_run_spec_param(spec, "relax_preparation", 0.0) > 0.5)
        ps.relax = (gf_packing_relax){.mu = spec->contact.friction, .t_contact_s = gf_run_spec_t_contact_s(spec),
                                      .restitution = spec->contact.restitution};
    gf_packing_result pr;
    if (st == GF_OK)
        st = gf_scene_deposit(sim, &ps, &pr);
    gf_particles_destroy(&base);
    gf_particles_destroy(&under);
    GF_TRY(st);
    if (pr.n_grains == 0)
        return GF_FAIL(ctx, GF_ERR_CONFIG,
                       "column_collapse: the preparation left no grain in the %.3g m x %.3g m column "
                       "(H0 = %.2g D is too low; raise column_length_over_D or aspect_ratio)",
                       g.R0, g.H0, g.H0 / g.D);
    /* re-equilibrate with the run's contacts behind the closed gate */
    int locked = gf_run_spec_param(spec, "settle_rotation_locked", 0.0) > 0.5;
    if (locked)
        GF_TRY(gf_sim_set_rotation_locked(sim, 1));
    GF_TRY(gf_scene_settle(sim, spec, gf_run_spec_param(spec, "settle_time_nd", 5.0)));
    if (locked)
        GF_TRY(gf_sim_set_rotation_locked(sim, 0)); /* free from t = 0 on (and on a restart) */
    gf_sim_reset_clock(sim);
    /* fluid: free-slip top, no-slip floor and walls (default), periodic z */
    GF_TRY(gf_sim_set_fluid_bc(sim, 1, 1, GF_BC_FREE_SLIP));
    const double gauge_x[3] = {13.0 / 16.0, 0.25, 0.5};
    const char *gauge_name[3] = {"base_x13_16R0", "base_x4_16R0", "base_x8_16R0"};
    for (int k = 0; k < 3; ++k) {
        double xg[3] = {gauge_x[k] * g.R0, 0.0, 0.5 * g.W};
        GF_TRY(gf_sim_add_gauge(sim, gauge_name[k], xg));
    }
    /* dry collapse lasts a few T0 = sqrt(2 H0/g) plus the spreading; the rest test stops it earlier */
    double T0 = sqrt(2.0 * g.H0 / spec->gravity_m_s2), t_grain = sqrt(g.D / spec->gravity_m_s2);
    double t_end = 10.0 * T0 + 40.0 * t_grain;
    if (gf_sim_scales(sim)->t_visq_s > 0.0)
        t_end = fmax(t_end, 2.0e4 * gf_sim_scales(sim)->t_visq_s); /* Izard §5.5: static by ~18 000 T_visq */
    return gf_sim_set_end_time(sim, t_end);
}

static gf_status column_start(gf_sim *sim)
{
    return gf_sim_set_wall_active(sim, WALL_GATE, 0); /* the gate is removed at t = 0 */
}

/*
 * Izard (2014, §5.5) made the loose column (Phi_i ~0.58) by letting grains placed at random settle
 * inside the viscous fluid with the coupled method, the dense one by settling them dry. With
 * sediment_T_visq > 0 the prepared column is stretched SEDIMENT_STRETCH-fold about the floor (solid
 * fraction ~0.37: no contact left), every grain at rest, and settles through the fluid behind the
 * closed gate; the gate then opens and the clock restarts at t = 0. The grain count is the
 * preparation's, so the column's height is what the settling leaves. The suspension falls ~0.6 H0
 * at its hindered speed (Richardson & Zaki at phi ~0.37: ~0.12 of Stokes' speed), 6 000 T_visq at
 * H0 = 8 D; the resolved tier settles ~20 % slower than Richardson–Zaki (docs/resolved.md), hence
 * 8 000 in the configurations. A prepared dry column of the same Phi_i runs 1-4 % farther than the
 * dense one, a sedimented one 9-17 % (docs/notes/resolved-multigrain.md).
 */
#define SEDIMENT_STRETCH 1.6

/* The settling's length: sediment_T_visq T_visq (0: no prelude). */
static double column_prelude_time_s(const gf_run_spec *spec, const gf_scales *scales)
{
    return gf_run_spec_param(spec, "sediment_T_visq", 0.0) * scales->t_visq_s;
}

static gf_status column_prelude(gf_sim *sim)
{
    const gf_run_spec *spec = gf_sim_spec(sim);
    const double t_settle_s = column_prelude_time_s(spec, gf_sim_scales(sim));
    if (!(t_settle_s > 0.0))
        return GF_OK;
    const double r_floor = 0.5 * spec->grains.diameter_m;
    gf_particles *p = gf_sim_particles(sim);
    for (size_t i = 0; i < p->n_local; ++i)
        if (!(p->flags[i] & GF_P_GLUED)) {
            p->y_m[i] = r_floor + (p->y_m[i] - r_floor) * SEDIMENT_STRETCH;
            p->vx_m_s[i] = p->vy_m_s[i] = p->vz_m_s[i] = 0.0;
            p->wx_rad_s[i] = p->wy_rad_s[i] = p->wz_rad_s[i] = 0.0;
        }
    GF_TRY(gf_sim_set_wall_active(sim, WALL_GATE, 1));
    GF_TRY(gf_sim_rebuild_neighbours(sim));
    GF_TRY(gf_sim_advance(sim, (long)ceil(t_settle_s / gf_sim_dt_s(sim))));
    GF_TRY(gf_sim_set_wall_active(sim, WALL_GATE, 0));
    gf_sim_reset_clock(sim);
    return GF_OK;
}

/* Settling through the fluid needs a fluid. */
static const char *column_check(const gf_run_spec *spec, char *why, size_t n)
{
    if (gf_run_spec_param(spec, "sediment_T_visq", 0.0) > 0.0 &&
        (strcmp(spec->fluid.model, "none") == 0 || !(spec->fluid.viscosity_Pa_s > 0.0))) {
        snprintf(why, n, "settling through the fluid before t = 0 needs a fluid (fluid.model is %s)", spec->fluid.model);
        return "sediment_T_visq";
    }
    return NULL;
}

static gf_measure_domain column_domain(gf_sim *sim)
{
    gf_measure_domain d;
    gf_sim_box(sim, d.lo_m, d.hi_m, d.periodic);
    return d;
}

static double column_region_phi(gf_sim *sim, const column_geom *g)
{
    gf_measure_domain d = column_domain(sim);
    double m = 1.5 * g->D;
    double lo[3] = {m, m, d.lo_m[2]}, hi[3] = {g->R0 - m, g->H0 - m, d.hi_m[2]};
    if (hi[1] - lo[1] < g->D) /* short columns: keep at least one D of height */
        lo[1] = 0.5 * g->D, hi[1] = fmax(g->H0 - 0.5 * g->D, 1.5 * g->D);
    return gf_measure_solid_fraction_box(gf_sim_particles(sim), &d, lo, hi, g->D / 8.0, 0);
}

/* Solid volume of the mobile grains at x < x_max over R0 H0 W (Rondon et al. 2011's estimate of the
 * column's packing); over every x it is the same at every time. */
static double column_phi(gf_sim *sim, const column_geom *g, double x_max)
{
    const gf_particles *p = gf_sim_particles(sim);
    double vol = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        if (!(p->flags[i] & GF_P_GLUED) && p->x_m[i] < x_max)
            vol += sphere_volume(p->radius_m[i]);
    return vol / (g->R0 * g->H0 * g->W);
}

static gf_status column_diagnose(gf_sim *sim, double *v)
{
    column_geom g;
    column_geom_of(gf_sim_spec(sim), &g);
    gf_measure_domain d = column_domain(sim);
    int n_bins = (int)ceil(g.L / g.D);
    double *solid = malloc((size_t)n_bins * sizeof *solid);
    if (!solid)
        return GF_FAIL(gf_sim_ctx(sim), GF_ERR_NOMEM, "column_collapse: cannot allocate %d bins", n_bins);
    gf_measure_deposit dep;
    gf_status st = gf_measure_deposit_profile(gf_sim_ctx(sim), gf_sim_particles(sim), &d, 0.0, g.D, n_bins,
                                              0.25 * g.D, 1, NULL, solid, &dep);
    if (st == GF_OK) {
        const double phi_col = column_phi(sim, &g, INFINITY);
        v[0] = dep.front_m;
        v[1] = dep.height_m;
        v[2] = column_region_phi(sim, &g);
        v[3] = gf_measure_profile_extent(solid, n_bins, g.D, phi_col * g.D);
        v[4] = gf_measure_profile_extent(solid, n_bins, g.D, phi_col * 2.0 * g.D);
    }
    free(solid);
    return st;
}

static int column_done(gf_sim *sim)
{
    const gf_run_spec *s = gf_sim_spec(sim);
    column_geom g;
    column_geom_of(s, &g);
    double T0 = sqrt(2.0 * g.H0 / s->gravity_m_s2);
    if (gf_sim_time_s(sim) < 2.0 * T0)
        return 0;
    return gf_scene_at_rest(sim, gf_run_spec_param(s, "rest_energy", 1e-4));
}

static gf_status column_initial_packing(gf_sim *sim, double *phi_measured, double *phi_local)
{
    column_geom g;
    column_geom_of(gf_sim_spec(sim), &g);
    *phi_measured = column_phi(sim, &g, g.R0);
    *phi_local = column_region_phi(sim, &g);
    return GF_OK;
}

static void column_geometry(const gf_run_spec *spec, double *length_m, double *height_m)
{
    column_geom g;
    column_geom_of(spec, &g);
    *length_m = g.R0;
    *height_m = g.H0;
}

/* phi R0 H0 W over the mean grain volume, and the glued floor: gf_packing_rough_base places
 * grains at random until 500 misses in a row, about 0.45 per D^2 (the 404 and 960 grains of
 * the a = 1 columns at R0 = 10 and 16 D). */
static double column_grain_count(const gf_run_spec *spec)
{
    column_geom g;
    column_geom_of(spec, &g);
    double column = g.phi * g.R0 * g.H0 * g.W / sphere_volume(0.5 * g.D);
    return column + (g.rough ? 0.45 * g.L * g.W / (g.D * g.D) : 0.0);
}

const gf_scene_desc gf_scene_column_collapse = {
    .name = "column_collapse",
    .caption = "granular column released by a gate, quasi-2D slab (Lajeunesse 2005; Rondon 2011; Izard 2014 ch. 5)",
    .needs = GF_NEED_CONTACTS | GF_NEED_FLUID | GF_NEED_PROBES | GF_NEED_PACKING,
    GF_SCENE_PARAMS(column_params),
    .default_end_time_nd = 0.0,
    .build = column_build,
    .start = column_start,
    .prelude = column_prelude,
    GF_SCENE_DIAG(column_diag),
    .diagnose = column_diagnose,
    .done = column_done,
    .check = column_check,
    .initial_packing = column_initial_packing,
    .column_geometry = column_geometry,
    .grain_count = column_grain_count,
    .fluid_box = column_fluid_box,
    .prelude_time_s = column_prelude_time_s,
};
