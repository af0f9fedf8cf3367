/*
 * The scene registry: one row per scene (docs/architecture.md). A new scene is one
 * file gf_scene_<name>.c defining `const gf_scene_desc gf_scene_<name>` and
 * TWO lines here: its extern declaration and its row, kept in the same order.
 */
#include "scenes/gf_scene.h"

/* --- declarations (one per scene) --- */
extern const gf_scene_desc gf_scene_avalanche;
extern const gf_scene_desc gf_scene_binary_collision;
extern const gf_scene_desc gf_scene_bounce;
extern const gf_scene_desc gf_scene_column_collapse;
extern const gf_scene_desc gf_scene_elastic_gas;
extern const gf_scene_desc gf_scene_friction_clamp;
extern const gf_scene_desc gf_scene_janssen;
extern const gf_scene_desc gf_scene_packing_preparation;
extern const gf_scene_desc gf_scene_settled_bed;
extern const gf_scene_desc gf_scene_settling;
extern const gf_scene_desc gf_scene_silo;

/* --- rows (one per scene) --- */
static const gf_scene_desc *const gf_scene_table[] = {
    &gf_scene_avalanche,
    &gf_scene_binary_collision,
    &gf_scene_bounce,
    &gf_scene_column_collapse,
    &gf_scene_elastic_gas,
    &gf_scene_friction_clamp,
    &gf_scene_janssen,
    &gf_scene_packing_preparation,
    &gf_scene_settled_bed,
    &gf_scene_settling,
    &gf_scene_silo,
};

const gf_scene_desc *const *gf_scene_all(int *n)
{
    *n = (int)(sizeof gf_scene_table / sizeof gf_scene_table[0]);
    return gf_scene_table;
}
