/* Packing preparation to a target Phi_i; the protocol and the measures are in gf_packing.h. */
#include "particles/gf_packing.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/gf_clones.h"
#include "core/gf_rng.h"

/* Preparation constants (see gf_packing.h): contact duration and step in
 * sqrt(D/g), restitution, terminal speed of the settling drag in sqrt(gD),
 * Verlet skin in D, rest criterion on the mean kinetic energy per grain in
 * m g D, and the longest deposition in sqrt(D/g). */
enum { PREP_MAX_WALLS = 5 };
static const double PREP_TC_ND = 0.02, PREP_DT_OVER_TC = 1.0 / 15.0, PREP_RESTITUTION = 0.3;
static const double PREP_TERMINAL_ND = 2.0, PREP_SKIN_D = 0.3, PREP_REST_KE = 1e-4, PREP_MAX_TIME_ND = 400.0;

typedef struct prep_wall {
    double point[3], normal[3];
} prep_wall;

typedef struct prep {
    size_t n, n_mobile;                 /* mobile grains [0, n_mobile), glued after */
    double *x, *v, *w, *f, *t;          /* 3 n each */
    double *r, *m, *inv_i, *x_ref;
    double lo[3], hi[3], len[3];
    int per[3];
    prep_wall wall[PREP_MAX_WALLS];
    int n_walls;
    double *wall_hist;                  /* n * PREP_MAX_WALLS * 3 */
    double k_n, zeta, k_t, mu, mu_obs, dt, tau, g, skin, r_max;
    int rolling;                        /* 0: rotations blocked during the preparation */
    /* half Verlet table in CSR form, j sorted per i, with tangential history */
    size_t *start, *nbr, n_pairs, cap_pairs;
    double *hist;
    double *pair_sqrt_mk;               /* sqrt(m_eff k_n) of each pair, set at the rebuild */
    size_t *wall_cand, wall_start[PREP_MAX_WALLS + 1]; /* per wall, the grains within the skin at the rebuild */
    int *head, *next;
    size_t n_cells;
} prep;

static void prep_free(prep *s)
{
    free(s->x), free(s->v), free(s->w), free(s->f), free(s->t);
    free(s->r), free(s->m), free(s->inv_i), free(s->x_ref), free(s->wall_hist);
    free(s->start), free(s->nbr), free(s->hist), free(s->head), free(s->next), free(s->pair_sqrt_mk);
    free(s->wall_cand);
    memset(s, 0, sizeof *s);
}

static double min_image(const prep *s, int c, double d)
{
    if (s->per[c]) {
        if (d > 0.5 * s->len[c])
            d -= s->len[c];
        else if (d < -0.5 * s->len[c])
            d += s->len[c];
    }
    return d;
}

static int cell_coord(const prep *s, int c, double xc, double cs, int nc, double ylo)
{
    double origin = c == 1 ? ylo : s->lo[c];
    int k = (int)floor((xc - origin) / cs);
    if (s->per[c])
        k = ((k % nc) + nc) % nc;
    else
        k = k < 0 ? 0 : (k >= nc ? nc - 1 : k);
    return k;
}

/* Reduced mass of pair (i, j); a glued grain counts as infinitely heavy. */
static double pair_mass(const prep *s, size_t i, size_t j)
{
    int gi = i >= s->n_mobile, gj = j >= s->n_mobile;
    return gi ? s->m[j] : (gj ? s->m[i] : s->m[i] * s->m[j] / (s->m[i] + s->m[j]));
}

/* Lists, for each wall, the mobile grains whose gap to it is below the skin.
 * A grain moves less than skin/2 between rebuilds, so one farther away
 * cannot touch the wall before the next rebuild: its wall history, which the
 * full loop would clear at every step, is cleared here once. The force loop
 * visits the candidates in ascending order, wall after wall, which adds the
 * walls' forces to each grain in the order of the full loop. */
static gf_status wall_candidates(gf_ctx *ctx, prep *s)
{
    if (!s->wall_cand) {
        s->wall_cand = malloc((s->n_mobile * PREP_MAX_WALLS + 1) * sizeof *s->wall_cand);
        if (!s->wall_cand)
            return GF_FAIL(ctx, GF_ERR_NOMEM, "packing: cannot allocate the wall candidates");
    }
    size_t m = 0;
    for (int k = 0; k < s->n_walls; ++k) {
        const prep_wall *wl = &s->wall[k];
        s->wall_start[k] = m;
        for (size_t i = 0; i < s->n_mobile; ++i) {
            double dist = 0.0;
            for (int c = 0; c < 3; ++c)
                dist += (s->x[3 * i + c] - wl->point[c]) * wl->normal[c];
            if (dist < s->r[i] + s->skin) {
                s->wall_cand[m++] = i;
            } else {
                double *h = &s->wall_hist[(i * PREP_MAX_WALLS + (size_t)k) * 3];
                h[0] = h[1] = h[2] = 0.0;
            }
        }
    }
    s->wall_start[s->n_walls] = m;
    return GF_OK;
}

/* Rebuilds the Verlet table, carrying the tangential history of pairs that persist. */
static gf_status prep_rebuild(gf_ctx *ctx, prep *s)
{
    double cut = 2.0 * s->r_max + s->skin;
    double ylo = INFINITY, yhi = -INFINITY;
    for (size_t i = 0; i < s->n; ++i) {
        ylo = fmin(ylo, s->x[3 * i + 1]);
        yhi = fmax(yhi, s->x[3 * i + 1]);
    }
    int nc[3];
    double cs[3];
    for (int c = 0; c < 3; ++c) {
        double extent = c == 1 ? (yhi - ylo + 1e-9) : s->len[c];
        nc[c] = (int)floor(extent / cut);
        if (nc[c] < 1)
            nc[c] = 1;
        if (nc[c] > 4096)
            nc[c] = 4096;
        cs[c] = extent / nc[c];
        if (c != 1 && !s->per[c])
            cs[c] = fmax(cs[c], cut);
    }
    size_t n_cells = (size_t)nc[0] * (size_t)nc[1] * (size_t)nc[2];
    if (n_cells > s->n_cells) {
        free(s->head);
        s->head = malloc(n_cells * sizeof *s->head);
        if (!s->head)
            return GF_FAIL(ctx, GF_ERR_NOMEM, "packing: cannot allocate %zu cells", n_cells);
        s->n_cells = n_cells;
    }
    for (size_t q = 0; q < n_cells; ++q)
        s->head[q] = -1;
    int *cell_of = malloc(s->n * 3 * sizeof *cell_of);
    if (!cell_of)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "packing: cannot allocate cell index");
    for (size_t i = 0; i < s->n; ++i) {
        for (int c = 0; c < 3; ++c)
            cell_of[3 * i + c] = cell_coord(s, c, s->x[3 * i + c], cs[c], nc[c], ylo);
        size_t q = ((size_t)cell_of[3 * i + 2] * nc[1] + cell_of[3 * i + 1]) * nc[0] + cell_of[3 * i];
        s->next[i] = s->head[q];
        s->head[q] = (int)i;
    }
    size_t *new_start = malloc((s->n + 1) * sizeof *new_start);
    size_t cap = s->cap_pairs ? s->cap_pairs : 16 * s->n + 16, np = 0;
    size_t *new_nbr = malloc(cap * sizeof *new_nbr);
    double *new_hist = NULL;
    if (!new_start || !new_nbr) {
        free(cell_of), free(new_start), free(new_nbr);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "packing: cannot allocate the Verlet table");
    }
    for (size_t i = 0; i < s->n; ++i) {
        new_start[i] = np;
        int list[3][4], cnt[3];
        for (int c = 0; c < 3; ++c) {
            cnt[c] = 0;
            if (s->per[c] && nc[c] < 3) {
                for (int k = 0; k < nc[c]; ++k)
                    list[c][cnt[c]++] = k;
            } else {
                for (int d = -1; d <= 1; ++d) {
                    int k = cell_of[3 * i + c] + d;
                    if (s->per[c])
                        k = (k + nc[c]) % nc[c];
                    else if (k < 0 || k >= nc[c])
                        continue;
                    list[c][cnt[c]++] = k;
                }
            }
        }
        size_t first = np;
        for (int a = 0; a < cnt[0]; ++a)
            for (int b = 0; b < cnt[1]; ++b)
                for (int e = 0; e < cnt[2]; ++e) {
                    size_t q = ((size_t)list[2][e] * nc[1] + list[1][b]) * nc[0] + list[0][a];
                    for (int j = s->head[q]; j >= 0; j = s->next[j]) {
                        if ((size_t)j <= i || (i >= s->n_mobile && (size_t)j >= s->n_mobile))
                            continue;
                        double d2 = 0.0;
                        for (int c = 0; c < 3; ++c) {
                            double d = min_image(s, c, s->x[3 * i + c] - s->x[3 * j + c]);
                            d2 += d * d;
                        }
                        double rc = s->r[i] + s->r[j] + s->skin;
                        if (d2 > rc * rc)
                            continue;
                        if (np == cap) {
                            cap *= 2;
                            size_t *tmp = realloc(new_nbr, cap * sizeof *tmp);
                            if (!tmp) {
                                free(cell_of), free(new_start), free(new_nbr);
                                return GF_FAIL(ctx, GF_ERR_NOMEM, "packing: cannot grow the Verlet table");
                            }
                            new_nbr = tmp;
                        }
                        new_nbr[np++] = (size_t)j;
                    }
                }
        /* insertion sort of i's partners (a dozen at most) so histories merge in one pass */
        for (size_t u = first + 1; u < np; ++u) {
            size_t key = new_nbr[u], k = u;
            while (k > first && new_nbr[k - 1] > key) {
                new_nbr[k] = new_nbr[k - 1];
                --k;
            }
            new_nbr[k] = key;
        }
    }
    new_start[s->n] = np;
    new_hist = calloc(3 * (np ? np : 1), sizeof *new_hist);
    if (!new_hist) {
        free(cell_of), free(new_start), free(new_nbr);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "packing: cannot allocate contact history");
    }
    if (s->start) {
        for (size_t i = 0; i < s->n; ++i) {
            size_t a = s->start[i], ae = s->start[i + 1];
            for (size_t b = new_start[i]; b < new_start[i + 1] && a < ae; ++b) {
                while (a < ae && s->nbr[a] < new_nbr[b])
                    ++a;
                if (a < ae && s->nbr[a] == new_nbr[b])
                    memcpy(&new_hist[3 * b], &s->hist[3 * a], 3 * sizeof(double));
            }
        }
    }
    free(cell_of);
    double *sqrt_mk = malloc((np ? np : 1) * sizeof *sqrt_mk);
    if (!sqrt_mk) {
        free(new_start), free(new_nbr), free(new_hist);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "packing: cannot allocate the pair masses");
    }
    for (size_t i = 0; i < s->n; ++i)
        for (size_t q = new_start[i]; q < new_start[i + 1]; ++q)
            sqrt_mk[q] = sqrt(pair_mass(s, i, new_nbr[q]) * s->k_n);
    free(s->start), free(s->nbr), free(s->hist), free(s->pair_sqrt_mk);
    s->start = new_start, s->nbr = new_nbr, s->hist = new_hist, s->pair_sqrt_mk = sqrt_mk;
    s->n_pairs = np, s->cap_pairs = cap;
    memcpy(s->x_ref, s->x, 3 * s->n * sizeof *s->x);
    return wall_candidates(ctx, s);
}

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Linear spring-dashpot + tangential spring with Coulomb cap (Cundall & Strack 1979), force on i.
 * vrel: relative surface velocity at the contact, n from j to i, sqrt_mk = sqrt(m_eff k_n) of the pair
 * (m_eff its reduced mass). The wall contacts use it; the pair loop's prep_compute writes the same
 * expressions with selects, so that grain-grain contacts vectorise. */
static inline __attribute__((always_inline)) void contact_force(const prep *s, const double n[3], double overlap,
                                                                const double vrel[3], double sqrt_mk, double mu,
                                                                double *hist, double force[3], double f_t[3])
{
    double vn = vrel[0] * n[0] + vrel[1] * n[1] + vrel[2] * n[2];
    double fn = s->k_n * overlap - 2.0 * s->zeta * sqrt_mk * vn;
    if (fn < 0.0)
        fn = 0.0;
    double hn = hist[0] * n[0] + hist[1] * n[1] + hist[2] * n[2];
    double len0 = sqrt(hist[0] * hist[0] + hist[1] * hist[1] + hist[2] * hist[2]);
    for (int c = 0; c < 3; ++c)
        hist[c] -= hn * n[c];
    double len1 = sqrt(hist[0] * hist[0] + hist[1] * hist[1] + hist[2] * hist[2]);
    if (len1 > 0.0)
        for (int c = 0; c < 3; ++c)
            hist[c] *= len0 / len1;
    for (int c = 0; c < 3; ++c)
        hist[c] += (vrel[c] - vn * n[c]) * s->dt;
    double ft2 = 0.0;
    for (int c = 0; c < 3; ++c) {
        f_t[c] = -s->k_t * hist[c];
        ft2 += f_t[c] * f_t[c];
    }
    double cap = mu * fn;
    if (ft2 > cap * cap) {
        double scale = ft2 > 0.0 ? cap / sqrt(ft2) : 0.0;
        for (int c = 0; c < 3; ++c) {
            f_t[c] *= scale;
            hist[c] = -f_t[c] / s->k_t;
        }
    }
    for (int c = 0; c < 3; ++c)
        force[c] = fn * n[c] + f_t[c];
}

/* The pair loop runs in blocks of PREP_BLOCK pairs and three passes, as the
 * engine's dry loop (engine/gf_sim_pairs.c): (1) scan: distance test of every
 * pair, contacts appended with their pair vector, separated pairs' histories
 * cleared; (2) compute: each contact's force (contact_force, written with
 * selects instead of branches), a loop without dependences between contacts
 * that GCC vectorises (AVX-512 clone chosen at load time); (3) scatter: forces
 * and torques added in list order. Every expression and every sum is the one
 * of the former single loop, so the deposits are bitwise the same. */
enum { PREP_BLOCK = 256 };

typedef struct prep_block {
    int64_t i3[PREP_BLOCK], j3[PREP_BLOCK], q3[PREP_BLOCK]; /* 3 i, 3 j, 3 q: offsets into x, v, w, f, t, hist */
    double dx[PREP_BLOCK], dy[PREP_BLOCK], dz[PREP_BLOCK], d2[PREP_BLOCK], rs[PREP_BLOCK];
    double ri[PREP_BLOCK], rj[PREP_BLOCK], sqrt_mk[PREP_BLOCK], mu[PREP_BLOCK];
    double fx[PREP_BLOCK], fy[PREP_BLOCK], fz[PREP_BLOCK], tx[PREP_BLOCK], ty[PREP_BLOCK], tz[PREP_BLOCK];
} prep_block;

#ifdef _OPENMP
#define PREP_SIMD _Pragma("omp simd")
#else
#define PREP_SIMD
#endif

/* Pass 1: pairs [*pq, *pq + PREP_BLOCK) (rows followed in *prow); returns the contacts. */
static size_t prep_scan(prep *s, size_t *pq, size_t *prow, prep_block *b)
{
    size_t q = *pq, i = *prow, nc = 0;
    const size_t qstop = s->n_pairs - q < PREP_BLOCK ? s->n_pairs : q + PREP_BLOCK;
    for (; q < qstop; ++q) {
        while (q >= s->start[i + 1])
            ++i;
        size_t j = s->nbr[q];
        double d[3], d2 = 0.0;
        for (int c = 0; c < 3; ++c) {
            d[c] = min_image(s, c, s->x[3 * i + c] - s->x[3 * j + c]);
            d2 += d[c] * d[c];
        }
        double rs = s->r[i] + s->r[j];
        int in = d2 < rs * rs;
        if (!in) {
            double *h = &s->hist[3 * q];
            h[0] = h[1] = h[2] = 0.0;
        }
        int glued = i >= s->n_mobile || j >= s->n_mobile;
        b->i3[nc] = 3 * (int64_t)i, b->j3[nc] = 3 * (int64_t)j, b->q3[nc] = 3 * (int64_t)q;
        b->dx[nc] = d[0], b->dy[nc] = d[1], b->dz[nc] = d[2], b->d2[nc] = d2, b->rs[nc] = rs;
        b->ri[nc] = s->r[i], b->rj[nc] = s->r[j], b->sqrt_mk[nc] = s->pair_sqrt_mk[q];
        b->mu[nc] = glued ? s->mu_obs : s->mu;
        nc += (size_t)in;
    }
    *pq = q, *prow = i;
    return nc;
}

/* Pass 2: contact_force of every contact of the block, with selects. */
GF_AVX512_CLONES static void prep_compute(prep *s, prep_block *restrict b, size_t nc)
{
    const double *restrict v = s->v, *restrict w = s->w;
    double *restrict hist = s->hist;
    const double k_n = s->k_n, zeta = s->zeta, k_t = s->k_t, dt = s->dt;
    PREP_SIMD
    for (size_t c = 0; c < nc; ++c) {
        const int64_t i3 = b->i3[c], j3 = b->j3[c], q3 = b->q3[c];
        double dist = sqrt(b->d2[c]);
        double n0 = b->dx[c] / dist, n1 = b->dy[c] / dist, n2 = b->dz[c] / dist;
        double ri = b->ri[c], rj = b->rj[c];
        double a0 = -ri * n0, a1 = -ri * n1, a2 = -ri * n2; /* lever of i: -R_i n */
        double e0 = rj * n0, e1 = rj * n1, e2 = rj * n2;    /* lever of j: R_j n */
        double wi0 = w[i3 + 1] * a2 - w[i3 + 2] * a1, wi1 = w[i3 + 2] * a0 - w[i3] * a2,
               wi2 = w[i3] * a1 - w[i3 + 1] * a0;
        double wj0 = w[j3 + 1] * e2 - w[j3 + 2] * e1, wj1 = w[j3 + 2] * e0 - w[j3] * e2,
               wj2 = w[j3] * e1 - w[j3 + 1] * e0;
        double u0 = v[i3] - v[j3] + wi0 - wj0, u1 = v[i3 + 1] - v[j3 + 1] + wi1 - wj1,
               u2 = v[i3 + 2] - v[j3 + 2] + wi2 - wj2;
        /* contact_force: normal spring-dashpot, never attractive */
        double vn = u0 * n0 + u1 * n1 + u2 * n2;
        double fn = k_n * (b->rs[c] - dist) - 2.0 * zeta * b->sqrt_mk[c] * vn;
        fn = fn < 0.0 ? 0.0 : fn;
        /* history rotated into the tangent plane, its length kept */
        double h0 = hist[q3], h1 = hist[q3 + 1], h2 = hist[q3 + 2];
        double hn = h0 * n0 + h1 * n1 + h2 * n2;
        double len0 = sqrt(h0 * h0 + h1 * h1 + h2 * h2);
        h0 -= hn * n0, h1 -= hn * n1, h2 -= hn * n2;
        double len1 = sqrt(h0 * h0 + h1 * h1 + h2 * h2);
        double ratio = len0 / (len1 > 0.0 ? len1 : 1.0);
        h0 = len1 > 0.0 ? h0 * ratio : h0, h1 = len1 > 0.0 ? h1 * ratio : h1, h2 = len1 > 0.0 ? h2 * ratio : h2;
        h0 += (u0 - vn * n0) * dt, h1 += (u1 - vn * n1) * dt, h2 += (u2 - vn * n2) * dt;
        /* tangential spring with the Coulomb cap */
        double t0 = -k_t * h0, t1 = -k_t * h1, t2 = -k_t * h2;
        double ft2 = t0 * t0 + t1 * t1 + t2 * t2, cap = b->mu[c] * fn;
        int slip = ft2 > cap * cap;
        double scale = cap / sqrt(ft2 > 0.0 ? ft2 : 1.0);
        scale = ft2 > 0.0 ? scale : 0.0;
        t0 = slip ? t0 * scale : t0, t1 = slip ? t1 * scale : t1, t2 = slip ? t2 * scale : t2;
        hist[q3] = slip ? -t0 / k_t : h0, hist[q3 + 1] = slip ? -t1 / k_t : h1, hist[q3 + 2] = slip ? -t2 / k_t : h2;
        b->fx[c] = fn * n0 + t0, b->fy[c] = fn * n1 + t1, b->fz[c] = fn * n2 + t2;
        b->tx[c] = n1 * t2 - n2 * t1, b->ty[c] = n2 * t0 - n0 * t2, b->tz[c] = n0 * t1 - n1 * t0; /* n x F_t */
    }
}

/* Pass 3: forces and torques (r_c x F_t = -R n x F_t for both grains) in list order. */
static void prep_scatter(prep *s, const prep_block *b, size_t nc)
{
    for (size_t c = 0; c < nc; ++c) {
        const int64_t i3 = b->i3[c], j3 = b->j3[c];
        const double F[3] = {b->fx[c], b->fy[c], b->fz[c]}, T[3] = {b->tx[c], b->ty[c], b->tz[c]};
        for (int k = 0; k < 3; ++k) {
            s->f[i3 + k] += F[k];
            s->f[j3 + k] -= F[k];
            s->t[i3 + k] -= b->ri[c] * T[k];
            s->t[j3 + k] -= b->rj[c] * T[k];
        }
    }
}

static void prep_forces(prep *s)
{
    memset(s->f, 0, 3 * s->n * sizeof *s->f);
    memset(s->t, 0, 3 * s->n * sizeof *s->t);
    for (size_t i = 0; i < s->n_mobile; ++i) {
        s->f[3 * i + 1] -= s->m[i] * s->g;
        for (int c = 0; c < 3; ++c)
            s->f[3 * i + c] -= s->m[i] * s->v[3 * i + c] / s->tau;
    }
    prep_block blk;
    size_t row = 0;
    for (size_t q = 0; q < s->n_pairs;) {
        size_t nc = prep_scan(s, &q, &row, &blk);
        prep_compute(s, &blk, nc);
        prep_scatter(s, &blk, nc);
    }
    for (int k = 0; k < s->n_walls; ++k)
        for (size_t u = s->wall_start[k]; u < s->wall_start[k + 1]; ++u) {
            const size_t i = s->wall_cand[u];
            const prep_wall *wl = &s->wall[k];
            double dist = 0.0;
            for (int c = 0; c < 3; ++c)
                dist += (s->x[3 * i + c] - wl->point[c]) * wl->normal[c];
            double *h = &s->wall_hist[(i * PREP_MAX_WALLS + (size_t)k) * 3];
            if (dist >= s->r[i]) {
                h[0] = h[1] = h[2] = 0.0;
                continue;
            }
            double ri[3], wi[3], vrel[3], force[3], ft[3], tq[3];
            for (int c = 0; c < 3; ++c)
                ri[c] = -s->r[i] * wl->normal[c];
            cross(&s->w[3 * i], ri, wi);
            for (int c = 0; c < 3; ++c)
                vrel[c] = s->v[3 * i + c] + wi[c];
            contact_force(s, wl->normal, s->r[i] - dist, vrel, sqrt(s->m[i] * s->k_n), 0.0, h, force, ft);
            cross(wl->normal, ft, tq);
            for (int c = 0; c < 3; ++c) {
                s->f[3 * i + c] += force[c];
                s->t[3 * i + c] -= s->r[i] * tq[c];
            }
        }
}

/* Symplectic Euler (Izard 2014 (2.7), §2.1.2.2); returns the largest displacement since the last rebuild. */
static double prep_integrate(prep *s)
{
    double max_d2 = 0.0;
    for (size_t i = 0; i < s->n_mobile; ++i) {
        double d2 = 0.0;
        for (int c = 0; c < 3; ++c) {
            s->v[3 * i + c] += s->f[3 * i + c] / s->m[i] * s->dt;
            if (s->rolling)
                s->w[3 * i + c] += s->t[3 * i + c] * s->inv_i[i] * s->dt;
            s->x[3 * i + c] += s->v[3 * i + c] * s->dt;
            double d = s->x[3 * i + c] - s->x_ref[3 * i + c];
            d2 += d * d;
        }
        max_d2 = fmax(max_d2, d2);
    }
    for (size_t i = 0; i < s->n_mobile; ++i)
        for (int c = 0; c < 3; c += 2)
            if (s->per[c]) {
                /* wrapping moves x and x_ref together so the displacement test is unaffected */
                double sh = 0.0;
                if (s->x[3 * i + c] < s->lo[c])
                    sh = s->len[c];
                else if (s->x[3 * i + c] >= s->hi[c])
                    sh = -s->len[c];
                s->x[3 * i + c] += sh;
                s->x_ref[3 * i + c] += sh;
            }
    return sqrt(max_d2);
}

static double container_base_m(const gf_packing_spec *sp)
{
    double base = sp->lo_m[1];
    const gf_particles *o = sp->obstacles;
    if (o)
        for (size_t i = 0; i < o->n_local; ++i) {
            /* only grains under the column footprint and near the floor form the base */
            if (o->y_m[i] < sp->lo_m[1] + 2.0 * sp->psd.mean_radius_m)
                base = fmax(base, o->y_m[i] + o->radius_m[i]);
        }
    return base;
}

/* Contact law of the mean pair: stiffness for t_c (unclipped law, Schäfer et al. 1996), damping ratio for
 * eps, k_t = 0.2 k_n, friction mu (and on the obstacles unless mu_obstacles is set); dt follows t_c. */
static void prep_contacts(prep *s, const gf_packing_spec *sp, double t_c, double eps, double mu)
{
    double D = 2.0 * sp->psd.mean_radius_m, m_mean = sp->density_kg_m3 * M_PI * D * D * D / 6.0;
    double le = log(eps);
    s->k_n = 0.5 * m_mean * (M_PI * M_PI + le * le) / (t_c * t_c);
    s->zeta = -le / sqrt(M_PI * M_PI + le * le);
    s->k_t = 0.2 * s->k_n;
    s->mu = mu;
    s->mu_obs = sp->mu_obstacles > 0.0 ? sp->mu_obstacles : mu;
    s->dt = PREP_DT_OVER_TC * t_c;
}

static gf_status prep_setup(gf_ctx *ctx, const gf_packing_spec *sp, double mu_prep, prep *s)
{
    memset(s, 0, sizeof *s);
    double D = 2.0 * sp->psd.mean_radius_m, g = sp->gravity_m_s2;
    double area = 1.0, H = sp->hi_m[1], base = container_base_m(sp);
    for (int c = 0; c < 3; ++c) {
        s->lo[c] = sp->lo_m[c], s->hi[c] = sp->hi_m[c], s->len[c] = sp->hi_m[c] - sp->lo_m[c];
        s->per[c] = c == 1 ? 0 : sp->periodic[c];
    }
    area = s->len[0] * s->len[2];
    s->r_max = gf_psd_max_radius_m(&sp->psd);
    /* enough grains for a deposit at Phi = 0.66 to reach H + 2D: at any looser Phi the top is higher */
    double vol_mean = gf_psd_mean_volume_m3(&sp->psd);
    size_t n_mob = (size_t)ceil(0.66 * area * (H - base + 2.0 * D) / vol_mean);
    size_t n_obs = sp->obstacles ? sp->obstacles->n_local : 0;
    s->n = n_mob + n_obs, s->n_mobile = n_mob;
    size_t n = s->n;
    s->x = calloc(3 * n, sizeof *s->x), s->v = calloc(3 * n, sizeof *s->v), s->w = calloc(3 * n, sizeof *s->w);
    s->f = calloc(3 * n, sizeof *s->f), s->t = calloc(3 * n, sizeof *s->t), s->x_ref = calloc(3 * n, sizeof(double));
    s->r = calloc(n, sizeof *s->r), s->m = calloc(n, sizeof *s->m), s->inv_i = calloc(n, sizeof *s->inv_i);
    s->wall_hist = calloc(n * PREP_MAX_WALLS * 3, sizeof(double));
    s->next = malloc(n * sizeof *s->next);
    if (!s->x || !s->v || !s->w || !s->f || !s->t || !s->x_ref || !s->r || !s->m || !s->inv_i || !s->wall_hist ||
        !s->next) {
        prep_free(s);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "packing: cannot allocate %zu grains", n);
    }
    /* loose jittered lattice, spacing 1.25 x the largest diameter (solid fraction ~0.3) */
    gf_rng rng;
    gf_rng_seed(&rng, sp->seed);
    double spacing = 2.2 * s->r_max, margin_w = 1.05 * s->r_max;
    int nl[3];
    double x0[3], step[3];
    for (int c = 0; c < 3; c += 2) {
        double avail = s->len[c] - (s->per[c] ? 0.0 : 2.0 * margin_w);
        nl[c] = (int)floor(avail / spacing) + (s->per[c] ? 0 : 1);
        if (nl[c] < 1)
            nl[c] = 1;
        step[c] = s->per[c] ? s->len[c] / nl[c] : (nl[c] > 1 ? avail / (nl[c] - 1) : 0.0);
        x0[c] = s->lo[c] + (s->per[c] ? 0.5 * step[c] : margin_w);
        if (!s->per[c] && nl[c] == 1)
            x0[c] = 0.5 * (s->lo[c] + s->hi[c]);
    }
    for (size_t i = 0; i < n_mob; ++i) {
        size_t layer = i / (size_t)(nl[0] * nl[2]), in = i % (size_t)(nl[0] * nl[2]);
        int a = (int)(in % (size_t)nl[0]), b = (int)(in / (size_t)nl[0]);
        double jit = 0.1 * (spacing - 2.0 * s->r_max);
        s->x[3 * i + 0] = x0[0] + a * step[0] + gf_rng_range(&rng, -jit, jit);
        s->x[3 * i + 1] = base + margin_w + 0.1 * D + (double)layer * spacing + gf_rng_range(&rng, -jit, jit);
        s->x[3 * i + 2] = x0[2] + b * step[2] + gf_rng_range(&rng, -jit, jit);
        s->r[i] = gf_psd_draw_radius_m(&sp->psd, &rng);
        for (int c = 0; c < 3; ++c)
            s->v[3 * i + c] = 0.1 * sqrt(g * D) * gf_rng_normal(&rng);
    }
    for (size_t k = 0; k < n_obs; ++k) {
        size_t i = n_mob + k;
        const gf_particles *o = sp->obstacles;
        s->x[3 * i] = o->x_m[k], s->x[3 * i + 1] = o->y_m[k], s->x[3 * i + 2] = o->z_m[k];
        s->r[i] = o->radius_m[k];
    }
    for (size_t i = 0; i < n; ++i) {
        s->m[i] = sp->density_kg_m3 * 4.0 / 3.0 * M_PI * s->r[i] * s->r[i] * s->r[i];
        s->inv_i[i] = 1.0 / (0.4 * s->m[i] * s->r[i] * s->r[i]);
    }
    /* walls: floor, and x / z planes where asked */
    s->wall[s->n_walls++] = (prep_wall){{0, sp->lo_m[1], 0}, {0, 1, 0}};
    const double back = sp->wall_setback_m;
    if (sp->walls_x && !s->per[0]) {
        s->wall[s->n_walls++] = (prep_wall){{sp->lo_m[0] - back, 0, 0}, {1, 0, 0}};
        s->wall[s->n_walls++] = (prep_wall){{sp->hi_m[0] + back, 0, 0}, {-1, 0, 0}};
    }
    if (sp->walls_z && !s->per[2]) {
        s->wall[s->n_walls++] = (prep_wall){{0, 0, sp->lo_m[2] - back}, {0, 0, 1}};
        s->wall[s->n_walls++] = (prep_wall){{0, 0, sp->hi_m[2] + back}, {0, 0, -1}};
    }
    prep_contacts(s, sp, PREP_TC_ND * sqrt(D / g), PREP_RESTITUTION, mu_prep);
    s->rolling = sp->free_pour;
    /* g tau = terminal speed PREP_TERMINAL_ND sqrt(gD); a free pour has no drag */
    s->tau = sp->free_pour ? INFINITY : PREP_TERMINAL_ND * sqrt(D / g);
    s->g = g;
    s->skin = PREP_SKIN_D * D;
    return prep_rebuild(ctx, s);
}

/* Runs until rest (mean kinetic energy per grain below PREP_REST_KE m g D) or the time limit. */
static gf_status prep_settle(gf_ctx *ctx, prep *s, double D)
{
    double t_unit = sqrt(D / s->g), m_mean = 0.0;
    for (size_t i = 0; i < s->n_mobile; ++i)
        m_mean += s->m[i] / (double)s->n_mobile;
    long max_steps = (long)(PREP_MAX_TIME_ND * t_unit / s->dt), check = (long)(0.5 * t_unit / s->dt) + 1;
    for (long step = 1; step <= max_steps; ++step) {
        prep_forces(s);
        if (prep_integrate(s) > 0.5 * s->skin)
            GF_TRY(prep_rebuild(ctx, s));
        if (step % check == 0) {
            double ke = 0.0;
            for (size_t i = 0; i < s->n_mobile; ++i)
                for (int c = 0; c < 3; ++c)
                    ke += 0.5 * s->m[i] * s->v[3 * i + c] * s->v[3 * i + c];
            if (ke / (double)s->n_mobile < PREP_REST_KE * m_mean * s->g * D && step * s->dt > 5.0 * t_unit) {
                gf_log(ctx, GF_LOG_DEBUG, "packing: settled after %.1f sqrt(D/g) (%ld steps, %zu pairs)",
                       step * s->dt / t_unit, step, s->n_pairs);
                return GF_OK;
            }
        }
    }
    return GF_OK; /* time limit: the deposit is measured as it is; the Phi check decides */
}

static void control_box(const gf_packing_spec *sp, double lo[3], double hi[3])
{
    double D = 2.0 * sp->psd.mean_radius_m;
    double m = sp->interior_margin_m > 0.0 ? sp->interior_margin_m : 1.5 * D;
    for (int c = 0; c < 3; ++c) {
        int open = c == 1 || !sp->periodic[c];
        lo[c] = sp->lo_m[c] + (open ? m : 0.0);
        hi[c] = sp->hi_m[c] - (open ? m : 0.0);
    }
    lo[1] = container_base_m(sp) + m;
}

/* Copies the mobile grains of s with centre at or below y_max into out (at rest). */
static gf_status prep_export(gf_ctx *ctx, const prep *s, const gf_packing_spec *sp, double y_max, gf_particles *out)
{
    for (size_t i = 0; i < s->n_mobile; ++i)
        if (s->x[3 * i + 1] <= y_max)
            GF_TRY(gf_particles_add(ctx, out, s->x[3 * i], s->x[3 * i + 1], s->x[3 * i + 2], s->r[i],
                                    sp->density_kg_m3, 0, NULL));
    return GF_OK;
}

static gf_status check_spec(gf_ctx *ctx, const gf_packing_spec *sp)
{
    GF_TRY(gf_psd_check(ctx, &sp->psd));
    double D = 2.0 * sp->psd.mean_radius_m;
    for (int c = 0; c < 3; ++c)
        if (!(sp->hi_m[c] - sp->lo_m[c] >= 2.0 * D))
            return GF_FAIL(ctx, GF_ERR_CONFIG, "packing: container axis %d is %g m long, below 2 D = %g m", c,
                           sp->hi_m[c] - sp->lo_m[c], 2.0 * D);
    if (sp->periodic[1])
        return GF_FAIL(ctx, GF_ERR_CONFIG, "packing: the vertical axis cannot be periodic");
    if (!(sp->density_kg_m3 > 0.0) || !(sp->gravity_m_s2 > 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "packing: grain density and gravity must be > 0");
    if (sp->relax.mu > 0.0 && !(sp->relax.t_contact_s > 0.0 && sp->relax.restitution > 0.0 &&
                                sp->relax.restitution <= 1.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "packing: the relaxation needs t_c > 0 and 0 < eps <= 1 (got %g s, %g)",
                       sp->relax.t_contact_s, sp->relax.restitution);
    if (sp->free_pour && !isnan(sp->phi_target))
        return GF_FAIL(ctx, GF_ERR_CONFIG,
                       "packing: a free pour takes the packing it reaches; phi_initial %g cannot be requested with it",
                       sp->phi_target);
    if (!isnan(sp->phi_target) && !(sp->phi_target >= 0.5 && sp->phi_target <= 0.645))
        return GF_FAIL(ctx, GF_ERR_PHYSICS,
                       "packing: phi_initial %g outside what deposition can build [0.50, 0.645]", sp->phi_target);
    return GF_OK;
}

double gf_packing_solid_fraction_box(const gf_particles *p, const double dom_lo[3], const double dom_hi[3],
                                     const int periodic[3], const double lo[3], const double hi[3], double h,
                                     int include_glued)
{
    long n[3];
    for (int c = 0; c < 3; ++c) {
        n[c] = (long)floor((hi[c] - lo[c]) / h);
        if (n[c] < 1)
            return NAN;
    }
    size_t total = (size_t)n[0] * (size_t)n[1] * (size_t)n[2];
    uint8_t *mark = calloc(total, 1);
    if (!mark)
        return NAN;
    /* lattice point (a, b, c) sits at lo + (index + 1/2) h: cell-centred sampling */
    for (size_t i = 0; i < p->n_local; ++i) {
        if (!include_glued && (p->flags[i] & GF_P_GLUED))
            continue;
        double r = p->radius_m[i];
        double ctr[3] = {p->x_m[i], p->y_m[i], p->z_m[i]};
        /* periodic images: shifts -L, 0, +L on periodic axes */
        for (int sx = -1; sx <= 1; ++sx)
            for (int sz = -1; sz <= 1; ++sz) {
                int shift[3] = {sx, 0, sz};
                double c3[3];
                int skip = 0;
                for (int c = 0; c < 3; ++c) {
                    if (shift[c] != 0 && !periodic[c]) {
                        skip = 1;
                        break;
                    }
                    c3[c] = ctr[c] + shift[c] * (dom_hi[c] - dom_lo[c]);
                }
                if (skip)
                    continue;
                long a0[3], a1[3];
                int empty = 0;
                for (int c = 0; c < 3; ++c) {
                    a0[c] = (long)ceil((c3[c] - r - lo[c]) / h - 0.5);
                    a1[c] = (long)floor((c3[c] + r - lo[c]) / h - 0.5);
                    if (a0[c] < 0)
                        a0[c] = 0;
                    if (a1[c] > n[c] - 1)
                        a1[c] = n[c] - 1;
                    if (a1[c] < a0[c])
                        empty = 1;
                }
                if (empty)
                    continue;
                double r2 = r * r;
                for (long a = a0[0]; a <= a1[0]; ++a) {
                    double dx = lo[0] + (a + 0.5) * h - c3[0];
                    for (long b = a0[1]; b <= a1[1]; ++b) {
                        double dy = lo[1] + (b + 0.5) * h - c3[1];
                        double rem = r2 - dx * dx - dy * dy;
                        if (rem < 0.0)
                            continue;
                        for (long k = a0[2]; k <= a1[2]; ++k) {
                            double dz = lo[2] + (k + 0.5) * h - c3[2];
                            if (dz * dz <= rem)
                                mark[((size_t)k * (size_t)n[1] + (size_t)b) * (size_t)n[0] + (size_t)a] = 1;
                        }
                    }
                }
            }
    }
    size_t count = 0;
    for (size_t q = 0; q < total; ++q)
        count += mark[q];
    free(mark);
    return (double)count / (double)total;
}

/* One deposit: settled prep state and its interior Phi. */
static gf_status deposit(gf_ctx *ctx, const gf_packing_spec *sp, double mu_prep, prep *s, double *phi_local)
{
    GF_TRY(check_spec(ctx, sp));
    GF_TRY(prep_setup(ctx, sp, mu_prep, s));
    gf_status st = prep_settle(ctx, s, 2.0 * sp->psd.mean_radius_m);
    if (st == GF_OK && sp->relax.mu > 0.0) {
        /* as the run will start: its contacts, unloaded tangential springs (gf_packing.h, step 3) */
        prep_contacts(s, sp, sp->relax.t_contact_s, sp->relax.restitution, sp->relax.mu);
        memset(s->hist, 0, 3 * s->n_pairs * sizeof *s->hist);
        memset(s->wall_hist, 0, s->n * PREP_MAX_WALLS * 3 * sizeof *s->wall_hist);
        st = prep_rebuild(ctx, s); /* the pairs' sqrt(m k_n) follow the new stiffness */
        if (st == GF_OK)
            st = prep_settle(ctx, s, 2.0 * sp->psd.mean_radius_m);
    }
    if (st != GF_OK) {
        prep_free(s);
        return st;
    }
    /* interior Phi of the untrimmed deposit: the control box ends a margin below H */
    gf_particles *tmp = NULL;
    st = gf_particles_create(ctx, s->n_mobile, &tmp);
    if (st == GF_OK)
        st = prep_export(ctx, s, sp, INFINITY, tmp);
    if (st != GF_OK) {
        gf_particles_destroy(&tmp);
        prep_free(s);
        return st;
    }
    double lo[3], hi[3];
    control_box(sp, lo, hi);
    *phi_local = gf_packing_solid_fraction_box(tmp, sp->lo_m, sp->hi_m, sp->periodic, lo, hi,
                                               sp->psd.mean_radius_m / 8.0, 0);
    gf_particles_destroy(&tmp);
    return GF_OK;
}

gf_status gf_packing_deposit(gf_ctx *ctx, const gf_packing_spec *sp, double mu_prep, gf_particles *out,
                             double *phi_local)
{
    prep s;
    GF_TRY(deposit(ctx, sp, mu_prep, &s, phi_local));
    gf_status st = prep_export(ctx, &s, sp, INFINITY, out);
    prep_free(&s);
    return st;
}

/* First guess of mu_prep for a target, from the calibration of this protocol
 * (6D x 3D periodic footprint, 12D deep, seed 7): Phi = 0.6375 at mu = 0,
 * 0.612 at 0.1, 0.578 at 0.2, 0.557 at 0.3, 0.518 at 0.4; further up the
 * non-rolling grains arch across narrow boxes and the deposit becomes a
 * loose skeleton, hence MU_MAX = 0.4. Only a starting point. */
static double mu_guess(double phi)
{
    static const double tab_phi[] = {0.6375, 0.612, 0.578, 0.557, 0.518};
    static const double tab_mu[] = {0.0, 0.10, 0.20, 0.30, 0.40};
    int n = (int)(sizeof tab_phi / sizeof tab_phi[0]);
    if (phi >= tab_phi[0])
        return 0.0;
    for (int k = 1; k < n; ++k)
        if (phi >= tab_phi[k]) {
            double f = (tab_phi[k - 1] - phi) / (tab_phi[k - 1] - tab_phi[k]);
            return tab_mu[k - 1] + f * (tab_mu[k] - tab_mu[k - 1]);
        }
    return tab_mu[n - 1];
}

gf_status gf_packing_build(gf_ctx *ctx, const gf_packing_spec *sp, gf_particles *out, gf_packing_result *res)
{
    GF_TRY(check_spec(ctx, sp));
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    double tol = sp->tolerance > 0.0 ? sp->tolerance : 0.005;
    int max_it = sp->max_iterations > 0 ? sp->max_iterations : 8;
    const double MU_MAX = 0.4;
    prep best;
    memset(&best, 0, sizeof best);
    double best_phi = NAN, best_mu = NAN, best_err = INFINITY;
    int it = 0;
    if (isnan(sp->phi_target)) {
        GF_TRY(deposit(ctx, sp, sp->mu_natural, &best, &best_phi));
        best_mu = sp->mu_natural, it = 1;
    } else {
        /* bracket [mu_lo, mu_hi] with Phi(mu_lo) >= target >= Phi(mu_hi); Phi decreases with mu */
        double mu_lo = 0.0, phi_lo = NAN, mu_hi = MU_MAX, phi_hi = NAN;
        double mu = mu_guess(sp->phi_target);
        for (it = 1; it <= max_it; ++it) {
            prep s;
            double phi;
            gf_status st = deposit(ctx, sp, mu, &s, &phi);
            if (st != GF_OK) {
                prep_free(&best);
                return st;
            }
            double err = fabs(phi - sp->phi_target);
            gf_log(ctx, GF_LOG_INFO, "packing: deposit %d at mu_prep = %.4f: Phi_local = %.4f (target %.4f)", it, mu,
                   phi, sp->phi_target);
            if (err < best_err) {
                prep_free(&best);
                best = s, best_phi = phi, best_mu = mu, best_err = err;
            } else {
                prep_free(&s);
            }
            if (err <= tol)
                break;
            if (phi > sp->phi_target)
                mu_lo = mu, phi_lo = phi;
            else
                mu_hi = mu, phi_hi = phi;
            if (phi > sp->phi_target && mu >= MU_MAX) {
                prep_free(&best);
                return GF_FAIL(ctx, GF_ERR_PHYSICS,
                               "packing: phi_initial %.3f is looser than deposition reaches (%.3f at mu_prep = %g)",
                               sp->phi_target, phi, MU_MAX);
            }
            if (phi < sp->phi_target && mu <= 0.0) {
                prep_free(&best);
                return GF_FAIL(ctx, GF_ERR_PHYSICS,
                               "packing: phi_initial %.3f is denser than frictionless deposition reaches (%.3f)",
                               sp->phi_target, phi);
            }
            /* next mu: safeguarded regula falsi once both ends are measured (Phi is close to linear
             * in mu over the useful range), else a step of 0.05 towards the target */
            double next;
            if (!isnan(phi_lo) && !isnan(phi_hi)) {
                double f = (phi_lo - sp->phi_target) / (phi_lo - phi_hi);
                f = fmin(fmax(f, 0.2), 0.8); /* noise of a finite deposit: stay well inside the bracket */
                next = mu_lo + f * (mu_hi - mu_lo);
            } else if (isnan(phi_hi)) {
                next = fmin(MU_MAX, mu + 0.05);
            } else {
                next = fmax(0.0, mu - 0.05);
            }
            mu = next;
        }
        if (best_err > tol) {
            /* a small control box samples few grains: its Phi scatters by more than the tolerance */
            double lo[3], hi[3], D = 2.0 * sp->psd.mean_radius_m;
            control_box(sp, lo, hi);
            prep_free(&best);
            return GF_FAIL(ctx, GF_ERR_PHYSICS,
                           "packing: phi_initial %.4f not reached within %.2g in %d deposits (closest %.4f at "
                           "mu_prep = %.4f), measured over an interior box of %.1f x %.1f x %.1f D: a larger "
                           "container or a larger phi_tolerance may help",
                           sp->phi_target, tol, max_it, best_phi, best_mu, (hi[0] - lo[0]) / D, (hi[1] - lo[1]) / D,
                           (hi[2] - lo[2]) / D);
        }
    }
    /* trim at H and export */
    double H = sp->hi_m[1];
    size_t n_before = out->n_local;
    gf_status st = prep_export(ctx, &best, sp, H, out);
    prep_free(&best);
    GF_TRY(st);
    double vol = 0.0, top = 0.0;
    for (size_t i = n_before; i < out->n_local; ++i) {
        double r = out->radius_m[i];
        vol += 4.0 / 3.0 * M_PI * r * r * r;
        top = fmax(top, out->y_m[i] + r);
    }
    double footprint = (sp->hi_m[0] - sp->lo_m[0]) * (sp->hi_m[2] - sp->lo_m[2]);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    res->phi_global = vol / (footprint * (H - container_base_m(sp)));
    res->phi_local = best_phi;
    res->mu_prep = best_mu;
    res->iterations = it > max_it ? max_it : it;
    res->n_grains = out->n_local - n_before;
    res->top_m = top;
    res->cpu_s = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    res->reused = 0;
    return GF_OK;
}

gf_status gf_packing_rough_base(gf_ctx *ctx, gf_particles *out, const gf_psd *psd, double density, double y,
                                double x0, double x1, double z0, double z1, const int periodic_xz[2], uint64_t seed)
{
    GF_TRY(gf_psd_check(ctx, psd));
    if (!(x1 - x0 > 2.0 * psd->mean_radius_m) || !(z1 - z0 > 2.0 * psd->mean_radius_m))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "packing: rough base of %g x %g m is smaller than one grain", x1 - x0,
                       z1 - z0);
    gf_rng rng;
    gf_rng_seed(&rng, seed ^ 0x9e3779b97f4a7c15ull);
    double lx = x1 - x0, lz = z1 - z0;
    size_t first = out->n_local;
    for (int fails = 0; fails < 500;) {
        double r = gf_psd_draw_radius_m(psd, &rng);
        double x = x0 + lx * gf_rng_uniform(&rng), z = z0 + lz * gf_rng_uniform(&rng);
        /* non-periodic sides: keep the grain inside the strip */
        if ((!periodic_xz[0] && (x - r < x0 || x + r > x1)) || (!periodic_xz[1] && (z - r < z0 || z + r > z1))) {
            ++fails;
            continue;
        }
        int ok = 1;
        for (size_t j = first; j < out->n_local && ok; ++j) {
            double dx = out->x_m[j] - x, dz = out->z_m[j] - z;
            if (periodic_xz[0])
                dx -= lx * round(dx / lx);
            if (periodic_xz[1])
                dz -= lz * round(dz / lz);
            double rr = out->radius_m[j] + r;
            ok = dx * dx + dz * dz >= rr * rr;
        }
        if (!ok) {
            ++fails;
            continue;
        }
        fails = 0;
        GF_TRY(gf_particles_add(ctx, out, x, y, z, r, density, GF_P_GLUED, NULL));
    }
    return GF_OK;
}
