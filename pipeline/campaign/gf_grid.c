/* Campaign grid expansion; see gf_grid.h. */
#include "campaign/gf_grid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "campaign/gf_spec_schema.h"

static gf_status check_value(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, int g, double v)
{
    const char *why;
    if (!gf_group_value_ok(g, v, &why))
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s = %g: %s", gf_group_names[g], v, why);
    return GF_OK;
}

static gf_status read_range(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, int g, gf_grid_axis *ax)
{
    static const char *const keys[] = {"from", "to", "num", "scale", NULL};
    static const char *const scales[] = {"lin", "log", NULL};
    for (int i = 0; i < node->n_items; ++i) {
        int ok = 0;
        for (const char *const *k = keys; *k; ++k)
            ok |= strcmp(*k, node->items[i]->key) == 0;
        if (!ok)
            return gf_cfg_fail_unknown_key(ctx, doc, node->items[i], "a grid range", keys);
    }
    const gf_cfg_node *from = gf_cfg_get(node, "from"), *to = gf_cfg_get(node, "to"), *num = gf_cfg_get(node, "num");
    const gf_cfg_node *scale = gf_cfg_get(node, "scale");
    if (!from || !to || !num)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: a range needs from, to and num", gf_group_names[g]);
    double a, b, nd;
    GF_TRY(gf_cfg_to_double(ctx, doc, from, -INFINITY, INFINITY, &a));
    GF_TRY(gf_cfg_to_double(ctx, doc, to, -INFINITY, INFINITY, &b));
    GF_TRY(gf_cfg_to_double(ctx, doc, num, 1, GF_GRID_MAX_POINTS, &nd));
    if (nd != floor(nd))
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, num, 0, "num = %g: expected a whole number", nd);
    GF_TRY(check_value(ctx, doc, from, g, a));
    GF_TRY(check_value(ctx, doc, to, g, b));
    char sc[8] = "lin";
    if (scale)
        GF_TRY(gf_cfg_to_name(ctx, doc, scale, scales, sc, sizeof sc));
    const int log_scale = strcmp(sc, "log") == 0, n = (int)nd;
    ax->values = malloc((size_t)n * sizeof *ax->values);
    if (!ax->values)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "grid: out of memory");
    ax->n = n;
    for (int k = 0; k < n; ++k) {
        double t = n > 1 ? (double)k / (n - 1) : 0.0;
        ax->values[k] = log_scale ? a * pow(b / a, t) : a + (b - a) * t;
    }
    if (n > 1)
        ax->values[n - 1] = b; /* exact end point, whatever pow's rounding */
    return GF_OK;
}

static gf_status read_axis(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, int g, gf_grid_axis *ax)
{
    ax->node = node;
    if (node->kind == GF_CFG_MAP)
        return read_range(ctx, doc, node, g, ax);
    int n = node->kind == GF_CFG_SEQ ? node->n_items : 1;
    if (n == 0)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: empty list", gf_group_names[g]);
    ax->values = malloc((size_t)n * sizeof *ax->values);
    if (!ax->values)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "grid: out of memory");
    ax->n = n;
    for (int k = 0; k < n; ++k) {
        const gf_cfg_node *item = node->kind == GF_CFG_SEQ ? node->items[k] : node;
        GF_TRY(gf_cfg_to_double(ctx, doc, item, -INFINITY, INFINITY, &ax->values[k]));
        GF_TRY(check_value(ctx, doc, item, g, ax->values[k]));
    }
    return GF_OK;
}

gf_status gf_grid_read(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, gf_grid *grid)
{
    memset(grid, 0, sizeof *grid);
    grid->n_points = 1;
    grid->node = node;
    if (!node)
        return GF_OK;
    GF_TRY(gf_cfg_expect(ctx, doc, node, GF_CFG_MAP));
    static const char *const keys[] = {"St", "r", "a", "Phi_i", "combine", NULL};
    static const char *const combines[] = {"product", "zip", NULL};
    for (int i = 0; i < node->n_items; ++i) {
        const gf_cfg_node *item = node->items[i];
        const int g = gf_group_index(item->key);
        if (g >= 0) {
            GF_TRY(read_axis(ctx, doc, item, g, &grid->axes[g]));
        } else if (strcmp(item->key, "combine") == 0) {
            char c[16];
            GF_TRY(gf_cfg_to_name(ctx, doc, item, combines, c, sizeof c));
            grid->zip = strcmp(c, "zip") == 0;
        } else {
            return gf_cfg_fail_unknown_key(ctx, doc, item, "grid", keys);
        }
    }
    double count = 1.0;
    int zip_n = -1;
    for (int g = 0; g < 4; ++g) {
        const gf_grid_axis *ax = &grid->axes[g];
        if (!ax->n)
            continue;
        if (grid->zip) {
            if (zip_n >= 0 && ax->n != zip_n)
                return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, ax->node, 0,
                                   "combine: zip needs lists of equal length: %s has %d values, the previous %d",
                                   gf_group_names[g], ax->n, zip_n);
            zip_n = ax->n;
        } else {
            count *= ax->n;
        }
    }
    if (grid->zip)
        count = zip_n > 0 ? zip_n : 1;
    if (count > GF_GRID_MAX_POINTS)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "grid has %.0f points, more than %d", count,
                           GF_GRID_MAX_POINTS);
    grid->n_points = (int)count;
    return GF_OK;
}

void gf_grid_point(const gf_grid *grid, int k, double values[4])
{
    /* Product: mixed-radix digits of k, Phi_i fastest. */
    for (int g = 3; g >= 0; --g) {
        const gf_grid_axis *ax = &grid->axes[g];
        if (!ax->n) {
            values[g] = NAN;
            continue;
        }
        if (grid->zip) {
            values[g] = ax->values[k];
        } else {
            values[g] = ax->values[k % ax->n];
            k /= ax->n;
        }
    }
}

void gf_grid_free(gf_grid *grid)
{
    for (int g = 0; g < 4; ++g) {
        free(grid->axes[g].values);
        grid->axes[g].values = NULL;
        grid->axes[g].n = 0;
    }
}
