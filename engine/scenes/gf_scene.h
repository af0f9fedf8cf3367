/*
 * A scene reads like a figure caption: a name, the stages it needs, a table
 * of parameters (key, unit, default, range) and a few short callbacks.
 * Scenes never read YAML; they receive a resolved gf_run_spec. A new scene is
 * one file gf_scene_<name>.c and one row in gf_scene_table.c.
 */
#ifndef GF_SCENE_H
#define GF_SCENE_H

#include "gf_run_spec.h"
#include "gf_sim.h"
#include "io/gf_nc.h"

enum {
    GF_NEED_CONTACTS = 1u << 0,
    GF_NEED_FLUID = 1u << 1,     /* honours spec.fluid.model; without it the scene is always dry */
    GF_NEED_PROBES = 1u << 2,
    GF_NEED_PACKING = 1u << 3,   /* builds a packing at phi_initial */
};

#define GF_SCENE_MAINTAIN_EVERY 100

typedef struct gf_param_info {
    const char *key;
    const char *unit;            /* udunits string, "1" for dimensionless */
    double def, min, max;        /* default and inclusive range */
    const char *doc;
} gf_param_info;

/* A descriptor's parameter and diagnostic tables with their lengths, e.g.
 * { .name = "x", GF_SCENE_PARAMS(x_params), GF_SCENE_DIAG(x_diag), ... }. */
#define GF_SCENE_PARAMS(table) .params = (table), .n_params = (int)(sizeof(table) / sizeof((table)[0]))
#define GF_SCENE_DIAG(table) .diag = (table), .n_diag = (int)(sizeof(table) / sizeof((table)[0]))

typedef struct gf_scene_desc {
    const char *name;
    const char *caption;         /* one line: what and after whom */
    int internal;                /* 1: built only by the library (a preparation's container); a campaign cannot name it */
    unsigned needs;
    const gf_param_info *params;
    int n_params;
    double default_end_time_nd;  /* sqrt(D/g) units, used when spec.end_time_nd == 0 */
    /* Box, walls, grains (packing included), gauges. Required. */
    gf_status (*build)(gf_sim *sim, const gf_run_spec *spec);
    /* At t = 0 after build: open the gate, tilt gravity. May be NULL. */
    gf_status (*start)(gf_sim *sim);
    /* After start, once the fluid is set up, before t = 0 (not on a restart): e.g. a
     * column settling through the fluid behind its gate; resets the clock when it
     * advances. May be NULL. */
    gf_status (*prelude)(gf_sim *sim);
    /* Scene-specific scalar diagnostics (diagnostics.nc), n_diag values. */
    int n_diag;
    const gf_var_info *diag;
    gf_status (*diagnose)(gf_sim *sim, double *values);
    /* Non-zero when the scene's end condition holds (e.g. at rest). May be NULL. */
    int (*done)(gf_sim *sim);
    /* Scene upkeep between steps, every GF_SCENE_MAINTAIN_EVERY steps of the
     * clock in gf_sim_run (e.g. a silo's reinjection of the grains that left;
     * a scene that moves grains calls gf_sim_grains_moved). May be NULL. */
    gf_status (*maintain)(gf_sim *sim);
    /* Consistency of the parameters together (each one's range is the table's):
     * NULL when consistent, else the key at fault, with one line in why. May be NULL. */
    const char *(*check)(const gf_run_spec *spec, char *why, size_t n);
    /* Achieved initial packing, for the phi_initial_measured / phi_initial_local
     * attributes (gf_nc_meta): call once right after gf_sim_create, before any
     * step (it measures the current state). NaN when not applicable. May be NULL. */
    gf_status (*initial_packing)(gf_sim *sim, double *phi_measured, double *phi_local);
    /* Column geometry R0 (length) and H0 (height) in m from the resolved spec,
     * for the collapse scales (T_visq, T0, t0) and the column_length_m /
     * column_height_m attributes; scenes derive them from their own
     * parameters. May be NULL (not a column). */
    void (*column_geometry)(const gf_run_spec *spec, double *length_m, double *height_m);
    /* Grains the scene will hold, glued ones included, from the resolved spec
     * without building anything (the packing fraction asked times the volume
     * it fills): the cost that `grainflow check` prints. May be NULL. */
    double (*grain_count)(const gf_run_spec *spec);
    /* The box the fluid fills (the run's box), from the resolved spec without
     * building anything, and the simulated time the prelude runs under the
     * fluid before t = 0 (given the run's time scales): what a grid tier's cost
     * grows with. May be NULL (the fluid's cost is then unknown to a grid tier;
     * no prelude). */
    void (*fluid_box)(const gf_run_spec *spec, double size_m[3]);
    double (*prelude_time_s)(const gf_run_spec *spec, const gf_scales *scales);
} gf_scene_desc;

/* NULL when unknown. */
const gf_scene_desc *gf_scene_find(const char *name);
/* All scenes, *n set to their count. */
const gf_scene_desc *const *gf_scene_all(int *n);
/* Fills absent scene parameters with defaults and checks every value is in
 * range and every key is known. Errors name the key and the range. */
gf_status gf_scene_resolve_params(gf_ctx *ctx, gf_run_spec *spec);
/* The same; on a consistency error (the scene's check) *bad_key names the key
 * at fault, for a located message; NULL otherwise. */
gf_status gf_scene_resolve_params_at(gf_ctx *ctx, gf_run_spec *spec, const char **bad_key);

#endif
