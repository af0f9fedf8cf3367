/*
 * Grain-wall contacts of the step: a plane wall is a grain of infinite
 * radius and mass (Izard 2014 §2.1.2.1): m* = m_i, torque arm R_i, the
 * contact law's kernel with the wall's friction, and Brenner lubrication
 * with R_eff^2 -> R_i^2 (Izard 2014 (2.36)). A wall with a hole touches the
 * grains over it at its rim (gf_wall_distance). The loads on each wall are
 * summed per chunk (gf_sim_accum.wall_force_N). The wall history (3 doubles
 * per grain and wall) is kept here too: its size and its layout when a wall
 * is added.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "contact/gf_lubrication.h"
#include "gf_sim_internal.h"

/* First entry >= i of the ascending candidates [k0, k1). */
static size_t first_candidate(const int32_t *c, size_t k0, size_t k1, size_t i)
{
    while (k0 < k1) {
        size_t mid = k0 + (k1 - k0) / 2;
        if ((size_t)c[mid] < i)
            k0 = mid + 1;
        else
            k1 = mid;
    }
    return k0;
}

/* Grain-wall contacts of grains [i0, i1): the wall's candidates of the last
 * build in that range (all grains when the candidates are stale: a wall or a
 * grain added since). Same grains in the same order either way. */
void gf_sim_wall_rows(gf_sim *s, size_t i0, size_t i1, double *const f[6], gf_sim_accum *acc)
{
    const gf_particles *p = s->p;
    const double lub_cut = s->lubrication ? s->lub_cutoff_m : 0.0;
    const size_t stride = (size_t)s->n_walls + 1;
    const gf_neighbours *nb = &s->nb;
    const int listed = nb->wall_cand_walls == s->n_walls && nb->wall_cand_grains == p->n_local;
    for (int w = 0; w < s->n_walls; ++w) {
        const gf_wall *wl = &s->walls[w];
        const double *nw_plane = wl->normal, *pw = wl->point_m;
        size_t k = listed ? first_candidate(nb->wall_cand, nb->wall_cand_start[w], nb->wall_cand_start[w + 1], i0) : i0;
        const size_t k_end = listed ? nb->wall_cand_start[w + 1] : i1;
        for (; k < k_end; ++k) {
            const size_t i = listed ? (size_t)nb->wall_cand[k] : k;
            if (i >= i1)
                break;
            double *h = &s->wall_hist[3 * (i * stride + (size_t)w)];
            double ri = p->radius_m[i], c[3] = {p->x_m[i], p->y_m[i], p->z_m[i]}, n_loc[3];
            double dist = wl->has_hole ? gf_wall_distance(wl, c, n_loc)
                                       : (c[0] - pw[0]) * nw_plane[0] + (c[1] - pw[1]) * nw_plane[1] +
                                             (c[2] - pw[2]) * nw_plane[2];
            const double *nw = wl->has_hole ? n_loc : nw_plane;
            double overlap = ri - dist;
            if (!wl->active || (p->flags[i] & GF_P_GLUED) || overlap <= -lub_cut) {
                if (h[0] != 0.0 || h[1] != 0.0 || h[2] != 0.0)
                    h[0] = h[1] = h[2] = 0.0;
                continue;
            }
            double v[3] = {p->vx_m_s[i], p->vy_m_s[i], p->vz_m_s[i]};
            double F[3] = {0.0, 0.0, 0.0};
            double vn = nb->vx_pred[i] * nw[0] + nb->vy_pred[i] * nw[1] + nb->vz_pred[i] * nw[2];
            if (overlap > 0.0) {
                gf_contact_geom g;
                g.v_n_m_s = vn;
                g.n[0] = nw[0], g.n[1] = nw[1], g.n[2] = nw[2];
                g.overlap_m = overlap;
                double rw[3] = {ri * p->wx_rad_s[i], ri * p->wy_rad_s[i], ri * p->wz_rad_s[i]}, rwn[3];
                gf_cross(rw, g.n, rwn);
                g.v_rel_m_s[0] = v[0] - rwn[0], g.v_rel_m_s[1] = v[1] - rwn[1], g.v_rel_m_s[2] = v[2] - rwn[2];
                g.m_eff_kg = p->mass_kg[i];
                g.sqrt_mk = sqrt(p->mass_kg[i] * s->cp.k_n_N_m);
                g.mu = wl->friction;
                double f_n, f_t[3], nxt[3];
                s->law->kernel(&s->cp, &g, s->dt_s, h, &f_n, f_t);
                F[0] = f_n * nw[0] + f_t[0], F[1] = f_n * nw[1] + f_t[1], F[2] = f_n * nw[2] + f_t[2];
                gf_cross(g.n, f_t, nxt);
                f[3][i] -= ri * nxt[0], f[4][i] -= ri * nxt[1], f[5][i] -= ri * nxt[2];
                acc->n_contacts++;
                if (overlap > acc->max_overlap_m)
                    acc->max_overlap_m = overlap;
            } else if (h[0] != 0.0 || h[1] != 0.0 || h[2] != 0.0) {
                h[0] = h[1] = h[2] = 0.0;
            }
            if (lub_cut > 0.0 && (s->lub_overlap != GF_LUB_OVERLAP_OFF || overlap <= 0.0)) {
                double gap = overlap > 0.0 ? gf_lubrication_overlap_gap(s->lub_overlap, ri, s->lub_eta_Pa_s,
                                                                        s->cp.k_n_N_m, p->mass_kg[i], vn, overlap)
                                           : -overlap;
                double c = -gf_lubrication_damping(s->dt_s, 6.0 * M_PI * s->lub_eta_Pa_s * ri * ri / (gap + s->lub_roughness_m),
                                        p->mass_kg[i]) * vn;
                F[0] += c * nw[0], F[1] += c * nw[1], F[2] += c * nw[2];
            }
            f[0][i] += F[0], f[1][i] += F[1], f[2][i] += F[2];
            acc->wall_force_N[w][0] -= F[0], acc->wall_force_N[w][1] -= F[1], acc->wall_force_N[w][2] -= F[2];
        }
    }
}

gf_status gf_sim_reserve_wall_history(gf_sim *s, size_t n)
{
    if (n <= s->wall_hist_cap)
        return GF_OK;
    size_t cap = n + n / 4 + 16, stride = (size_t)s->n_walls + 1;
    double *h = realloc(s->wall_hist, cap * stride * 3 * sizeof(double));
    if (!h)
        return GF_FAIL(s->ctx, GF_ERR_NOMEM, "sim: cannot allocate wall history for %zu grains", n);
    /* new grains start without wall history */
    memset(h + s->wall_hist_cap * stride * 3, 0, (cap - s->wall_hist_cap) * stride * 3 * sizeof(double));
    s->wall_hist = h;
    s->wall_hist_cap = cap;
    return GF_OK;
}

gf_status gf_sim_relayout_walls(gf_sim *s, int n_walls_old)
{
    size_t cap = s->wall_hist_cap, so = (size_t)n_walls_old + 1, sn = (size_t)s->n_walls + 1;
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
