/* The checkpoint file of one simulation; see gf_checkpoint.h. */
#include "io/gf_checkpoint.h"

#include <stdlib.h>
#include <string.h>

#include "io/gf_restart.h"

#define GF_CK_F64_FIELDS(X)                                                                                     \
    X(x_m) X(y_m) X(z_m) X(vx_m_s) X(vy_m_s) X(vz_m_s) X(wx_rad_s) X(wy_rad_s) X(wz_rad_s) X(fx_N) X(fy_N)    \
    X(fz_N) X(tx_N_m) X(ty_N_m) X(tz_N_m) X(radius_m) X(mass_kg) X(inertia_kg_m2)

/* The per-grain arrays of doubles, in file order: the store's fields, the
 * reference positions, the wall history. */
#define GF_CK_N_ARRAYS 22
typedef struct grain_array {
    const char *name;
    double *v;
    size_t len;
} grain_array;

static void grain_arrays(const gf_checkpoint_view *v, grain_array a[GF_CK_N_ARRAYS])
{
    gf_particles *p = v->p;
    const size_t n = p->n_local;
    int k = 0;
#define GF_CK_ARRAY(f) a[k++] = (grain_array){#f, p->f, n};
    GF_CK_F64_FIELDS(GF_CK_ARRAY)
#undef GF_CK_ARRAY
    a[k++] = (grain_array){"x_ref", v->ref_m[0], n};
    a[k++] = (grain_array){"y_ref", v->ref_m[1], n};
    a[k++] = (grain_array){"z_ref", v->ref_m[2], n};
    a[k++] = (grain_array){"wall_history", v->wall_hist, 3 * n * (size_t)(v->n_walls + 1)};
}

/* The grains' datasets (ids, flags, the arrays above), written (writing)
 * or read back, in one order. */
static gf_status grain_datasets(gf_restart *r, const gf_checkpoint_view *v, int writing)
{
    gf_particles *p = v->p;
    const size_t n = p->n_local;
    GF_TRY(writing ? gf_restart_put_i64(r, "id", n, p->id) : gf_restart_get_i64(r, "id", n, p->id));
    GF_TRY(writing ? gf_restart_put_u8(r, "flags", n, p->flags) : gf_restart_get_u8(r, "flags", n, p->flags));
    grain_array a[GF_CK_N_ARRAYS];
    grain_arrays(v, a);
    for (int k = 0; k < GF_CK_N_ARRAYS; ++k)
        GF_TRY(writing ? gf_restart_put_f64(r, a[k].name, a[k].len, a[k].v)
                       : gf_restart_get_f64(r, a[k].name, a[k].len, a[k].v));
    return GF_OK;
}

static gf_status write_walls(gf_restart *r, const gf_checkpoint_view *v)
{
    uint8_t active[GF_CHECKPOINT_MAX_WALLS];
    double wall_force[3 * GF_CHECKPOINT_MAX_WALLS];
    for (int w = 0; w < v->n_walls; ++w) {
        active[w] = (uint8_t)*v->wall_active[w];
        memcpy(&wall_force[3 * w], v->wall_force_N[w], 3 * sizeof(double));
    }
    GF_TRY(gf_restart_put_u8(r, "wall_active", (size_t)v->n_walls, active));
    return gf_restart_put_f64(r, "wall_force", 3 * (size_t)v->n_walls, wall_force);
}

static gf_status write_all(gf_restart *r, const gf_checkpoint_view *v, const gf_coupling *coupling,
                           long next_fluid_step, int n_substeps)
{
    const gf_particles *p = v->p;
    const size_t n = p->n_local;
    int64_t counts[3] = {(int64_t)n, *v->step, p->next_id};
    double clock[5] = {*v->t_s, *v->dt_s, *v->t_end_s, *v->max_overlap_m, (double)*v->n_contacts};
    GF_TRY(gf_restart_put_i64(r, "counts", 3, counts));
    GF_TRY(gf_restart_put_f64(r, "clock", 5, clock));
    GF_TRY(gf_restart_put_u64(r, "rng", 4, v->rng_s));
    GF_TRY(gf_restart_put_f64(r, "gravity", 3, v->gravity_m_s2));
    GF_TRY(gf_restart_put_i64(r, "sort_state", 1, (const int64_t[1]){*v->n_rebuilds}));
    GF_TRY(gf_restart_put_i64(r, "sort_layout", 1, (const int64_t[1]){*v->store_layout}));
    GF_TRY(gf_restart_put_f64(r, "scene_counters", (size_t)v->n_scene_counters, v->scene_counters));
    GF_TRY(write_walls(r, v));
    GF_TRY(grain_datasets(r, v, 1));
    GF_TRY(gf_restart_put_i64(r, "contact_ids", 2 * v->n_pairs, v->pair_ids));
    GF_TRY(gf_restart_put_f64(r, "contact_history", 3 * v->n_pairs, v->pair_hist));
    GF_TRY(gf_restart_put_u8(r, "contact_images", v->n_pairs, v->pair_image));
    if (!coupling)
        return GF_OK;
    GF_TRY(gf_restart_put_i64(r, "fluid_schedule", 2, (const int64_t[2]){next_fluid_step, n_substeps}));
    return gf_coupling_save(coupling, r);
}

gf_status gf_checkpoint_write(gf_ctx *ctx, const char *path, const gf_checkpoint_view *v, const gf_coupling *coupling,
                              long next_fluid_step, int n_substeps)
{
    gf_restart *r = NULL;
    GF_TRY(gf_restart_create(ctx, path, &r));
    gf_status st = write_all(r, v, coupling, next_fluid_step, n_substeps);
    if (st != GF_OK) {
        gf_restart_abort(&r); /* the previous checkpoint stays */
        return st;
    }
    return gf_restart_close(&r);
}

/* The optional datasets of older checkpoints: the sort schedule (absent: the
 * next rebuild sorts), the layout, the scene counters (scenes that keep none). */
static gf_status read_optional(gf_restart *r, gf_checkpoint_view *v)
{
    int64_t sort_state = 0, layout = -1;
    if (gf_restart_has(r, "sort_state"))
        GF_TRY(gf_restart_get_i64(r, "sort_state", 1, &sort_state));
    *v->n_rebuilds = (long)sort_state;
    v->layout_saved = gf_restart_has(r, "sort_layout");
    if (v->layout_saved) {
        GF_TRY(gf_restart_get_i64(r, "sort_layout", 1, &layout));
        *v->store_layout = (int)layout;
    }
    if (gf_restart_has(r, "scene_counters"))
        GF_TRY(gf_restart_get_f64(r, "scene_counters", (size_t)v->n_scene_counters, v->scene_counters));
    return GF_OK;
}

static gf_status read_walls(gf_ctx *ctx, gf_restart *r, gf_checkpoint_view *v)
{
    size_t nw = 0;
    GF_TRY(gf_restart_len(r, "wall_active", &nw));
    if (nw != (size_t)v->n_walls)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "restart: checkpoint has %zu walls, scene %s builds %d", nw, v->scene,
                       v->n_walls);
    uint8_t active[GF_CHECKPOINT_MAX_WALLS];
    double wall_force[3 * GF_CHECKPOINT_MAX_WALLS];
    GF_TRY(gf_restart_get_u8(r, "wall_active", nw, active));
    GF_TRY(gf_restart_get_f64(r, "wall_force", 3 * nw, wall_force));
    for (int w = 0; w < v->n_walls; ++w) {
        *v->wall_active[w] = active[w];
        memcpy(v->wall_force_N[w], &wall_force[3 * w], 3 * sizeof(double));
    }
    return GF_OK;
}

static gf_status read_pairs(gf_ctx *ctx, gf_restart *r, gf_checkpoint_view *v)
{
    size_t m2 = 0;
    GF_TRY(gf_restart_len(r, "contact_ids", &m2));
    const size_t m = m2 / 2;
    v->pair_ids = malloc((2 * m + 1) * sizeof(int64_t));
    v->pair_hist = malloc((3 * m + 1) * sizeof(double));
    v->n_pairs = m;
    if (!v->pair_ids || !v->pair_hist)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "restart: cannot allocate contacts");
    GF_TRY(gf_restart_get_i64(r, "contact_ids", 2 * m, v->pair_ids));
    GF_TRY(gf_restart_get_f64(r, "contact_history", 3 * m, v->pair_hist));
    if (!gf_restart_has(r, "contact_images")) /* written before pairs could have two images */
        return GF_OK;
    v->pair_image = malloc(m + 1);
    if (!v->pair_image)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "restart: cannot allocate contact images");
    return gf_restart_get_u8(r, "contact_images", m, v->pair_image);
}

static gf_status read_all(gf_ctx *ctx, gf_restart *r, gf_checkpoint_view *v, double *dt_saved, double *t_end_saved)
{
    gf_particles *p = v->p;
    int64_t counts[3];
    double clock[5];
    GF_TRY(gf_restart_get_i64(r, "counts", 3, counts));
    if ((size_t)counts[0] != p->n_local)
        return GF_FAIL(ctx, GF_ERR_CONFIG,
                       "restart: checkpoint holds %lld grains but scene %s builds %zu (different spec?)",
                       (long long)counts[0], v->scene, p->n_local);
    GF_TRY(gf_restart_get_f64(r, "clock", 5, clock));
    GF_TRY(gf_restart_get_u64(r, "rng", 4, v->rng_s));
    GF_TRY(gf_restart_get_f64(r, "gravity", 3, v->gravity_m_s2));
    GF_TRY(read_optional(r, v));
    GF_TRY(read_walls(ctx, r, v));
    GF_TRY(grain_datasets(r, v, 0));
    p->next_id = counts[2];
    *v->step = counts[1];
    *v->t_s = clock[0], *v->max_overlap_m = clock[3], *v->n_contacts = (size_t)clock[4];
    *dt_saved = clock[1], *t_end_saved = clock[2];
    return read_pairs(ctx, r, v);
}

gf_status gf_checkpoint_read(gf_ctx *ctx, const char *path, gf_checkpoint_view *v, double *dt_saved_s,
                             double *t_end_saved_s)
{
    gf_restart *r = NULL;
    v->pair_ids = NULL, v->pair_hist = NULL, v->pair_image = NULL, v->n_pairs = 0;
    GF_TRY(gf_restart_open(ctx, path, &r));
    gf_status st = read_all(ctx, r, v, dt_saved_s, t_end_saved_s);
    gf_restart_close(&r);
    return st;
}

gf_status gf_checkpoint_read_coupling(gf_ctx *ctx, const char *path, gf_coupling *coupling, long *next_fluid_step,
                                      int *n_substeps)
{
    gf_restart *r = NULL;
    GF_TRY(gf_restart_open(ctx, path, &r));
    int64_t schedule[2] = {0, 0};
    gf_status st = gf_coupling_load(coupling, r); /* refuses a checkpoint without fluid */
    if (st == GF_OK)
        st = gf_restart_get_i64(r, "fluid_schedule", 2, schedule);
    gf_restart_close(&r);
    GF_TRY(st);
    *next_fluid_step = (long)schedule[0];
    *n_substeps = (int)schedule[1];
    return GF_OK;
}
