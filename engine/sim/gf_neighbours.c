/*
 * Neighbour upkeep of the step: the Verlet list (contact/gf_nlist.h) rebuilt
 * from the current positions when a grain has moved more than half the skin
 * (Verlet 1967; Izard 2014 §2.1.2.2), with what hangs on each build: the
 * spatial sort of the store on its schedule (gf_sort.c), the reference
 * positions of the displacement check, the integrator factors, the per-pair
 * effective masses, the grains within reach of each wall, the near list's
 * reservation (gf_near_list.c); and the per-grain arrays of the sim
 * (gf_sim_reserve) and the wall history's layout.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/gf_soa.h"
#include "gf_sim_internal.h"
#include "integrate/gf_integrate.h"

gf_status gf_sim_reserve(gf_sim *s, size_t n)
{
    if (n <= s->ref_cap)
        return GF_OK;
    size_t cap = n + n / 4 + 16, stride = (size_t)s->n_walls + 1;
    enum { n_arrays = 13 };
    double **arr[n_arrays] = {&s->x_ref,    &s->y_ref,   &s->z_ref,       &s->vx_pred, &s->vy_pred,
                              &s->vz_pred,  &s->inv_mass, &s->inv_inertia, &s->mobile,  &s->contact_inv_mass,
                              &s->x_near,   &s->y_near,  &s->z_near};
    void *old[n_arrays], *fresh[n_arrays];
    for (int a = 0; a < n_arrays; ++a)
        old[a] = *arr[a];
    void *block = gf_soa_alloc(n_arrays, sizeof(double), cap, GF_SOA_LINE_SIM, fresh, old, s->ref_cap);
    if (!block)
        return GF_FAIL(s->ctx, GF_ERR_NOMEM, "sim: cannot allocate per-grain arrays for %zu grains", n);
    for (int a = 0; a < n_arrays; ++a)
        *arr[a] = fresh[a];
    gf_soa_free(s->ref_block);
    s->ref_block = block;
    double *h = realloc(s->wall_hist, cap * stride * 3 * sizeof(double));
    if (!h)
        return GF_FAIL(s->ctx, GF_ERR_NOMEM, "sim: cannot allocate wall history for %zu grains", n);
    /* new grains start without wall history */
    memset(h + s->ref_cap * stride * 3, 0, (cap - s->ref_cap) * stride * 3 * sizeof(double));
    s->wall_hist = h;
    s->ref_cap = s->wall_hist_cap = cap;
    return GF_OK;
}

gf_status gf_sim_relayout_walls(gf_sim *s, int n_walls_old)
{
    size_t cap = s->ref_cap, so = (size_t)n_walls_old + 1, sn = (size_t)s->n_walls + 1;
    if (cap == 0)
        return GF_OK;
    double *h = calloc(cap * sn * 3, sizeof(double));
    if (!h)
        return GF_FAIL(s->ctx, GF_ERR_NOMEM, "sim: cannot allocate wall history");
    for (size_t i = 0; i < cap; ++i)
        memcpy(&h[3 * i * sn], &s->wall_hist[3 * i * so], 3 * (size_t)n_walls_old * sizeof(double));
    free(s->wall_hist);
    s->wall_hist = h;
    return GF_OK;
}



static gf_nlist_geom list_geom(const gf_sim *s)
{
    gf_nlist_geom g;
    for (int a = 0; a < 3; ++a) {
        g.lo_m[a] = s->lo_m[a];
        g.hi_m[a] = s->hi_m[a];
        g.periodic[a] = s->periodic[a];
    }
    g.extra_m = s->extra_m;
    g.skin_m = s->skin_m;
    return g;
}

/* The grains each wall can touch before the next build: gap to the wall at
 * the build positions below skin + lubrication range (a grain moves less
 * than skin/2 between builds, so one farther away stays beyond the contact
 * and lubrication range; its wall history is cleared here, as the force
 * loop would at its next evaluation). Saves the wall loop from reading every
 * grain's position and history at every step. */
static gf_status build_wall_candidates(gf_sim *s)
{
    const gf_particles *p = s->p;
    const size_t n = p->n_local, stride = (size_t)s->n_walls + 1;
    const double reach = s->skin_m + (s->lubrication ? s->lub_cutoff_m : 0.0);
    s->wall_cand_walls = -1;
    size_t m = 0;
    for (int w = 0; w < s->n_walls; ++w) {
        const double *nw = s->walls[w].normal, *pw = s->walls[w].point_m;
        s->wall_cand_start[w] = m;
        for (size_t i = 0; i < n; ++i) {
            double gap = (s->x_ref[i] - pw[0]) * nw[0] + (s->y_ref[i] - pw[1]) * nw[1] + (s->z_ref[i] - pw[2]) * nw[2] -
                         p->radius_m[i];
            if (gap >= reach) {
                double *h = &s->wall_hist[3 * (i * stride + (size_t)w)];
                h[0] = h[1] = h[2] = 0.0;
                continue;
            }
            if (m == s->wall_cand_cap) {
                size_t cap = m + m / 2 + 1024;
                int32_t *c = realloc(s->wall_cand, cap * sizeof *c);
                if (!c)
                    return GF_FAIL(s->ctx, GF_ERR_NOMEM, "sim: cannot allocate wall candidates (%zu)", cap);
                s->wall_cand = c, s->wall_cand_cap = cap;
            }
            s->wall_cand[m++] = (int32_t)i;
        }
    }
    s->wall_cand_start[s->n_walls] = m;
    s->wall_cand_walls = s->n_walls;
    s->wall_cand_grains = n;
    return GF_OK;
}

/* The walls each grain touches at the build positions, for the balance of
 * the threads' chunks (a floor's contacts all fall in the bottom chunk).
 * NULL when there is one chunk or no wall. */
static gf_status count_wall_contacts(gf_sim *s, const uint8_t **out)
{
    const gf_particles *p = s->p;
    const size_t n = p->n_local;
    *out = NULL;
    if (s->n_threads < 2 || s->n_walls == 0)
        return GF_OK;
    if (n > s->wall_contacts_cap) {
        uint8_t *c = realloc(s->wall_contacts, n);
        if (!c)
            return GF_FAIL(s->ctx, GF_ERR_NOMEM, "sim: cannot allocate wall contact counts (%zu)", n);
        s->wall_contacts = c, s->wall_contacts_cap = n;
    }
    memset(s->wall_contacts, 0, n);
    for (int w = 0; w < s->n_walls; ++w) {
        const double *nw = s->walls[w].normal, *pw = s->walls[w].point_m;
        if (!s->walls[w].active)
            continue;
        for (size_t i = 0; i < n; ++i) {
            double gap = (s->x_ref[i] - pw[0]) * nw[0] + (s->y_ref[i] - pw[1]) * nw[1] + (s->z_ref[i] - pw[2]) * nw[2] -
                         p->radius_m[i];
            s->wall_contacts[i] += gap < 0.0;
        }
    }
    *out = s->wall_contacts;
    return GF_OK;
}

gf_status gf_sim_rebuild_from_ref(gf_sim *s)
{
    gf_particles *p = s->p;
    gf_nlist_geom g = list_geom(s);
    GF_TRY(gf_sim_reserve(s, p->n_local));
    const uint8_t *wall_contacts;
    GF_TRY(count_wall_contacts(s, &wall_contacts));
    GF_TRY(gf_nlist_build(s->ctx, s->nl, &g, p->n_local, s->x_ref, s->y_ref, s->z_ref, p->radius_m, p->id,
                          wall_contacts, s->n_threads));
    /* flags (glued, sleeping) and masses are read here, at every build */
    gf_integrate_factors_fill(p, p->n_local, s->inv_mass, s->inv_inertia, s->mobile);
    if (s->rotation_locked)
        memset(s->inv_inertia, 0, p->n_local * sizeof *s->inv_inertia);
    for (size_t i = 0; i < p->n_local; ++i)
        s->contact_inv_mass[i] = (p->flags[i] & GF_P_GLUED) ? 0.0 : 1.0 / p->mass_kg[i];
    /* per-pair effective mass and damping scale sqrt(m* k_n): constant between
     * builds, so the contact loop does no division or root for them */
    const gf_nlist *nl = s->nl;
    if (nl->n_pairs > s->pair_cap) {
        size_t cap = nl->n_pairs + nl->n_pairs / 4 + 64;
        double *a = realloc(s->pair_meff, cap * sizeof(double));
        if (a)
            s->pair_meff = a;
        double *b = a ? realloc(s->pair_sqrt_mk, cap * sizeof(double)) : NULL;
        if (!b)
            return GF_FAIL(s->ctx, GF_ERR_NOMEM, "sim: cannot allocate pair arrays (%zu pairs)", cap);
        s->pair_sqrt_mk = b;
        s->pair_cap = cap;
    }
    for (size_t i = 0; i < nl->n; ++i)
        for (size_t k = nl->row_start[i]; k < nl->row_start[i + 1]; ++k) {
            double inv = s->contact_inv_mass[i] + s->contact_inv_mass[nl->j[k]];
            double m = inv > 0.0 ? 1.0 / inv : 0.0; /* two glued grains never interact */
            s->pair_meff[k] = m;
            s->pair_sqrt_mk[k] = sqrt(m * s->cp.k_n_N_m);
        }
    s->need_build = 0;
    s->near.valid = s->near.held = 0; /* written back before the build; its pairs were the old list's */
    GF_TRY(gf_sim_near_reserve(s));
    return build_wall_candidates(s);
}

static gf_status rebuild(gf_sim *s, int scheduled)
{
    gf_particles *p = s->p;
    gf_sim_near_flush(s); /* the build carries the list's history over */
    GF_TRY(gf_sim_reserve(s, p->n_local));
    gf_nlist_geom g = list_geom(s);
    gf_nlist_wrap(&g, p->n_local, p->x_m, p->y_m, p->z_m);
    if (scheduled) { /* spatial order (gf_sort.c): on a schedule of the rebuild count alone */
        if (gf_sim_sorts(s) && s->n_rebuilds % s->sort_every == 0)
            GF_TRY(gf_sim_sort_grains(s));
        s->n_rebuilds++;
    }
    memcpy(s->x_ref, p->x_m, p->n_local * sizeof(double));
    memcpy(s->y_ref, p->y_m, p->n_local * sizeof(double));
    memcpy(s->z_ref, p->z_m, p->n_local * sizeof(double));
    return gf_sim_rebuild_from_ref(s);
}

gf_status gf_sim_rebuild(gf_sim *s)
{
    return rebuild(s, 1);
}

gf_status gf_sim_rebuild_unscheduled(gf_sim *s)
{
    return rebuild(s, 0);
}
