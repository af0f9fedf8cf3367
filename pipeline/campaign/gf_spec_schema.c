/*
 * The configuration schema table and the reader built on it (gf_spec_schema.h).
 *
 * Ranges are generous physical bounds, not preferences: they reject typos
 * (a diameter of 7.6 instead of 7.6e-3 m is a boulder) and values that make
 * the model meaningless (restitution above 1, a negative viscosity), while
 * leaving every regime of the seeds (Izard 2014 Tables 4.2, 5.1) inside.
 * The stability of the time step is the engine's check (gf_sim_create), not
 * the schema's, because it depends on several values at once.
 */
#include "campaign/gf_spec_schema.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "contact/gf_contact.h"
#include "contact/gf_lubrication.h"
#include "coupling/gf_drag.h"
#include "coupling/gf_ibm_markers.h"
#include "fluid/gf_fluid_ns2.h"
#include "scenes/gf_scene.h"

static const char *const fluid_models[] = {"none", "unresolved", "resolved", "auto", NULL};
static const char *const methods[] = {"dem", "continuum", NULL};

#define D(sec, k, field, lo, hi, open, unit, doc) \
    {sec, k, GF_FIELD_DOUBLE, offsetof(gf_run_spec, field), 0, lo, hi, open, unit, NULL, doc, NULL}
#define B(sec, k, field, doc) {sec, k, GF_FIELD_BOOL, offsetof(gf_run_spec, field), 0, 0, 1, 0, "", NULL, doc, NULL}
#define N(sec, k, field, choices, doc) \
    {sec, k, GF_FIELD_NAME, offsetof(gf_run_spec, field), GF_NAME_LEN, 0, 0, 0, "", choices, doc, NULL}
/* A name whose allowed values are a registry's (the registry is the only list). */
#define R(sec, k, field, registry, doc) \
    {sec, k, GF_FIELD_NAME, offsetof(gf_run_spec, field), GF_NAME_LEN, 0, 0, 0, "", NULL, doc, registry}

static const gf_spec_field fields[] = {
    {"", "seed", GF_FIELD_U64, offsetof(gf_run_spec, seed), 0, 0, 0, 0, "", NULL, "RNG seed (packing, radii)", NULL},
    D("", "end_time", end_time_nd, 0, 1e7, 0, "1", "end time in sqrt(D/g); 0: the scene's default"),
    D("", "gravity", gravity_m_s2, 0, 1e3, 1, "m s-2", "|g|"),
    N("", "method", method, methods, "dem: grains; continuum: the mu(I) continuum (column_collapse, avalanche)"),
    D("grains", "diameter_m", grains.diameter_m, 0, 1.0, 1, "m", "mean grain diameter D"),
    D("grains", "polydispersity", grains.polydispersity, 0, 0.5, 0, "1", "radii uniform in R(1 -+ p)"),
    D("grains", "density_kg_m3", grains.density_kg_m3, 0, 1e5, 1, "kg m-3", "grain density rho_p"),
    R("contact", "law", contact.law, gf_contact_law_names, "normal force law"),
    D("contact", "t_contact_nd", contact.t_contact_nd, 0, 1.0, 1, "1", "contact duration t_c sqrt(g/D)"),
    D("contact", "restitution", contact.restitution, 0, 1.0, 1, "1", "dry normal restitution eps_max"),
    D("contact", "friction", contact.friction, 0, 10.0, 0, "1", "grain-grain Coulomb friction mu_c"),
    D("contact", "wall_friction", contact.wall_friction, 0, 10.0, 0, "1", "grain-wall friction"),
    D("contact", "kt_over_kn", contact.kt_over_kn, 0, 10.0, 0, "1", "tangential / normal stiffness"),
    B("contact", "allow_attraction", contact.allow_attraction, "keep the attractive part of the dashpot"),
    D("contact", "dt_over_tc", contact.dt_over_tc, 0, 0.5, 1, "1", "DEM time step / t_c"),
    D("contact", "skin_over_D", contact.skin_over_D, 0, 5.0, 0, "1", "Verlet skin / D"),
    D("contact", "sleep_speed_nd", contact.sleep_speed_nd, 0, 0.05, 0, "1", "sleep below this speed / sqrt(gD); 0: off"),
    D("contact", "overlap_target_over_D", contact.overlap_target_over_D, 0, 0.05, 0, "1",
      "t_c from the scene's pressure: static overlaps below this x D (replaces t_contact_nd); 0: off"),
    N("fluid", "model", fluid.model, fluid_models, "fluid tier"),
    D("fluid", "density_kg_m3", fluid.density_kg_m3, 0, 1e5, 0, "kg m-3", "fluid density rho_f (0: dry)"),
    D("fluid", "viscosity_Pa_s", fluid.viscosity_Pa_s, 0, 1e6, 0, "Pa s", "dynamic viscosity eta_f (0: dry)"),
    R("fluid", "drag", fluid.drag, gf_drag_names, "drag closure (unresolved tier)"),
    D("fluid", "cell_over_D", fluid.cell_over_D, 0, 100.0, 1, "1", "fluid cell size / D"),
    D("fluid", "cfl", fluid.cfl, 0, 1.0, 1, "1", "advective CFL bound"),
    B("fluid", "lubrication", fluid.lubrication, "Brenner normal lubrication"),
    D("fluid", "roughness_over_R", fluid.roughness_over_R, 0, 1.0, 0, "1", "effective roughness eta_e / R"),
    D("fluid", "lub_cutoff_over_R", fluid.lub_cutoff_over_R, 0, 10.0, 0, "1", "lubrication range / R"),
    D("continuum", "mu_s", continuum.mu_s, 0, 5.0, 0, "1", "mu(I): static friction mu_s"),
    D("continuum", "mu_2", continuum.mu_2, 0, 5.0, 1, "1", "mu(I): limiting friction mu_2 (> mu_s)"),
    D("continuum", "I0", continuum.I0, 0, 10.0, 1, "1", "mu(I): I0 (> 0)"),
    D("continuum", "phi", continuum.phi, 0, 0.7405, 1, "1", "solid fraction of the continuum"),
    D("continuum", "cell_over_D", continuum.cell_over_D, 0, 10.0, 1, "1", "cell edge / D"),
    D("continuum", "gdot_min_nd", continuum.gdot_min_nd, 0, 1.0, 1, "1", "|gdot| floor x sqrt(D/g)"),
    N("fluid", "lub_overlap", fluid.lub_overlap, gf_lub_overlap_names,
      "lubrication while surfaces overlap: clamp (gap 0), off (contact law alone), film (elastic film, Izard 2014 (3.28))"),
    D("fluid", "d_over_dx", fluid.d_over_dx, 0, 64.0, 0, "1", "resolved tier: grid cells per diameter D/dx (8-20; 0: 16)"),
    D("fluid", "ibm_retraction_dx", fluid.ibm_retraction_dx, 0, 1.0, 0, "1",
      "resolved tier: solid-fraction profile (or markers) centred on R minus this many cells (Breugem 2012; 0: on R)"),
    N("fluid", "time_scheme", fluid.time_scheme, gf_ns2_scheme_names,
      "resolved tier: ab2 (Adams-Bashforth 2) or rk3 (three-substep Runge-Kutta), Crank-Nicolson viscosity"),
    D("fluid", "diffusion_number", fluid.diffusion_number, 0, 1.0, 1, "1",
      "resolved tier: nu dt/dx^2 of the fluid step where viscosity bounds it (0.5; stability limit 1)"),
    N("fluid", "advection", fluid.advection, gf_ns2_advection_names,
      "resolved tier: advective (u.grad)u or divergence div(uu), the energy-conserving form"),
    N("fluid", "ibm_forcing", fluid.ibm_forcing, gf_ibm_forcing_names,
      "resolved tier: smoothed (solid fraction, Izard 2014) or markers (surface markers, Uhlmann 2005)"),
    B("fluid", "ibm_contact_correction", fluid.ibm_contact_correction,
      "resolved tier, smoothed forcing: contacts and lubrication act in full (1, default), or at (rho_p - rho)/rho_p "
      "as under Izard's force formula alone (0)"),
    D("output", "interval_nd", output.interval_nd, 0, 1e7, 1, "1", "output interval in sqrt(D/g)"),
    B("output", "particles", output.particles, "write particles.nc"),
    B("output", "fields", output.fields, "write fields.nc"),
    B("output", "probes", output.probes, "write probes.nc"),
    B("output", "diagnostics", output.diagnostics, "write diagnostics.nc"),
    D("output", "checkpoint_interval_nd", output.checkpoint_interval_nd, 0, 1e7, 0, "1",
      "periodic checkpoint interval in sqrt(D/g); 0: none"),
};

const gf_spec_field *gf_spec_fields(int *n)
{
    *n = (int)(sizeof fields / sizeof *fields);
    return fields;
}

const gf_spec_field *gf_spec_field_find(const char *section, const char *key)
{
    for (size_t i = 0; i < sizeof fields / sizeof *fields; ++i)
        if (strcmp(fields[i].section, section) == 0 && strcmp(fields[i].key, key) == 0)
            return &fields[i];
    return NULL;
}

void gf_spec_field_format(const gf_spec_field *f, const gf_run_spec *spec, char *buf, size_t n)
{
    const char *base = (const char *)spec + f->offset;
    switch (f->type) {
    case GF_FIELD_DOUBLE:
        snprintf(buf, n, "%.17g", *(const double *)base);
        break;
    case GF_FIELD_BOOL:
        snprintf(buf, n, "%s", *(const int *)base ? "true" : "false");
        break;
    case GF_FIELD_U64:
        snprintf(buf, n, "%llu", (unsigned long long)*(const uint64_t *)base);
        break;
    case GF_FIELD_NAME:
        snprintf(buf, n, "%s", base);
        break;
    }
}

const char *const gf_group_names[4] = {"St", "r", "a", "Phi_i"};

int gf_group_index(const char *name)
{
    for (int j = 0; j < 4; ++j)
        if (strcmp(name, gf_group_names[j]) == 0)
            return j;
    return -1;
}

double *gf_spec_group(gf_run_spec *spec, int i)
{
    switch (i) {
    case 0: return &spec->stokes_St;
    case 1: return &spec->density_ratio_r;
    case 2: return &spec->aspect_ratio_a;
    default: return &spec->phi_initial;
    }
}

int gf_group_value_ok(int i, double v, const char **why)
{
    /* Phi_i: random loose packing of spheres is ~0.55, random close ~0.64,
     * crystalline 0.74; beyond that no packing exists. */
    static const double lo[4] = {0, 0, 0, 0}, hi[4] = {1e12, 1e6, 1e4, 0.7405};
    static const char *const text[4] = {"St must be in (0, 1e12]", "r must be in (0, 1e6]",
                                        "a must be in (0, 1e4]", "Phi_i must be in (0, 0.7405] (hexagonal packing)"};
    if (isfinite(v) && v > lo[i] && v <= hi[i])
        return 1;
    *why = text[i];
    return 0;
}

static gf_status read_field(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_spec_field *f, const gf_cfg_node *node,
                            gf_run_spec *spec)
{
    char *base = (char *)spec + f->offset;
    switch (f->type) {
    case GF_FIELD_DOUBLE: {
        double v;
        GF_TRY(gf_cfg_to_double(ctx, doc, node, f->min, f->max, &v));
        if (f->min_open && !(v > f->min))
            return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s = %g is out of range: must be > %g", f->key, v,
                               f->min);
        *(double *)base = v;
        return GF_OK;
    }
    case GF_FIELD_BOOL:
        return gf_cfg_to_bool(ctx, doc, node, (int *)base);
    case GF_FIELD_U64:
        return gf_cfg_to_u64(ctx, doc, node, (uint64_t *)base);
    case GF_FIELD_NAME:
        return gf_cfg_to_name(ctx, doc, node, f->registry_choices ? f->registry_choices() : f->choices, base,
                              f->size);
    }
    return GF_OK;
}

static gf_status read_section(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *map, const char *section,
                              gf_run_spec *spec)
{
    GF_TRY(gf_cfg_expect(ctx, doc, map, GF_CFG_MAP));
    const char *keys[64];
    int nk = 0, n;
    const gf_spec_field *all = gf_spec_fields(&n);
    for (int i = 0; i < n && nk < 63; ++i)
        if (strcmp(all[i].section, section) == 0)
            keys[nk++] = all[i].key;
    keys[nk] = NULL;
    for (int i = 0; i < map->n_items; ++i) {
        const gf_cfg_node *item = map->items[i];
        const gf_spec_field *f = gf_spec_field_find(section, item->key);
        if (!f)
            return gf_cfg_fail_unknown_key(ctx, doc, item, section, keys);
        GF_TRY(read_field(ctx, doc, f, item, spec));
    }
    return GF_OK;
}

/* Scene parameters of one map (scene: or domain:), checked against the scene's table. */
static gf_status read_scene_params(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *map,
                                   const gf_scene_desc *scene, const char *section, gf_run_spec *spec)
{
    GF_TRY(gf_cfg_expect(ctx, doc, map, GF_CFG_MAP));
    const char *keys[GF_MAX_SCENE_PARAMS + 2];
    int nk = 0;
    if (strcmp(section, "scene") == 0)
        keys[nk++] = "name";
    for (int i = 0; i < scene->n_params && nk < GF_MAX_SCENE_PARAMS + 1; ++i)
        keys[nk++] = scene->params[i].key;
    keys[nk] = NULL;
    for (int i = 0; i < map->n_items; ++i) {
        const gf_cfg_node *item = map->items[i];
        if (strcmp(section, "scene") == 0 && strcmp(item->key, "name") == 0)
            continue;
        const gf_param_info *info = NULL;
        for (int j = 0; j < scene->n_params; ++j)
            if (strcmp(scene->params[j].key, item->key) == 0)
                info = &scene->params[j];
        if (!info) {
            char where[80];
            snprintf(where, sizeof where, "%s (scene %s)", section, scene->name);
            return gf_cfg_fail_unknown_key(ctx, doc, item, where, keys);
        }
        double v;
        int flag;
        if (item->kind == GF_CFG_SCALAR && !item->quoted &&
            (strcmp(item->text, "true") == 0 || strcmp(item->text, "false") == 0)) {
            GF_TRY(gf_cfg_to_bool(ctx, doc, item, &flag));
            v = flag;
        } else {
            GF_TRY(gf_cfg_to_double(ctx, doc, item, -INFINITY, INFINITY, &v));
        }
        if (v < info->min || v > info->max)
            return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, item, 0, "%s = %g %s is out of range [%g, %g]%s%s",
                               item->key, v, info->unit && strcmp(info->unit, "1") ? info->unit : "", info->min,
                               info->max, info->doc ? ": " : "", info->doc ? info->doc : "");
        GF_TRY(gf_run_spec_set_param(ctx, spec, item->key, v));
    }
    return GF_OK;
}

static gf_status read_groups(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *map, gf_run_spec *spec)
{
    GF_TRY(gf_cfg_expect(ctx, doc, map, GF_CFG_MAP));
    const char *keys[] = {"St", "r", "a", "Phi_i", NULL};
    for (int i = 0; i < map->n_items; ++i) {
        const gf_cfg_node *item = map->items[i];
        const int g = gf_group_index(item->key);
        if (g < 0)
            return gf_cfg_fail_unknown_key(ctx, doc, item, "groups", keys);
        double v;
        const char *why;
        GF_TRY(gf_cfg_to_double(ctx, doc, item, -INFINITY, INFINITY, &v));
        if (!gf_group_value_ok(g, v, &why))
            return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, item, 0, "%s = %g: %s", item->key, v, why);
        *gf_spec_group(spec, g) = v;
    }
    return GF_OK;
}

static const char *const top_keys[] = {"name",  "description", "seed",   "end_time", "gravity",
                                       "scene", "grains",      "contact", "fluid",   "output",
                                       "domain", "groups",     "grid",   "variants", "method", "continuum", NULL};

gf_status gf_spec_read(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *root, gf_run_spec *spec)
{
    gf_run_spec_defaults(spec);
    if (!root)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, NULL, 0, "empty configuration (expected scene:, grains:, ...)");
    if (root->kind != GF_CFG_MAP)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, root, 0,
                           "a configuration is a mapping of sections (scene:, grains:, ...), not %s",
                           root->kind == GF_CFG_SEQ ? "a list" : "a single value");
    for (int i = 0; i < root->n_items; ++i) {
        const gf_cfg_node *item = root->items[i];
        int known = 0;
        for (const char *const *k = top_keys; *k; ++k)
            known |= strcmp(*k, item->key) == 0;
        if (!known)
            return gf_cfg_fail_unknown_key(ctx, doc, item, "the top level", top_keys);
    }

    /* The scene first: its table decides which scene keys exist. */
    const gf_cfg_node *scene_node = gf_cfg_get(root, "scene");
    if (!scene_node)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, root, 0, "missing section 'scene:' (e.g. scene: {name: %s})",
                           spec->scene);
    const gf_cfg_node *name_node = scene_node->kind == GF_CFG_MAP ? gf_cfg_get(scene_node, "name") : scene_node;
    if (!name_node)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, scene_node, 0, "scene: missing 'name'");
    int n_scenes = 0;
    const gf_scene_desc *const *all = gf_scene_all(&n_scenes);
    const char *names[64];
    int nn = 0;
    for (int i = 0; i < n_scenes && nn < 63; ++i)
        if (!all[i]->internal)
            names[nn++] = all[i]->name;
    names[nn] = NULL;
    GF_TRY(gf_cfg_to_name(ctx, doc, name_node, names, spec->scene, sizeof spec->scene));
    const gf_scene_desc *scene = gf_scene_find(spec->scene);
    if (!scene)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, name_node, 0, "unknown scene '%s'", spec->scene);

    for (int i = 0; i < root->n_items; ++i) {
        const gf_cfg_node *item = root->items[i];
        const char *k = item->key;
        if (strcmp(k, "scene") == 0 && item->kind == GF_CFG_MAP)
            GF_TRY(read_scene_params(ctx, doc, item, scene, "scene", spec));
        else if (strcmp(k, "domain") == 0)
            GF_TRY(read_scene_params(ctx, doc, item, scene, "domain", spec));
        else if (strcmp(k, "groups") == 0)
            GF_TRY(read_groups(ctx, doc, item, spec));
        else if (!strcmp(k, "grains") || !strcmp(k, "contact") || !strcmp(k, "fluid") || !strcmp(k, "output") ||
                 !strcmp(k, "continuum"))
            GF_TRY(read_section(ctx, doc, item, k, spec));
        else if (gf_spec_field_find("", k))
            GF_TRY(read_field(ctx, doc, gf_spec_field_find("", k), item, spec));
        else if (strcmp(k, "name") == 0 || strcmp(k, "description") == 0)
            GF_TRY(gf_cfg_expect(ctx, doc, item, GF_CFG_SCALAR));
    }
    return GF_OK;
}
