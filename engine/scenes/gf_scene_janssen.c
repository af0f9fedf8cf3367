/*
 * Janssen silo: grains poured into a square box whose side walls are made of
 * glued grains, settled under gravity (Izard 2014 §2.1.3.2; Janssen 1895).
 *
 * Geometry (seed: 0.1 x 0.1 x 5 m, R = 5 mm +- 10 %, 56 400 grains): a free
 * box [0, S]^2 x [0, h] (S = side_over_D D, 10 D in the seed; h the fill
 * height) whose four side walls are glued grains ("walls made of glued
 * grains, so that the wall friction is under control"); a plane floor y = 0
 * and a lid well above the fill. The thesis does not say how its glued
 * grains are arranged, and the wall friction they mobilise depends on it
 * (docs/notes/validation-dem.md, row 6: f_p 0.28 on the lattice, 0.34 on the
 * random wall). Default (random_walls = 1), a random wall as the rough
 * bases of the other scenes: a layer of glued grains placed by random
 * sequential adsorption (add_random_wall), backed half a grain behind by a
 * square lattice of glued grains, because the random layer's holes are
 * nearly a grain wide: alone, it let grains through to the safety planes
 * (10.7 % of the side load on them at the seed's section, measured).
 * random_walls = 0: the square lattice alone (add_glued_wall), whose
 * largest grains touch the side plane; its spacing is fitted to the side.
 * Frictionless plane walls behind the glued grains are only a safety net
 * (no vertical force, so they do not bias the wall load). S^2 and 4 S are the nominal cross-section and perimeter, and
 * the seed's C_tot = N V / (S^2 h) uses the same box (grains nesting into
 * the wall make the effective section slightly larger; the test measures it).
 *
 * Filling (the seed's "settling from a taller box"): gf_packing deposits the
 * grains between the glued walls (its obstacles, with the run's grain
 * friction mu_c on grain-wall contacts) at the requested interior packing
 * fraction (seed C_tot = 0.59, tolerance phi_tolerance), so that the wall
 * friction is mobilised by the filling itself (a column prepared
 * between frictionless planes and handed to rough walls at rest carries no
 * wall load; a violent pour from a tall gas overshoots and reverses it).
 * The column then settles with the run's contacts for settle_time_nd, and
 * the floor is lowered by floor_drop_over_D D in five steps (lower_floor:
 * Vanel et al. PRL 84 1439, 2000 pull the bottom piston down so that the
 * wall friction is fully mobilised upwards, Janssen's assumption); t = 0
 * after. The achieved C_tot = N V / (S^2 h_top) is measured.
 * free_pour = 1 fills the thesis' way instead: the grains fall from a loose
 * lattice twice the fill height with the run's friction, free rotations and
 * no drag (gf_packing's free pour), at whatever packing they reach (0.60
 * here). With the default 0.05 D floor drop the rebound of that pour leaves
 * the wall friction reversed in the upper column (docs/notes/validation-dem.md,
 * row 6, measured), hence the tuned filling by default.
 * done(): mean kinetic energy per mobile grain below 1e-6 m g D (static).
 *
 * Janssen law with a free top (Izard 2014 (2.11)-(2.15), where P is printed in the
 * exponent but P_m is meant): sigma(d) = rho_e g lambda (1 - exp(-d/lambda)) with
 * lambda = S^2 / (f_p K 4 S) = S / (4 f_p K), d the depth below the top.
 * The vertical stress profile is gf_measure_silo_vertical_stress (weight of
 * the grains above a plane minus what the glued walls carry).
 * No scalar diagnostics (docs/output.md: profiles go to janssen.nc).
 */
#include <math.h>

#include "particles/gf_packing.h"
#include "scenes/gf_measure.h"
#include "scenes/gf_scene.h"
#include "scenes/gf_scene_box.h"
#include "scenes/gf_scene_deposit.h"
#include "scenes/gf_scene_settle.h"

static const gf_param_info janssen_params[] = {
    {"side_over_D", "1", 10.0, 3.0, 1000.0, "box side S / D (seed: 0.1 m / 1 cm = 10)"},
    {"fill_height_over_D", "1", 40.0, 3.0, 10000.0, "fill height h / D (seed: 500)"},
    {"phi_target", "1", 0.59, 0.50, 0.645, "interior packing fraction requested (seed C_tot = 0.59)"},
    {"phi_tolerance", "1", 0.01, 0.001, 0.05, "accepted |Phi - target| of the preparation (seed row 4: 0.01)"},
    {"settle_time_nd", "1", 10.0, 0.0, 1e4, "settling with the run's contacts before t = 0, sqrt(D/g)"},
    {"floor_drop_over_D", "1", 0.05, 0.0, 1.0, "floor lowered by this / D in 5 steps to mobilise wall friction"},
    {"free_pour", "1", 0.0, 0.0, 1.0,
     "1: the seed's filling, grains falling from a loose lattice with the run's friction, free rotations and no "
     "drag, at the packing they reach (phi_target unused); 0: deposited at phi_target"},
    {"random_walls", "1", 1.0, 0.0, 1.0,
     "1: each glued wall is a random layer (random sequential adsorption, as the rough bases) backed by a square "
     "lattice; 0: the square lattice alone"},
};

static double glued_radius_max(const gf_run_spec *s)
{
    return 0.5 * s->grains.diameter_m * (1.0 + s->grains.polydispersity);
}

/* One wall of glued grains whose inner face is the plane x_axis = face (`out` = -1 for the low side,
 * +1 for the high side): a square lattice of spacing D (1 + p) in (t, y), t over [-r_w, S + r_w] so that
 * the corners close, centres at face + out (r_w + behind) (r_w = R (1 + p)): with behind = 0 the largest
 * grains touch the face, the others sit up to 2 p R behind it. A grain resting in a lattice hole keeps its
 * centre ~0.1 D inside the face (holes of diagonal 0.55 D), so the section is S^2 within a few per cent.
 * behind > 0: the backing of a random wall. */
static gf_status add_glued_wall(gf_ctx *ctx, gf_particles *p, const gf_run_spec *spec, int axis, double face,
                                double out, double side, double height, double behind, gf_rng *rng)
{
    double D = spec->grains.diameter_m, pd = spec->grains.polydispersity, a = D * (1.0 + pd);
    double rw = glued_radius_max(spec), span = side + 2.0 * rw;
    int nt = (int)ceil(span / a) + 1, ny = (int)ceil(height / a);
    double at_t = span / (nt - 1), n_pos = face + out * (rw + behind);
    for (int j = 0; j < ny; ++j)
        for (int k = 0; k < nt; ++k) {
            if (axis == 2 && (k == 0 || k == nt - 1))
                continue; /* the corner columns belong to the x walls */
            double t = -rw + k * at_t, y = (j + 0.5) * a;
            double r = 0.5 * D * (1.0 + pd * gf_rng_range(rng, -1.0, 1.0));
            double x = axis == 0 ? n_pos : t, z = axis == 0 ? t : n_pos;
            GF_TRY(gf_particles_add(ctx, p, x, y, z, r, spec->grains.density_kg_m3, GF_P_GLUED, NULL));
        }
    return GF_OK;
}

/* The random wall's backing lattice, this far / D behind its random layer: the random layer's holes are
 * nearly a grain wide, so the column's grains nest into them down to the backing (not through them). */
#define RANDOM_WALL_BACK_OVER_D 0.5

/* Where a wall's frictionless safety plane sits behind its face: behind the glued grains. */
static double wall_setback(const gf_run_spec *s, int random_walls)
{
    double rw = glued_radius_max(s);
    return random_walls ? 2.0 * rw + RANDOM_WALL_BACK_OVER_D * s->grains.diameter_m : rw;
}

/* The front layer of a random wall: glued grains placed by random sequential adsorption on the plane
 * (gf_packing_rough_base, the rough bases' method: close to the jammed coverage, 0.55 of the plane),
 * centres at face + out r_w as the lattice's, over t in [-2 r_w, S + 2 r_w] for the x walls (which close
 * the corners) and [0, S] for the z walls. */
static gf_status add_random_wall(gf_ctx *ctx, gf_particles *p, const gf_run_spec *spec, int axis, double face,
                                 double out, double side, double height, uint64_t seed)
{
    double rw = glued_radius_max(spec), n_pos = face + out * rw;
    double t0 = axis == 0 ? -2.0 * rw : 0.0, t1 = axis == 0 ? side + 2.0 * rw : side;
    gf_psd psd = {0.5 * spec->grains.diameter_m, spec->grains.polydispersity};
    gf_particles *layer = NULL;
    GF_TRY(gf_particles_create(ctx, 1024, &layer));
    gf_status st = gf_packing_rough_base(ctx, layer, &psd, spec->grains.density_kg_m3, 0.0, t0, t1, 0.0, height,
                                         (const int[2]){0, 0}, seed);
    for (size_t i = 0; st == GF_OK && i < layer->n_local; ++i) { /* (t, 0, height) -> the wall plane */
        double t = layer->x_m[i], y = layer->z_m[i];
        st = gf_particles_add(ctx, p, axis == 0 ? n_pos : t, y, axis == 0 ? t : n_pos, layer->radius_m[i],
                              spec->grains.density_kg_m3, GF_P_GLUED, NULL);
    }
    gf_particles_destroy(&layer);
    return st;
}

/* Mobilises the wall friction as Vanel et al. (PRL 2000) do by pulling the silo's bottom piston down:
 * the floor (wall 0) is replaced by planes 1/N_DROP, 2/N_DROP, ... of floor_drop_over_D D lower, one at a
 * time with 2 sqrt(D/g) of settling each, so the column slides down the glued walls by a small fraction
 * of a grain and every wall contact reaches its Coulomb limit upwards (Janssen's assumption). */
static gf_status lower_floor(gf_sim *sim, const gf_run_spec *spec)
{
    enum { N_DROP = 5 };
    double D = spec->grains.diameter_m, drop = gf_run_spec_param(spec, "floor_drop_over_D", 0.05) * D;
    if (!(drop > 0.0))
        return GF_OK;
    int previous = 0; /* the floor y = 0 is wall 0 */
    for (int k = 1; k <= N_DROP; ++k) {
        double pt[3] = {0.0, -drop * k / N_DROP, 0.0}, up[3] = {0.0, 1.0, 0.0};
        int id;
        GF_TRY(gf_sim_add_wall(sim, pt, up, spec->contact.wall_friction, &id));
        GF_TRY(gf_sim_set_wall_active(sim, previous, 0));
        previous = id;
        GF_TRY(gf_scene_settle(sim, spec, 2.0));
    }
    return GF_OK;
}

static gf_status janssen_build(gf_sim *sim, const gf_run_spec *spec)
{
    gf_ctx *ctx = gf_sim_ctx(sim);
    gf_particles *p = gf_sim_particles(sim);
    double D = spec->grains.diameter_m, g = spec->gravity_m_s2;
    double S = gf_run_spec_param(spec, "side_over_D", 10.0) * D;
    double h = gf_run_spec_param(spec, "fill_height_over_D", 40.0) * D;
    double top = h + 6.0 * D;
    int random_walls = gf_run_spec_param(spec, "random_walls", 1.0) > 0.5;
    double sb = wall_setback(spec, random_walls), margin = fmax(2.0 * D, sb + D);
    const double lo[3] = {-margin, -D, -margin}, hi[3] = {S + margin, top, S + margin};
    GF_TRY(gf_scene_box_under_gravity(sim, lo, hi, (const int[3]){0, 0, 0}, g));
    /* floor and lid frictional; the side planes frictionless, the glued grains are the walls */
    const double mu = spec->contact.wall_friction;
    const gf_scene_plane planes[] = {
        {{0, 0, 0}, {0, 1, 0}, mu},       {{0, top, 0}, {0, -1, 0}, mu},
        {{-sb, 0, 0}, {1, 0, 0}, 0.0},    {{S + sb, 0, 0}, {-1, 0, 0}, 0.0},
        {{0, 0, -sb}, {0, 0, 1}, 0.0},    {{0, 0, S + sb}, {0, 0, -1}, 0.0},
    };
    GF_TRY(gf_scene_add_planes(sim, 6, planes));
    /* glued walls first (kept apart as the preparation's obstacles), then the deposit between them */
    gf_rng *rng = gf_sim_rng(sim);
    gf_particles *walls = NULL;
    GF_TRY(gf_particles_create(ctx, 1024, &walls));
    gf_status st = GF_OK;
    for (int k = 0; k < 4 && st == GF_OK; ++k) {
        int axis = k < 2 ? 0 : 2;
        double face = k % 2 ? S : 0.0, out = k % 2 ? 1.0 : -1.0;
        if (random_walls) {
            st = add_random_wall(ctx, walls, spec, axis, face, out, S, top, spec->seed + 7919u * (uint64_t)(k + 1));
            if (st == GF_OK)
                st = add_glued_wall(ctx, walls, spec, axis, face, out, S, top, RANDOM_WALL_BACK_OVER_D * D, rng);
        } else
            st = add_glued_wall(ctx, walls, spec, axis, face, out, S, top, 0.0, rng);
    }
    for (size_t i = 0; st == GF_OK && i < walls->n_local; ++i)
        st = gf_particles_add(ctx, p, walls->x_m[i], walls->y_m[i], walls->z_m[i], walls->radius_m[i],
                              spec->grains.density_kg_m3, GF_P_GLUED, NULL);
    int pour = gf_run_spec_param(spec, "free_pour", 0.0) > 0.5;
    double phi_req = isnan(spec->phi_initial) ? gf_run_spec_param(spec, "phi_target", 0.59) : spec->phi_initial;
    gf_packing_spec ps = {.lo_m = {0, 0, 0}, .hi_m = {S, h, S}, .periodic = {0, 0, 0}, .walls_x = 1, .walls_z = 1,
                          .wall_setback_m = sb, /* the run's frictionless safety planes, behind the glued walls */
                          .phi_target = pour ? NAN : phi_req, .free_pour = pour,
                          .mu_natural = spec->contact.friction,
                          .tolerance = gf_run_spec_param(spec, "phi_tolerance", 0.01),
                          .psd = {0.5 * D, spec->grains.polydispersity}, .density_kg_m3 = spec->grains.density_kg_m3,
                          .gravity_m_s2 = g, .obstacles = walls, .mu_obstacles = spec->contact.friction,
                          .seed = spec->seed};
    gf_packing_result pr;
    if (st == GF_OK)
        st = gf_scene_deposit(sim, &ps, &pr);
    gf_particles_destroy(&walls);
    GF_TRY(st);
    GF_TRY(gf_scene_settle(sim, spec, gf_run_spec_param(spec, "settle_time_nd", 10.0)));
    GF_TRY(lower_floor(sim, spec));
    gf_sim_reset_clock(sim);
    return GF_OK;
}

static int janssen_done(gf_sim *sim) { return gf_scene_at_rest(sim, 1e-6); }

static gf_status janssen_initial_packing(gf_sim *sim, double *phi_measured, double *phi_local)
{
    /* C_tot of the seed: grain volume / (S^2 x fill height), the fill height being where the slab solid
     * fraction falls to half its plateau; local: an interior box 1.5 D inside the walls, 3 D from the ends */
    const gf_run_spec *s = gf_sim_spec(sim);
    const gf_particles *p = gf_sim_particles(sim);
    double D = s->grains.diameter_m, S = gf_run_spec_param(s, "side_over_D", 10.0) * D, vol = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        if (!(p->flags[i] & GF_P_GLUED))
            vol += 4.0 / 3.0 * M_PI * pow(p->radius_m[i], 3);
    gf_measure_domain d;
    gf_sim_box(sim, d.lo_m, d.hi_m, d.periodic);
    enum { MAX_SLABS = 8192 };
    static _Thread_local double phi[MAX_SLABS];
    int n = (int)fmin(MAX_SLABS, ceil(d.hi_m[1] / D));
    GF_TRY(gf_measure_profile_y(gf_sim_ctx(sim), p, &d, 0.0, D, n, phi, NULL));
    double h = gf_measure_bed_height_m(phi, n, 0.0, D, 0.5);
    *phi_measured = vol / (S * S * h);
    double lo[3] = {1.5 * D, 3.0 * D, 1.5 * D}, hi[3] = {S - 1.5 * D, h - 3.0 * D, S - 1.5 * D};
    *phi_local = gf_measure_solid_fraction_box(p, &d, lo, hi, D / 8.0, 0);
    return GF_OK;
}

/* phi S^2 h over the mean grain volume, and four walls of glued grains, one per D^2. */
static double janssen_grain_count(const gf_run_spec *spec)
{
    double S = gf_run_spec_param(spec, "side_over_D", 10.0), h = gf_run_spec_param(spec, "fill_height_over_D", 40.0);
    double phi = isnan(spec->phi_initial) ? gf_run_spec_param(spec, "phi_target", 0.59) : spec->phi_initial;
    return phi * S * S * h / (M_PI / 6.0) + 4.0 * S * h;
}

const gf_scene_desc gf_scene_janssen = {
    .name = "janssen",
    .caption = "Janssen silo with walls of glued grains, settled at rest (Izard 2014 §2.1.3.2)",
    .needs = GF_NEED_CONTACTS | GF_NEED_PACKING,
    GF_SCENE_PARAMS(janssen_params),
    .default_end_time_nd = 50.0,
    .build = janssen_build,
    .start = NULL,
    .n_diag = 0,
    .diag = NULL,
    .diagnose = NULL,
    .done = janssen_done,
    .initial_packing = janssen_initial_packing,
    .grain_count = janssen_grain_count,
};
