/* Run labels for figure legends; see gf_post_label.h. */
#include "stages/gf_post_label.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const group_names[] = {"St", "r", "a", "Phi_i"};
enum { N_GROUPS = sizeof group_names / sizeof group_names[0] };

static int is_dry(const gf_post_row *w) { return w->fluid_model[0] == '\0' || strcmp(w->fluid_model, "none") == 0; }

static int several_tiers(const gf_post_row *rows, int n)
{
    const char *first = NULL;
    for (int i = 0; i < n; ++i) {
        if (is_dry(&rows[i]))
            continue;
        if (first && strcmp(first, rows[i].fluid_model) != 0)
            return 1;
        first = rows[i].fluid_model;
    }
    return 0;
}

static void variant_name(const gf_post_row *w, int tiers, char *out, size_t len)
{
    if (is_dry(w))
        snprintf(out, len, "dry");
    else if (tiers)
        snprintf(out, len, "immersed (%s)", w->fluid_model);
    else
        snprintf(out, len, "immersed");
}

void gf_post_run_variants(const gf_post_row *rows, int n, int *variant, gf_post_variants *out)
{
    out->n = 0;
    int tiers = several_tiers(rows, n);
    for (int i = 0; i < n; ++i) {
        char name[GF_POST_LABEL_LEN];
        variant_name(&rows[i], tiers, name, sizeof name);
        int v = 0;
        while (v < out->n && strcmp(out->names[v], name) != 0)
            ++v;
        if (v == out->n && out->n < GF_POST_MAX_VARIANTS)
            snprintf(out->names[out->n++], GF_POST_LABEL_LEN, "%s", name);
        variant[i] = v < out->n ? v : out->n - 1;   /* past the last slot: shares the last one */
    }
}

/* Does group g take two different finite values across the rows? */
static int group_varies(const gf_post_row *rows, int n, const char *g)
{
    double first = NAN;
    for (int i = 0; i < n; ++i) {
        double v = gf_post_row_get(&rows[i], g);
        if (!isfinite(v))
            continue;
        if (isfinite(first) && v != first)
            return 1;
        first = v;
    }
    return 0;
}

void gf_post_run_labels(const gf_post_row *rows, int n, char (*labels)[GF_POST_LABEL_LEN])
{
    int tiers = several_tiers(rows, n), with_variant = 0, with_group[N_GROUPS];
    for (int i = 1; i < n; ++i)
        with_variant |= is_dry(&rows[i]) != is_dry(&rows[0]);
    with_variant |= tiers;
    for (int g = 0; g < N_GROUPS; ++g)
        with_group[g] = n == 1 || group_varies(rows, n, group_names[g]);
    for (int i = 0; i < n; ++i) {
        char *out = labels[i];
        size_t len = 0;
        out[0] = '\0';
        if (with_variant)
            variant_name(&rows[i], tiers, out, GF_POST_LABEL_LEN);
        len = strlen(out);
        for (int g = 0; g < N_GROUPS && len < GF_POST_LABEL_LEN; ++g) {
            double v = gf_post_row_get(&rows[i], group_names[g]);
            if (with_group[g] && isfinite(v))
                len += (size_t)snprintf(out + len, GF_POST_LABEL_LEN - len, "%s%s=%g", len ? ", " : "",
                                        group_names[g], v);
        }
        if (len == 0)
            snprintf(out, GF_POST_LABEL_LEN, "%s", rows[i].run_id);
    }
    /* a label shared by two runs (seeds, or variants this cannot tell apart): add the run ids */
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            if (strcmp(labels[i], labels[j]) == 0) {
                for (int k = 0; k < n; ++k)
                    if (k != i && strcmp(labels[k], labels[i]) == 0) {
                        size_t l = strlen(labels[k]);
                        snprintf(labels[k] + l, GF_POST_LABEL_LEN - l, " [%s]", rows[k].run_id);
                    }
                size_t l = strlen(labels[i]);
                snprintf(labels[i] + l, GF_POST_LABEL_LEN - l, " [%s]", rows[i].run_id);
            }
}
