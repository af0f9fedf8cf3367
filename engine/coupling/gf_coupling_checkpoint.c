/*
 * Checkpoint of the unresolved coupling (gf_coupling.h), so that an
 * interrupted immersed run continues where it stopped instead of from a
 * fluid at rest.
 *
 * What a fluid step reads from the previous one, and nothing else:
 *   - the face velocities u^n and the excess pressure p^n (the incremental
 *     pressure-correction step of gf_fluid.h starts from both);
 *   - the fluid fraction eps^n (the next step's eps_old, whose change drives
 *     the projection's source term);
 *   - what the last fluid step left on each grain for the DEM substeps: the
 *     drag coefficient, the fluid velocity and the pressure force at the
 *     grain, its fluid fraction (held_grain), keyed by grain id;
 *   - the output fields of that step (fields.nc, the flow rate and the mean
 *     fluid velocity read them between fluid steps), the automatic or imposed
 *     mean pressure gradient and the counters of gf_coupling_stats.
 * The Poisson solve starts from phi = 0 at every step and the kernels, beta
 * and the cell-centred velocities are rebuilt at the start of every step, so
 * they are not saved. The grid must be the one the spec builds (checked).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "coupling/gf_coupling_restart.h"
#include "coupling/gf_coupling_unresolved.h"

#define HELD_F64 9 /* K, uf[3], f_other[3], eps, mass */

static const char *const field_names[FLD_N] = {"field_eps", "field_u", "field_v", "field_w", "field_p"};
static const char *const face_names[3] = {"fluid_u", "fluid_v", "fluid_w"};

enum { GRID_ARRAYS = 3 + 2 + FLD_N };

/* The face velocities, excess pressure and fluid fraction, then the output fields, in the order they are
 * written. */
static void grid_arrays(const gf_unresolved *c, gf_restart_array list[GRID_ARRAYS])
{
    const gf_fluid *f = c->fluid;
    size_t n_cells = f->grid.n_cells;
    int n = 0;
    for (int a = 0; a < 3; ++a)
        list[n++] = (gf_restart_array){face_names[a], f->grid.n_faces[a], f->u[a]};
    list[n++] = (gf_restart_array){"fluid_p", n_cells, f->p_Pa};
    list[n++] = (gf_restart_array){"fluid_eps", n_cells, f->eps};
    for (int v = 0; v < FLD_N; ++v)
        list[n++] = (gf_restart_array){field_names[v], n_cells, c->fields[v]};
}

static void held_pack(const held_grain *h, double *v)
{
    v[0] = h->K_kg_s;
    memcpy(&v[1], h->uf, 3 * sizeof(double));
    memcpy(&v[4], h->f_other_N, 3 * sizeof(double));
    v[7] = h->eps, v[8] = h->mass_kg;
}

static void held_unpack(const double *v, held_grain *h)
{
    h->K_kg_s = v[0];
    memcpy(h->uf, &v[1], 3 * sizeof(double));
    memcpy(h->f_other_N, &v[4], 3 * sizeof(double));
    h->eps = v[7], h->mass_kg = v[8];
    h->phi1_x = NAN; /* evaluated again at the first substep */
}

static gf_status save_held(const gf_unresolved *c, gf_restart *r)
{
    size_t n = c->n_held;
    int64_t *id = malloc((n + 1) * sizeof *id);
    double *v = malloc((HELD_F64 * n + 1) * sizeof *v);
    gf_status st = id && v ? GF_OK : GF_FAIL(c->ctx, GF_ERR_NOMEM, "checkpoint: cannot pack %zu held grains", n);
    for (size_t i = 0; st == GF_OK && i < n; ++i) {
        id[i] = c->held[i].id;
        held_pack(&c->held[i], &v[HELD_F64 * i]);
    }
    if (st == GF_OK)
        st = gf_restart_put_i64(r, "coupling_held_id", n, id);
    if (st == GF_OK)
        st = gf_restart_put_f64(r, "coupling_held", HELD_F64 * n, v);
    free(id), free(v);
    return st;
}

gf_status gf_unresolved_save(const gf_coupling *base, gf_restart *r)
{
    const gf_unresolved *c = (const gf_unresolved *)base;
    const gf_fluid *f = c->fluid;
    const gf_grid *g = &f->grid;
    const gf_coupling_stats *s = &c->stats;
    int64_t counts[7] = {g->n[0], g->n[1], g->n[2], c->first_step, c->user_gradp, s->n_steps, s->poisson_iterations};
    double sums[10] = {c->mean_gradp[0],     c->mean_gradp[1],     c->mean_gradp[2],
                       s->fluid_s,           s->poisson_s,         s->last_mass_residual,
                       (double)s->eps_clipped_cells, s->mean_gradp_Pa_m[0], s->mean_gradp_Pa_m[1],
                       s->mean_gradp_Pa_m[2]};
    GF_TRY(gf_restart_put_i64(r, "coupling_counts", 7, counts));
    GF_TRY(gf_restart_put_f64(r, "coupling_sums", 10, sums));
    GF_TRY(gf_restart_put_f64(r, "coupling_volumes", 2,
                              (const double[2]){s->solid_volume_grid_m3, s->solid_volume_grains_m3}));
    gf_restart_array list[GRID_ARRAYS];
    grid_arrays(c, list);
    GF_TRY(gf_coupling_put_arrays(r, list, GRID_ARRAYS));
    return save_held(c, r);
}

static gf_status load_held(gf_unresolved *c, gf_restart *r)
{
    size_t n = 0;
    GF_TRY(gf_restart_len(r, "coupling_held_id", &n));
    GF_TRY(gf_unresolved_reserve(c, n));
    int64_t *id = malloc((n + 1) * sizeof *id);
    double *v = malloc((HELD_F64 * n + 1) * sizeof *v);
    gf_status st = id && v ? GF_OK : GF_FAIL(c->ctx, GF_ERR_NOMEM, "restart: cannot read %zu held grains", n);
    if (st == GF_OK)
        st = gf_restart_get_i64(r, "coupling_held_id", n, id);
    if (st == GF_OK)
        st = gf_restart_get_f64(r, "coupling_held", HELD_F64 * n, v);
    for (size_t i = 0; st == GF_OK && i < n; ++i) {
        c->held[i].id = id[i];
        held_unpack(&v[HELD_F64 * i], &c->held[i]);
    }
    if (st == GF_OK)
        c->n_held = n;
    free(id), free(v);
    return st;
}

gf_status gf_unresolved_load(gf_coupling *base, gf_restart *r)
{
    gf_unresolved *c = (gf_unresolved *)base;
    gf_coupling_stats *s = &c->stats;
    if (!gf_restart_has(r, "coupling_counts"))
        return GF_FAIL(c->ctx, GF_ERR_CONFIG,
                       "restart: the checkpoint holds no fluid state (written by a dry run?) but this run is immersed");
    int64_t counts[7];
    double sums[10], vol[2];
    GF_TRY(gf_restart_get_i64(r, "coupling_counts", 7, counts));
    GF_TRY(gf_coupling_check_grid(c->ctx, counts, &c->fluid->grid));
    GF_TRY(gf_restart_get_f64(r, "coupling_sums", 10, sums));
    GF_TRY(gf_restart_get_f64(r, "coupling_volumes", 2, vol));
    gf_restart_array list[GRID_ARRAYS];
    grid_arrays(c, list);
    GF_TRY(gf_coupling_get_arrays(r, list, GRID_ARRAYS));
    GF_TRY(load_held(c, r));
    c->first_step = (int)counts[3];
    c->user_gradp = (int)counts[4];
    s->n_steps = (long)counts[5];
    s->poisson_iterations = (long)counts[6];
    memcpy(c->mean_gradp, sums, 3 * sizeof(double));
    memcpy(s->mean_gradp_Pa_m, &sums[7], 3 * sizeof(double));
    s->fluid_s = sums[3], s->poisson_s = sums[4], s->last_mass_residual = sums[5];
    s->eps_clipped_cells = (long)sums[6];
    s->solid_volume_grid_m3 = vol[0], s->solid_volume_grains_m3 = vol[1];
    return GF_OK;
}
