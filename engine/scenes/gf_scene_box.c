/*
 * A scene's container (gf_scene_box.h): the box, gravity along -y and the
 * plane walls from the scene's table, added first so that their ids are the
 * table's rows.
 */
#include "scenes/gf_scene_box.h"

gf_status gf_scene_box_under_gravity(gf_sim *sim, const double lo[3], const double hi[3], const int periodic[3],
                                     double g_m_s2)
{
    GF_TRY(gf_sim_set_box(sim, lo, hi, periodic));
    return gf_sim_set_gravity(sim, (const double[3]){0.0, -g_m_s2, 0.0});
}

gf_status gf_scene_add_planes(gf_sim *sim, int n, const gf_scene_plane *planes)
{
    for (int k = 0; k < n; ++k) {
        int id = -1;
        GF_TRY(gf_sim_add_wall(sim, planes[k].point_m, planes[k].normal, planes[k].friction, &id));
        if (id != k)
            return GF_FAIL(gf_sim_ctx(sim), GF_ERR_ARG, "scene %s: wall %d got id %d (walls must be added first)",
                           gf_sim_spec(sim)->scene, k, id);
    }
    return GF_OK;
}
