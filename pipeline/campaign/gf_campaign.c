/* Campaign expansion: variants x grid -> resolved runs; see gf_campaign.h. */
#include "campaign/gf_campaign.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "campaign/gf_groups_map.h"
#include "campaign/gf_spec_schema.h"
#include "campaign/gf_spec_text.h"
#include "coupling/gf_coupling.h"
#include "scenes/gf_scene.h"

#define MAX_SETS 64

typedef struct loader {
    gf_ctx *ctx;
    gf_cfg_doc *doc;
    gf_cfg_node *root;          /* owned copy with the --set entries laid over */
    gf_grid grid;
    const gf_cfg_node *variants;
    char *origins[MAX_SETS];    /* "--set key=value" strings, the origins of --set nodes */
    int n_origins;
} loader;

static void loader_free(loader *L)
{
    gf_grid_free(&L->grid);
    gf_cfg_node_free(L->root);
    for (int i = 0; i < L->n_origins; ++i)
        free(L->origins[i]);
    gf_cfg_destroy(&L->doc);
}

/* scene: column_collapse  ->  scene: {name: column_collapse}, so that dotted
 * paths (scene.aspect_ratio) always have a map to land in. */
static gf_status normalise_scene(loader *L, gf_cfg_node *root)
{
    for (int i = 0; i < root->n_items; ++i) {
        gf_cfg_node *s = root->items[i];
        if (strcmp(s->key, "scene") != 0 || s->kind != GF_CFG_SCALAR)
            continue;
        gf_cfg_node *name = gf_cfg_clone(s);
        if (!name)
            return GF_FAIL(L->ctx, GF_ERR_NOMEM, "config: out of memory");
        free(name->key);
        name->key = NULL;
        s->kind = GF_CFG_MAP;
        free(s->text);
        s->text = NULL;
        return gf_cfg_map_set_path(L->ctx, s, "name", name);
    }
    return GF_OK;
}

static gf_status apply_sets(loader *L, const char *const *sets, int n_sets)
{
    if (n_sets > MAX_SETS)
        return GF_FAIL(L->ctx, GF_ERR_ARG, "--set: more than %d entries", MAX_SETS);
    for (int i = 0; i < n_sets; ++i) {
        const char *eq = strchr(sets[i], '=');
        size_t len = strlen(sets[i]) + 8;
        char *origin = malloc(len);
        if (!origin)
            return GF_FAIL(L->ctx, GF_ERR_NOMEM, "out of memory");
        snprintf(origin, len, "--set %s", sets[i]);
        L->origins[L->n_origins++] = origin;
        if (!eq || eq == sets[i])
            return GF_FAIL(L->ctx, GF_ERR_ARG, "%s: expected key.path=value", origin);
        char path[128];
        size_t n = (size_t)(eq - sets[i]);
        if (n >= sizeof path)
            return GF_FAIL(L->ctx, GF_ERR_ARG, "%s: key path too long", origin);
        memcpy(path, sets[i], n);
        path[n] = '\0';
        gf_cfg_node *v = gf_cfg_scalar_new(eq + 1, origin);
        if (!v)
            return GF_FAIL(L->ctx, GF_ERR_NOMEM, "out of memory");
        GF_TRY(gf_cfg_map_set_path(L->ctx, L->root, path, v));
    }
    return GF_OK;
}

/* Lays a variant's entries over a tree. Keys are dotted paths; a map value is
 * laid entry by entry (so {fluid: {model: x}} keeps the other fluid keys). */
static gf_status overlay(loader *L, gf_cfg_node *root, const char *prefix, const gf_cfg_node *map)
{
    for (int i = 0; i < map->n_items; ++i) {
        const gf_cfg_node *item = map->items[i];
        if (!prefix[0] && strcmp(item->key, "label") == 0)
            continue;
        char path[256];
        snprintf(path, sizeof path, "%s%s%s", prefix, prefix[0] ? "." : "", item->key);
        if (!prefix[0] && (strcmp(path, "grid") == 0 || strcmp(path, "variants") == 0 ||
                           strcmp(path, "name") == 0 || strcmp(path, "scene.name") == 0 ||
                           (strcmp(path, "scene") == 0 && gf_cfg_get(item, "name"))))
            return gf_cfg_fail(L->ctx, GF_ERR_CONFIG, L->doc, item, 1,
                               "a variant cannot change '%s' (one campaign = one scene and one grid)", path);
        if (item->kind == GF_CFG_MAP) {
            GF_TRY(overlay(L, root, path, item));
            continue;
        }
        gf_cfg_node *v = gf_cfg_clone(item);
        if (!v)
            return GF_FAIL(L->ctx, GF_ERR_NOMEM, "out of memory");
        gf_status st = gf_cfg_map_set_path(L->ctx, root, path, v);
        if (st != GF_OK)
            return gf_cfg_fail(L->ctx, GF_ERR_CONFIG, L->doc, item, 1, "cannot set '%s': %s", path,
                               gf_ctx_message(L->ctx));
    }
    return GF_OK;
}

static gf_status read_name(loader *L, const char *path, char *name, size_t n)
{
    const gf_cfg_node *node = gf_cfg_get(L->root, "name");
    if (node) {
        GF_TRY(gf_cfg_to_name(L->ctx, L->doc, node, NULL, name, n));
        for (const char *c = name; *c; ++c)
            if (!(*c == '_' || *c == '-' || *c == '.' || (*c >= '0' && *c <= '9') || (*c >= 'a' && *c <= 'z') ||
                  (*c >= 'A' && *c <= 'Z')) || name[0] == '.')
                return gf_cfg_fail(L->ctx, GF_ERR_CONFIG, L->doc, node, 0,
                                   "name: '%s' must be letters, digits, '_', '-' or '.' (it names a directory)",
                                   name);
        return GF_OK;
    }
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    snprintf(name, n, "%s", base);
    char *dot = strrchr(name, '.');
    if (dot && dot != name)
        *dot = '\0';
    for (char *c = name; *c; ++c)
        if (*c == ' ' || *c == '/')
            *c = '_';
    if (!name[0])
        snprintf(name, n, "campaign");
    return GF_OK;
}

static gf_status check_grid_vs_groups(loader *L)
{
    const gf_cfg_node *groups = gf_cfg_get(L->root, "groups");
    for (int g = 0; g < 4; ++g)
        if (L->grid.axes[g].n && gf_cfg_get(groups, gf_group_names[g]))
            return gf_cfg_fail(L->ctx, GF_ERR_CONFIG, L->doc, gf_cfg_get(groups, gf_group_names[g]), 1,
                               "%s is both in groups: and on the grid", gf_group_names[g]);
    return GF_OK;
}

/* The node that sets scene parameter key, for a located error: the
 * variant's (dotted scene.key or nested), else the file's scene: or domain:
 * map; fallback when the key was left to its default. */
static const gf_cfg_node *scene_key_node(const loader *L, const gf_cfg_node *variant, const char *key,
                                         const gf_cfg_node *fallback)
{
    char dotted[GF_NAME_LEN + 8];
    snprintf(dotted, sizeof dotted, "scene.%s", key);
    const gf_cfg_node *n = NULL;
    if (variant && !(n = gf_cfg_get(variant, dotted))) {
        const gf_cfg_node *sec = gf_cfg_get(variant, "scene");
        n = sec && sec->kind == GF_CFG_MAP ? gf_cfg_get(sec, key) : NULL;
    }
    for (int k = 0; !n && k < 2; ++k) {
        const gf_cfg_node *sec = gf_cfg_get(L->root, k ? "domain" : "scene");
        n = sec && sec->kind == GF_CFG_MAP ? gf_cfg_get(sec, key) : NULL;
    }
    return n ? n : fallback;
}

/* One run: variant v, grid point k. */
/* The node of the key an engine message opens with ("fluid.d_over_dx = 4: ..."): the key when the file
 * sets it, else its section, else fallback. The step's refusal names contact.dt_over_tc, which the file
 * may set through contact.t_contact_nd instead. */
static const gf_cfg_node *key_named_by(const loader *L, const char *msg, const gf_cfg_node *fallback)
{
    char sec[64] = "", key[64] = "";
    if (sscanf(msg, "%63[a-z_].%63[a-zA-Z0-9_]", sec, key) != 2)
        return fallback;
    const gf_cfg_node *section = gf_cfg_get(L->root, sec);
    if (!section)
        return fallback;
    const gf_cfg_node *node = gf_cfg_get(section, key);
    if (!node && strcmp(key, "dt_over_tc") == 0)
        node = gf_cfg_get(section, "t_contact_nd");
    return node ? node : section;
}

static gf_status build_run(loader *L, int v, int k, int index, gf_campaign_run *run)
{
    gf_ctx *ctx = L->ctx;
    memset(run, 0, sizeof *run);
    run->index = index;
    const gf_cfg_node *variant = L->variants ? L->variants->items[v] : NULL;
    gf_cfg_node *tree = L->root;
    gf_cfg_node *copy = NULL;
    if (variant) {
        copy = gf_cfg_clone(L->root);
        if (!copy)
            return GF_FAIL(ctx, GF_ERR_NOMEM, "out of memory");
        tree = copy;
        gf_status st = overlay(L, copy, "", variant);
        const gf_cfg_node *label = gf_cfg_get(variant, "label");
        if (st == GF_OK && label)
            st = gf_cfg_to_name(ctx, L->doc, label, NULL, run->label, sizeof run->label);
        if (st != GF_OK) {
            gf_cfg_node_free(copy);
            return st;
        }
    }
    gf_status st = gf_spec_read(ctx, L->doc, tree, &run->spec);
    gf_cfg_node_free(copy);
    GF_TRY(st);

    double point[4];
    gf_grid_point(&L->grid, k, point);
    for (int g = 0; g < 4; ++g)
        if (!isnan(point[g]))
            *gf_spec_group(&run->spec, g) = point[g];

    /* Locate mapping errors at the grid (or groups:, or the variant). */
    const gf_cfg_node *at = L->grid.node ? L->grid.node : gf_cfg_get(L->root, "groups");
    if (!at)
        at = variant ? variant : gf_cfg_get(L->root, "scene");
    char label[200] = "";
    if (L->grid.n_points > 1 || variant) {
        int len = snprintf(label, sizeof label, "run %d (", run->index);
        const char *sep = "";
        for (int g = 0; g < 4; ++g)
            if (!isnan(*gf_spec_group(&run->spec, g))) {
                len += snprintf(label + len, sizeof label - (size_t)len, "%s%s=%g", sep, gf_group_names[g],
                                *gf_spec_group(&run->spec, g));
                sep = " ";
            }
        snprintf(label + len, sizeof label - (size_t)len, "%s%s%s): ", run->label[0] ? sep : "",
                 run->label[0] ? "variant " : "", run->label);
    }
    st = gf_groups_map_apply(ctx, &run->spec);
    const char *bad_key = NULL;
    if (st == GF_OK && (st = gf_scene_resolve_params_at(ctx, &run->spec, &bad_key)) != GF_OK && bad_key)
        at = scene_key_node(L, variant, bad_key, at);
    if (st == GF_OK)
        st = gf_groups_map_realised(ctx, &run->spec, &run->scales);
    if (st == GF_OK && (st = gf_run_spec_check_time_step(ctx, &run->spec)) != GF_OK) {
        /* the engine's own refusal, located at the key that sets the step when the file has it */
        const gf_cfg_node *contact = gf_cfg_get(L->root, "contact");
        const gf_cfg_node *key = contact ? gf_cfg_get(contact, "dt_over_tc") : NULL;
        at = key ? key : contact ? contact : at;
    }
    if (st == GF_OK && (st = gf_run_spec_check_method(ctx, &run->spec)) != GF_OK) {
        /* located at the continuum: section when it has one, else at method: */
        const gf_cfg_node *cont = gf_cfg_get(L->root, "continuum"), *method = gf_cfg_get(L->root, "method");
        const gf_cfg_node *key = cont ? gf_cfg_get(cont, "mu_2") : NULL;
        at = (key && strstr(gf_ctx_message(ctx), "mu_2")) ? key : cont ? cont : method ? method : at;
    }
    if (st == GF_OK && strcmp(run->spec.fluid.model, "none") != 0 && strcmp(run->spec.fluid.model, "auto") != 0 &&
        (st = gf_coupling_check(ctx, &run->spec)) != GF_OK)
        at = key_named_by(L, gf_ctx_message(ctx), at); /* the coupling tier's refusal, at the key it names */
    if (st != GF_OK) {
        char msg[512];
        snprintf(msg, sizeof msg, "%s", gf_ctx_message(ctx));
        return gf_cfg_fail(ctx, st, L->doc, at, 0, "%s%s", label, msg);
    }
    gf_spec_set_run_id(&run->spec);
    return GF_OK;
}

/* A scene parameter that a group replaces (the scene's table says "the
 * campaign's ... wins") is ignored in every run that sets the group: said
 * once, at the key, so that --set scene.aspect_ratio=2 on a grid over a does
 * not pass unnoticed. */
static void warn_overridden_scene_keys(const loader *L, const gf_campaign *c)
{
    static const struct {
        int group;
        const char *key;
    } pairs[] = {{2, "aspect_ratio"}, {3, "phi_target"}};
    const gf_cfg_node *scene = gf_cfg_get(L->root, "scene");
    for (size_t k = 0; scene && k < sizeof pairs / sizeof *pairs; ++k) {
        const gf_cfg_node *node = gf_cfg_get(scene, pairs[k].key);
        int n_set = 0;
        for (int i = 0; node && i < c->n_runs; ++i)
            n_set += !isnan(*gf_spec_group(&c->runs[i].spec, pairs[k].group));
        if (!n_set)
            continue;
        char where[512];
        const char *g = gf_group_names[pairs[k].group];
        gf_log(L->ctx, GF_LOG_WARN,
               "%s: warning: scene.%s is overridden by the group %s that %d of the %d runs set (grid, groups or "
               "variant): set grid.%s or groups.%s instead",
               gf_cfg_where(L->doc, node, 1, where, sizeof where), pairs[k].key, g, n_set, c->n_runs, g, g);
    }
}

static int by_run_id(const void *a, const void *b)
{
    const gf_campaign_run *const *x = a, *const *y = b;
    int d = strcmp((*x)->spec.run_id, (*y)->spec.run_id);
    return d ? d : (*x)->index - (*y)->index;
}

static gf_status check_unique(loader *L, const gf_campaign *c)
{
    const gf_campaign_run **sorted = malloc((size_t)c->n_runs * sizeof *sorted);
    if (!sorted)
        return GF_FAIL(L->ctx, GF_ERR_NOMEM, "out of memory");
    for (int i = 0; i < c->n_runs; ++i)
        sorted[i] = &c->runs[i];
    qsort(sorted, (size_t)c->n_runs, sizeof *sorted, by_run_id);
    gf_status st = GF_OK;
    for (int i = 1; i < c->n_runs && st == GF_OK; ++i)
        if (strcmp(sorted[i]->spec.run_id, sorted[i - 1]->spec.run_id) == 0)
            st = gf_cfg_fail(L->ctx, GF_ERR_CONFIG, L->doc, L->grid.node ? L->grid.node : L->variants, 0,
                             "runs %d and %d resolve to the same spec (run id %s): repeated grid values?",
                             sorted[i - 1]->index, sorted[i]->index, sorted[i]->spec.run_id);
    free(sorted);
    return st;
}

static gf_status load(loader *L, const char *path, const char *const *sets, int n_sets, gf_campaign **out)
{
    gf_ctx *ctx = L->ctx;
    if (!L->doc->root)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, L->doc, NULL, 0, "empty configuration (expected scene:, grains:, ...)");
    if (L->doc->root->kind != GF_CFG_MAP)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, L->doc, L->doc->root, 0,
                           "a configuration is a mapping of sections (scene:, grains:, ...), not %s",
                           L->doc->root->kind == GF_CFG_SEQ ? "a list" : "a single value");
    L->root = gf_cfg_clone(L->doc->root);
    if (!L->root)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "out of memory");
    GF_TRY(normalise_scene(L, L->root));
    GF_TRY(apply_sets(L, sets, n_sets));
    GF_TRY(gf_grid_read(ctx, L->doc, gf_cfg_get(L->root, "grid"), &L->grid));
    GF_TRY(check_grid_vs_groups(L));
    L->variants = gf_cfg_get(L->root, "variants");
    int n_variants = 1;
    if (L->variants) {
        GF_TRY(gf_cfg_expect(ctx, L->doc, L->variants, GF_CFG_SEQ));
        if (L->variants->n_items == 0)
            return gf_cfg_fail(ctx, GF_ERR_CONFIG, L->doc, L->variants, 0, "variants: empty list");
        for (int i = 0; i < L->variants->n_items; ++i)
            GF_TRY(gf_cfg_expect(ctx, L->doc, L->variants->items[i], GF_CFG_MAP));
        n_variants = L->variants->n_items;
    }
    if ((double)n_variants * L->grid.n_points > GF_GRID_MAX_POINTS)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, L->doc, L->variants, 0, "more than %d runs", GF_GRID_MAX_POINTS);

    gf_campaign *c = calloc(1, sizeof *c);
    if (!c)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "out of memory");
    c->n_points = L->grid.n_points;
    c->n_variants = n_variants;
    c->n_runs = n_variants * L->grid.n_points;
    c->runs = calloc((size_t)c->n_runs, sizeof *c->runs);
    c->source_path = malloc(strlen(path) + 1);
    gf_status st = c->runs && c->source_path ? GF_OK : GF_FAIL(ctx, GF_ERR_NOMEM, "out of memory");
    if (st == GF_OK) {
        strcpy(c->source_path, path);
        st = read_name(L, path, c->name, sizeof c->name);
    }
    for (int v = 0; v < n_variants && st == GF_OK; ++v)
        for (int k = 0; k < L->grid.n_points && st == GF_OK; ++k) {
            const int index = v * L->grid.n_points + k;
            st = build_run(L, v, k, index, &c->runs[index]);
        }
    if (st == GF_OK)
        warn_overridden_scene_keys(L, c);
    /* Two grid points that resolve to the same run would share a directory. */
    if (st == GF_OK)
        st = check_unique(L, c);
    if (st != GF_OK) {
        gf_campaign_destroy(&c);
        return st;
    }
    *out = c;
    return GF_OK;
}

gf_status gf_campaign_load_string(gf_ctx *ctx, const char *name, const char *text, size_t len,
                                  const char *const *sets, int n_sets, gf_campaign **out)
{
    *out = NULL;
    loader L = {.ctx = ctx};
    gf_status st = gf_cfg_parse_string(ctx, name, text, len, &L.doc);
    if (st == GF_OK)
        st = load(&L, name, sets, n_sets, out);
    loader_free(&L);
    return st;
}

gf_status gf_campaign_load_file(gf_ctx *ctx, const char *path, const char *const *sets, int n_sets,
                                gf_campaign **out)
{
    *out = NULL;
    loader L = {.ctx = ctx};
    gf_status st = gf_cfg_parse_file(ctx, path, &L.doc);
    if (st == GF_OK)
        st = load(&L, path, sets, n_sets, out);
    loader_free(&L);
    return st;
}

void gf_campaign_destroy(gf_campaign **c)
{
    if (!c || !*c)
        return;
    free((*c)->runs);
    free((*c)->source_path);
    free(*c);
    *c = NULL;
}

int gf_campaign_find(const gf_campaign *c, const char *run_id)
{
    for (int i = 0; i < c->n_runs; ++i)
        if (strcmp(c->runs[i].spec.run_id, run_id) == 0)
            return i;
    return -1;
}
