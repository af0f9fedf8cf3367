/*
 * A coupling tier: the table of operations one way of coupling the fluid to
 * the grains provides, and the registry of tiers (gf_coupling_table.c),
 * chosen by name through spec.fluid.model as contact laws and scenes are.
 *
 * What a tier must provide (docs/architecture.md, "Coupling tiers"):
 *   create/destroy   build the fluid and its coupling for a run spec and a
 *                    box (gf_coupling_setup); the object starts with
 *                    `gf_coupling base` as its first member, base.tier set
 *   dt_max_s         the largest stable fluid step for the current grains
 *   fluid_step       advance the fluid over one fluid step with the grains
 *                    frozen, and hold the fluid force (and torque) on each
 *                    grain for the DEM substeps that follow (Izard 2014 §2.3.1)
 *   add_forces       add the held forces and torques to the grains, every
 *                    DEM substep; forces_in_order/add_forces_range the same
 *                    by ranges of grains on several threads
 *   fields           the grid and its fields for fields.nc (CF names)
 *   excess_pressure_Pa, fluid_flow_rate, fluid_mass_kg   diagnostics and probes
 *   grain_force      the fluid force held on one grain (what add_forces adds)
 *   save/load        checkpoint: a run restarted from it continues bitwise
 *   set_gravity, set_threads                            run-time settings
 *   check            refuse a spec this tier cannot run, naming the limit
 *                    (called by gf_sim_create and by `grainflow check`)
 *   auto_fits        whether `fluid: auto` may choose the tier for a run that
 *                    needs a fluid, and why (one line)
 *   cost             what the fluid will cost a run, from the spec alone
 *                    (`grainflow check`, campaign/gf_cost.h)
 * Optional operations are NULL; the dispatcher (gf_coupling.c) gives the
 * default stated beside each.
 */
#ifndef GF_COUPLING_TIER_H
#define GF_COUPLING_TIER_H

#include "coupling/gf_coupling.h"

typedef struct gf_coupling_tier gf_coupling_tier;

/* The part every tier's object starts with. */
struct gf_coupling {
    const gf_coupling_tier *tier;
};

/* What `fluid: auto` knows of a run when it asks a tier (coupling/gf_tier.h). */
typedef struct gf_tier_query {
    double stokes_St, density_ratio_r;
} gf_tier_query;

/* What a tier is told of a run when it estimates its cost (campaign/gf_cost.h). */
typedef struct gf_tier_cost_query {
    double n_grains;      /* the scene's estimate (gf_scene_desc.grain_count) */
    double box_m[3];      /* the box the fluid fills (gf_scene_desc.fluid_box); NaN when the scene gives none */
    double fluid_time_s;  /* simulated time under the fluid: the scene's prelude and the run */
} gf_tier_cost_query;

/* The tier's answer: NaN where it cannot say. */
typedef struct gf_tier_cost {
    double cpu_s;         /* CPU seconds of the fluid and the coupling on one core, the DEM's excluded */
    double cells;         /* fluid cells (NaN: the tier's grid is not the question) */
    double fluid_steps;   /* fluid steps over fluid_time_s */
    int at_least;         /* the step was sized at rest and shortens as the flow speeds up: cpu_s is a lower bound */
} gf_tier_cost;

struct gf_coupling_tier {
    const char *name;      /* the value of spec.fluid.model */
    const char *summary;   /* one line for `grainflow check` and the docs */
    gf_status (*create)(gf_ctx *ctx, const gf_run_spec *spec, const gf_coupling_setup *setup, gf_coupling **out);
    void (*destroy)(gf_coupling *c);
    gf_status (*check)(gf_ctx *ctx, const gf_run_spec *spec);                 /* NULL: accepts every spec */
    int (*auto_fits)(const gf_tier_query *q, char *why, size_t n_why);        /* NULL: never chosen by auto */
    void (*set_threads)(gf_coupling *c, int n_threads);                       /* NULL: one thread */
    double (*dt_max_s)(const gf_coupling *c, const gf_particles *p);
    gf_status (*fluid_step)(gf_coupling *c, const gf_particles *p, double dt_s);
    gf_status (*add_forces)(gf_coupling *c, gf_particles *p);
    int (*forces_in_order)(const gf_coupling *c, const gf_particles *p);      /* NULL: never (serial add) */
    void (*add_forces_range)(gf_coupling *c, gf_particles *p, size_t i0, size_t i1);
    double (*excess_pressure_Pa)(const gf_coupling *c, const double x_m[3]);  /* NULL: NaN */
    int (*fields)(const gf_coupling *c, int n_cells[3], double lo_m[3], double cell_m[3], const gf_var_info **vars,
                  const double *const **fields);                              /* NULL: no fields.nc */
    gf_status (*set_gravity)(gf_coupling *c, const double gravity_m_s2[3]);
    gf_status (*save)(const gf_coupling *c, gf_restart *r);
    gf_status (*load)(gf_coupling *c, gf_restart *r);
    double (*fluid_flow_rate)(const gf_coupling *c);                          /* NULL: NaN */
    double (*fluid_mass_kg)(const gf_coupling *c);                            /* NULL: NaN */
    int (*grain_force)(const gf_coupling *c, const gf_particles *p, size_t i, double f_N[3]); /* NULL: not kept */
    void (*cost)(const gf_run_spec *spec, const gf_tier_cost_query *q, gf_tier_cost *out); /* NULL: unknown */
};

/* The registry, in the order `fluid: auto` asks (cheapest first). */
const gf_coupling_tier *const *gf_coupling_tier_all(int *n);
/* The tier named name, or NULL. */
const gf_coupling_tier *gf_coupling_tier_find(const char *name);
/* The tier of a coupling object. */
const gf_coupling_tier *gf_coupling_tier_of(const gf_coupling *c);
/* "a, b or c": the registered names, for error messages. */
void gf_coupling_tier_names(char *buf, size_t n);

#endif
