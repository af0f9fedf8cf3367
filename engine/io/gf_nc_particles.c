/*
 * particles.nc: grain trajectories, CF featureType "trajectory" in the
 * orthogonal multidimensional representation (CF 1.10 §9.3.1, H.4.1): every
 * grain present at open is one trajectory, and x, y, z, u, v, w are
 * (trajectory, time) arrays. The representation fits because the grain
 * count of a run is fixed; a grain that leaves (or is absent from this
 * rank) is written as NaN, the variables' _FillValue.
 *
 * Grains are matched by their stable global id (gf_particles.h invariant),
 * not by their index, because the store reorders grains (sorting, removal).
 * The ids at open are sorted once; an append is a binary search per grain,
 * O(n log n), negligible against the DEM step.
 *
 * Chunking: one time record per chunk and up to 65536 grains across, so an
 * append writes whole chunks (no read-modify-write through the HDF5 chunk
 * cache, whatever the grain count) and reading one snapshot, what the
 * post-processing stages do, touches only that record's chunks. Shuffle +
 * deflate level 1 roughly halves positions that vary smoothly in space.
 */
#include <math.h>
#include <netcdf.h>
#include <stdlib.h>
#include <string.h>

#include "io/gf_nc_internal.h"

enum { CHUNK_GRAINS = 65536 };

static const gf_var_info pos_info[3] = {
    {"x", "m", "grain centre position along x (streamwise)", NULL},
    {"y", "m", "grain centre position along y (vertical, bed-normal)", NULL},
    {"z", "m", "grain centre position along z (spanwise)", NULL},
};
static const gf_var_info vel_info[3] = {
    {"u", "m s-1", "grain velocity along x", NULL},
    {"v", "m s-1", "grain velocity along y", NULL},
    {"w", "m s-1", "grain velocity along z", NULL},
};
static const gf_var_info id_info = {"trajectory_id", "1", "grain identifier (stable across reordering)", NULL};
static const gf_var_info radius_info = {"radius", "m", "grain radius", NULL};
static const gf_var_info glued_info = {"glued", "1", "fixed grain (rough bed or wall): 1, mobile: 0", NULL};

typedef struct id_slot {
    int64_t id;
    size_t slot;
} id_slot;

static int cmp_id_slot(const void *a, const void *b)
{
    int64_t x = ((const id_slot *)a)->id, y = ((const id_slot *)b)->id;
    return (x > y) - (x < y);
}

/* Sorted (id, trajectory index) table for the append lookup. Duplicate ids
 * break the store's invariant; they are refused rather than merged. */
static gf_status build_id_map(gf_nc_writer *w, const gf_particles *p)
{
    size_t n = w->n_traj;
    id_slot *tab = malloc(n * sizeof *tab);
    w->sorted_id = malloc(n * sizeof *w->sorted_id);
    w->sorted_slot = malloc(n * sizeof *w->sorted_slot);
    w->buf = malloc(6 * n * sizeof *w->buf);
    if (!tab || !w->sorted_id || !w->sorted_slot || !w->buf) {
        free(tab);
        return GF_FAIL(w->ctx, GF_ERR_NOMEM, "%s: out of memory for %zu grains", w->path, n);
    }
    for (size_t i = 0; i < n; ++i)
        tab[i] = (id_slot){p->id[i], i};
    qsort(tab, n, sizeof *tab, cmp_id_slot);
    for (size_t i = 0; i < n; ++i) {
        if (i > 0 && tab[i].id == tab[i - 1].id) {
            int64_t dup = tab[i].id;
            free(tab);
            return GF_FAIL(w->ctx, GF_ERR_ARG, "%s: grain id %lld appears twice", w->path, (long long)dup);
        }
        w->sorted_id[i] = tab[i].id;
        w->sorted_slot[i] = tab[i].slot;
    }
    free(tab);
    return GF_OK;
}

static gf_status define_particles(gf_nc_writer *w, int *dim_traj)
{
    GF_TRY(gf_nc_check(w, nc_def_dim(w->ncid, "trajectory", w->n_traj, dim_traj), "def_dim trajectory"));
    int var_id, var_radius, var_glued;
    GF_TRY(gf_nc_def_var(w, "trajectory_id", NC_INT64, 1, dim_traj, &id_info, &var_id));
    GF_TRY(gf_nc_check(w, nc_put_att_text(w->ncid, var_id, "cf_role", 13, "trajectory_id"), "cf_role"));
    GF_TRY(gf_nc_def_var(w, "radius", NC_DOUBLE, 1, dim_traj, &radius_info, &var_radius));
    GF_TRY(gf_nc_def_var(w, "glued", NC_BYTE, 1, dim_traj, &glued_info, &var_glued));
    signed char flags[2] = {0, 1};
    GF_TRY(gf_nc_check(w, nc_put_att_schar(w->ncid, var_glued, "flag_values", NC_BYTE, 2, flags), "flag_values"));
    GF_TRY(gf_nc_check(w, nc_put_att_text(w->ncid, var_glued, "flag_meanings", 12, "mobile fixed"),
                       "flag_meanings"));
    int dims[2] = {*dim_traj, w->dim_time};
    size_t chunks[2] = {w->n_traj < CHUNK_GRAINS ? w->n_traj : CHUNK_GRAINS, 1};
    static const char axes[3] = {'X', 'Y', 'Z'};
    for (int k = 0; k < 3; ++k) {
        GF_TRY(gf_nc_def_var(w, pos_info[k].name, NC_DOUBLE, 2, dims, &pos_info[k], &w->var_pos[k]));
        GF_TRY(gf_nc_check(w, nc_put_att_text(w->ncid, w->var_pos[k], "axis", 1, &axes[k]), "axis"));
        GF_TRY(gf_nc_compress(w, w->var_pos[k], chunks));
    }
    for (int k = 0; k < 3; ++k) {
        GF_TRY(gf_nc_def_var(w, vel_info[k].name, NC_DOUBLE, 2, dims, &vel_info[k], &w->var_vel[k]));
        GF_TRY(gf_nc_check(w, nc_put_att_text(w->ncid, w->var_vel[k], "coordinates", 10, "time z y x"),
                           "coordinates"));
        GF_TRY(gf_nc_compress(w, w->var_vel[k], chunks));
    }
    return gf_nc_end_def(w);
}

static gf_status put_static(gf_nc_writer *w, const gf_particles *p)
{
    size_t n = w->n_traj;
    int var_id, var_radius, var_glued;
    GF_TRY(gf_nc_check(w, nc_inq_varid(w->ncid, "trajectory_id", &var_id), "inq trajectory_id"));
    GF_TRY(gf_nc_check(w, nc_inq_varid(w->ncid, "radius", &var_radius), "inq radius"));
    GF_TRY(gf_nc_check(w, nc_inq_varid(w->ncid, "glued", &var_glued), "inq glued"));
    signed char *glued = malloc(n ? n : 1);
    if (!glued)
        return GF_FAIL(w->ctx, GF_ERR_NOMEM, "%s: out of memory", w->path);
    for (size_t i = 0; i < n; ++i)
        glued[i] = (p->flags[i] & GF_P_GLUED) ? 1 : 0;
    long long *ids = malloc(n * sizeof *ids);
    gf_status st = ids ? GF_OK : GF_FAIL(w->ctx, GF_ERR_NOMEM, "%s: out of memory", w->path);
    if (st == GF_OK) {
        for (size_t i = 0; i < n; ++i)
            ids[i] = p->id[i];
        st = gf_nc_check(w, nc_put_var_longlong(w->ncid, var_id, ids), "put trajectory_id");
    }
    if (st == GF_OK)
        st = gf_nc_check(w, nc_put_var_double(w->ncid, var_radius, p->radius_m), "put radius");
    if (st == GF_OK)
        st = gf_nc_check(w, nc_put_var_schar(w->ncid, var_glued, glued), "put glued");
    free(ids);
    free(glued);
    return st;
}

gf_status gf_nc_particles_reload_ids(gf_nc_writer *w)
{
    int var_id;
    size_t n = w->n_traj;
    GF_TRY(gf_nc_check(w, nc_inq_varid(w->ncid, "trajectory_id", &var_id), "inq trajectory_id"));
    long long *ids = malloc((n ? n : 1) * sizeof *ids);
    id_slot *tab = malloc((n ? n : 1) * sizeof *tab);
    gf_status st = ids && tab ? gf_nc_check(w, nc_get_var_longlong(w->ncid, var_id, ids), "read trajectory_id")
                              : GF_FAIL(w->ctx, GF_ERR_NOMEM, "%s: out of memory", w->path);
    for (size_t i = 0; st == GF_OK && i < n; ++i)
        tab[i] = (id_slot){(int64_t)ids[i], i};
    if (st == GF_OK) {
        qsort(tab, n, sizeof *tab, cmp_id_slot);
        for (size_t i = 0; i < n; ++i)
            w->sorted_id[i] = tab[i].id, w->sorted_slot[i] = tab[i].slot;
    }
    free(ids);
    free(tab);
    return st;
}

gf_status gf_nc_particles_open(gf_ctx *ctx, const char *path, const gf_nc_meta *meta, const gf_particles *p,
                               gf_nc_writer **out)
{
    *out = NULL;
    if (!p)
        return GF_FAIL(ctx, GF_ERR_ARG, "%s: NULL particle store", path ? path : "particles");
    if (p->n_local == 0)
        return GF_FAIL(ctx, GF_ERR_ARG, "%s: no grains to record (n_local = 0)", path ? path : "particles");
    gf_nc_writer *w;
    GF_TRY(gf_nc_begin(ctx, path, meta, GF_NC_PARTICLES, "trajectory", &w));
    w->n_traj = p->n_local;
    int dim_traj;
    gf_status st = build_id_map(w, p);
    if (st == GF_OK)
        st = define_particles(w, &dim_traj);
    if (st == GF_OK)
        st = put_static(w, p);
    return gf_nc_open_done(w, st, out);
}

static long find_slot(const gf_nc_writer *w, int64_t id)
{
    size_t lo = 0, hi = w->n_traj;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (w->sorted_id[mid] < id)
            lo = mid + 1;
        else
            hi = mid;
    }
    return (lo < w->n_traj && w->sorted_id[lo] == id) ? (long)w->sorted_slot[lo] : -1;
}

gf_status gf_nc_particles_append(gf_nc_writer *w, double t_s, const gf_particles *p)
{
    if (!w || w->kind != GF_NC_PARTICLES)
        return GF_FAIL(w ? w->ctx : NULL, GF_ERR_ARG, "particles append: not a particles writer");
    if (!p)
        return GF_FAIL(w->ctx, GF_ERR_ARG, "%s: NULL particle store", w->path);
    size_t n = w->n_traj;
    for (size_t i = 0; i < 6 * n; ++i)
        w->buf[i] = NAN;
    const double *src[6] = {p->x_m, p->y_m, p->z_m, p->vx_m_s, p->vy_m_s, p->vz_m_s};
    for (size_t ip = 0; ip < p->n_local; ++ip) {
        long slot = find_slot(w, p->id[ip]);
        if (slot < 0)
            return GF_FAIL(w->ctx, GF_ERR_ARG,
                           "%s: grain id %lld was not present at open (the trajectory count is fixed per run)",
                           w->path, (long long)p->id[ip]);
        for (int k = 0; k < 6; ++k)
            w->buf[(size_t)k * n + (size_t)slot] = src[k][ip];
    }
    GF_TRY(gf_nc_put_time(w, t_s));
    size_t start[2] = {0, w->n_records}, count[2] = {n, 1};
    for (int k = 0; k < 6; ++k) {
        int var = k < 3 ? w->var_pos[k] : w->var_vel[k - 3];
        GF_TRY(gf_nc_check(w, nc_put_vara_double(w->ncid, var, start, count, w->buf + (size_t)k * n),
                           "put trajectory record"));
    }
    w->n_records++;
    return GF_OK;
}
