/* Asked groups -> physical values; see gf_groups_map.h for the map and its sources. */
#include "campaign/gf_groups_map.h"

#include <math.h>
#include <string.h>

#include "scenes/gf_scene.h"

static int scene_has_param(const gf_run_spec *spec, const char *key)
{
    const gf_scene_desc *scene = gf_scene_find(spec->scene);
    if (!scene)
        return 0;
    for (int i = 0; i < scene->n_params; ++i)
        if (strcmp(scene->params[i].key, key) == 0)
            return 1;
    return 0;
}

/* Scene parameter value: the spec's, else the scene table's default. */
static double scene_param(const gf_run_spec *spec, const char *key, double fallback)
{
    const gf_scene_desc *scene = gf_scene_find(spec->scene);
    if (scene)
        for (int i = 0; i < scene->n_params; ++i)
            if (strcmp(scene->params[i].key, key) == 0)
                fallback = scene->params[i].def;
    return gf_run_spec_param(spec, key, fallback);
}

double gf_groups_map_slope_sin(const gf_run_spec *spec)
{
    if (!scene_has_param(spec, "incline_deg"))
        return 1.0;
    const double theta_deg = scene_param(spec, "incline_deg", 90.0);
    return sin(theta_deg * M_PI / 180.0);
}

static gf_status map_fluid(gf_ctx *ctx, gf_run_spec *spec)
{
    const int has_St = !isnan(spec->stokes_St), has_r = !isnan(spec->density_ratio_r);
    if (!has_St && !has_r)
        return GF_OK;
    if (strcmp(spec->fluid.model, "none") == 0)
        return GF_FAIL(ctx, GF_ERR_CONFIG,
                       "St and r describe a fluid but fluid.model is none (set fluid.model: unresolved or auto)");
    const double s = gf_groups_map_slope_sin(spec);
    if (!(s > 0.0))
        return GF_FAIL(ctx, GF_ERR_PHYSICS, "St needs a positive slope: sin(incline_deg) = %g", s);
    const double g_eff = spec->gravity_m_s2 * s, D = spec->grains.diameter_m, rho_p = spec->grains.density_kg_m3;
    double r = spec->density_ratio_r;
    if (!has_r) {
        if (!(spec->fluid.density_kg_m3 > 0.0))
            return GF_FAIL(ctx, GF_ERR_CONFIG, "St without r needs fluid.density_kg_m3 > 0 to fix r");
        r = sqrt(5.0 * rho_p / (3.0 * spec->fluid.density_kg_m3));
    }
    if (!has_St) {
        if (!(r > sqrt(5.0 / 3.0)))
            return GF_FAIL(ctx, GF_ERR_PHYSICS,
                           "r = %g <= sqrt(5/3) = 1.291: grains would not be denser than the fluid", r);
        spec->fluid.density_kg_m3 = 5.0 * rho_p / (3.0 * r * r);
        if (!(spec->fluid.viscosity_Pa_s > 0.0))
            return GF_FAIL(ctx, GF_ERR_CONFIG, "r without St needs fluid.viscosity_Pa_s > 0 to fix St");
        return GF_OK;
    }
    if (!(r > sqrt(5.0 / 3.0)))
        return GF_FAIL(ctx, GF_ERR_PHYSICS, "r = %g <= sqrt(5/3) = 1.291: grains would not be denser than the fluid",
                       r);
    return gf_groups_invert(ctx, spec->stokes_St, r, D, rho_p, g_eff, &spec->fluid.density_kg_m3,
                            &spec->fluid.viscosity_Pa_s);
}

gf_status gf_groups_map_apply(gf_ctx *ctx, gf_run_spec *spec)
{
    GF_TRY(map_fluid(ctx, spec));
    if (!isnan(spec->aspect_ratio_a)) {
        if (!scene_has_param(spec, "aspect_ratio"))
            return GF_FAIL(ctx, GF_ERR_CONFIG, "a (aspect ratio) does not apply: scene %s has no aspect_ratio",
                           spec->scene);
        GF_TRY(gf_run_spec_set_param(ctx, spec, "aspect_ratio", spec->aspect_ratio_a));
    }
    if (!isnan(spec->phi_initial)) {
        /* The packing target: phi_initial, or phi_target (column_collapse's name for it). */
        const char *key = scene_has_param(spec, "phi_initial") ? "phi_initial"
                          : scene_has_param(spec, "phi_target") ? "phi_target"
                                                                : NULL;
        if (!key)
            return GF_FAIL(ctx, GF_ERR_CONFIG, "Phi_i does not apply: scene %s has no phi_initial (packing target)",
                           spec->scene);
        GF_TRY(gf_run_spec_set_param(ctx, spec, key, spec->phi_initial));
    }
    return GF_OK;
}

gf_status gf_groups_map_realised(gf_ctx *ctx, const gf_run_spec *spec, gf_scales *out)
{
    const double D = spec->grains.diameter_m;
    double R0 = 0.0, H0 = 0.0;
    if (scene_has_param(spec, "column_length_over_D")) {
        R0 = scene_param(spec, "column_length_over_D", 0.0) * D;
        H0 = scene_param(spec, "aspect_ratio", 0.0) * R0;
    }
    const int dry = strcmp(spec->fluid.model, "none") == 0;
    gf_groups_input in = {.diameter_m = D,
                          .grain_density_kg_m3 = spec->grains.density_kg_m3,
                          .fluid_density_kg_m3 = dry ? 0.0 : spec->fluid.density_kg_m3,
                          .viscosity_Pa_s = dry ? 0.0 : spec->fluid.viscosity_Pa_s,
                          .gravity_m_s2 = spec->gravity_m_s2,
                          .slope_sin = gf_groups_map_slope_sin(spec),
                          .column_height_m = H0,
                          .column_length_m = R0};
    return gf_groups_compute(ctx, &in, out);
}
