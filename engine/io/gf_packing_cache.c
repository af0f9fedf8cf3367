/* Deposits shared between the runs of a campaign; see gf_packing_cache.h. */
#include "io/gf_packing_cache.h"

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/gf_build_info.h"
#include "core/gf_timer.h"
#include "io/gf_restart.h"

enum { KEY_LEN = 2048, RESULT_LEN = 6 };

/* The spec as text: every field that changes the deposit, in a fixed order. */
static int key_text(const gf_packing_spec *sp, char *buf, size_t n)
{
    size_t n_obs = sp->obstacles ? sp->obstacles->n_local : 0;
    return snprintf(buf, n,
                    "grainflow %s (%s) packing protocol %d\n"
                    "lo %.17g %.17g %.17g\nhi %.17g %.17g %.17g\nperiodic %d %d %d\nwalls %d %d setback %.17g\n"
                    "phi_target %.17g mu_natural %.17g free_pour %d relax %.17g %.17g %.17g\n"
                    "tolerance %.17g max_iterations %d margin %.17g\n"
                    "radius %.17g polydispersity %.17g density %.17g gravity %.17g\n"
                    "mu_obstacles %.17g obstacles %zu seed %" PRIu64 "\n",
                    GF_VERSION, gf_build_revision(), GF_PACKING_PROTOCOL, sp->lo_m[0], sp->lo_m[1], sp->lo_m[2],
                    sp->hi_m[0], sp->hi_m[1], sp->hi_m[2], sp->periodic[0], sp->periodic[1], sp->periodic[2],
                    sp->walls_x, sp->walls_z, sp->wall_setback_m, sp->phi_target, sp->mu_natural, sp->free_pour,
                    sp->relax.mu, sp->relax.t_contact_s, sp->relax.restitution, sp->tolerance, sp->max_iterations,
                    sp->interior_margin_m, sp->psd.mean_radius_m, sp->psd.polydispersity, sp->density_kg_m3,
                    sp->gravity_m_s2, sp->mu_obstacles, n_obs, sp->seed);
}

static uint64_t fnv1a(uint64_t h, const void *data, size_t n)
{
    const unsigned char *b = data;
    for (size_t i = 0; i < n; ++i) {
        h ^= b[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

/* Obstacles as x, y, z, radius per grain (what the preparation reads of them). */
static double *obstacle_table(const gf_particles *o, size_t *n)
{
    *n = o ? 4 * o->n_local : 0;
    double *t = malloc((*n ? *n : 1) * sizeof *t);
    for (size_t i = 0; t && o && i < o->n_local; ++i) {
        t[4 * i] = o->x_m[i], t[4 * i + 1] = o->y_m[i], t[4 * i + 2] = o->z_m[i], t[4 * i + 3] = o->radius_m[i];
    }
    return t;
}

static gf_status read_f64(gf_restart *r, const char *name, size_t *n, double **v)
{
    *v = NULL;
    GF_TRY(gf_restart_len(r, name, n));
    *v = malloc((*n ? *n : 1) * sizeof **v);
    return *v ? gf_restart_get_f64(r, name, *n, *v) : GF_ERR_NOMEM;
}

/* Reads the deposit at path when its key and obstacles match (*hit = 1). The
 * grains are appended to out only once the whole file has been read; the only
 * error returned is the store's (GF_ERR_NOMEM), anything wrong with the file
 * is a miss. */
static gf_status load(gf_ctx *ctx, const char *path, const char *key, const double *obs, size_t n_obs,
                      gf_particles *out, gf_packing_result *res, double density, int *hit_out)
{
    *hit_out = 0;
    if (access(path, R_OK) != 0)
        return GF_OK;
    gf_ctx quiet = {.log_level = GF_LOG_QUIET};
    gf_restart *r = NULL;
    size_t n_key = 0, n_o = 0, n_res = 0, n[4] = {0};
    unsigned char *k = NULL;
    double *o = NULL, *rv = NULL, *col[4] = {NULL};
    static const char *names[4] = {"x", "y", "z", "radius"};
    int hit = 0;
    gf_status st = gf_restart_open(&quiet, path, &r);
    if (st == GF_OK)
        st = gf_restart_len(r, "key", &n_key);
    if (st == GF_OK && n_key == strlen(key)) {
        k = malloc(n_key);
        st = k ? gf_restart_get_u8(r, "key", n_key, k) : GF_ERR_NOMEM;
        hit = st == GF_OK && memcmp(k, key, n_key) == 0;
    }
    if (hit)
        st = read_f64(r, "obstacles", &n_o, &o);
    hit = hit && st == GF_OK && n_o == n_obs && (n_obs == 0 || memcmp(o, obs, n_obs * sizeof *o) == 0);
    if (hit)
        st = read_f64(r, "result", &n_res, &rv);
    hit = hit && st == GF_OK && n_res == RESULT_LEN;
    for (int c = 0; hit && c < 4; ++c) {
        st = read_f64(r, names[c], &n[c], &col[c]);
        hit = st == GF_OK && n[c] == n[0];
    }
    gf_restart_close(&r);
    gf_status ret = GF_OK;
    if (hit) {
        size_t first = out->n_local;
        for (size_t i = 0; i < n[0] && ret == GF_OK; ++i)
            ret = gf_particles_add(ctx, out, col[0][i], col[1][i], col[2][i], col[3][i], density, 0, NULL);
        *res = (gf_packing_result){.phi_global = rv[0], .phi_local = rv[1], .mu_prep = rv[2],
                                   .iterations = (int)rv[3], .n_grains = out->n_local - first,
                                   .top_m = rv[4], .cpu_s = rv[5], .reused = 1};
        *hit_out = ret == GF_OK;
    } else if (st == GF_ERR_NOMEM) {
        ret = GF_FAIL(ctx, GF_ERR_NOMEM, "preparations: out of memory reading %s", path);
    } else if (st != GF_OK) {
        gf_log(ctx, GF_LOG_WARN, "preparations: %s is unreadable (%s); the deposit is built again", path,
               quiet.last_msg[0] ? quiet.last_msg : gf_status_str(st));
    }
    free(k), free(o), free(rv);
    for (int c = 0; c < 4; ++c)
        free(col[c]);
    return ret;
}

static gf_status store(gf_ctx *ctx, const char *path, const char *key, const double *obs, size_t n_obs,
                       const gf_particles *out, size_t first, const gf_packing_result *res)
{
    size_t n = out->n_local - first;
    double rv[RESULT_LEN] = {res->phi_global, res->phi_local, res->mu_prep, res->iterations, res->top_m, res->cpu_s};
    gf_restart *r = NULL;
    GF_TRY(gf_restart_create(ctx, path, &r)); /* written aside, renamed complete (io/gf_restart.h) */
    gf_status st = gf_restart_put_u8(r, "key", strlen(key), (const uint8_t *)key);
    if (st == GF_OK)
        st = gf_restart_put_f64(r, "obstacles", n_obs, obs);
    if (st == GF_OK)
        st = gf_restart_put_f64(r, "result", RESULT_LEN, rv);
    if (st == GF_OK)
        st = gf_restart_put_f64(r, "x", n, out->x_m + first);
    if (st == GF_OK)
        st = gf_restart_put_f64(r, "y", n, out->y_m + first);
    if (st == GF_OK)
        st = gf_restart_put_f64(r, "z", n, out->z_m + first);
    if (st == GF_OK)
        st = gf_restart_put_f64(r, "radius", n, out->radius_m + first);
    if (st != GF_OK) {
        gf_restart_abort(&r);
        return st;
    }
    return gf_restart_close(&r);
}

gf_status gf_packing_build_cached(gf_ctx *ctx, const gf_packing_spec *sp, const char *dir, gf_particles *out,
                                  gf_packing_result *res)
{
    if (!dir)
        return gf_packing_build(ctx, sp, out, res);
    char key[KEY_LEN];
    int len = key_text(sp, key, sizeof key);
    if (len < 0 || (size_t)len >= sizeof key)
        return gf_packing_build(ctx, sp, out, res);
    size_t n_obs = 0;
    double *obs = obstacle_table(sp->obstacles, &n_obs);
    if (!obs)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "preparations: cannot allocate %zu obstacle values", n_obs);
    uint64_t h = fnv1a(fnv1a(0xcbf29ce484222325ull, key, (size_t)len), obs, n_obs * sizeof *obs);
    char path[4200];
    snprintf(path, sizeof path, "%s/packing-%016" PRIx64 ".h5", dir, h);
    const double t0 = gf_wtime();
    int hit = 0;
    gf_status lst = load(ctx, path, key, obs, n_obs, out, res, sp->density_kg_m3, &hit);
    if (lst != GF_OK || hit) {
        free(obs);
        if (lst != GF_OK)
            return lst;
        gf_log(ctx, GF_LOG_INFO, "packing: deposit read from %s in %.2f s (built in %.1f s)", path,
               gf_wtime() - t0, res->cpu_s);
        return GF_OK;
    }
    size_t first = out->n_local;
    gf_status st = gf_packing_build(ctx, sp, out, res);
    if (st == GF_OK) {
        gf_ctx quiet = {.log_level = GF_LOG_QUIET};
        gf_status ws = mkdir(dir, 0777) == 0 || errno == EEXIST
                           ? store(&quiet, path, key, obs, n_obs, out, first, res)
                           : GF_FAIL(&quiet, GF_ERR_IO, "cannot create %s: %s", dir, strerror(errno));
        if (ws != GF_OK)
            gf_log(ctx, GF_LOG_WARN, "preparations: the deposit is not kept (%s)", quiet.last_msg);
    }
    free(obs);
    return st;
}
