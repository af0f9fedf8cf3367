/*
 * Settled bed, the DEM benchmark: N grains poured onto a flat frictional
 * floor (plane y = 0) in a box periodic along x and z, settled under gravity
 * with the run's own contacts, then timed at rest. A dense, static pack with
 * ~6 contacts per grain and tangential history on every contact is the
 * workload of the seeds' quasi-static phases (Izard 2014 §2.1.2.2 cost
 * figures) and the standard LAMMPS granular benchmark (bench/in.chute style).
 * Pouring: a stack that is already nearly at rest, so that settling takes
 * a few sqrt(D/g) even at 1e5 grains: a jittered body-centred stack
 * (each grain above the pocket of four below, ~8 neighbours in contact
 * range) built layer by layer, each grain placed at rest on the highest of
 * its supports (no overlap, no fall); settle_time_nd of settling under
 * gravity (the grains roll into their pockets), kinetic-energy quenches in
 * the last quarter, then the clock is reset to 0. The pack is ordered (not a random pour): the benchmark
 * measures cost per contact and per neighbour, which the coordination and
 * the neighbour count set, not the disorder.
 * width_over_D = 0 picks a square footprint for a bed ~ 20 D deep.
 * Immersed (fluid.model unresolved): the bed is settled dry inside build (the
 * coupling starts at t = 0, fluid at rest and hydrostatic), the top of the
 * box is a free-slip lid, and a basal gauge "base_centre" sits on the floor
 * at the centre of the footprint: a bed at rest must read zero excess pore
 * pressure there (tests/stress/test_stress_static_bed.c, immersed mode).
 */
#include <math.h>

#include "coupling/gf_coupling.h" /* gf_fluid_bc */
#include "scenes/gf_scene.h"
#include "scenes/gf_scene_box.h"

static const gf_param_info bed_params[] = {
    {"n_grains", "1", 1e4, 1.0, 1e7, "number of grains"},
    {"width_over_D", "1", 0.0, 0.0, 1e4, "x and z extent / D (0: auto, bed ~20 D deep)"},
    {"settle_time_nd", "1", 4.0, 0.0, 1e4, "settling time before t = 0, sqrt(D/g)"},
    {"glue_base", "1", 0.0, 0.0, 1.0, "1: after settling, glue the grains touching the floor (a rough base)"},
};

static gf_status bed_build(gf_sim *sim, const gf_run_spec *spec)
{
    gf_ctx *ctx = gf_sim_ctx(sim);
    gf_particles *p = gf_sim_particles(sim);
    gf_rng *rng = gf_sim_rng(sim);
    double D = spec->grains.diameter_m, rho = spec->grains.density_kg_m3, pd = spec->grains.polydispersity;
    double g = spec->gravity_m_s2;
    long n = (long)gf_run_spec_param(spec, "n_grains", 1e4);
    double W = gf_run_spec_param(spec, "width_over_D", 0.0);
    double d_max = D * (1.0 + pd);
    /* body-centred stack: square layers of spacing ax >= 1.16 D_max, odd
     * layers shifted by ax/2 so that each grain sits in the pocket of four
     * below, layer spacing sqrt(D_max^2 - ax^2/2) (just touching diagonally) */
    int m = W > 0.0 ? (int)floor(W * D / (1.16 * d_max)) : (int)lround(sqrt((double)n / 35.0));
    if (m < 4)
        m = 4;
    double L = W > 0.0 ? W * D : m * 1.16 * d_max, ax = L / m;
    if (ax > 1.4 * d_max)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "settled_bed: %ld grains are too few for a %g D wide bed", n, L / D);
    double dy = sqrt(d_max * d_max - 0.5 * ax * ax) + 0.01 * D;
    double layers = ceil((double)n / ((double)m * m));
    /* open top: room above the stack */
    const double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {L, 2.0 * layers * dy + 10.0 * d_max, L};
    GF_TRY(gf_scene_box_under_gravity(sim, lo, hi, (const int[3]){1, 0, 1}, g));
    const gf_scene_plane floor_plane = {{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, spec->contact.wall_friction};
    GF_TRY(gf_scene_add_planes(sim, 1, &floor_plane));
    double jitter = 0.02 * D;
    (void)dy;
    size_t per_layer = (size_t)m * (size_t)m;
    for (long k = 0; k < n; ++k) {
        size_t i;
        long layer = k / ((long)m * m);
        double shift = (layer % 2) * 0.5 * ax;
        double r = 0.5 * D * (1.0 + pd * gf_rng_range(rng, -1.0, 1.0));
        double x = (k % m + 0.25) * ax + shift + jitter * gf_rng_range(rng, -1.0, 1.0);
        double z = (k / m % m + 0.25) * ax + shift + jitter * gf_rng_range(rng, -1.0, 1.0);
        /* lowest height at which the grain touches nothing below: on the
         * floor, or resting on the highest grain of the two layers below
         * (the one right under it belongs to layer - 2; minimum image along x
         * and z), so the stack starts without overlap and without a fall */
        double y = r;
        if (layer > 0)
            for (size_t q = (size_t)(layer > 1 ? layer - 2 : 0) * per_layer; q < (size_t)layer * per_layer; ++q) {
                double dx = x - p->x_m[q], dz = z - p->z_m[q], rs = r + p->radius_m[q];
                dx -= L * round(dx / L), dz -= L * round(dz / L);
                double h2 = rs * rs - dx * dx - dz * dz;
                if (h2 > 0.0 && p->y_m[q] + sqrt(h2) > y)
                    y = p->y_m[q] + sqrt(h2);
            }
        GF_TRY(gf_particles_add(ctx, p, x, y, z, r, rho, 0, &i));
    }
    /* settle: free compaction for 3/4 of the time, then kinetic-energy quenches
     * (all velocities and spins zeroed every 0.25 sqrt(D/g)), a standard
     * static relaxation that brings the pack to rest in a few sqrt(D/g) */
    double t_settle = gf_run_spec_param(spec, "settle_time_nd", 4.0) * sqrt(D / g);
    long chunk = (long)ceil(0.25 * sqrt(D / g) / gf_run_spec_dt_s(spec));
    long n_chunks = (long)ceil(t_settle / (chunk * gf_run_spec_dt_s(spec)));
    for (long c = 0; c < n_chunks; ++c) {
        GF_TRY(gf_sim_advance(sim, chunk));
        if (4 * c >= 3 * n_chunks)
            for (size_t i = 0; i < p->n_local; ++i)
                p->vx_m_s[i] = p->vy_m_s[i] = p->vz_m_s[i] = p->wx_rad_s[i] = p->wy_rad_s[i] = p->wz_rad_s[i] = 0.0;
    }
    if (gf_run_spec_param(spec, "glue_base", 0.0) > 0.5) /* spheres roll on a flat floor: roughen it */
        for (size_t i = 0; i < p->n_local; ++i)
            if (p->y_m[i] < p->radius_m[i] + 0.01 * D) {
                p->flags[i] |= GF_P_GLUED;
                p->vx_m_s[i] = p->vy_m_s[i] = p->vz_m_s[i] = p->wx_rad_s[i] = p->wy_rad_s[i] = p->wz_rad_s[i] = 0.0;
            }
    gf_sim_reset_clock(sim);
    GF_TRY(gf_sim_set_fluid_bc(sim, 1, 1, GF_BC_FREE_SLIP)); /* ignored when dry */
    double gauge[3] = {0.5 * L, 0.0, 0.5 * L};
    return gf_sim_add_gauge(sim, "base_centre", gauge);
}

static int bed_done(gf_sim *sim) { return 0; }

const gf_scene_desc gf_scene_settled_bed = {
    .name = "settled_bed",
    .caption = "dense bed at rest on a floor, periodic x and z: the DEM benchmark",
    .needs = GF_NEED_CONTACTS | GF_NEED_FLUID | GF_NEED_PROBES,
    GF_SCENE_PARAMS(bed_params),
    .default_end_time_nd = 1.0,
    .build = bed_build,
    .done = bed_done,
};
