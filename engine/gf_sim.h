/*
 * gf_sim: one simulation — a scene built from a gf_run_spec, advanced by a
 * step loop made only of the stages the scene needs (docs/architecture.md):
 *
 *   dry:      contacts -> integrate -> (diagnostics, output)
 *   immersed: fluid step -> (contacts + lubrication + fluid forces) x substeps -> ...
 *
 * Opaque handle. The builder calls (gf_sim_set_box, gf_sim_add_wall, ...) are
 * for scenes, inside their build() callback; everything else is for drivers
 * (the pipeline, tests, benchmarks).
 */
#ifndef GF_SIM_H
#define GF_SIM_H

#include <stddef.h>

#include "core/gf_groups.h"
#include "core/gf_rng.h"
#include "core/gf_status.h"
#include "core/gf_timer.h"
#include "gf_run_spec.h"
#include "gf_sim_tuning.h"
#include "particles/gf_particles.h"

typedef struct gf_sim gf_sim;

typedef struct gf_sim_options {
    const char *output_dir;     /* NULL: write no files (tests, benchmarks) */
    const char *resolved_yaml;  /* embedded in every netCDF file; may be NULL */
    const char *restart_path;   /* continue from this HDF5 checkpoint; NULL: fresh start */
    int n_threads;              /* OpenMP threads; 0: library default */
    /* Called about once per wall second while running; may be NULL. */
    void (*progress)(void *user, double t_s, double t_end_s, double steps_per_s);
    void *progress_user;
    volatile int *interrupt;    /* non-zero: stop at the next step, checkpoint, return GF_ERR_INTERRUPTED */
    /* Directory where scenes keep the deposits of their packing preparation
     * for the other runs of a campaign (io/gf_packing_cache.h); the deposit
     * read back is the one the run would build. NULL: build every time. */
    const char *preparation_dir;
    /* Performance knobs, for benchmarks and the tests that compare the fast
     * paths with the plain ones (engine/gf_sim_tuning.h); zero: the defaults. */
    gf_sim_tuning tuning;
} gf_sim_options;
/* Default near skin, a fraction of contact.skin_over_D (docs/notes/benchmarks.md, "Near list"). */
#define GF_SIM_NEAR_SKIN_DEFAULT 0.05

/* Work a run leaves out because its spec and scene do not need it (issue #6),
 * decided once at gf_sim_create (engine/sim/gf_skips.c; docs/notes/benchmarks.md):
 *   GF_SKIP_TANGENTIAL   mu_c = 0 on grains and walls: no tangential force or
 *                        history, no torque, no rotation (exact);
 *   GF_SKIP_LUBRICATION  the spec names a viscous fluid and asks for
 *                        lubrication but the run's tier is dry (scene without
 *                        fluid, fluid.model none, or `auto` chose none). */
enum { GF_SKIP_TANGENTIAL = 1u, GF_SKIP_LUBRICATION = 2u };

/* Builds the scene of spec (packing preparation included). Returns owned sim.
 * Errors: unknown scene, invalid/impossible parameters (GF_ERR_CONFIG,
 * GF_ERR_PHYSICS), dt above the contact stability limit (GF_ERR_NUMERIC). */
gf_status gf_sim_create(gf_ctx *ctx, const gf_run_spec *spec, const gf_sim_options *opt, gf_sim **out);
void gf_sim_destroy(gf_sim **sim);

/* Runs to the end time or the scene's end condition, writing the requested
 * outputs (temporary names, renamed when complete). */
gf_status gf_sim_run(gf_sim *sim);
/* Advances n DEM steps (fluid steps interleaved as the scene needs), no output. */
gf_status gf_sim_advance(gf_sim *sim, long n_steps);
/* Sorts the particle store by space now (gf_sim_tuning.sort_every), whatever
 * the schedule and the grain count: for drivers holding a state written by a
 * build without the sort, or in insertion order. Rebuilds the list. */
gf_status gf_sim_sort(gf_sim *sim);
/* Writes a checkpoint (HDF5) that gf_sim_options.restart_path can resume. */
gf_status gf_sim_checkpoint(gf_sim *sim, const char *path);

/* Accessors (borrowed pointers, valid until destroy). */
gf_particles *gf_sim_particles(gf_sim *sim);
const gf_run_spec *gf_sim_spec(const gf_sim *sim);
const gf_scales *gf_sim_scales(const gf_sim *sim);
gf_ctx *gf_sim_ctx(gf_sim *sim);
gf_rng *gf_sim_rng(gf_sim *sim);
const gf_timers *gf_sim_timers(const gf_sim *sim);
/* Neighbour-list counters since creation (benchmarks): list builds, near-list
 * builds (engine/sim/gf_near_list.c), and the pairs of each list now. */
typedef struct gf_sim_list_stats {
    long builds, near_builds;
    size_t pairs, near_pairs;
} gf_sim_list_stats;
gf_sim_list_stats gf_sim_list_counters(const gf_sim *sim);
double gf_sim_time_s(const gf_sim *sim);
double gf_sim_dt_s(const gf_sim *sim);
double gf_sim_end_time_s(const gf_sim *sim);
long gf_sim_step_count(const gf_sim *sim);
void gf_sim_box(const gf_sim *sim, double lo[3], double hi[3], int periodic[3]);
/* Number of grain-grain and grain-wall contacts, and the largest overlap / D. */
void gf_sim_contact_stats(const gf_sim *sim, size_t *n_contacts, double *max_overlap_over_D);
/* GF_SKIP_* bits of the run; text (may be NULL) gets their names, comma-separated, "" when none. */
unsigned gf_sim_skips(const gf_sim *sim, char *text, size_t n);
/* Total force the grains exert on wall w (N), accumulated at the last force evaluation. */
void gf_sim_wall_force(const gf_sim *sim, int wall_id, double f_N[3]);

/* Excess pore pressure (relative to hydrostatic) at x, Pa, as the gauges read
 * it; NAN on a dry run (no fluid tier). */
double gf_sim_excess_pressure_Pa(const gf_sim *sim, const double x_m[3]);

/* Full granular stress tensor sigma_G = sigma^p + sigma^k of the seed
 * (Izard 2014 (2.16)-(2.20)) on n horizontal slabs
 * [y0 + k dy, y0 + (k + 1) dy] spanning the x-z footprint, with the sign
 * flipped so that compression is positive:
 *   S_ij = (1/V_k) sum_c f^c_i b^c_j w_k(c) + (1/V_k) sum_{alpha in k} m u'_i u'_j
 * f^c the contact force on alpha from beta, b^c = x_alpha - x_beta, w_k(c)
 * the fraction of the branch segment inside slab k (so a contact straddling
 * two slabs is shared, and the slab sum of S_yy equals the method-of-planes
 * stress), u' the velocity about the slab's mass-weighted mean (grains by
 * centre). Contact forces are re-evaluated from the contact law at the
 * current state and the stored tangential springs (no increment). Pairs with
 * one glued grain count (the rough base carries the bed); glued-glued pairs
 * do not. S[6 k + c], c = xx, yy, zz, xy, xz, yz. Then P_G = tr(S)/3 and the
 * shear stress in the flow plane is -S_xy (> 0 resisting a flow towards +x). */
gf_status gf_sim_stress_tensor_slabs(gf_sim *sim, double y0_m, double dy_m, int n_slabs, double *S_Pa);
/* The same over the footprint {x_lo, x_hi, z_lo, z_hi} only: each branch
 * segment counts by the fraction of its length inside the footprint and the
 * slab (so contacts with grains outside, e.g. the glued grains of a wall
 * behind the footprint's edge, count up to the edge), the kinetic part by
 * grain centre, V_k = footprint area x dy. */
gf_status gf_sim_stress_tensor_slabs_in(gf_sim *sim, const double footprint_m[4], double y0_m, double dy_m,
                                        int n_slabs, double *S_Pa);

/* Contacts and contact candidates, for measurements, audits and tests that
 * read the contact network without the engine's internals
 * (engine/sim/gf_contact_walk.c). One record per grain pair of the neighbour list
 * (within contact range plus the Verlet skin and the lubrication range;
 * overlap_m <= 0 when apart) and per grain and wall (wall >= 0, j unused).
 * history: the tangential spring (GF_CONTACT_HISTORY doubles, the
 * delta_t vector of Cundall & Strack 1979), current as of the last force
 * evaluation. The callback returns non-zero to stop the walk. */
typedef struct gf_sim_contact {
    size_t i, j;             /* store indices of the grains (j: pairs only) */
    int wall;                /* -1: a grain pair; else the wall id */
    double branch_m[3];      /* x_i - x_j (periodic image), or from the wall's contact point to x_i */
    double normal[3];        /* unit normal from j (or the wall) towards i */
    double overlap_m;        /* R_i + R_j - |branch| (R_i - distance for a wall); > 0 in contact */
    double m_eff_kg;         /* m* = 1/(1/m_i + 1/m_j), 1/m = 0 for glued grains (m_i for a wall) */
    const double *history;   /* tangential history of the contact */
} gf_sim_contact;
typedef int (*gf_sim_contact_fn)(void *user, const gf_sim_contact *c);
gf_status gf_sim_foreach_contact(const gf_sim *sim, gf_sim_contact_fn fn, void *user);

/* Entry points for drivers, tests and benchmarks that look inside a run
 * without the engine's internals (engine/sim/gf_sim_access.c). */
/* The neighbour list, read-only (contact/gf_nlist.h): its rows, pairs, the
 * chunks of the threads and their reach runs. Valid until the next step or
 * rebuild. */
struct gf_nlist;
const struct gf_nlist *gf_sim_neighbour_list(const gf_sim *sim);
/* Rebuilds the neighbour list now, the contact history carried over (the
 * step rebuilds it by itself when a grain has moved half the skin). */
gf_status gf_sim_rebuild_neighbours(gf_sim *sim);
/* Makes the next step rebuild the list whatever the displacements. */
void gf_sim_rebuild_at_next_step(gf_sim *sim);
/* Forgets the tangential history of every grain pair (a control for tests
 * of the history's transfer across rebuilds). */
void gf_sim_forget_pair_history(gf_sim *sim);
/* Evaluates the contact, lubrication and wall forces of the current state
 * into the store now (the dashpot sees v(t)), as at creation. */
gf_status gf_sim_evaluate_forces(gf_sim *sim);
/* The contact law's parameters the run derived (contact/gf_contact.h). */
struct gf_contact_params;
const struct gf_contact_params *gf_sim_contact_params(const gf_sim *sim);
/* The fluid coupling of an immersed run (coupling/gf_coupling.h), NULL when dry. */
struct gf_coupling;
struct gf_coupling *gf_sim_coupling(gf_sim *sim);
/* DEM steps per fluid step, as last chosen (0 when dry). */
int gf_sim_fluid_substeps(const gf_sim *sim);
/* Gravity of the run, m s-2 (the scene may tilt it). */
void gf_sim_gravity(const gf_sim *sim, double g_m_s2[3]);
/* 1 when the run is immersed (a fluid tier was chosen, even before the
 * coupling starts after the scene's preparation). */
int gf_sim_immersed(const gf_sim *sim);
/* Position of the gauge called name (gf_sim_add_gauge); 0 when there is none. */
int gf_sim_gauge_position(const gf_sim *sim, const char *name, double x_m[3]);

/* Mechanical energy of the mobile grains (engine/audit/gf_energy_audit.c):
 * kinetic, rotational, buoyant-weight potential, and the elastic energy
 * stored in the normal and tangential springs, from the contact law's own
 * energy hooks (gf_contact_info.normal_energy, tangential_energy). Without a
 * driving force it can only fall; audits compare it along a run. */
typedef struct gf_sim_energy {
    double kinetic_J, rotational_J, gravity_J, elastic_normal_J, elastic_tangential_J, total_J;
} gf_sim_energy;
gf_status gf_sim_energy_audit(const gf_sim *sim, gf_sim_energy *e);

/* A scene moved grains (teleported, e.g. a silo's reinjection, Djouwe
 * Meffeja 2012 §3.3) between steps: the next step rebuilds the neighbour list
 * and the forces first. */
gf_status gf_sim_grains_moved(gf_sim *sim);
/* A scene's own running totals (e.g. grains discharged), GF_SIM_SCENE_COUNTERS
 * values, zero at creation, written to and read from checkpoints. Borrowed. */
#define GF_SIM_SCENE_COUNTERS 8
double *gf_sim_scene_counters(gf_sim *sim);

/* --- builder calls, for scenes --- */
/* Domain box; periodic axes wrap, others must be closed by walls. */
gf_status gf_sim_set_box(gf_sim *sim, const double lo_m[3], const double hi_m[3], const int periodic[3]);
gf_status gf_sim_set_gravity(gf_sim *sim, const double g_m_s2[3]);
/* Plane wall through point with unit normal pointing into the grains
 * (an infinite-radius, infinite-mass particle: Izard 2014 §2.1.2.1).
 * Returns its id in *wall_id (may be NULL). */
gf_status gf_sim_add_wall(gf_sim *sim, const double point_m[3], const double normal[3], double friction,
                          int *wall_id);
/* Activates/deactivates a wall: a gate is a wall a scene removes at t = 0. */
gf_status gf_sim_set_wall_active(gf_sim *sim, int wall_id, int active);
/* Opens a rectangular hole in plane wall wall_id (a silo's orifice): the
 * rectangle [lo, hi] on the two axes other than the wall normal's, which must
 * be a box axis. Grains over the hole touch only its rim (engine/sim/gf_sim_internal.h:
 * gf_wall_distance). */
gf_status gf_sim_set_wall_hole(gf_sim *sim, int wall_id, const double lo_m[3], const double hi_m[3]);
gf_status gf_sim_set_end_time(gf_sim *sim, double t_end_s);
/* Basal pore-pressure gauge (probes.nc station). */
gf_status gf_sim_add_gauge(gf_sim *sim, const char *name, const double x_m[3]);
/* Fluid boundary condition of a box face (axis 0..2, side 0 = low, 1 = high);
 * the default is no-slip on non-periodic faces. Ignored by dry runs. */
gf_status gf_sim_set_fluid_bc(gf_sim *sim, int axis, int side, int bc /* gf_fluid_bc */);
/* Blocks (1) or frees (0) the rotation of every grain (infinite rolling
 * resistance), for a preparation phase inside build that must keep a packing
 * made with rotations blocked (gf_packing.h); locking also zeroes the spins.
 * A scene frees the rotations again before build returns. */
gf_status gf_sim_set_rotation_locked(gf_sim *sim, int locked);
/* The run's gf_sim_options.preparation_dir (NULL when none), for scenes
 * that prepare a packing (gf_packing_build_cached). */
const char *gf_sim_preparation_dir(const gf_sim *sim);
/* Resets the clock to 0 (after a preparation phase run inside build). */
void gf_sim_reset_clock(gf_sim *sim);
/* Particle and fluid state consistency check: positions inside the box,
 * overlaps below 5 % of D, finite values. */
gf_status gf_sim_check_state(gf_sim *sim);

#endif
