/*
 * Packing preparation: the container a packing is deposited in
 * (particles/gf_packing.h), as a scene of the engine, so that the
 * preparation's grains settle under the same DEM as every run
 * (scenes/gf_packing_settle.c drives it). The box is given whole, periodic
 * or not along x and z; a floor (plane y = floor_y_m) and, where asked,
 * plane walls at the given x and z close it. The walls take
 * contact.wall_friction (the preparation sets 0: frictionless walls hold no
 * arches). The scene adds no grains: the preparation adds the grains it
 * settles and the glued obstacles (rough base, rough walls) after
 * gf_sim_create, so a run of this scene on its own holds an empty container.
 */
#include <math.h>
#include <stdio.h>

#include "scenes/gf_scene.h"
#include "scenes/gf_scene_box.h"

#define PREP_EXTENT 1e6 /* bound of the coordinates (m): any container */

static const gf_param_info prep_params[] = {
    {"box_lo_x_m", "m", 0.0, -PREP_EXTENT, PREP_EXTENT, "box, low corner x"},
    {"box_lo_y_m", "m", 0.0, -PREP_EXTENT, PREP_EXTENT, "box, low corner y"},
    {"box_lo_z_m", "m", 0.0, -PREP_EXTENT, PREP_EXTENT, "box, low corner z"},
    {"box_hi_x_m", "m", 1.0, -PREP_EXTENT, PREP_EXTENT, "box, high corner x"},
    {"box_hi_y_m", "m", 1.0, -PREP_EXTENT, PREP_EXTENT, "box, high corner y"},
    {"box_hi_z_m", "m", 1.0, -PREP_EXTENT, PREP_EXTENT, "box, high corner z"},
    {"periodic_x", "1", 0.0, 0.0, 1.0, "1: x periodic"},
    {"periodic_z", "1", 0.0, 0.0, 1.0, "1: z periodic"},
    {"floor_y_m", "m", 0.0, -PREP_EXTENT, PREP_EXTENT, "height of the floor plane"},
    {"walls_x", "1", 0.0, 0.0, 1.0, "1: plane walls at wall_x_lo_m and wall_x_hi_m (x not periodic)"},
    {"wall_x_lo_m", "m", 0.0, -PREP_EXTENT, PREP_EXTENT, "x of the low x wall"},
    {"wall_x_hi_m", "m", 1.0, -PREP_EXTENT, PREP_EXTENT, "x of the high x wall"},
    {"walls_z", "1", 0.0, 0.0, 1.0, "1: plane walls at wall_z_lo_m and wall_z_hi_m (z not periodic)"},
    {"wall_z_lo_m", "m", 0.0, -PREP_EXTENT, PREP_EXTENT, "z of the low z wall"},
    {"wall_z_hi_m", "m", 1.0, -PREP_EXTENT, PREP_EXTENT, "z of the high z wall"},
};

static double param(const gf_run_spec *spec, const char *key) { return gf_run_spec_param(spec, key, NAN); }

static gf_status add_wall_pair(gf_sim *sim, const gf_run_spec *spec, int axis, const char *lo_key,
                               const char *hi_key)
{
    double pt[3] = {0, 0, 0}, n[3] = {0, 0, 0};
    pt[axis] = param(spec, lo_key), n[axis] = 1.0;
    GF_TRY(gf_sim_add_wall(sim, pt, n, spec->contact.wall_friction, NULL));
    pt[axis] = param(spec, hi_key), n[axis] = -1.0;
    return gf_sim_add_wall(sim, pt, n, spec->contact.wall_friction, NULL);
}

static gf_status prep_build(gf_sim *sim, const gf_run_spec *spec)
{
    const double lo[3] = {param(spec, "box_lo_x_m"), param(spec, "box_lo_y_m"), param(spec, "box_lo_z_m")};
    const double hi[3] = {param(spec, "box_hi_x_m"), param(spec, "box_hi_y_m"), param(spec, "box_hi_z_m")};
    const int periodic[3] = {param(spec, "periodic_x") > 0.5, 0, param(spec, "periodic_z") > 0.5};
    GF_TRY(gf_scene_box_under_gravity(sim, lo, hi, periodic, spec->gravity_m_s2));
    const double floor_pt[3] = {0.0, param(spec, "floor_y_m"), 0.0}, up[3] = {0.0, 1.0, 0.0};
    GF_TRY(gf_sim_add_wall(sim, floor_pt, up, spec->contact.wall_friction, NULL));
    if (param(spec, "walls_x") > 0.5 && !periodic[0])
        GF_TRY(add_wall_pair(sim, spec, 0, "wall_x_lo_m", "wall_x_hi_m"));
    if (param(spec, "walls_z") > 0.5 && !periodic[2])
        GF_TRY(add_wall_pair(sim, spec, 2, "wall_z_lo_m", "wall_z_hi_m"));
    return GF_OK;
}

static const char *prep_check(const gf_run_spec *spec, char *why, size_t n)
{
    static const char *const axes[3][2] = {
        {"box_lo_x_m", "box_hi_x_m"}, {"box_lo_y_m", "box_hi_y_m"}, {"box_lo_z_m", "box_hi_z_m"}};
    for (int a = 0; a < 3; ++a)
        if (!(param(spec, axes[a][1]) > param(spec, axes[a][0]))) {
            snprintf(why, n, "the box must have %s > %s", axes[a][1], axes[a][0]);
            return axes[a][1];
        }
    return NULL;
}

const gf_scene_desc gf_scene_packing_preparation = {
    .name = "packing_preparation",
    .caption = "the container of a packing preparation (particles/gf_packing.h), grains added by the preparation",
    .internal = 1,
    .needs = GF_NEED_CONTACTS,
    GF_SCENE_PARAMS(prep_params),
    .default_end_time_nd = 1.0,
    .build = prep_build,
    .check = prep_check,
};
