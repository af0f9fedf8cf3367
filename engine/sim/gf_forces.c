/*
 * Force evaluation of the step loop: grain-grain contacts and Brenner
 * lubrication over the Verlet half list, grain-wall contacts and lubrication
 * (the list itself is kept by gf_neighbours.c).
 *
 * Geometry (Izard 2014 §2.1.1, (2.4)-(2.6)): n = (x_i - x_j)/|x_i - x_j|
 * points from j to i, overlap delta = R_i + R_j - |x_i - x_j| > 0 in contact,
 * relative surface velocity at the contact point
 *     u_rel = u_i - u_j - (R_i w_i + R_j w_j) x n     (Djouwe 2012 §1.1),
 * effective mass m* = 1/(1/m_i + 1/m_j) with 1/m = 0 for glued grains and
 * walls (infinite mass; a wall is also an infinite radius: m* = m_i, torque
 * arm R_i). Force on i: F_n n + F_t; on j its opposite. Torques
 * r_c x F_t: -R_i n x F_t on i and -R_j n x F_t on j (both arms point to the
 * contact point, the force on j is -F_t).
 *
 * Lubrication (Brenner 1961 with effective roughness eta_e; Izard 2014 (2.36),
 * (3.18)), normal only, on i:
 *     F = -6 pi eta_f ((u_i - u_j).n) / (gap + eta_e) (R_i R_j/(R_i+R_j))^2 n
 * active for gap <= cutoff (lub_cutoff_over_R x mean R); during overlap the
 * gap is clamped at 0 (constant damping 6 pi eta R_eff^2/eta_e, the damping the
 * rebound model of Izard 2014 §3.1 assumes in contact, eq. (3.26); the default),
 * the force is off (the contact law alone) or the gap is the elastic film's
 * (eq. (3.28)), as fluid.lub_overlap says (gf_lubrication.h); wall:
 * R_eff^2 -> R_i^2.
 *
 * OpenMP: a half list races on j, so the rows are cut into one pair-balanced
 * chunk per configured thread. Each chunk adds into the particle store the
 * forces on its own rows and on partners inside it, and into a buffer of its
 * own those on partners in later chunks (j > i: a chunk never reaches back);
 * after a barrier each thread adds the earlier chunks' buffers to its grains,
 * over the runs of grains they reach (gf_nlist reach runs: on a store sorted
 * across the cut, one layer of grains). Not a full list, which would compute
 * every contact twice. Each pair's history belongs
 * to its row's chunk. With a fixed thread count the result is bitwise
 * reproducible (restart identity relies on it).
 */
#include <math.h>
#include <sched.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "contact/gf_contact_kernels.h"
#include "core/gf_soa.h"
#include "contact/gf_lubrication.h"
#include "gf_sim_internal.h"
#include "integrate/gf_integrate.h"

/* Grain-grain pairs of rows [i0, i1) into the accumulators f[0..5] (fx..tz).
 * Specialised on the law: linear (the seeds' law, inlined) or any table row;
 * normal_only: the linear normal law alone (mu_c = 0, GF_SKIP_TANGENTIAL). */
static inline __attribute__((always_inline)) void pair_rows_impl(gf_sim *s, size_t i0, size_t i1,
                                                                 double *const f[6], gf_sim_accum *acc,
                                                                 const int linear, const int normal_only)
{
    const gf_particles *p = s->p;
    const gf_nlist *nl = s->nb.nl;
    const double *x = p->x_m, *y = p->y_m, *z = p->z_m, *R = p->radius_m;
    const double *restrict pair_meff = s->nb.pair_meff, *restrict pair_sqrt_mk = s->nb.pair_sqrt_mk;
    uint8_t *restrict touching = nl->touching;
    double *restrict hist = nl->hist;
    const double lub_cut = s->lubrication ? s->lub_cutoff_m : 0.0;
    const double dt = s->dt_s, mu = s->cp.mu_grain;
    const gf_contact_params cp = s->cp; /* local copy: history stores cannot alias it */
    size_t n_contacts = 0;
    double max_overlap = acc->max_overlap_m;
    const double *vpx = s->nb.vx_pred, *vpy = s->nb.vy_pred, *vpz = s->nb.vz_pred;
    gf_contact_kernel *kernel = s->law->kernel;
    for (size_t i = i0; i < i1; ++i) {
        const double xi = x[i], yi = y[i], zi = z[i], ri = R[i];
        const int glued_i = p->flags[i] & GF_P_GLUED;
        const int frozen_i = p->flags[i] & (GF_P_GLUED | GF_P_SLEEPING);
        double fxi = 0.0, fyi = 0.0, fzi = 0.0, txi = 0.0, tyi = 0.0, tzi = 0.0; /* row sums, stored once */
        for (size_t k = nl->row_start[i]; k < nl->row_start[i + 1]; ++k) {
            const size_t j = (size_t)nl->j[k];
            /* two grains that do not move (sleeping or glued, at least one
             * sleeping): neither force is integrated; the pair keeps its
             * history for when one of them wakes (gf_sleep.c) */
            if (frozen_i && (p->flags[j] & (GF_P_GLUED | GF_P_SLEEPING)) &&
                ((p->flags[i] | p->flags[j]) & GF_P_SLEEPING))
                continue;
            double *const *fj = j < acc->far_from ? f : acc->far; /* partner in a later chunk: its buffer */
            const double *sh = nl->shift_m[nl->image[k]];
            double d[3] = {xi - x[j] + sh[0], yi - y[j] + sh[1], zi - z[j] + sh[2]};
            double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            double rsum = ri + R[j], reach = rsum + lub_cut;
            double *h = &hist[3 * k];
            if (r2 >= reach * reach || (glued_i && (p->flags[j] & GF_P_GLUED))) {
                if (touching[k]) { /* the pair separated: forget its history */
                    h[0] = h[1] = h[2] = 0.0;
                    touching[k] = 0;
                }
                continue;
            }
            double r = sqrt(r2), inv_r = 1.0 / r;
            gf_contact_geom g;
            g.n[0] = d[0] * inv_r, g.n[1] = d[1] * inv_r, g.n[2] = d[2] * inv_r;
            g.overlap_m = rsum - r;
            double F[3] = {0.0, 0.0, 0.0};
            double vp[3] = {vpx[i] - vpx[j], vpy[i] - vpy[j], vpz[i] - vpz[j]};
            g.v_n_m_s = vp[0] * g.n[0] + vp[1] * g.n[1] + vp[2] * g.n[2];
            if (normal_only && g.overlap_m > 0.0) {
                const double f_n = gf_contact_linear_normal_inline(&cp, &g, pair_sqrt_mk[k]);
                F[0] = f_n * g.n[0], F[1] = f_n * g.n[1], F[2] = f_n * g.n[2];
                touching[k] = 1;
                n_contacts++;
                max_overlap = g.overlap_m > max_overlap ? g.overlap_m : max_overlap;
            } else if (g.overlap_m > 0.0) {
                double vt[3] = {p->vx_m_s[i] - p->vx_m_s[j], p->vy_m_s[i] - p->vy_m_s[j], p->vz_m_s[i] - p->vz_m_s[j]};
                double rw[3] = {ri * p->wx_rad_s[i] + R[j] * p->wx_rad_s[j], ri * p->wy_rad_s[i] + R[j] * p->wy_rad_s[j],
                                ri * p->wz_rad_s[i] + R[j] * p->wz_rad_s[j]};
                double rwn[3];
                gf_cross(rw, g.n, rwn);
                g.v_rel_m_s[0] = vt[0] - rwn[0], g.v_rel_m_s[1] = vt[1] - rwn[1], g.v_rel_m_s[2] = vt[2] - rwn[2];
                /* glued grains: infinite mass, 1/m = 0 (contact_inv_mass) */
                g.m_eff_kg = pair_meff[k];
                g.sqrt_mk = pair_sqrt_mk[k];
                touching[k] = 1;
                g.mu = mu;
                double f_n, f_t[3];
                if (linear)
                    gf_contact_linear_inline(&cp, &g, dt, h, &f_n, f_t);
                else
                    kernel(&cp, &g, dt, h, &f_n, f_t);
                F[0] = f_n * g.n[0] + f_t[0], F[1] = f_n * g.n[1] + f_t[1], F[2] = f_n * g.n[2] + f_t[2];
                double nxt[3];
                gf_cross(g.n, f_t, nxt);
                txi -= ri * nxt[0], tyi -= ri * nxt[1], tzi -= ri * nxt[2];
                fj[3][j] -= R[j] * nxt[0], fj[4][j] -= R[j] * nxt[1], fj[5][j] -= R[j] * nxt[2];
                n_contacts++;
                max_overlap = g.overlap_m > max_overlap ? g.overlap_m : max_overlap;
            } else if (touching[k]) {
                h[0] = h[1] = h[2] = 0.0;
                touching[k] = 0;
            }
            if (lub_cut > 0.0) {
                double reff = ri * R[j] / rsum;
                double gap = g.overlap_m > 0.0 ? gf_lubrication_overlap_gap(s->lub_overlap, reff, s->lub_eta_Pa_s,
                                                                            cp.k_n_N_m, pair_meff[k], g.v_n_m_s,
                                                                            g.overlap_m)
                                               : -g.overlap_m;
                if (gap <= lub_cut && (s->lub_overlap != GF_LUB_OVERLAP_OFF || g.overlap_m <= 0.0)) {
                    double c = -gf_lubrication_damping(s->dt_s, 6.0 * M_PI * s->lub_eta_Pa_s * reff * reff / (gap + s->lub_roughness_m),
                                            pair_meff[k]) * g.v_n_m_s;
                    F[0] += c * g.n[0], F[1] += c * g.n[1], F[2] += c * g.n[2];
                }
            }
            fxi += F[0], fyi += F[1], fzi += F[2];
            fj[0][j] -= F[0], fj[1][j] -= F[1], fj[2][j] -= F[2];
        }
        f[0][i] += fxi, f[1][i] += fyi, f[2][i] += fzi;
        f[3][i] += txi, f[4][i] += tyi, f[5][i] += tzi;
    }
    acc->n_contacts += n_contacts;
    acc->max_overlap_m = max_overlap;
}

static void pair_rows_linear(gf_sim *s, size_t i0, size_t i1, double *const f[6], gf_sim_accum *acc)
{
    pair_rows_impl(s, i0, i1, f, acc, 1, 0);
}

static void pair_rows_linear_normal(gf_sim *s, size_t i0, size_t i1, double *const f[6], gf_sim_accum *acc)
{
    pair_rows_impl(s, i0, i1, f, acc, 1, 1);
}

static void pair_rows_table(gf_sim *s, size_t i0, size_t i1, double *const f[6], gf_sim_accum *acc)
{
    pair_rows_impl(s, i0, i1, f, acc, 0, 0);
}

static gf_status reserve_accumulators(gf_sim *s, size_t n)
{
    for (int t = 0; t + 1 < s->nb.nl->n_chunks; ++t) { /* the last chunk has no partners beyond it */
        gf_sim_accum *a = &s->acc[t];
        if (a->cap >= n)
            continue;
        /* contents need not survive: each chunk clears its buffer before use */
        void *fresh[6];
        void *block = gf_soa_alloc(6, sizeof(double), n + 1, GF_SOA_LINE_SIM + 10 + 6 * (size_t)t, fresh, NULL, 0);
        if (!block)
            return GF_FAIL(s->ctx, GF_ERR_NOMEM, "sim: cannot allocate thread force buffers");
        gf_soa_free(a->buf_block);
        a->buf_block = block;
        for (int c = 0; c < 6; ++c)
            a->buf[c] = fresh[c];
        a->cap = n;
    }
    return GF_OK;
}

/* Chunk c's destinations: the store for its rows and the partners before
 * its end; its buffer, cleared over the reach runs, for the partners beyond
 * (the last chunk has none: everything into the store). */
static void open_chunk(gf_sim *s, int c, double *const store[6], size_t n)
{
    const gf_nlist *nl = s->nb.nl;
    gf_sim_accum *a = &s->acc[c];
    a->n_contacts = 0;
    a->max_overlap_m = 0.0;
    memset(a->wall_force_N, 0, sizeof a->wall_force_N);
    const int last = c + 1 == nl->n_chunks;
    a->far_from = last ? n : nl->chunk_row[c + 1];
    for (int q = 0; q < 6; ++q)
        a->far[q] = last ? store[q] : a->buf[q];
    if (last)
        return;
    for (size_t r = 0; r < nl->n_reach_runs; ++r) {
        size_t b = nl->reach_run[2 * r], e = nl->reach_run[2 * r + 1];
        b = b > a->far_from ? b : a->far_from;
        for (int q = 0; q < 6 && b < e; ++q)
            memset(a->far[q] + b, 0, (e - b) * sizeof(double));
    }
}

/* Adds to the grains of chunk c what the chunks before it sent them, in
 * chunk order, over the reach runs: by the thread that integrates chunk c,
 * once every chunk has run. */
static void add_from_earlier_chunks(const gf_sim *s, int c, double *const store[6])
{
    const gf_nlist *nl = s->nb.nl;
    const size_t lo = nl->chunk_row[c], hi = nl->chunk_row[c + 1];
    for (size_t r = 0; r < nl->n_reach_runs; ++r) {
        size_t b = nl->reach_run[2 * r], e = nl->reach_run[2 * r + 1];
        b = b > lo ? b : lo, e = e < hi ? e : hi;
        for (size_t j = b; j < e; ++j)
            for (int u = 0; u < c; ++u)
                for (int q = 0; q < 6; ++q)
                    store[q][j] += s->acc[u].far[q][j];
    }
}

/* Waits until every chunk before c has finished its pair rows of force
 * evaluation `count` (a short wait: the thread drifts its own grains first). */
static void wait_for_earlier_chunks(gf_sim *s, int c, unsigned long count)
{
    for (int u = 0; u < c; ++u)
        for (unsigned spins = 0; atomic_load_explicit(&s->acc[u].pairs_done, memory_order_acquire) != count; ++spins)
            if (spins > 1u << 12)
                sched_yield();
}

/* Pair and wall rows of chunk c into the store and the chunk's buffer; then
 * publishes that the chunk is done with the other chunks' grains. own: the
 * thread that runs the chunk also finishes its grains (one chunk per
 * thread, complete_chunks). */
static void run_chunk(gf_sim *s, int c, double *const store[6], size_t n, unsigned long count, int own)
{
    gf_sim_accum *a = &s->acc[c];
    const size_t i0 = s->nb.nl->chunk_row[c], i1 = s->nb.nl->chunk_row[c + 1];
    a->finished = 0;
    a->finish_s = 0.0;
    open_chunk(s, c, store, n);
    if (s->law->kernel == gf_contact_linear && (s->skips & GF_SKIP_TANGENTIAL))
        pair_rows_linear_normal(s, i0, i1, store, a);
    else if (s->law->kernel == gf_contact_linear && s->opt.tuning.generic_pair_loop)
        pair_rows_linear(s, i0, i1, store, a);
    else if (s->law->kernel == gf_contact_linear) {
        if (s->nb.near.use && !s->nb.near.valid)
            gf_near_list_build_chunk(&s->nb, s->p, s->lubrication ? s->lub_cutoff_m : 0.0, c);
        /* a step that ends here, on the thread that finishes the chunk: the
         * grains no earlier chunk reaches are finished as their rows complete
         * (their forces are then whole, and no other row reads them) */
        a->finished = s->stepper.fuse && (s->nb.nl->n_chunks == 1 || own);
        a->finished_d2 = gf_sim_pair_rows_blocked_linear(s, i0, i1, store, a, a->finished);
    }
    else
        pair_rows_table(s, i0, i1, store, a);
    if (!a->finished)
        gf_sim_wall_rows(s, i0, i1, store, a);
    atomic_store_explicit(&a->pairs_done, count, memory_order_release);
}

/* Thread t of m, its chunks run: completes the forces of the grains it
 * integrates and, when the step asks for it (drift), finishes them
 * (gf_sim_finish_range: fluid forces, kicks, drift). Returns their largest
 * squared displacement since the build (0 without drift).
 * With one chunk per thread there is no barrier: the grains of a chunk
 * outside the reach runs get no force from other chunks and are read by
 * none, so its thread finishes them at once (in its pair loop, as their rows
 * complete, when the blocked loop runs: run_chunk); it then waits for the
 * earlier chunks' rows only, adds their buffers and finishes the rest (a
 * thread that would wait at a barrier for the slower chunk drifts
 * meanwhile). */
static gf_drift_d2 complete_chunks(gf_sim *s, int t, int m, int drift, double *const store[6], unsigned long count)
{
    const int nc = s->nb.nl->n_chunks;
    if (drift && nc == 1 && s->acc[0].finished) /* by the pair loop, row batch by row batch */
        return t == 0 ? s->acc[0].finished_d2 : (gf_drift_d2){0.0, 0.0};
    if (drift && m == nc && m > 1) {
        gf_drift_d2 d2[2];
        const size_t lo = s->nb.nl->chunk_row[t], hi = s->nb.nl->chunk_row[t + 1];
        d2[0] = s->acc[t].finished ? s->acc[t].finished_d2 : gf_sim_finish_runs(s, lo, hi, 0);
        wait_for_earlier_chunks(s, t, count);
        add_from_earlier_chunks(s, t, store);
        d2[1] = gf_sim_finish_runs(s, lo, hi, 1);
        return gf_drift_d2_max(d2, 2);
    }
    if (nc > 1) {
#ifdef _OPENMP
#pragma omp barrier
#endif
        for (int c = t; c < nc; c += m) /* by the thread that integrates them */
            add_from_earlier_chunks(s, c, store);
#ifdef _OPENMP
        if (drift && m > 1 && m != nc) { /* a thread finishes grains other than those it completed */
#pragma omp barrier
        }
#endif
    }
    return drift ? gf_sim_finish_share(s, t, m) : (gf_drift_d2){0.0, 0.0};
}

/* Contact counts, largest overlap and wall loads, summed over the chunks. */
static void sum_chunk_totals(gf_sim *s)
{
    s->n_contacts = 0;
    s->max_overlap_m = 0.0;
    for (int w = 0; w < s->n_walls; ++w)
        s->walls[w].force_N[0] = s->walls[w].force_N[1] = s->walls[w].force_N[2] = 0.0;
    for (int t = 0; t < s->nb.nl->n_chunks; ++t) {
        s->n_contacts += s->acc[t].n_contacts;
        if (s->acc[t].max_overlap_m > s->max_overlap_m)
            s->max_overlap_m = s->acc[t].max_overlap_m;
        for (int w = 0; w < s->n_walls; ++w)
            for (int c = 0; c < 3; ++c)
                s->walls[w].force_N[c] += s->acc[t].wall_force_N[w][c];
    }
}

gf_status gf_sim_compute_forces(gf_sim *s)
{
    gf_particles *p = s->p;
    size_t n = p->n_local;
    if (!s->nb.near.use) /* this evaluation runs over the whole list */
        gf_near_list_flush(&s->nb);
    if (s->nb.nl->n != n)
        GF_TRY(gf_sim_rebuild(s));
    GF_TRY(reserve_accumulators(s, n));
    GF_TRY(gf_sim_reserve(s, n));
    gf_step_state *stp = &s->stepper;
    if (stp->phase != GF_STEP_MOVED) { /* not called from a step: the dashpot sees v(t) itself */
        memcpy(s->nb.vx_pred, p->vx_m_s, n * sizeof(double));
        memcpy(s->nb.vy_pred, p->vy_m_s, n * sizeof(double));
        memcpy(s->nb.vz_pred, p->vz_m_s, n * sizeof(double));
    }
    /* the drift zeroed [0, n_moved) on the threads that own them */
    gf_particles_clear_forces_from(p, stp->phase == GF_STEP_MOVED ? stp->n_moved : 0);
    /* chunk c of the list (cost-balanced rows) accumulates into the store,
     * and its partners in later chunks into buffer c, added to them in chunk
     * order (open_chunk, add_from_earlier_chunks). The result depends on the
     * chunk count (the configured thread count) only, not on how many threads
     * actually run: small systems run the chunks serially, which avoids
     * fork/join costs that exceed the work below ~1000 grains. */
    double *store[6] = {p->fx_N, p->fy_N, p->fz_N, p->tx_N_m, p->ty_N_m, p->tz_N_m};
    const int drift = stp->fuse;
    gf_drift_d2 d2[GF_SIM_MAX_THREADS] = {{0.0, 0.0}};
    double drift_t0 = 0.0;
    int used = 1;
    const unsigned long count = ++s->force_count;
#ifdef _OPENMP
#pragma omp parallel num_threads(s->n_threads) if (s->n_threads > 1 && n >= GF_SIM_PARALLEL_MIN_GRAINS)
#endif
    {
        const gf_team team = gf_sim_team();
        const int t = team.t, m = team.m;
        for (int c = t; c < s->nb.nl->n_chunks; c += m)
            run_chunk(s, c, store, n, count, m == s->nb.nl->n_chunks);
        if (t == 0)
            used = m, drift_t0 = gf_wtime();
        d2[t] = complete_chunks(s, t, m, drift, store, count);
    }
    sum_chunk_totals(s);
    if (s->nb.near.use && !s->nb.near.valid) { /* every chunk built its part */
        s->nb.near.valid = s->nb.near.held = 1;
        s->nb.near.n_builds++;
    }
    if (!drift) {
        stp->phase = GF_STEP_AT_T;
        return GF_OK;
    }
    /* F(t + dt) is spent (the drift zeroed it) and v* is the next step's */
    stp->fused_s = gf_wtime() - drift_t0 + s->acc[0].finish_s; /* thread 0's drift, after the loop or inside it */
    stp->fused_d2 = gf_drift_d2_max(d2, used);
    stp->fused = 1;
    stp->phase = GF_STEP_MOVED;
    stp->n_moved = n;
    return GF_OK;
}
