/*
 * Scene lookup and parameter resolution: a run spec's scene parameters are
 * checked against the scene's own table (key, unit, default, inclusive range);
 * absent keys get their default. Unknown keys and out-of-range values are
 * configuration errors that name the key, the value and the range.
 */
#include <math.h>
#include <string.h>

#include "core/gf_registry.h"
#include "scenes/gf_scene.h"

static const char *scene_name(size_t i)
{
    int n = 0;
    return gf_scene_all(&n)[i]->name;
}

const gf_scene_desc *gf_scene_find(const char *name)
{
    int n = 0;
    const gf_scene_desc *const *all = gf_scene_all(&n);
    long i = gf_registry_index((size_t)n, scene_name, name);
    return i < 0 ? NULL : all[i];
}

static const gf_param_info *find_param(const gf_scene_desc *d, const char *key)
{
    for (int i = 0; i < d->n_params; ++i)
        if (strcmp(d->params[i].key, key) == 0)
            return &d->params[i];
    return NULL;
}

gf_status gf_scene_resolve_params(gf_ctx *ctx, gf_run_spec *spec) { return gf_scene_resolve_params_at(ctx, spec, NULL); }

gf_status gf_scene_resolve_params_at(gf_ctx *ctx, gf_run_spec *spec, const char **bad_key)
{
    if (bad_key)
        *bad_key = NULL;
    const gf_scene_desc *d = gf_scene_find(spec->scene);
    if (!d)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "scene: unknown scene '%s'", spec->scene);
    for (int i = 0; i < spec->n_scene_params; ++i) {
        const gf_param *q = &spec->scene_params[i];
        const gf_param_info *info = find_param(d, q->key);
        if (!info)
            return GF_FAIL(ctx, GF_ERR_CONFIG, "scene %s: unknown parameter '%s'", d->name, q->key);
        if (!isfinite(q->value) || q->value < info->min || q->value > info->max)
            return GF_FAIL(ctx, GF_ERR_CONFIG, "scene %s: parameter %s = %g %s outside [%g, %g]", d->name, q->key,
                           q->value, info->unit, info->min, info->max);
    }
    for (int i = 0; i < d->n_params; ++i) {
        const gf_param_info *info = &d->params[i];
        int present = 0;
        for (int k = 0; k < spec->n_scene_params; ++k)
            present |= strcmp(spec->scene_params[k].key, info->key) == 0;
        if (!present)
            GF_TRY(gf_run_spec_set_param(ctx, spec, info->key, info->def));
    }
    char why[256];
    const char *key = d->check ? d->check(spec, why, sizeof why) : NULL;
    if (key) {
        if (bad_key)
            *bad_key = key;
        return GF_FAIL(ctx, GF_ERR_CONFIG, "scene %s: %s", d->name, why);
    }
    return GF_OK;
}
