/* Canonical spec text and run id; see gf_spec_text.h. */
#include "campaign/gf_spec_text.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "campaign/gf_spec_schema.h"

typedef struct out_buf {
    char *p;
    size_t n, len;
} out_buf;

static void put(out_buf *o, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void put(out_buf *o, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int k = vsnprintf(o->p + o->len, o->len < o->n ? o->n - o->len : 0, fmt, ap);
    va_end(ap);
    if (k > 0)
        o->len += (size_t)k;
    if (o->len >= o->n && o->n > 0)
        o->len = o->n - 1; /* truncated; callers size with GF_SPEC_TEXT_MAX */
}

static int by_key(const void *a, const void *b)
{
    return strcmp(((const gf_param *)a)->key, ((const gf_param *)b)->key);
}

size_t gf_spec_text(const gf_run_spec *spec, char *buf, size_t n)
{
    out_buf o = {.p = buf, .n = n, .len = 0};
    if (n)
        buf[0] = '\0';
    int nf;
    const gf_spec_field *f = gf_spec_fields(&nf);
    char value[64];
    for (int i = 0; i < nf; ++i)
        if (!f[i].section[0]) {
            /* method: dem is left out, so the run ids written before it existed do not change */
            if (strcmp(f[i].key, "method") == 0 && strcmp(spec->method, "dem") == 0)
                continue;
            gf_spec_field_format(&f[i], spec, value, sizeof value);
            put(&o, "%s: %s\n", f[i].key, value);
        }
    put(&o, "scene:\n  name: %s\n", spec->scene);
    gf_param params[GF_MAX_SCENE_PARAMS];
    int np = spec->n_scene_params < GF_MAX_SCENE_PARAMS ? spec->n_scene_params : GF_MAX_SCENE_PARAMS;
    memcpy(params, spec->scene_params, (size_t)np * sizeof *params);
    qsort(params, (size_t)np, sizeof *params, by_key);
    for (int i = 0; i < np; ++i)
        put(&o, "  %s: %.17g\n", params[i].key, params[i].value);
    const char *sections[] = {"grains", "contact", "fluid", "output", "continuum"};
    int n_sections = strcmp(spec->method, "continuum") == 0 ? 5 : 4; /* the continuum's keys only when it runs */
    for (int s = 0; s < n_sections; ++s) {
        put(&o, "%s:\n", sections[s]);
        for (int i = 0; i < nf; ++i)
            if (strcmp(f[i].section, sections[s]) == 0) {
                /* an off sleep knob is left out, so the run ids of specs written
                 * before it existed do not change */
                if (strcmp(f[i].key, "sleep_speed_nd") == 0 && spec->contact.sleep_speed_nd == 0.0)
                    continue;
                if (strcmp(f[i].key, "overlap_target_over_D") == 0 && spec->contact.overlap_target_over_D == 0.0)
                    continue;
                if (strcmp(f[i].key, "d_over_dx") == 0 && spec->fluid.d_over_dx == 0.0)
                    continue;
                if (strcmp(f[i].key, "lub_overlap") == 0 && strcmp(spec->fluid.lub_overlap, "clamp") == 0)
                    continue;
                if (strcmp(f[i].key, "ibm_retraction_dx") == 0 && spec->fluid.ibm_retraction_dx == 0.0)
                    continue;
                if (strcmp(f[i].key, "diffusion_number") == 0 && spec->fluid.diffusion_number == 0.5)
                    continue;
                if (strcmp(f[i].key, "ibm_forcing") == 0 && strcmp(spec->fluid.ibm_forcing, "smoothed") == 0)
                    continue;
                /* written for every resolved run, so that those made before it existed (without the
                 * correction) do not pass for runs with it */
                if (strcmp(f[i].key, "ibm_contact_correction") == 0 && strcmp(spec->fluid.model, "resolved") != 0)
                    continue;
                /* the resolved tier's numerics only where it runs: its runs before the keys existed used
                 * another advection form, so their ids change with them, and no other run's does */
                if ((strcmp(f[i].key, "time_scheme") == 0 || strcmp(f[i].key, "advection") == 0) &&
                    strcmp(spec->fluid.model, "resolved") != 0)
                    continue;
                gf_spec_field_format(&f[i], spec, value, sizeof value);
                put(&o, "  %s: %s\n", f[i].key, value);
            }
    }
    int any = 0;
    for (int g = 0; g < 4; ++g) {
        double v = *gf_spec_group((gf_run_spec *)spec, g);
        if (!isnan(v)) {
            if (!any++)
                put(&o, "groups:\n");
            put(&o, "  %s: %.17g\n", gf_group_names[g], v);
        }
    }
    return o.len;
}

uint64_t gf_fnv1a64(const void *data, size_t n)
{
    const unsigned char *p = data;
    uint64_t h = 14695981039346656037ull; /* FNV offset basis */
    for (size_t i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 1099511628211ull; /* FNV prime */
    }
    return h;
}

void gf_spec_set_run_id(gf_run_spec *spec)
{
    char text[GF_SPEC_TEXT_MAX];
    size_t len = gf_spec_text(spec, text, sizeof text);
    uint64_t h = gf_fnv1a64(text, len);
    snprintf(spec->run_id, sizeof spec->run_id, "%012llx", (unsigned long long)(h >> 16));
}
