/*
 * The integrator's passes over ranges of grains (integrate/gf_integrate.h),
 * shared by the step (gf_step.c) and the force pass that finishes a step
 * inside its region (gf_forces.c, gf_pairs_blocked.c): which grains a thread
 * integrates, the per-grain factors, and the step's end for a range of
 * grains (held fluid forces, closing half-kick, the next opening half-kick
 * and drift) once their forces are complete.
 */
#ifdef _OPENMP
#include <omp.h>
#endif

#include "coupling/gf_coupling.h"
#include "core/gf_timer.h"
#include "gf_sim_internal.h"
#include "integrate/gf_integrate.h"

/* The grains thread t of m integrates: its chunk's rows when the list has one
 * chunk per thread, so that a thread writes the grains whose forces it summed
 * and whose rows it ran (their cache lines stay on its core); else an even
 * split (the results do not depend on the split: each grain alone). */
void gf_sim_thread_grains(const gf_sim *s, size_t n, int t, int m, size_t *i0, size_t *i1)
{
    if (s->nb.nl->n_chunks == m && s->nb.nl->n == n) {
        *i0 = s->nb.nl->chunk_row[t], *i1 = s->nb.nl->chunk_row[t + 1];
        return;
    }
    *i0 = (size_t)((long)n * (long)t / m), *i1 = (size_t)((long)n * (long)(t + 1) / m);
}

/* The per-grain factors of the kicks; no inverse inertia: translation only
 * (no torque ever, GF_SKIP_TANGENTIAL). */
gf_integrate_factors gf_sim_integrate_factors(const gf_sim *s)
{
    const gf_neighbours *nb = &s->nb;
    return (gf_integrate_factors){nb->inv_mass, (s->skips & GF_SKIP_TANGENTIAL) ? NULL : nb->inv_inertia, nb->mobile};
}

/* The arrays the kicks and drift read besides the store: the displacement
 * references and the per-grain factors. Without a near list its
 * displacement is the build's: the same arrays, no second stream. */
static void drift_inputs(const gf_sim *s, gf_drift_refs *ref, gf_integrate_factors *k)
{
    const gf_neighbours *nb = &s->nb;
    const int near = nb->near.skin_m > 0.0;
    *ref = (gf_drift_refs){{nb->x_ref, nb->y_ref, nb->z_ref},
                           {near ? nb->x_near : nb->x_ref, near ? nb->y_near : nb->y_ref,
                            near ? nb->z_near : nb->z_ref}};
    *k = gf_sim_integrate_factors(s);
}

gf_drift_d2 gf_sim_kick_drift_range(gf_sim *s, size_t i0, size_t i1, int n_kicks)
{
    gf_drift_refs ref;
    gf_integrate_factors k;
    drift_inputs(s, &ref, &k);
    double *vp[3] = {s->nb.vx_pred, s->nb.vy_pred, s->nb.vz_pred};
    return gf_integrate_kick_drift(s->p, i0, i1, n_kicks, s->dt_s, s->gravity_m_s2, &ref, vp, &k);
}

gf_drift_d2 gf_sim_finish_range(gf_sim *s, size_t i0, size_t i1)
{
    if (s->coupling)
        gf_coupling_add_forces_range(s->coupling, s->p, i0, i1);
    return gf_sim_kick_drift_range(s, i0, i1, 2);
}

void gf_sim_prefetch_finish(const gf_sim *s, size_t i0, size_t i1)
{
    /* drift_inputs: the arrays only the finish reads (the pair loop has
     * brought the store's into the caches already) */
    gf_drift_refs ref;
    gf_integrate_factors k;
    drift_inputs(s, &ref, &k);
    const int near = ref.near[0] != ref.build[0];
    const double *const cold[9] = {ref.build[0], ref.build[1], ref.build[2],
                                   near ? ref.near[0] : NULL, near ? ref.near[1] : NULL, near ? ref.near[2] : NULL,
                                   k.inv_mass, k.mobile, k.inv_inertia};
    for (int q = 0; q < 9; ++q)
        for (size_t i = i0; cold[q] && i < i1; i += 8) /* a line holds 8 doubles */
            __builtin_prefetch(cold[q] + i, 0, 2);
}

gf_drift_d2 gf_sim_finish_share(gf_sim *s, int t, int m)
{
    size_t i0, i1;
    gf_sim_thread_grains(s, s->p->n_local, t, m, &i0, &i1);
    return gf_sim_finish_range(s, i0, i1);
}

/* The step's end and the next one's drift (gf_sim_finish_range) for the
 * grains of [i0, i1) outside the reach runs (in_runs 0; all of them with one
 * chunk, which has none) or inside them (1). The runs start on cache lines,
 * and so do the chunks and the pair loop's row batches. */
gf_drift_d2 gf_sim_finish_runs(gf_sim *s, size_t i0, size_t i1, int in_runs)
{
    const gf_nlist *nl = s->nb.nl;
    const size_t *run = nl->reach_run, n_runs = nl->n_reach_runs;
    size_t r = 0, hi = n_runs; /* the first run that ends after i0 (row batches call this often) */
    while (r < hi) {
        size_t mid = r + (hi - r) / 2;
        if (run[2 * mid + 1] <= i0)
            r = mid + 1;
        else
            hi = mid;
    }
    gf_drift_d2 d2[2] = {{0.0, 0.0}, {0.0, 0.0}};
    for (size_t at = i0; at < i1; ++r) {
        size_t b = r < n_runs && run[2 * r] < i1 ? run[2 * r] : i1;
        size_t e = r < n_runs && run[2 * r + 1] < i1 ? run[2 * r + 1] : i1;
        b = b > at ? b : at;
        const size_t from = in_runs ? b : at, to = in_runs ? e : b;
        if (from < to) {
            d2[1] = gf_sim_finish_range(s, from, to);
            d2[0] = gf_drift_d2_max(d2, 2);
        }
        at = e > at ? e : at;
        if (r >= n_runs)
            break;
    }
    return d2[0];
}

gf_drift_d2 gf_sim_finish_rows(gf_sim *s, size_t i0, size_t i1, double *const f[6], gf_sim_accum *acc)
{
    gf_sim_wall_rows(s, i0, i1, f, acc);
    const double t0 = gf_wtime(); /* two clock reads per batch of >= 64 rows: no measurable cost (docs/notes/benchmarks.md) */
    const gf_drift_d2 d2 = gf_sim_finish_runs(s, i0, i1, 0);
    acc->finish_s += gf_wtime() - t0;
    return d2;
}

gf_drift_d2 gf_sim_grain_passes(gf_sim *s, gf_sim_grain_pass *pass, void *user)
{
    const long n = (long)s->p->n_local;
    gf_drift_d2 d2[GF_SIM_MAX_THREADS] = {{0.0, 0.0}};
    int used = 1;
#ifdef _OPENMP
#pragma omp parallel num_threads(s->n_threads) if (s->n_threads > 1 && n >= GF_SIM_PARALLEL_MIN_GRAINS)
#endif
    {
        const gf_team team = gf_sim_team();
        const int t = team.t, m = team.m;
        if (t == 0)
            used = m;
        size_t i0, i1;
        gf_sim_thread_grains(s, (size_t)n, t, m, &i0, &i1);
        d2[t] = pass(s, i0, i1, user);
    }
    return gf_drift_d2_max(d2, used);
}
