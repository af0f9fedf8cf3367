/*
 * The configuration schema: which YAML key sets which gf_run_spec field, its
 * unit, range and allowed names. One table serves the reader (YAML tree ->
 * spec, with located errors), `grainflow check` (every resolved value with
 * its unit) and the canonical text of a spec (run.yaml, run ids), so the
 * three cannot disagree. Defaults are not here: they come from
 * gf_run_spec_defaults() (engine/gf_run_spec.c), the one place they live,
 * and scene parameters come from the scene's own table (gf_scene_desc.params).
 *
 * Layout of a configuration (docs/campaigns.md has the full reference):
 *
 *   name: demo              # campaign name (default: file name without .yaml)
 *   seed: 1
 *   end_time: 40            # sqrt(D/g); 0: the scene's default
 *   gravity: 9.81           # m s-2
 *   scene: {name: column_collapse, column_length_over_D: 16, aspect_ratio: 1}
 *   grains: {diameter_m: 7.6e-3, polydispersity: 0.05, density_kg_m3: 2500}
 *   contact: {...}  fluid: {...}  output: {...}
 *   groups: {St: 0.6, r: 3.65}   # asked groups for a single run (mapped, see gf_groups_map.h)
 *   grid: {a: [0.5, 1], Phi_i: {from: 0.58, to: 0.6, num: 2}, combine: product}
 *   variants: [{label: dry}, {label: immersed, fluid.model: unresolved}]
 *
 * `domain:` is accepted as a second home for scene parameters (box sizes).
 */
#ifndef GF_SPEC_SCHEMA_H
#define GF_SPEC_SCHEMA_H

#include <stddef.h>

#include "config/gf_cfg.h"
#include "gf_run_spec.h"

typedef enum gf_field_type { GF_FIELD_DOUBLE, GF_FIELD_BOOL, GF_FIELD_U64, GF_FIELD_NAME } gf_field_type;

typedef struct gf_spec_field {
    const char *section;          /* "" for top level, else grains/contact/fluid/output */
    const char *key;
    gf_field_type type;
    size_t offset;                /* into gf_run_spec */
    size_t size;                  /* for names: buffer size */
    double min, max;              /* numbers: range; min_open: min excluded */
    int min_open;
    const char *unit;             /* udunits, "1" dimensionless, "" for names/flags */
    const char *const *choices;   /* names: NULL-terminated allowed values, or NULL */
    const char *doc;
    /* names kept by a registry (contact laws): its list, read at each use, in
     * place of choices; NULL otherwise. */
    const char *const *(*registry_choices)(void);
} gf_spec_field;

/* The table, *n set to its length. */
const gf_spec_field *gf_spec_fields(int *n);
const gf_spec_field *gf_spec_field_find(const char *section, const char *key);
/* Canonical text of the field's value in spec (%.17g for numbers: exact round trip). */
void gf_spec_field_format(const gf_spec_field *f, const gf_run_spec *spec, char *buf, size_t n);

/* Names of the asked groups, in grid order: St, r, a, Phi_i. */
extern const char *const gf_group_names[4];
/* The index of the group named name in gf_group_names, -1 if none. */
int gf_group_index(const char *name);
/* Pointer to the asked group i (0..3) of spec. */
double *gf_spec_group(gf_run_spec *spec, int i);
/* Range check of an asked group value; message without location. */
int gf_group_value_ok(int i, double v, const char **why);

/* Reads a configuration tree (a mapping) into *spec, starting from the
 * defaults. Checks every key (did-you-mean), type and range; scene
 * parameters are checked against the scene's table and completed with its
 * defaults. Skips name, description, grid and variants (campaign level).
 * Errors: GF_ERR_CONFIG with "file:line:column: message". */
gf_status gf_spec_read(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *root, gf_run_spec *spec);

#endif
