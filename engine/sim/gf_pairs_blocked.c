/*
 * The linear pair loop (the seeds' law, with or without Brenner lubrication),
 * in blocks of GF_PAIR_BLOCK candidates and three passes per block, so that
 * the costly part runs without branches and without scattered stores:
 *   1. scan: distance test of every neighbour pair of the rows; pairs in
 *      contact (or, with lubrication, within the lubrication range) are
 *      appended (branch-free compaction) with their pair vector; pairs beyond
 *      it forget their history (gf_nlist.h);
 *   2. compute: geometry, linear normal force and tangential spring of each
 *      contact, and the lubrication damping of each candidate within its range
 *      (the same expressions, in the same order, as gf_contact_linear_inline
 *      and gf_lubrication_damping: bitwise the results of the generic loop),
 *      with selects instead of branches, into per-candidate arrays; a loop with
 *      no dependence between candidates, vectorised (`omp simd`);
 *   3. scatter: the forces and torques are added to i (row sums) and
 *      subtracted from j in list order, exactly the order of the generic
 *      loop (gf_forces.c), so the sums are bitwise the same.
 * Measured on the settled bed of 1e4 grains: docs/notes/benchmarks.md.
 * Glued and sleeping grains (rare) take the decisions of the generic loop in
 * the scan; pairs of two frozen grains are skipped with their history kept.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "core/gf_clones.h"
#include "contact/gf_lubrication.h"
#include "gf_sim_internal.h"

#ifdef _OPENMP
#define GF_PRAGMA(x) _Pragma(#x)
#define GF_SIMD GF_PRAGMA(omp simd)
#else
#define GF_SIMD
#endif

#define GF_PAIR_BLOCK 256
/* Software prefetch in the scan (see scan_impl), from this many grains on:
 * below, the store stays in the last-level cache and the prefetches are
 * only instructions (docs/notes/benchmarks.md, "Prefetching the partners"). */
#define GF_PAIR_PREFETCH_MIN_GRAINS 25000
/* How many pairs ahead the scan prefetches a partner's position. */
#define GF_PAIR_PREFETCH_AHEAD 16

/* The compute pass is compiled for AVX-512 too (gathers, scatters, masked
 * selects: GCC vectorises the loop there and not for AVX2, which lacks
 * masked stores), chosen at load time. -ffp-contract=off (ISO C mode) keeps
 * both clones free of fused multiply-adds: they give the same bits. */

/* Candidate contacts of one block (pass 1) and their results (pass 2). */
typedef struct pair_block {
    /* 64-bit like the doubles (one vector length); k3 = 3 k, the history
     * offset (gathers through base + k3 vectorise, 3 k inside the loop does not) */
    int64_t i[GF_PAIR_BLOCK], j[GF_PAIR_BLOCK], k[GF_PAIR_BLOCK], k3[GF_PAIR_BLOCK];
    double dx[GF_PAIR_BLOCK], dy[GF_PAIR_BLOCK], dz[GF_PAIR_BLOCK], r2[GF_PAIR_BLOCK], rsum[GF_PAIR_BLOCK];
    double fx[GF_PAIR_BLOCK], fy[GF_PAIR_BLOCK], fz[GF_PAIR_BLOCK];
    double ti[3][GF_PAIR_BLOCK], tj[3][GF_PAIR_BLOCK]; /* torque terms R_i n x F_t, R_j n x F_t */
    double overlap[GF_PAIR_BLOCK];
} pair_block;

/* Row sums of the row being scattered, and the row's force before them
 * (base): fx[i] = base + sums is stored after every contact, so the last
 * store is the generic loop's single fx[i] += row sum without a branch at
 * row changes. They outlive a block (a row may be split between blocks). */
typedef struct row_sums {
    int64_t i;
    double base[6], f[6];
} row_sums;

/* The pairs the loop runs over, and their per-pair data: the neighbour
 * list's, or the near list's (gf_near_list.c), which holds the same fields
 * for its pairs only. */
typedef struct pair_view {
    const int32_t *i, *j;
    const uint8_t *image;
    uint8_t *touching;
    double *hist;
    const double *sqrt_mk, *meff;
} pair_view;

/* The lines of candidate k that the force and scatter passes of this block
 * will read (partner j's predicted velocity, velocity, spin; the pair's
 * damping scale) and write (j's force and torque; the pair's tangential
 * history, 24 bytes that may straddle two lines): requested now, they arrive
 * while the scan goes on. The history is a stream the scan itself does not
 * read, so nothing else brings it in before the force pass gathers it.
 * Into the L2 only (locality 2, prefetcht1): a block's ~200 candidates make
 * ~3500 requests, several times the 512 lines of a 32 kB L1, so lines sent
 * to the L1 pushed out each other and the lines the passes were reading
 * (docs/notes/benchmarks.md, "Prefetching into the L2"). */
static inline __attribute__((always_inline)) void prefetch_candidate(const gf_sim *s, const pair_view *v, int32_t j,
                                                                     size_t k)
{
    const gf_particles *p = s->p;
    const double *const rd[9] = {s->nb.vx_pred, s->nb.vy_pred, s->nb.vz_pred, p->vx_m_s, p->vy_m_s,
                                 p->vz_m_s,  p->wx_rad_s, p->wy_rad_s, p->wz_rad_s};
    const double *const wr[6] = {p->fx_N, p->fy_N, p->fz_N, p->tx_N_m, p->ty_N_m, p->tz_N_m};
    for (int q = 0; q < 9; ++q)
        __builtin_prefetch(rd[q] + j, 0, 2);
    for (int q = 0; q < 6; ++q)
        __builtin_prefetch(wr[q] + j, 1, 2);
    __builtin_prefetch(v->hist + 3 * k, 1, 2), __builtin_prefetch(v->hist + 3 * k + 2, 1, 2);
    __builtin_prefetch(v->sqrt_mk + k, 0, 2);
}

/* Pass 1, pairs [*pk, k1) of the view: appends up to GF_PAIR_BLOCK
 * candidates. flagged = 0: no grain the rows reach is glued or sleeping (the
 * common case), so the flag tests are compiled out. prefetch: a store too
 * large for the caches, whose partners' lines the passes would wait for one
 * by one (the hottest instructions of a 1e5-grain bed were the first loads of
 * each partner's position and force): the scan requests the position of the
 * partner GF_PAIR_PREFETCH_AHEAD pairs ahead and the other lines of each
 * candidate (prefetch_candidate). */
static inline __attribute__((always_inline)) size_t scan_impl(const gf_sim *s, const pair_view *v, size_t *pk,
                                                              size_t k1, pair_block *b, const int flagged,
                                                              const int lub, const int prefetch)
{
    const double lub_cut = s->lub_cutoff_m;
    const gf_particles *p = s->p;
    const gf_nlist *nl = s->nb.nl;
    const double *x = p->x_m, *y = p->y_m, *z = p->z_m, *R = p->radius_m;
    const uint8_t *flags = p->flags;
    const int32_t *pi = v->i, *pj = v->j;
    const uint8_t *image = v->image;
    uint8_t *touching = v->touching;
    double *hist = v->hist;
    size_t k = *pk, nc = 0;
    const size_t kstop = k1 - k < GF_PAIR_BLOCK ? k1 : k + GF_PAIR_BLOCK; /* at most one candidate per pair */
    for (; k < kstop; ++k) {
        const int32_t i = pi[k], j = pj[k];
        if (prefetch) {
            const int32_t ja = pj[k + GF_PAIR_PREFETCH_AHEAD < k1 ? k + GF_PAIR_PREFETCH_AHEAD : k];
            __builtin_prefetch(x + ja, 0, 3), __builtin_prefetch(y + ja, 0, 3), __builtin_prefetch(z + ja, 0, 3);
            __builtin_prefetch(R + ja, 0, 3);
        }
        const double *sh = nl->shift_m[image[k]];
        double dx = x[i] - x[j] + sh[0], dy = y[i] - y[j] + sh[1], dz = z[i] - z[j] + sh[2];
        double r2 = dx * dx + dy * dy + dz * dz, rsum = R[i] + R[j], reach = lub ? rsum + lub_cut : rsum;
        int in = r2 < reach * reach;
        const uint8_t fi = flagged ? flags[i] : 0, fl = flagged ? fi | flags[j] : 0;
        if (fl) { /* glued or sleeping: the generic loop's decisions */
            const uint8_t frozen = GF_P_GLUED | GF_P_SLEEPING;
            if ((fi & frozen) && (flags[j] & frozen) && (fl & GF_P_SLEEPING))
                continue; /* neither grain moves: history kept */
            in &= !((fi & GF_P_GLUED) && (flags[j] & GF_P_GLUED));
        }
        b->i[nc] = i, b->j[nc] = j, b->k[nc] = (int64_t)k, b->k3[nc] = 3 * (int64_t)k;
        b->dx[nc] = dx, b->dy[nc] = dy, b->dz[nc] = dz, b->r2[nc] = r2, b->rsum[nc] = rsum;
        if (prefetch && in) /* a candidate: the force and scatter passes will need its partner and history */
            prefetch_candidate(s, v, j, k);
        nc += (size_t)in;
        if (touching[k] & (in ^ 1)) { /* separated (rare; one predictable branch): forget the history */
            hist[3 * k] = hist[3 * k + 1] = hist[3 * k + 2] = 0.0;
            touching[k] = 0;
        }
    }
    *pk = k;
    return nc;
}

/* The eight cases compiled apart (flags seen or not, lubrication range or
 * contact only, prefetching or not). */
static size_t scan(const gf_sim *s, const pair_view *v, size_t *pk, size_t k1, pair_block *b, int flagged, int pf)
{
    if (pf) {
        if (s->lubrication)
            return flagged ? scan_impl(s, v, pk, k1, b, 1, 1, 1) : scan_impl(s, v, pk, k1, b, 0, 1, 1);
        return flagged ? scan_impl(s, v, pk, k1, b, 1, 0, 1) : scan_impl(s, v, pk, k1, b, 0, 0, 1);
    }
    if (s->lubrication)
        return flagged ? scan_impl(s, v, pk, k1, b, 1, 1, 0) : scan_impl(s, v, pk, k1, b, 0, 1, 0);
    return flagged ? scan_impl(s, v, pk, k1, b, 1, 0, 0) : scan_impl(s, v, pk, k1, b, 0, 0, 0);
}

/* Pass 2: the force of each candidate (gf_contact_linear_inline and
 * gf_contact_tangential_inline, equations in gf_contact.h, written with
 * selects). A candidate whose overlap rounds to <= 0 gets no force and a
 * zero history, as in the generic loop. */
static inline __attribute__((always_inline)) void compute_impl(const gf_sim *s, const pair_view *v,
                                                               pair_block *restrict b, size_t nc, const int lub)
{
    const gf_particles *p = s->p;
    const double *restrict R = p->radius_m;
    const double *restrict vpx = s->nb.vx_pred, *restrict vpy = s->nb.vy_pred, *restrict vpz = s->nb.vz_pred;
    const double *restrict vx = p->vx_m_s, *restrict vy = p->vy_m_s, *restrict vz = p->vz_m_s;
    const double *restrict wx = p->wx_rad_s, *restrict wy = p->wy_rad_s, *restrict wz = p->wz_rad_s;
    const double *restrict sqrt_mk = v->sqrt_mk, *restrict meff = v->meff;
    const double lub_cut = s->lub_cutoff_m, eta = s->lub_eta_Pa_s, rough = s->lub_roughness_m;
    const int in_overlap = s->lub_overlap == GF_LUB_OVERLAP_CLAMP; /* film: the generic loop (gf_sim.c) */
    double *restrict hx = v->hist, *restrict hy = hx + 1, *restrict hz = hx + 2; /* disjoint elements */
    const double dt = s->dt_s, mu = s->cp.mu_grain, k_n = s->cp.k_n_N_m, two_zeta = 2.0 * s->cp.zeta;
    const double k_t = s->cp.kt_over_kn * s->cp.k_n_N_m, inv_k = k_t > 0.0 ? 1.0 / k_t : 0.0;
    const int clip = !s->cp.allow_attraction;
    GF_SIMD
    for (size_t c = 0; c < nc; ++c) {
        const int64_t i = b->i[c], j = b->j[c], k = b->k[c], k3 = b->k3[c];
        const double ri = R[i], rj = R[j];
        double r = sqrt(b->r2[c]), inv_r = 1.0 / r;
        double n0 = b->dx[c] * inv_r, n1 = b->dy[c] * inv_r, n2 = b->dz[c] * inv_r;
        double overlap = b->rsum[c] - r;
        int touch = overlap > 0.0;
        /* normal: F_n = k_n delta - gamma_n v_n, v_n from the predicted velocities */
        double v_n = (vpx[i] - vpx[j]) * n0 + (vpy[i] - vpy[j]) * n1 + (vpz[i] - vpz[j]) * n2;
        double f_n = k_n * overlap - two_zeta * sqrt_mk[k] * v_n;
        f_n = (f_n < 0.0 && clip) ? 0.0 : f_n;
        /* relative surface velocity u_i - u_j - (R_i w_i + R_j w_j) x n */
        double rw0 = ri * wx[i] + rj * wx[j], rw1 = ri * wy[i] + rj * wy[j], rw2 = ri * wz[i] + rj * wz[j];
        double u0 = (vx[i] - vx[j]) - (rw1 * n2 - rw2 * n1);
        double u1 = (vy[i] - vy[j]) - (rw2 * n0 - rw0 * n2);
        double u2 = (vz[i] - vz[j]) - (rw0 * n1 - rw1 * n0);
        /* tangential history: re-projection keeping the length (series for small q) */
        double h0 = hx[k3], h1 = hy[k3], h2 = hz[k3];
        double hn = h0 * n0 + h1 * n1 + h2 * n2;
        double len2 = h0 * h0 + h1 * h1 + h2 * h2;
        double q = hn * hn / (hn != 0.0 ? len2 : 1.0); /* every division and root below runs on every lane */
        double big = 1.0 / sqrt(q < 1.0 ? 1.0 - q : 1.0);
        double sq = q < 1e-4 ? 1.0 + q * (0.5 + 0.375 * q) : (q < 1.0 ? big : 0.0);
        double p0 = (h0 - hn * n0) * sq, p1 = (h1 - hn * n1) * sq, p2 = (h2 - hn * n2) * sq;
        h0 = hn != 0.0 ? p0 : h0, h1 = hn != 0.0 ? p1 : h1, h2 = hn != 0.0 ? p2 : h2;
        double un = u0 * n0 + u1 * n1 + u2 * n2;
        h0 += (u0 - un * n0) * dt;
        h1 += (u1 - un * n1) * dt;
        h2 += (u2 - un * n2) * dt;
        /* spring with the Coulomb cap */
        double t0 = -k_t * h0, t1 = -k_t * h1, t2 = -k_t * h2;
        double ft2 = t0 * t0 + t1 * t1 + t2 * t2, cap = mu * fabs(f_n);
        int slip = ft2 > cap * cap;
        double sc = cap / sqrt(slip ? ft2 : 1.0);
        t0 = slip ? t0 * sc : t0, t1 = slip ? t1 * sc : t1, t2 = slip ? t2 * sc : t2;
        h0 = slip ? -t0 * inv_k : h0, h1 = slip ? -t1 * inv_k : h1, h2 = slip ? -t2 * inv_k : h2;
        /* outputs; no contact: no force, no history */
        f_n = touch ? f_n : 0.0;
        t0 = touch ? t0 : 0.0, t1 = touch ? t1 : 0.0, t2 = touch ? t2 : 0.0;
        hx[k3] = touch ? h0 : 0.0, hy[k3] = touch ? h1 : 0.0, hz[k3] = touch ? h2 : 0.0;
        double F0 = f_n * n0 + t0, F1 = f_n * n1 + t1, F2 = f_n * n2 + t2;
        if (lub) { /* Brenner damping, gf_lubrication_damping with selects (gap clamped at 0 in overlap) */
            double gap = overlap > 0.0 ? 0.0 : -overlap, reff = ri * rj / b->rsum[c], m = meff[k];
            double c_b = 6.0 * M_PI * eta * reff * reff / (gap + rough);
            double xl = c_b * dt / m, cap = 0.25 * m / dt;
            double c_eff = c_b * gf_lubrication_phi1(xl);
            c_eff = c_eff < cap ? c_eff : cap;
            c_eff = xl >= 0.29 ? cap : c_eff;
            c_eff = (m > 0.0 && m <= DBL_MAX) ? c_eff : c_b; /* not a finite positive mass: undamped Brenner */
            double cl = -c_eff * v_n;
            int in_range = gap <= lub_cut && (in_overlap || overlap <= 0.0);
            F0 = in_range ? F0 + cl * n0 : F0, F1 = in_range ? F1 + cl * n1 : F1, F2 = in_range ? F2 + cl * n2 : F2;
        }
        b->fx[c] = F0, b->fy[c] = F1, b->fz[c] = F2;
        double x0 = n1 * t2 - n2 * t1, x1 = n2 * t0 - n0 * t2, x2 = n0 * t1 - n1 * t0; /* n x F_t */
        b->ti[0][c] = ri * x0, b->ti[1][c] = ri * x1, b->ti[2][c] = ri * x2;
        b->tj[0][c] = rj * x0, b->tj[1][c] = rj * x1, b->tj[2][c] = rj * x2;
        b->overlap[c] = overlap;
    }
}

GF_AVX512_CLONES static void compute_dry(const gf_sim *s, const pair_view *v, pair_block *restrict b, size_t nc)
{
    compute_impl(s, v, b, nc, 0);
}

GF_AVX512_CLONES static void compute_lub(const gf_sim *s, const pair_view *v, pair_block *restrict b, size_t nc)
{
    compute_impl(s, v, b, nc, 1);
}

/* Pass 3: forces on i into the row sums, on j subtracted in place, in list order. */
static void scatter(const pair_view *v, const pair_block *b, size_t nc, double *const f[6], row_sums *rs,
                    gf_sim_accum *acc)
{
    uint8_t *touching = v->touching;
    size_t n_contacts = 0;
    double max_overlap = acc->max_overlap_m;
    for (size_t c = 0; c < nc; ++c) {
        const size_t i = (size_t)b->i[c], j = (size_t)b->j[c];
        const int new_row = b->i[c] != rs->i;
        const double F[6] = {b->fx[c], b->fy[c], b->fz[c], -b->ti[0][c], -b->ti[1][c], -b->ti[2][c]};
        for (int q = 0; q < 6; ++q) { /* selects, not branches: rows change every few contacts */
            rs->base[q] = new_row ? f[q][i] : rs->base[q];
            rs->f[q] = (new_row ? 0.0 : rs->f[q]) + F[q];
            f[q][i] = rs->base[q] + rs->f[q];
        }
        rs->i = b->i[c];
        double *const *fj = j < acc->far_from ? f : acc->far; /* partner in a later chunk: its buffer */
        fj[3][j] -= b->tj[0][c], fj[4][j] -= b->tj[1][c], fj[5][j] -= b->tj[2][c];
        fj[0][j] -= b->fx[c], fj[1][j] -= b->fy[c], fj[2][j] -= b->fz[c];
        const double ov = b->overlap[c];
        const int touch = ov > 0.0;
        touching[b->k[c]] = (uint8_t)touch;
        n_contacts += (size_t)touch;
        max_overlap = touch && ov > max_overlap ? ov : max_overlap;
    }
    acc->n_contacts += n_contacts;
    acc->max_overlap_m = max_overlap;
}

/* The rows [*done, upto) are complete (every pair that adds to their grains
 * has been scattered): their walls, and with finish their step's end and the
 * next step's drift (gf_sim_finish_rows), while their lines are still in the
 * caches. Batches of whole cache lines of doubles (8 grains). prefetch: the
 * finish's own arrays for a batch as long again are requested, so that they
 * arrive while the next rows run (docs/notes/benchmarks.md, "Prefetching into the
 * L2"). */
static void finish_rows(gf_sim *s, size_t *done, size_t upto, double *const f[6], gf_sim_accum *acc,
                        gf_drift_d2 *d2, int last, int prefetch, size_t i1)
{
    if (!last)
        upto &= ~(size_t)7;
    if (upto <= *done || (!last && upto < *done + 64))
        return;
    gf_drift_d2 both[2] = {*d2, gf_sim_finish_rows(s, *done, upto, f, acc)};
    *d2 = gf_drift_d2_max(both, 2);
    if (prefetch && !last) {
        const size_t next = upto + (upto - *done);
        gf_sim_prefetch_finish(s, upto, next < i1 ? next : i1);
    }
    *done = upto;
}

gf_drift_d2 gf_sim_pair_rows_blocked_linear(gf_sim *s, size_t i0, size_t i1, double *const f[6], gf_sim_accum *acc,
                                            int finish)
{
    pair_block b;
    row_sums rs = {.i = -1};
    const gf_nlist *nl = s->nb.nl;
    size_t k = nl->row_start[i0], k1 = nl->row_start[i1];
    pair_view v = {nl->i, nl->j, nl->image, nl->touching, nl->hist, s->nb.pair_sqrt_mk, s->nb.pair_meff};
    const gf_near_list *nr = &s->nb.near;
    if (nr->use) { /* the rows' near list (gf_near_list.c), stored from the same offset */
        v = (pair_view){nr->i, nr->j, nr->image, nr->touching, nr->hist, nr->sqrt_mk, nr->meff};
        k1 = k + nr->len[acc - s->acc]; /* acc is the accumulator of these rows' chunk */
    }
    uint8_t any = 0; /* the rows reach grains >= i0 only (j > i) */
    for (size_t g = i0; g < nl->n; ++g)
        any |= s->p->flags[g];
    const int prefetch = nl->n >= GF_PAIR_PREFETCH_MIN_GRAINS;
    gf_drift_d2 d2 = {0.0, 0.0};
    size_t done = i0;
    while (k < k1) {
        size_t nc = scan(s, &v, &k, k1, &b, any != 0, prefetch);
        if (s->lubrication)
            compute_lub(s, &v, &b, nc);
        else
            compute_dry(s, &v, &b, nc);
        scatter(&v, &b, nc, f, &rs, acc);
        if (finish) /* the rows before the next pair's are complete */
            finish_rows(s, &done, k < k1 ? (size_t)v.i[k] : i1, f, acc, &d2, 0, prefetch, i1);
    }
    if (finish)
        finish_rows(s, &done, i1, f, acc, &d2, 1, prefetch, i1);
    return d2;
}
