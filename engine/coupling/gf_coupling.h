/*
 * Fluid–grain coupling, the interface the step loop sees. One object per
 * run holds the fluid solver (engine/fluid) and the coupling tier named by
 * spec.fluid.model, a row of the tier registry (gf_coupling_tier.h,
 * gf_coupling_table.c): "unresolved" (locally averaged Navier–Stokes, drag
 * closure, pressure-gradient force; Anderson & Jackson 1967) and "resolved"
 * (Navier–Stokes inside the grains too, immersed-boundary direct forcing at
 * D/dx = 8-20; Uhlmann 2005, Izard 2014 §2.2), behind the same calls.
 *
 * Sub-cycling (Izard 2014 §2.3.1): the fluid advances once per dt_fluid with
 * the grains frozen, then the DEM runs M substeps with the fluid force on each
 * grain held (or relaxed implicitly for the drag part) while contacts and
 * lubrication are recomputed every substep.
 */
#ifndef GF_COUPLING_H
#define GF_COUPLING_H

#include "core/gf_status.h"
#include "gf_run_spec.h"
#include "io/gf_nc.h"
#include "io/gf_restart.h"
#include "particles/gf_particles.h"

typedef struct gf_coupling gf_coupling;

/* Fluid boundary condition of each box face: [axis][0 = low, 1 = high]. */
typedef enum gf_fluid_bc { GF_BC_PERIODIC = 0, GF_BC_NO_SLIP, GF_BC_FREE_SLIP } gf_fluid_bc;

typedef struct gf_coupling_setup {
    double lo_m[3], hi_m[3];
    gf_fluid_bc bc[3][2];
    double gravity_m_s2[3];          /* body force on the fluid (hydrostatic reference built from it) */
} gf_coupling_setup;

/* Refuses, with one line naming the value and the limit, a spec the tier it
 * names cannot run (GF_ERR_CONFIG / GF_ERR_UNSUPPORTED); gf_coupling_create
 * calls it too. For `grainflow check` before any run. */
gf_status gf_coupling_check(gf_ctx *ctx, const gf_run_spec *spec);
/* Returns owned coupling. Errors: model unknown, grid too small, unstable parameters. */
gf_status gf_coupling_create(gf_ctx *ctx, const gf_run_spec *spec, const gf_coupling_setup *setup,
                             gf_coupling **out);
void gf_coupling_destroy(gf_coupling **c);
/* The tier's name ("unresolved", "resolved"; "none" for NULL): the fluid_model attribute. */
const char *gf_coupling_model(const gf_coupling *c);
/* OpenMP threads for the fluid step's per-grain loops (default 1). The
 * results do not depend on it: each grain's values are computed alone, and
 * what is summed over grains (the drag spread to the cells) stays in grain
 * order on one thread. */
void gf_coupling_set_threads(gf_coupling *c, int n_threads);

/* Largest stable fluid step for the current state (CFL, viscous, drag relaxation), s. */
double gf_coupling_dt_max_s(const gf_coupling *c, const gf_particles *p);
/* Advances the fluid by dt_s with the grains as they are; computes and holds the
 * fluid force on each grain. GF_ERR_NUMERIC on a non-finite fluid state. */
gf_status gf_coupling_fluid_step(gf_coupling *c, const gf_particles *p, double dt_s);
/* Adds the held fluid force (drag, pressure gradient/buoyancy) on each grain to p->f. */
gf_status gf_coupling_add_forces(gf_coupling *c, gf_particles *p);
/* 1 when the held forces follow the store's order (no grain added, removed
 * or reordered since the fluid step or the last gf_coupling_add_forces):
 * then gf_coupling_add_forces_range may add them by ranges, on several
 * threads at once (each grain's force alone: the same bits). */
int gf_coupling_forces_in_order(const gf_coupling *c, const gf_particles *p);
/* gf_coupling_add_forces for grains [i0, i1); needs gf_coupling_forces_in_order. */
void gf_coupling_add_forces_range(gf_coupling *c, gf_particles *p, size_t i0, size_t i1);
/* Excess pore pressure (relative to hydrostatic) at x, Pa. */
double gf_coupling_excess_pressure_Pa(const gf_coupling *c, const double x_m[3]);
/* Grid and cell-centred fields for fields.nc (borrowed arrays, x fastest). */
int gf_coupling_fields(const gf_coupling *c, int n_cells[3], double lo_m[3], double cell_m[3],
                       const gf_var_info **vars, const double *const **fields);
/* New gravity after create (a scene's start() tilting it, e.g. the avalanche):
 * the hydrostatic reference, the buoyancy and the drag update follow it.
 * The step loop calls it whenever gf_sim_set_gravity changes gravity on a run
 * that already has a coupling. Errors: non-finite g. */
gf_status gf_coupling_set_gravity(gf_coupling *c, const double gravity_m_s2[3]);
/* Checkpoint of the fluid and of what the last fluid step left on the grains
 * (face velocities, excess pressure, fluid fraction, held drag coefficients,
 * fluid velocities and forces, output fields, counters), written beside the
 * DEM state of gf_sim_checkpoint: a run restarted from it continues bitwise.
 * gf_coupling_checkpoint.c. Load errors: a checkpoint of a dry run or of
 * another grid (GF_ERR_CONFIG), a damaged file (GF_ERR_IO). */
gf_status gf_coupling_save(const gf_coupling *c, gf_restart *r);
gf_status gf_coupling_load(gf_coupling *c, gf_restart *r);
/* Fluid volume flux through the domain along x per unit length (Q_f, m^3/s), and fluid mass, kg. */
double gf_coupling_fluid_flow_rate(const gf_coupling *c);
double gf_coupling_fluid_mass_kg(const gf_coupling *c);
/* The fluid force held on grain i, the one gf_coupling_add_forces adds to it (buoyancy
 * included: the fluid carries the excess pressure); 1, or 0 and NaNs where the tier
 * does not keep per-grain forces. */
int gf_coupling_grain_force(const gf_coupling *c, const gf_particles *p, size_t i, double f_N[3]);

#endif
