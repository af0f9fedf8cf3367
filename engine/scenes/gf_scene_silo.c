/*
 * Silo discharge through a rectangular orifice, kept steady by reinjecting
 * the grains that leave (Djouwe Meffeja 2012, ch. 3, §3.3).
 *
 * Geometry (thesis §3.3): a box of Lx x Ly (floor) x Lz (height), 25 d x
 * 25 d x 50 d by default, with frictional plane walls (mu_wall = 0.5 in the
 * thesis) and a rectangle Ltx x Lty cut in the middle of the floor (6 d x 6 d
 * usually, 4 d to 18 d in the Beverloo study). The axes are the project's: y
 * points up, the floor is y = 0, the orifice spans x and z. A grain over the
 * orifice touches only its rim (gf_sim_set_wall_hole): the thesis does not say
 * how its orifice edge acts, and an edge that grains roll off is the
 * geometric one.
 *
 * Filling (thesis §3.3: "settling with the orifice closed"): the grains fall
 * from a loose lattice and settle with the run's friction (gf_packing's free
 * pour) up to the fill height H, then settle with the run's contacts for
 * settle_time_nd while the floor is whole; t = 0 when the orifice opens
 * (at the end of build()).
 *
 * Reinjection (thesis §3.3): a grain whose centre falls below y = -d has left
 * (the thesis does not say where it stops counting one) and is moved, at rest
 * and without spin, to the next site of a lattice of spacing 2 R_max at the
 * reinjection height H_max: (R_max, H_max, R_max), then along x by 2 R_max,
 * then the next row along z, back to the first row past the last. A site
 * with a grain closer than 2 R_max is skipped (the thesis does not say what
 * it does when the grain placed there one lattice period earlier is still
 * there, which happens at large orifices); with none free the grain waits
 * below the floor, held at rest. Done every GF_SCENE_MAINTAIN_EVERY steps.
 *
 * Diagnostics (diagnostics.nc), at every output record:
 *   discharged_grains      grains that left since t = 0 (cumulative count)
 *   discharge_rate         grains per second since the previous record, Q
 *   discharge_mass_rate    kg per second since the previous record
 *   orifice_packing_fraction  solid fraction of the box over the orifice,
 *                          0 <= y <= d (phi_out of thesis §3.4.3)
 *   fill_height            the bed top (half-plateau of phi in slabs of d)
 * The steady Q, its error and the Beverloo and Q(H) fits are the post stage
 * flow_rate's (postproc/stages/gf_silo_flow.c).
 *
 * Orifice size D for Beverloo (Q = C rho_n sqrt(g) (D - k d)^(5/2), thesis
 * (3.16)): the hydraulic diameter 2 Ltx Lty / (Ltx + Lty) of the rectangle.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "particles/gf_packing.h"
#include "scenes/gf_measure.h"
#include "scenes/gf_scene.h"
#include "scenes/gf_scene_box.h"
#include "scenes/gf_scene_deposit.h"
#include "scenes/gf_scene_settle.h"

static const gf_param_info silo_params[] = {
    {"width_x_over_d", "1", 25.0, 4.0, 400.0, "box width Lx / d along x (thesis: 25)"},
    {"width_z_over_d", "1", 25.0, 4.0, 400.0, "box depth Ly / d along z (thesis: 25)"},
    {"height_over_d", "1", 50.0, 6.0, 2000.0, "box height Lz / d (thesis: 50)"},
    {"orifice_x_over_d", "1", 6.0, 2.0, 400.0, "orifice side Ltx / d along x (thesis: 6; 4 to 18 for Beverloo)"},
    {"orifice_z_over_d", "1", 6.0, 2.0, 400.0, "orifice side Lty / d along z (thesis: 6)"},
    {"fill_height_over_d", "1", 25.4, 1.0, 2000.0, "fill height H / d of the settled column (thesis: 25.4)"},
    {"reinject_height_over_d", "1", 45.0, 3.0, 2000.0,
     "reinjection height H_max / d of the lattice that takes back the grains that left (below the lid)"},
    {"settle_time_nd", "1", 20.0, 0.0, 1e4, "settling with the orifice closed before t = 0, sqrt(d/g)"},
};

/* Counters kept in the sim (gf_sim_scene_counters: checkpointed). */
enum { C_OUT, C_OUT_MASS, C_SITE, C_HOLD, C_REC_OUT, C_REC_MASS, C_REC_T };

typedef struct silo_geom {
    double d, Lx, Lz_box, Ly, ox0, ox1, oz0, oz1, H, H_max;
} silo_geom;

static silo_geom geometry(const gf_run_spec *s)
{
    double d = s->grains.diameter_m;
    silo_geom g = {.d = d};
    g.Lx = gf_run_spec_param(s, "width_x_over_d", 25.0) * d;
    g.Ly = gf_run_spec_param(s, "width_z_over_d", 25.0) * d;
    g.Lz_box = gf_run_spec_param(s, "height_over_d", 50.0) * d;
    double ax = gf_run_spec_param(s, "orifice_x_over_d", 6.0) * d, az = gf_run_spec_param(s, "orifice_z_over_d", 6.0) * d;
    g.ox0 = 0.5 * (g.Lx - ax), g.ox1 = 0.5 * (g.Lx + ax);
    g.oz0 = 0.5 * (g.Ly - az), g.oz1 = 0.5 * (g.Ly + az);
    g.H = gf_run_spec_param(s, "fill_height_over_d", 25.4) * d;
    g.H_max = gf_run_spec_param(s, "reinject_height_over_d", 45.0) * d;
    return g;
}

static double radius_max(const gf_run_spec *s) { return 0.5 * s->grains.diameter_m * (1.0 + s->grains.polydispersity); }

/* Where the grains that left are dropped and the box ends below the floor. */
#define EXIT_BELOW_OVER_D 1.0
#define BOX_BELOW_OVER_D 6.0
#define HOLD_ROW_OVER_D (-4.0)
#define FLOOR_WALL 0

static const char *silo_check(const gf_run_spec *s, char *why, size_t n)
{
    const double x = gf_run_spec_param(s, "width_x_over_d", 25.0), z = gf_run_spec_param(s, "width_z_over_d", 25.0);
    const double lz = gf_run_spec_param(s, "height_over_d", 50.0);
    const double ox = gf_run_spec_param(s, "orifice_x_over_d", 6.0), oz = gf_run_spec_param(s, "orifice_z_over_d", 6.0);
    const double h = gf_run_spec_param(s, "fill_height_over_d", 25.4);
    const double hm = gf_run_spec_param(s, "reinject_height_over_d", 45.0);
    /* a floor rim of at least one grain on each side of the orifice */
    if (ox > x - 2.0) {
        snprintf(why, n, "orifice_x_over_d = %g is larger than the floor allows (width_x_over_d - 2 = %g)", ox, x - 2.0);
        return "orifice_x_over_d";
    }
    if (oz > z - 2.0) {
        snprintf(why, n, "orifice_z_over_d = %g is larger than the floor allows (width_z_over_d - 2 = %g)", oz, z - 2.0);
        return "orifice_z_over_d";
    }
    /* the reinjected grains fall onto the column: their lattice sits above the fill and below the lid */
    if (hm > lz - 1.0) {
        snprintf(why, n, "reinject_height_over_d = %g does not fit below the lid (height_over_d - 1 = %g)", hm, lz - 1.0);
        return "reinject_height_over_d";
    }
    if (h > hm - 2.0) {
        snprintf(why, n,
                 "fill_height_over_d = %g does not fit the box: the fill must stay 2 d below the reinjection height "
                 "(reinject_height_over_d = %g, height_over_d = %g)",
                 h, hm, lz);
        return "fill_height_over_d";
    }
    return NULL;
}

static gf_status silo_build(gf_sim *sim, const gf_run_spec *spec)
{
    gf_ctx *ctx = gf_sim_ctx(sim);
    char why[256];
    if (silo_check(spec, why, sizeof why))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "scene silo: %s", why);
    const silo_geom g = geometry(spec);
    const double d = g.d, gr = spec->gravity_m_s2;
    const double lo[3] = {0.0, -BOX_BELOW_OVER_D * d, 0.0}, hi[3] = {g.Lx, g.Lz_box, g.Ly};
    GF_TRY(gf_scene_box_under_gravity(sim, lo, hi, (const int[3]){0, 0, 0}, gr));
    const double mu = spec->contact.wall_friction;
    const gf_scene_plane walls[] = {
        [FLOOR_WALL] = {{0, 0, 0}, {0, 1, 0}, mu}, {{0, g.Lz_box, 0}, {0, -1, 0}, mu},
        {{0, 0, 0}, {1, 0, 0}, mu},                {{g.Lx, 0, 0}, {-1, 0, 0}, mu},
        {{0, 0, 0}, {0, 0, 1}, mu},                {{0, 0, g.Ly}, {0, 0, -1}, mu},
    };
    GF_TRY(gf_scene_add_planes(sim, 6, walls));
    gf_packing_spec ps = {.lo_m = {0, 0, 0}, .hi_m = {g.Lx, g.H, g.Ly}, .periodic = {0, 0, 0}, .walls_x = 1,
                          .walls_z = 1, .phi_target = NAN, .free_pour = 1, .mu_natural = spec->contact.friction,
                          .psd = {0.5 * d, spec->grains.polydispersity}, .density_kg_m3 = spec->grains.density_kg_m3,
                          .gravity_m_s2 = gr, .seed = spec->seed};
    gf_packing_result pr;
    GF_TRY(gf_scene_deposit(sim, &ps, &pr));
    GF_TRY(gf_scene_settle(sim, spec, gf_run_spec_param(spec, "settle_time_nd", 20.0)));
    gf_sim_reset_clock(sim);
    /* t = 0: the orifice opens (here rather than in start(), which a restart
     * skips: a restarted run rebuilds the scene and must find the hole open) */
    double lo_h[3] = {g.ox0, 0.0, g.oz0}, hi_h[3] = {g.ox1, 0.0, g.oz1};
    return gf_sim_set_wall_hole(sim, FLOOR_WALL, lo_h, hi_h);
}

/* The reinjection lattice: sites of spacing a = 2 R_max, nx along x and nz
 * along z, in layers from H_max down (layer 0, the thesis' only one, first;
 * the lower layers take the grains only when every site above is taken),
 * down to 2 d above the fill. */
typedef struct lattice {
    double a, y0;
    long nx, nz, n_layers;
    unsigned char *taken;   /* n_layers x nz x nx */
} lattice;

static void lattice_site(const lattice *L, long layer, long k, double c[3])
{
    c[0] = 0.5 * L->a + L->a * (double)(k % L->nx);
    c[1] = L->y0 - L->a * (double)layer;
    c[2] = 0.5 * L->a + L->a * (double)(k / L->nx);
}

/* Marks the sites closer than a to a grain centre. */
static void lattice_mark(lattice *L, const double c[3])
{
    const double a = L->a;
    long l0 = (long)ceil((L->y0 - c[1] - a) / a), l1 = (long)floor((L->y0 - c[1] + a) / a);
    long i0 = (long)ceil((c[0] - 1.5 * a) / a), i1 = (long)floor((c[0] + 0.5 * a) / a);
    long k0 = (long)ceil((c[2] - 1.5 * a) / a), k1 = (long)floor((c[2] + 0.5 * a) / a);
    for (long l = l0 < 0 ? 0 : l0; l <= l1 && l < L->n_layers; ++l)
        for (long k = k0 < 0 ? 0 : k0; k <= k1 && k < L->nz; ++k)
            for (long i = i0 < 0 ? 0 : i0; i <= i1 && i < L->nx; ++i) {
                double s[3];
                lattice_site(L, l, k * L->nx + i, s);
                double dx = s[0] - c[0], dy = s[1] - c[1], dz = s[2] - c[2];
                if (dx * dx + dy * dy + dz * dz < a * a)
                    L->taken[(l * L->nz + k) * L->nx + i] = 1;
            }
}

static gf_status lattice_build(gf_ctx *ctx, const silo_geom *g, double r_max, const gf_particles *p, lattice *L)
{
    L->a = 2.0 * r_max;
    L->y0 = g->H_max;
    L->nx = (long)floor(g->Lx / L->a), L->nz = (long)floor(g->Ly / L->a);
    L->n_layers = 1 + (long)floor((g->H_max - (g->H + 2.0 * g->d)) / L->a);
    if (L->nx < 1 || L->nz < 1 || L->n_layers < 1)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "scene silo: no room for the reinjection lattice");
    L->taken = calloc((size_t)(L->n_layers * L->nx * L->nz), 1);
    if (!L->taken)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "scene silo: cannot allocate the reinjection lattice");
    const double y_lo = L->y0 - L->a * (double)L->n_layers;
    for (size_t j = 0; j < p->n_local; ++j)
        if (p->y_m[j] > y_lo && !(p->flags[j] & GF_P_GLUED))
            lattice_mark(L, (double[3]){p->x_m[j], p->y_m[j], p->z_m[j]});
    return GF_OK;
}

/* The next free site in the thesis' order from the cursor, top layer first; 0 when none. */
static int lattice_take(lattice *L, double *cursor, double c[3])
{
    const long n = L->nx * L->nz;
    for (long l = 0; l < L->n_layers; ++l)
        for (long t = 0; t < n; ++t) {
            long k = ((long)*cursor + t) % n;
            if (L->taken[l * n + k])
                continue;
            L->taken[l * n + k] = 1;
            *cursor = (double)((k + 1) % n);
            lattice_site(L, l, k, c);
            return 1;
        }
    return 0;
}

static void set_at_rest(gf_particles *p, size_t i)
{
    p->vx_m_s[i] = p->vy_m_s[i] = p->vz_m_s[i] = 0.0;
    p->wx_rad_s[i] = p->wy_rad_s[i] = p->wz_rad_s[i] = 0.0;
}

/* Counts the grains that left (mobile grains below y = -d) and moves them to
 * the reinjection lattice at rest. A grain that finds no free site waits,
 * glued, on a holding row below the floor, and is placed at a later call. */
static gf_status silo_maintain(gf_sim *sim)
{
    const gf_run_spec *spec = gf_sim_spec(sim);
    gf_particles *p = gf_sim_particles(sim);
    double *cnt = gf_sim_scene_counters(sim);
    const silo_geom g = geometry(spec);
    const double r_max = radius_max(spec), y_exit = -EXIT_BELOW_OVER_D * g.d;
    size_t n_out = 0;
    for (size_t i = 0; i < p->n_local; ++i)
        n_out += p->y_m[i] < y_exit;
    if (n_out == 0)
        return GF_OK;
    lattice L;
    GF_TRY(lattice_build(gf_sim_ctx(sim), &g, r_max, p, &L));
    const long n_hold = L.nx * L.nz;
    for (size_t i = 0; i < p->n_local; ++i) {
        if (!(p->y_m[i] < y_exit))
            continue;
        if (!(p->flags[i] & GF_P_GLUED)) { /* a held grain was counted when it left */
            cnt[C_OUT] += 1.0;
            cnt[C_OUT_MASS] += p->mass_kg[i];
        }
        double c[3];
        set_at_rest(p, i);
        if (lattice_take(&L, &cnt[C_SITE], c)) {
            p->flags[i] &= (uint8_t)~GF_P_GLUED;
        } else { /* wait below the floor, out of the way of the grains leaving */
            long k = (long)cnt[C_HOLD];
            cnt[C_HOLD] = (double)((k + 1) % n_hold);
            lattice_site(&L, 0, k, c);
            c[1] = HOLD_ROW_OVER_D * g.d;
            p->flags[i] |= GF_P_GLUED;
        }
        p->x_m[i] = c[0], p->y_m[i] = c[1], p->z_m[i] = c[2];
    }
    free(L.taken);
    return gf_sim_grains_moved(sim);
}

/* phi_out: solid fraction of the box over the orifice, 0 <= y <= d. */
static double orifice_packing(gf_sim *sim, const silo_geom *g)
{
    gf_measure_domain dom;
    gf_sim_box(sim, dom.lo_m, dom.hi_m, dom.periodic);
    double lo[3] = {g->ox0, 0.0, g->oz0}, hi[3] = {g->ox1, g->d, g->oz1};
    return gf_measure_solid_fraction_box(gf_sim_particles(sim), &dom, lo, hi, g->d / 8.0, 0);
}

static double fill_height(gf_sim *sim, const silo_geom *g)
{
    gf_measure_domain dom;
    gf_sim_box(sim, dom.lo_m, dom.hi_m, dom.periodic);
    enum { MAX_SLABS = 4096 };
    double phi[MAX_SLABS];
    int n = (int)fmin(MAX_SLABS, ceil(g->Lz_box / g->d));
    if (gf_measure_profile_y(gf_sim_ctx(sim), gf_sim_particles(sim), &dom, 0.0, g->d, n, phi, NULL) != GF_OK)
        return NAN;
    /* the reinjected grains falling above the column are too sparse to move the half-plateau */
    return gf_measure_bed_height_m(phi, n, 0.0, g->d, 0.5);
}

static const gf_var_info silo_diag[] = {
    {"discharged_grains", "1", "number of grains that left through the orifice since t = 0", NULL},
    {"discharge_rate", "s-1", "grains leaving per second, since the previous record", NULL},
    {"discharge_mass_rate", "kg s-1", "mass leaving per second, since the previous record", NULL},
    {"orifice_packing_fraction", "1", "solid fraction of the box over the orifice, 0 <= y <= d", NULL},
    {"fill_height", "m", "top of the granular column (half-plateau of the slab solid fraction)", NULL},
};

static gf_status silo_diagnose(gf_sim *sim, double *v)
{
    double *cnt = gf_sim_scene_counters(sim);
    const silo_geom g = geometry(gf_sim_spec(sim));
    double t = gf_sim_time_s(sim), dt = t - cnt[C_REC_T];
    v[0] = cnt[C_OUT];
    v[1] = dt > 0.0 ? (cnt[C_OUT] - cnt[C_REC_OUT]) / dt : NAN;
    v[2] = dt > 0.0 ? (cnt[C_OUT_MASS] - cnt[C_REC_MASS]) / dt : NAN;
    v[3] = orifice_packing(sim, &g);
    v[4] = fill_height(sim, &g);
    cnt[C_REC_OUT] = cnt[C_OUT], cnt[C_REC_MASS] = cnt[C_OUT_MASS], cnt[C_REC_T] = t;
    return GF_OK;
}

static gf_status silo_initial_packing(gf_sim *sim, double *phi_measured, double *phi_local)
{
    const silo_geom g = geometry(gf_sim_spec(sim));
    const gf_particles *p = gf_sim_particles(sim);
    double vol = 0.0, h = fill_height(sim, &g);
    for (size_t i = 0; i < p->n_local; ++i)
        vol += 4.0 / 3.0 * M_PI * pow(p->radius_m[i], 3);
    *phi_measured = vol / (g.Lx * g.Ly * h);
    gf_measure_domain d;
    gf_sim_box(sim, d.lo_m, d.hi_m, d.periodic);
    double lo[3] = {1.5 * g.d, 2.0 * g.d, 1.5 * g.d}, hi[3] = {g.Lx - 1.5 * g.d, h - 2.0 * g.d, g.Ly - 1.5 * g.d};
    *phi_local = hi[1] > lo[1] ? gf_measure_solid_fraction_box(p, &d, lo, hi, g.d / 8.0, 0) : NAN;
    return GF_OK;
}

const gf_scene_desc gf_scene_silo = {
    .name = "silo",
    .caption = "silo discharge through a floor orifice with reinjection (Djouwe Meffeja 2012 ch. 3)",
    .needs = GF_NEED_CONTACTS | GF_NEED_PACKING,
    GF_SCENE_PARAMS(silo_params),
    .default_end_time_nd = 200.0,
    .build = silo_build,
    .start = NULL,
    GF_SCENE_DIAG(silo_diag),
    .diagnose = silo_diagnose,
    .done = NULL,
    .maintain = silo_maintain,
    .check = silo_check,
    .initial_packing = silo_initial_packing,
};
