/*
 * Neighbour upkeep of the step: the Verlet list (contact/gf_nlist.h) rebuilt
 * from the current positions when a grain has moved more than half the skin
 * (Verlet 1967; Izard 2014 §2.1.2.2), with what hangs on each build: the
 * spatial sort of the store on its schedule (gf_sort.c), the reference
 * positions of the displacement check, the integrator factors, the per-pair
 * effective masses, the grains within reach of each wall, the near list's
 * reservation (gf_near_list.c); and the per-grain arrays it owns
 * (gf_neighbours_reserve). Narrow arguments: gf_neighbours.h.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/gf_soa.h"
#include "gf_neighbours.h"
#include "integrate/gf_integrate.h"

gf_status gf_neighbours_reserve(gf_ctx *ctx, gf_neighbours *nb, size_t n)
{
    if (n <= nb->ref_cap)
        return GF_OK;
    size_t cap = n + n / 4 + 16;
    enum { n_arrays = 13 };
    double **arr[n_arrays] = {&nb->x_ref,   &nb->y_ref,    &nb->z_ref,       &nb->vx_pred, &nb->vy_pred,
                              &nb->vz_pred, &nb->inv_mass, &nb->inv_inertia, &nb->mobile,  &nb->contact_inv_mass,
                              &nb->x_near,  &nb->y_near,   &nb->z_near};
    void *old[n_arrays], *fresh[n_arrays];
    for (int a = 0; a < n_arrays; ++a)
        old[a] = *arr[a];
    void *block = gf_soa_alloc(n_arrays, sizeof(double), cap, GF_SOA_LINE_SIM, fresh, old, nb->ref_cap);
    if (!block)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "sim: cannot allocate per-grain arrays for %zu grains", n);
    for (int a = 0; a < n_arrays; ++a)
        *arr[a] = fresh[a];
    gf_soa_free(nb->ref_block);
    nb->ref_block = block;
    nb->ref_cap = cap;
    return GF_OK;
}

void gf_neighbours_free(gf_neighbours *nb)
{
    gf_nlist_destroy(&nb->nl);
    gf_soa_free(nb->ref_block);
    free(nb->pair_meff), free(nb->pair_sqrt_mk), free(nb->wall_cand), free(nb->wall_contacts);
    gf_near_list_free(&nb->near);
    memset(nb, 0, sizeof *nb);
}

static gf_nlist_geom list_geom(const gf_neighbours *nb, const gf_nb_grains *g)
{
    gf_nlist_geom geom;
    for (int a = 0; a < 3; ++a) {
        geom.lo_m[a] = g->lo_m[a];
        geom.hi_m[a] = g->hi_m[a];
        geom.periodic[a] = g->periodic[a];
    }
    geom.extra_m = nb->extra_m;
    geom.skin_m = nb->skin_m;
    return geom;
}

/* Gap between grain i at its build position and the plane of wall w. */
static inline double build_gap(const gf_neighbours *nb, const gf_nb_grains *g, const gf_wall *w, size_t i)
{
    const double *nw = w->normal, *pw = w->point_m;
    return (nb->x_ref[i] - pw[0]) * nw[0] + (nb->y_ref[i] - pw[1]) * nw[1] + (nb->z_ref[i] - pw[2]) * nw[2] -
           g->p->radius_m[i];
}

/* The grains each wall can touch before the next build: gap to the wall at
 * the build positions below skin + lubrication range (a grain moves less
 * than skin/2 between builds, so one farther away stays beyond the contact
 * and lubrication range; its wall history is cleared here, as the force
 * loop would at its next evaluation). Saves the wall loop from reading every
 * grain's position and history at every step. */
static gf_status build_wall_candidates(gf_ctx *ctx, gf_neighbours *nb, const gf_nb_grains *g, const gf_nb_tuning *t)
{
    const size_t n = g->p->n_local, stride = (size_t)g->n_walls + 1;
    const double reach = nb->skin_m + t->lub_reach_m;
    nb->wall_cand_walls = -1;
    size_t m = 0;
    for (int w = 0; w < g->n_walls; ++w) {
        nb->wall_cand_start[w] = m;
        for (size_t i = 0; i < n; ++i) {
            if (build_gap(nb, g, &g->walls[w], i) >= reach) {
                double *h = &g->wall_hist[3 * (i * stride + (size_t)w)];
                h[0] = h[1] = h[2] = 0.0;
                continue;
            }
            if (m == nb->wall_cand_cap) {
                size_t cap = m + m / 2 + 1024;
                int32_t *c = realloc(nb->wall_cand, cap * sizeof *c);
                if (!c)
                    return GF_FAIL(ctx, GF_ERR_NOMEM, "sim: cannot allocate wall candidates (%zu)", cap);
                nb->wall_cand = c, nb->wall_cand_cap = cap;
            }
            nb->wall_cand[m++] = (int32_t)i;
        }
    }
    nb->wall_cand_start[g->n_walls] = m;
    nb->wall_cand_walls = g->n_walls;
    nb->wall_cand_grains = n;
    return GF_OK;
}

/* The walls each grain touches at the build positions, for the balance of
 * the threads' chunks (a floor's contacts all fall in the bottom chunk).
 * NULL when there is one chunk or no wall. */
static gf_status count_wall_contacts(gf_ctx *ctx, gf_neighbours *nb, const gf_nb_grains *g, const gf_nb_tuning *t,
                                     const uint8_t **out)
{
    const size_t n = g->p->n_local;
    *out = NULL;
    if (t->n_chunks < 2 || g->n_walls == 0)
        return GF_OK;
    if (n > nb->wall_contacts_cap) {
        uint8_t *c = realloc(nb->wall_contacts, n);
        if (!c)
            return GF_FAIL(ctx, GF_ERR_NOMEM, "sim: cannot allocate wall contact counts (%zu)", n);
        nb->wall_contacts = c, nb->wall_contacts_cap = n;
    }
    memset(nb->wall_contacts, 0, n);
    for (int w = 0; w < g->n_walls; ++w) {
        if (!g->walls[w].active)
            continue;
        for (size_t i = 0; i < n; ++i)
            nb->wall_contacts[i] += build_gap(nb, g, &g->walls[w], i) < 0.0;
    }
    *out = nb->wall_contacts;
    return GF_OK;
}

/* Per-pair effective mass and damping scale sqrt(m* k_n): constant between
 * builds, so the contact loop does no division or root for them. */
static gf_status fill_pair_masses(gf_ctx *ctx, gf_neighbours *nb, double k_n_N_m)
{
    const gf_nlist *nl = nb->nl;
    if (nl->n_pairs > nb->pair_cap) {
        size_t cap = nl->n_pairs + nl->n_pairs / 4 + 64;
        double *a = realloc(nb->pair_meff, cap * sizeof(double));
        if (a)
            nb->pair_meff = a;
        double *b = a ? realloc(nb->pair_sqrt_mk, cap * sizeof(double)) : NULL;
        if (!b)
            return GF_FAIL(ctx, GF_ERR_NOMEM, "sim: cannot allocate pair arrays (%zu pairs)", cap);
        nb->pair_sqrt_mk = b;
        nb->pair_cap = cap;
    }
    for (size_t i = 0; i < nl->n; ++i)
        for (size_t k = nl->row_start[i]; k < nl->row_start[i + 1]; ++k) {
            double inv = nb->contact_inv_mass[i] + nb->contact_inv_mass[nl->j[k]];
            double m = inv > 0.0 ? 1.0 / inv : 0.0; /* two glued grains never interact */
            nb->pair_meff[k] = m;
            nb->pair_sqrt_mk[k] = sqrt(m * k_n_N_m);
        }
    return GF_OK;
}

gf_status gf_neighbours_rebuild_from_ref(gf_ctx *ctx, gf_neighbours *nb, const gf_nb_grains *g,
                                         const gf_nb_tuning *t)
{
    const gf_particles *p = g->p;
    gf_nlist_geom geom = list_geom(nb, g);
    GF_TRY(gf_neighbours_reserve(ctx, nb, p->n_local));
    const uint8_t *wall_contacts;
    GF_TRY(count_wall_contacts(ctx, nb, g, t, &wall_contacts));
    GF_TRY(gf_nlist_build(ctx, nb->nl, &geom, p->n_local, nb->x_ref, nb->y_ref, nb->z_ref, p->radius_m, p->id,
                          wall_contacts, t->n_chunks));
    /* flags (glued, sleeping) and masses are read here, at every build */
    gf_integrate_factors_fill(p, p->n_local, nb->inv_mass, nb->inv_inertia, nb->mobile);
    if (t->rotation_locked)
        memset(nb->inv_inertia, 0, p->n_local * sizeof *nb->inv_inertia);
    for (size_t i = 0; i < p->n_local; ++i)
        nb->contact_inv_mass[i] = (p->flags[i] & GF_P_GLUED) ? 0.0 : 1.0 / p->mass_kg[i];
    GF_TRY(fill_pair_masses(ctx, nb, t->k_n_N_m));
    nb->need_build = 0;
    nb->near.valid = nb->near.held = 0; /* written back before the build; its pairs were the old list's */
    GF_TRY(gf_near_list_reserve(ctx, nb));
    return build_wall_candidates(ctx, nb, g, t);
}

gf_status gf_neighbours_rebuild(gf_ctx *ctx, gf_neighbours *nb, const gf_nb_grains *g, const gf_nb_tuning *t,
                                int scheduled)
{
    gf_particles *p = g->p;
    gf_near_list_flush(nb); /* the build carries the list's history over */
    GF_TRY(gf_neighbours_reserve(ctx, nb, p->n_local));
    gf_nlist_geom geom = list_geom(nb, g);
    gf_nlist_wrap(&geom, p->n_local, p->x_m, p->y_m, p->z_m);
    if (scheduled) { /* spatial order (gf_sort.c): on a schedule of the rebuild count alone */
        if (gf_sort_enabled(nb, t, p->n_local) && nb->n_rebuilds % nb->sort_every == 0)
            GF_TRY(gf_sort_grains(ctx, nb, g, t));
        nb->n_rebuilds++;
    }
    memcpy(nb->x_ref, p->x_m, p->n_local * sizeof(double));
    memcpy(nb->y_ref, p->y_m, p->n_local * sizeof(double));
    memcpy(nb->z_ref, p->z_m, p->n_local * sizeof(double));
    return gf_neighbours_rebuild_from_ref(ctx, nb, g, t);
}
