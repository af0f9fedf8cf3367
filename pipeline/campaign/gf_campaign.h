/*
 * A campaign: one configuration file expanded into fully resolved runs.
 *
 *   runs = variants x grid points        (variant slowest, Phi_i fastest)
 *
 * For each run the configuration tree is copied, the variant's entries
 * (dotted key paths: fluid.model, scene.aspect_ratio, groups.St, ...) and the
 * command line's --set entries are laid over it, the tree is read against the
 * schema (gf_spec_schema.h), the grid point's groups are set, the groups are
 * mapped to physical values (gf_groups_map.h), the scene parameters are
 * completed from the scene's table (gf_scene_resolve_params), and the run id
 * is the hash of the canonical text (gf_spec_text.h). Any error stops the
 * expansion with one located line: nothing is started from a campaign that
 * contains an impossible run.
 */
#ifndef GF_CAMPAIGN_H
#define GF_CAMPAIGN_H

#include "campaign/gf_grid.h"
#include "config/gf_cfg.h"
#include "core/gf_groups.h"
#include "gf_run_spec.h"

typedef struct gf_campaign_run {
    gf_run_spec spec;              /* resolved; spec.run_id set */
    gf_scales scales;              /* realised groups and time scales */
    char label[GF_NAME_LEN];       /* variant label ("" without variants) */
    int index;                     /* position in the campaign, 0-based */
} gf_campaign_run;

typedef struct gf_campaign {
    char name[GF_NAME_LEN];        /* name: key, else the file name without .yaml */
    char *source_path;             /* the configuration file ("<demo>" when embedded) */
    int n_runs, n_points, n_variants;
    gf_campaign_run *runs;
} gf_campaign;

/* Loads and expands a configuration. sets: n_sets strings "key.path=value"
 * laid over every run (command line --set). Returns owned *out.
 * Errors: GF_ERR_CONFIG / GF_ERR_PHYSICS with one located line. */
gf_status gf_campaign_load_file(gf_ctx *ctx, const char *path, const char *const *sets, int n_sets,
                                gf_campaign **out);
gf_status gf_campaign_load_string(gf_ctx *ctx, const char *name, const char *text, size_t len,
                                  const char *const *sets, int n_sets, gf_campaign **out);
void gf_campaign_destroy(gf_campaign **c);

/* Index of the run with this id, or -1. */
int gf_campaign_find(const gf_campaign *c, const char *run_id);

#endif
