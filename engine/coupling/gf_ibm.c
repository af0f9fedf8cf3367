/* Immersed boundary of the resolved tier: solid fraction, maps, forcing; equations and sources in gf_ibm.h. */
#include "coupling/gf_ibm.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

double gf_ibm_alpha(double s_m, const double n[3], double dx_m)
{
    double lambda = fabs(n[0]) + fabs(n[1]) + fabs(n[2]);
    double phi = 0.065 * (1.0 - lambda * lambda) + 0.39;
    /* 1/2 - 1/2 tanh(x) = 1 / (1 + exp(2x)): one exponential where tanh costs an expm1 and a division, and no
     * cancellation in the outer shell (alpha ~ 1e-6 at x = 7) */
    return 1.0 / (1.0 + exp(2.0 * s_m / (lambda * phi * M_SQRT2 * dx_m)));
}

void gf_ibm_free(gf_ibm_map *m)
{
    for (size_t i = 0; i < m->cap_grains; ++i)
        for (int a = 0; a < 3; ++a)
            free(m->grain[i].e[a]);
    free(m->grain);
    memset(m, 0, sizeof *m);
}

/* Threads for the per-component loops: one component each, at most three. */
static int component_threads(const gf_ibm_map *m)
{
    return m->n_threads >= 3 ? 3 : m->n_threads > 1 ? m->n_threads : 1;
}
static int face_threads(const gf_ibm_map *m) { return m->n_threads > 1 ? m->n_threads : 1; }

static gf_status reserve_grains(gf_ctx *ctx, gf_ibm_map *m, size_t n)
{
    if (n <= m->cap_grains)
        return GF_OK;
    size_t cap = n + n / 2 + 8;
    gf_ibm_grain *q = realloc(m->grain, cap * sizeof *q);
    if (!q)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "ibm: out of memory for %zu grains", n);
    memset(q + m->cap_grains, 0, (cap - m->cap_grains) * sizeof *q);
    for (size_t i = m->cap_grains; i < cap; ++i)
        q[i].key[0] = NAN;
    m->grain = q;
    m->cap_grains = cap;
    return GF_OK;
}

/* Appends e to component a of grain slot s; GF_ERR_NOMEM (no message: it runs on a worker thread) when full. */
static gf_status push(gf_ibm_grain *s, int a, const gf_ibm_entry *e)
{
    if (s->n_e[a] == s->cap_e[a]) {
        size_t cap = s->cap_e[a] ? 2 * s->cap_e[a] : 1024;
        gf_ibm_entry *q = realloc(s->e[a], cap * sizeof *q);
        if (!q)
            return GF_ERR_NOMEM;
        s->e[a] = q;
        s->cap_e[a] = cap;
    }
    s->e[a][s->n_e[a]++] = *e;
    return GF_OK;
}

int gf_ibm_face_index(const gf_grid *g, int a, int d, int m)
{
    if (g->periodic[d]) {
        int n = g->n[d];
        m %= n;
        return m < 0 ? m + n : m;
    }
    if (d == a)
        return (m >= 1 && m <= g->n[d] - 1) ? m : -1;
    return (m >= 0 && m < g->n[d]) ? m : -1;
}

/* Offset along axis d of face m of component a from the centre xc_d. */
static double face_offset(const gf_grid *g, int a, int d, int m, double xc_d)
{
    return g->lo_m[d] + (m + (d == a ? 0.0 : 0.5)) * g->h_m[d] - xc_d;
}

/* The offset of entry e of component a from the centre xc (minimum image: e holds the unwrapped indices). */
static void entry_offset(const gf_grid *g, int a, const gf_ibm_entry *e, const double xc[3], double r_m[3])
{
    for (int d = 0; d < 3; ++d)
        r_m[d] = face_offset(g, a, d, e->q[d], xc[d]);
}

/* Appends face u (unwrapped indices; q: wrapped) at offset r_m (squared length r2) to component a of grain
 * slot s when it lies within the profile's shell. */
static gf_status map_face(gf_ibm_grain *s, const gf_grid *g, int a, const int u[3], const int q[3],
                          const double r_m[3], double r2, double R)
{
    double h = g->h_m[0];
    double r = sqrt(r2);
    double n[3] = {1.0, 0.0, 0.0};
    if (r > 0.0)
        for (int d = 0; d < 3; ++d)
            n[d] = r_m[d] / r;
    double lambda = fabs(n[0]) + fabs(n[1]) + fabs(n[2]);
    double width = lambda * (0.065 * (1.0 - lambda * lambda) + 0.39) * M_SQRT2 * h;
    if (r - R > GF_IBM_SHELL_WIDTHS * width)
        return GF_OK;
    gf_ibm_entry e = {.alpha = gf_ibm_alpha(r - R, n, h), .face = (uint32_t)gf_grid_face(g, a, q[0], q[1], q[2]),
                      .q = {(int16_t)u[0], (int16_t)u[1], (int16_t)u[2]}};
    return push(s, a, &e);
}

/* The faces of component a around one grain, into slot s. The shell ends at most 7 x 0.4634 sqrt(2) = 4.587
 * cells beyond R (lambda phi peaks at 0.4634), inside the reach of GF_IBM_REACH_CELLS: a face farther than the
 * reach (a whole row of them, or one face) is dropped before its normal and width are computed. */
static gf_status map_grain(gf_ibm_grain *s, const gf_grid *g, int a, const double xc[3], double R)
{
    double h = g->h_m[0], reach = R + GF_IBM_REACH_CELLS * h, reach2 = reach * reach;
    int m0[3], m1[3];
    for (int d = 0; d < 3; ++d) {
        double off = d == a ? 0.0 : 0.5;
        m0[d] = (int)ceil((xc[d] - reach - g->lo_m[d]) / g->h_m[d] - off);
        m1[d] = (int)floor((xc[d] + reach - g->lo_m[d]) / g->h_m[d] - off);
    }
    s->n_e[a] = 0;
    for (int k = m0[2]; k <= m1[2]; ++k) {
        int kk = gf_ibm_face_index(g, a, 2, k);
        if (kk < 0)
            continue;
        double rz = face_offset(g, a, 2, k, xc[2]);
        for (int j = m0[1]; j <= m1[1]; ++j) {
            int jj = gf_ibm_face_index(g, a, 1, j);
            double ry = face_offset(g, a, 1, j, xc[1]);
            if (jj < 0 || ry * ry + rz * rz > reach2)
                continue;
            for (int i = m0[0]; i <= m1[0]; ++i) {
                int ii = gf_ibm_face_index(g, a, 0, i);
                if (ii < 0)
                    continue;
                const double r_m[3] = {face_offset(g, a, 0, i, xc[0]), ry, rz};
                double r2 = r_m[0] * r_m[0] + r_m[1] * r_m[1] + r_m[2] * r_m[2];
                if (r2 > reach2)
                    continue;
                const int u[3] = {i, j, k}, q[3] = {ii, jj, kk};
                gf_status st = map_face(s, g, a, u, q, r_m, r2, R);
                if (st != GF_OK)
                    return st;
            }
        }
    }
    return GF_OK;
}

/* 1 when grid g is the one the entries were built on. */
static int same_grid(const gf_grid *g, const gf_grid *built_on)
{
    for (int d = 0; d < 3; ++d)
        if (g->n[d] != built_on->n[d] || g->h_m[d] != built_on->h_m[d] || g->lo_m[d] != built_on->lo_m[d] ||
            g->periodic[d] != built_on->periodic[d])
            return 0;
    return 1;
}

/* Grain slot s for centre xc and profile radius R: rebuilt unless it holds exactly these (1 when rebuilt). */
static int map_slot(gf_ibm_grain *s, const gf_grid *g, const double xc[3], double R, gf_status *st)
{
    if (s->key[0] == xc[0] && s->key[1] == xc[1] && s->key[2] == xc[2] && s->key[3] == R)
        return 0;
    s->key[0] = NAN;
    for (int a = 0; a < 3 && *st == GF_OK; ++a)
        *st = map_grain(s, g, a, xc, R);
    if (*st == GF_OK)
        memcpy(s->key, (const double[4]){xc[0], xc[1], xc[2], R}, sizeof s->key);
    return 1;
}

gf_status gf_ibm_build(gf_ctx *ctx, gf_ibm_map *m, const gf_grid *g, const gf_particles *p)
{
    const long n = (long)p->n_local;
    for (int a = 0; a < 3; ++a)
        if (g->n[a] > GF_IBM_MAX_CELLS || g->n_faces[a] > UINT32_MAX)
            return GF_FAIL(ctx, GF_ERR_CONFIG, "ibm: %d cells along axis %d (%zu faces): the maps hold at most %d "
                           "cells per axis and 2^32 faces", g->n[a], a, g->n_faces[a], GF_IBM_MAX_CELLS);
    GF_TRY(reserve_grains(ctx, m, (size_t)n));
    if (!same_grid(g, &m->built_on))
        for (size_t i = 0; i < m->cap_grains; ++i)
            m->grain[i].key[0] = NAN;
    m->built_on = *g;
    m->n_grains = (size_t)n;
    const int nt = face_threads(m);
    gf_status st = GF_OK;
    size_t n_rebuilt = 0;
#pragma omp parallel for num_threads(nt) if (nt > 1 && n > 1) schedule(dynamic, 1) reduction(+ : n_rebuilt)
    for (long i = 0; i < n; ++i) {
        gf_status sti = GF_OK;
        const double xc[3] = {p->x_m[i], p->y_m[i], p->z_m[i]};
        n_rebuilt += (size_t)map_slot(&m->grain[i], g, xc, p->radius_m[i] - m->retraction_cells * g->h_m[0], &sti);
        if (sti != GF_OK) {
#pragma omp atomic write
            st = sti;
        }
    }
    m->n_rebuilt = n_rebuilt;
    if (st != GF_OK)
        return GF_FAIL(ctx, st, "ibm: out of memory for the face entries of %ld grains", n);
    return GF_OK;
}

/* Velocity component a of grain i's rigid motion at offset r. */
static double rigid_velocity(const gf_particles *p, size_t i, int a, const double r[3])
{
    const double w[3] = {p->wx_rad_s[i], p->wy_rad_s[i], p->wz_rad_s[i]};
    const double v[3] = {p->vx_m_s[i], p->vy_m_s[i], p->vz_m_s[i]};
    int b = (a + 1) % 3, c = (a + 2) % 3;
    return v[a] + w[b] * r[c] - w[c] * r[b];
}

/* sum_i alpha_i and (aU not NULL) sum_i alpha_i U_i of component a, scattered in grain order. */
static void scatter_component(const gf_ibm_map *m, const gf_grid *g, const gf_particles *p, int a, double *alpha_sum,
                              double *aU)
{
    memset(alpha_sum, 0, g->n_faces[a] * sizeof(double));
    if (aU)
        memset(aU, 0, g->n_faces[a] * sizeof(double));
    for (size_t i = 0; i < m->n_grains; ++i) {
        const gf_ibm_grain *s = &m->grain[i];
        for (size_t q = 0; q < s->n_e[a]; ++q) {
            const gf_ibm_entry *e = &s->e[a][q];
            alpha_sum[e->face] += e->alpha;
            if (aU) {
                double r_m[3];
                entry_offset(g, a, e, s->key, r_m);
                aU[e->face] += e->alpha * rigid_velocity(p, i, a, r_m);
            }
        }
    }
}

/* f = alpha (U - u~)/dt, alpha = min(1, sum_i alpha_i), face by face on nt threads. */
static void forcing_component(const gf_grid *g, int a, const double *u_pred, const double *alpha_sum,
                              const double *aU, double dt_s, int nt, double *force_out)
{
    const long n = (long)g->n_faces[a];
#pragma omp parallel for num_threads(nt) if (nt > 1) schedule(static)
    for (long fi = 0; fi < n; ++fi) {
        double s = alpha_sum[fi];
        force_out[fi] = s > 0.0 ? (s < 1.0 ? s : 1.0) * (aU[fi] / s - u_pred[fi]) / dt_s : 0.0;
    }
    gf_grid_sync_periodic(g, a, force_out);
}

/* F = sum alpha_i (U_i - u) and T = sum r x alpha_i (U_i - u) over grain i's own entries; U_i taken as 0 when
 * rigid is 0 (then F and T are minus the alpha-weighted momentum and angular momentum of u, per unit volume). */
static void entry_moments(const gf_ibm_map *m, const gf_grid *g, const gf_particles *p, size_t i,
                          const double *const u[3], int rigid, double F[3], double T[3])
{
    for (int d = 0; d < 3; ++d)
        F[d] = T[d] = 0.0;
    for (int a = 0; a < 3; ++a) {
        int b = (a + 1) % 3, c = (a + 2) % 3;
        const gf_ibm_grain *s = &m->grain[i];
        for (size_t q = 0; q < s->n_e[a]; ++q) {
            const gf_ibm_entry *e = &s->e[a][q];
            double r_m[3];
            entry_offset(g, a, e, s->key, r_m);
            double fa = e->alpha * ((rigid ? rigid_velocity(p, i, a, r_m) : 0.0) - u[a][e->face]);
            F[a] += fa;
            T[b] += r_m[c] * fa; /* r x (f_a e_a) = f_a (r_c e_b - r_b e_c), (a, b, c) cyclic */
            T[c] -= r_m[b] * fa;
        }
    }
}

/* Grain i's force and torque from the integral over its own alpha_i (Izard 2014 eqs. (2.32)-(2.33)). */
static void grain_integrals(const gf_ibm_map *m, const gf_grid *g, const gf_particles *p, size_t i,
                            const double *const u_pred[3], double dt_s, double rho_f, double *F_N, double *T_Nm)
{
    double dV = g->h_m[0] * g->h_m[1] * g->h_m[2];
    double R = p->radius_m[i];
    double rho_p = p->mass_kg[i] / (4.0 / 3.0 * M_PI * R * R * R);
    double factor = -rho_f * rho_p / (rho_p - rho_f) * dV / dt_s;
    double F[3], T[3];
    entry_moments(m, g, p, i, u_pred, 1, F, T);
    for (int d = 0; d < 3; ++d) {
        F_N[3 * i + d] = factor * F[d];
        T_Nm[3 * i + d] = factor * T[d];
    }
}

void gf_ibm_force(const gf_ibm_map *m, const gf_grid *g, const gf_particles *p, const double *const u_pred[3],
                  double dt_s, double rho_f, double *const force_out[3], double *const alpha_sum[3],
                  double *const aU[3], double *F_N, double *T_Nm)
{
    const int nc = component_threads(m), nt = face_threads(m);
#pragma omp parallel for num_threads(nc) if (nc > 1) schedule(static, 1)
    for (int a = 0; a < 3; ++a)
        scatter_component(m, g, p, a, alpha_sum[a], aU[a]);
    for (int a = 0; a < 3; ++a) {
        forcing_component(g, a, u_pred[a], alpha_sum[a], aU[a], dt_s, nt, force_out[a]);
        gf_grid_sync_periodic(g, a, alpha_sum[a]);
    }
    const long n = (long)m->n_grains;
#pragma omp parallel for num_threads(nt) if (nt > 1 && n > 1) schedule(static)
    for (long i = 0; i < n; ++i)
        grain_integrals(m, g, p, (size_t)i, u_pred, dt_s, rho_f, F_N, T_Nm);
}

void gf_ibm_fraction(const gf_ibm_map *m, const gf_grid *g, double *const alpha_sum[3])
{
    const int nc = component_threads(m);
#pragma omp parallel for num_threads(nc) if (nc > 1) schedule(static, 1)
    for (int a = 0; a < 3; ++a)
        scatter_component(m, g, NULL, a, alpha_sum[a], NULL);
    for (int a = 0; a < 3; ++a)
        gf_grid_sync_periodic(g, a, alpha_sum[a]);
}

void gf_ibm_momentum(const gf_ibm_map *m, const gf_grid *g, const gf_particles *p, const double *const u[3],
                     double *P, double *L)
{
    const double dV = g->h_m[0] * g->h_m[1] * g->h_m[2];
    const int nt = face_threads(m);
    const long n = (long)m->n_grains;
#pragma omp parallel for num_threads(nt) if (nt > 1 && n > 1) schedule(static)
    for (long i = 0; i < n; ++i) {
        double F[3], T[3];
        entry_moments(m, g, p, (size_t)i, u, 0, F, T);
        for (int d = 0; d < 3; ++d)
            P[3 * i + d] = -dV * F[d], L[3 * i + d] = -dV * T[d];
    }
}

void gf_ibm_cell_fraction(const gf_grid *g, const double *const alpha_sum[3], int n_threads, double *alpha_cell)
{
#pragma omp parallel for num_threads(n_threads) if (n_threads > 1) schedule(static)
    for (int k = 0; k < g->n[2]; ++k)
        for (int j = 0; j < g->n[1]; ++j)
            for (int i = 0; i < g->n[0]; ++i) {
                double s = 0.0;
                for (int a = 0; a < 3; ++a) {
                    int q[3] = {i, j, k};
                    s += alpha_sum[a][gf_grid_face(g, a, q[0], q[1], q[2])];
                    q[a] += 1;
                    s += alpha_sum[a][gf_grid_face(g, a, q[0], q[1], q[2])];
                }
                s /= 6.0;
                alpha_cell[gf_grid_cell(g, i, j, k)] = s < 1.0 ? s : 1.0;
            }
}
