/*
 * gf-bench-dem: throughput of the DEM core on the settled_bed scene, a dense
 * bed at rest (periodic x and z, floor, gravity), linear spring-dashpot with
 * tangential history (the seeds' law), t_c = t_contact_nd sqrt(D/g),
 * dt = t_c/50.
 *
 * For each N: build and settle the bed once, checkpoint it, then for each
 * thread count re-create the sim from the checkpoint (same state, bit for
 * bit) and time `steps` steps. Reports particle-timesteps per second, per
 * core, and the split neighbour / force / integrate from the step-loop timers.
 *
 *   gf-bench-dem [--n N]... [--threads T]... [--steps S] [--settle T_nd]
 *                [--lammps-data PATH] [--friction MU] [--bed PREFIX] [--dump PATH]
 *                [--scene settled_bed|column_collapse] [--sort-every K] [--sort-bed PREFIX] [--near-skin F]
 *
 * --lammps-data writes the settled bed of the LAST N as a LAMMPS data file
 * (atom_style sphere, gf_lammps_data.h) plus PATH.params (k_n, gamma_n, k_t, mu, dt, box),
 * for workflows/bench/lammps_compare.sh. --dump writes the grains after the
 * first timed run (one line "x y z radius" per grain, SI), the same columns
 * as the LAMMPS dump of lammps_compare.sh, for the observable comparison
 * (bed height, packing fraction: --settle 0 times the settling itself).
 * --scene column_collapse times the
 * dry collapse at a = 1 (R0 = 16 D, W = 3 D, rough base of glued grains, the
 * bed's material) from its release instead: the grain count is the scene's
 * (glued grains included), --n is ignored. --bed keeps the settled bed as the
 * checkpoint PREFIX_<N>.h5 and reuses it when it exists (settling 1e5 grains
 * costs far more than timing them; the same file also lets two builds be
 * timed on the same state). --sort-every K sets gf_sim_tuning.sort_every
 * (0: the engine's default, -1: never sort). --sort-bed PREFIX loads the bed,
 * sorts its store by space (gf_sim_sort), writes it as PREFIX_<N>.h5 and
 * times nothing: a bed kept by a build without the sort, made comparable.
 * A bed sorted for one thread layout is re-sorted into another's when a run
 * with that layout loads it (gf_sim_checkpoint.c), unless --sort-every -1.
 * --near-skin F sets gf_sim_tuning.near_skin (the near list's skin as a
 * fraction of the neighbour skin; 0 the default, < 0 no near list); each line
 * then also reports the list and near-list builds and pairs per grain.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "gf_bench_args.h"
#include "gf_bench_clock.h"
#include "gf_lammps_data.h"
#include "gf_sim.h"

typedef struct bench_args {
    long n[8];
    int n_n;
    int threads[8];
    int n_threads;
    long steps;
    double settle_nd, friction;
    const char *lammps, *dump;
    int collapse; /* --scene column_collapse: the dry collapse at a = 1 instead of the bed */
    const char *bed; /* reuse (or keep) the settled bed: PATH_<N>.h5 */
    int sort_every;
    double near_skin; /* gf_sim_tuning.near_skin */
    const char *sort_bed;
} bench_args;

static void spec_for(gf_ctx *ctx, gf_run_spec *s, const bench_args *a, long n, double settle_nd)
{
    gf_run_spec_defaults(s);
    snprintf(s->scene, sizeof s->scene, a->collapse ? "column_collapse" : "settled_bed");
    s->grains.diameter_m = 1e-3;
    s->grains.density_kg_m3 = 2500.0;
    s->grains.polydispersity = 0.1;
    s->contact.restitution = 0.5;
    s->contact.friction = a->friction;
    s->contact.wall_friction = a->friction;
    s->contact.t_contact_nd = 1e-2;
    s->contact.dt_over_tc = 0.02;
    if (a->collapse) { /* R0 = 16 D, a = 1, W = 3 D, rough base (docs/notes/benchmarks.md, sleeping grains) */
        gf_run_spec_set_param(ctx, s, "aspect_ratio", 1.0);
        gf_run_spec_set_param(ctx, s, "column_length_over_D", 16.0);
        gf_run_spec_set_param(ctx, s, "width_over_D", 3.0);
    } else {
        gf_run_spec_set_param(ctx, s, "n_grains", (double)n);
    }
    gf_run_spec_set_param(ctx, s, "settle_time_nd", settle_nd);
}

/* FNV-1a hash of the grain state in id order: two builds that claim the same
 * arithmetic must print the same hash after the same steps. */
static unsigned long long state_hash(gf_sim *sim)
{
    const gf_particles *p = gf_sim_particles(sim);
    const double *f[9] = {p->x_m, p->y_m, p->z_m, p->vx_m_s, p->vy_m_s, p->vz_m_s, p->wx_rad_s, p->wy_rad_s, p->wz_rad_s};
    int64_t max_id = 0;
    for (size_t i = 0; i < p->n_local; ++i)
        max_id = p->id[i] > max_id ? p->id[i] : max_id;
    size_t *slot = malloc(((size_t)max_id + 1) * sizeof(size_t));
    unsigned long long h = 1469598103934665603ULL;
    if (!slot)
        return 0;
    for (int64_t q = 0; q <= max_id; ++q)
        slot[q] = (size_t)-1;
    for (size_t i = 0; i < p->n_local; ++i)
        slot[p->id[i]] = i;
    for (int64_t q = 0; q <= max_id; ++q) {
        if (slot[q] == (size_t)-1)
            continue;
        for (int c = 0; c < 9; ++c) {
            unsigned long long b;
            double v = f[c][slot[q]] + 0.0; /* +0.0: -0 and +0 hash alike */
            memcpy(&b, &v, sizeof b);
            for (int k = 0; k < 8; ++k)
                h = (h ^ ((b >> (8 * k)) & 0xff)) * 1099511628211ULL;
        }
    }
    free(slot);
    return h;
}

/* Builds and settles the bed of n grains, and checkpoints it to ck. */
static int settle_bed(gf_ctx *ctx, const bench_args *a, long n, const char *ck)
{
    gf_run_spec spec;
    spec_for(ctx, &spec, a, n, a->settle_nd);
    gf_sim *sim = NULL;
    double w0 = gf_wtime();
    gf_sim_options opt = {.n_threads = 1};
    if (gf_sim_create(ctx, &spec, &opt, &sim) != GF_OK) {
        fprintf(stderr, "gf-bench-dem: %s\n", ctx->last_msg);
        return 0;
    }
    size_t nc;
    double ov;
    gf_sim_contact_stats(sim, &nc, &ov);
    printf("N = %ld: settled in %.1f s wall (%.1f sqrt(D/g)); %zu contacts (%.2f per grain), max overlap %.4f D, "
           "KE %.3g J\n",
           (long)gf_sim_particles(sim)->n_local, gf_wtime() - w0, a->settle_nd, nc,
           2.0 * nc / (double)gf_sim_particles(sim)->n_local, ov, gf_particles_kinetic_energy(gf_sim_particles(sim)));
    gf_status st = gf_sim_checkpoint(sim, ck);
    if (st != GF_OK)
        fprintf(stderr, "gf-bench-dem: %s\n", ctx->last_msg);
    gf_sim_destroy(&sim);
    return st == GF_OK;
}

/* The flags besides --n, --threads (each may repeat) and --scene (a name);
 * the usage line is main's. */
static const gf_bench_flag flags[] = {
    GF_BENCH_FLAG("--steps", LONG, bench_args, steps),
    GF_BENCH_FLAG("--settle", REAL, bench_args, settle_nd),
    GF_BENCH_FLAG("--friction", REAL, bench_args, friction),
    GF_BENCH_FLAG("--lammps-data", PATH, bench_args, lammps),
    GF_BENCH_FLAG("--dump", PATH, bench_args, dump),
    GF_BENCH_FLAG("--bed", PATH, bench_args, bed),
    GF_BENCH_FLAG("--sort-every", INT, bench_args, sort_every),
    GF_BENCH_FLAG("--near-skin", REAL, bench_args, near_skin),
    GF_BENCH_FLAG("--sort-bed", PATH, bench_args, sort_bed),
};

static int parse(int argc, char **argv, bench_args *a)
{
    memset(a, 0, sizeof *a);
    a->steps = 2000;
    a->settle_nd = 4.0;
    a->friction = 0.5;
    for (int i = 1; i < argc; i += 2) {
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!v)
            return 0;
        if (!strcmp(argv[i], "--n") && a->n_n < 8)
            a->n[a->n_n++] = atol(v);
        else if (!strcmp(argv[i], "--threads") && a->n_threads < 8)
            a->threads[a->n_threads++] = atoi(v);
        else if (!strcmp(argv[i], "--scene") && (!strcmp(v, "column_collapse") || !strcmp(v, "settled_bed")))
            a->collapse = !strcmp(v, "column_collapse");
        else if (!gf_bench_set_flag(flags, sizeof flags / sizeof *flags, a, argv[i], v))
            return 0;
    }
    if (!a->n_n)
        a->n[a->n_n++] = 10000;
    if (!a->n_threads)
        a->threads[0] = 1, a->threads[1] = 2, a->n_threads = 2;
    return 1;
}

int main(int argc, char **argv)
{
    bench_args a;
    if (!parse(argc, argv, &a)) {
        fprintf(stderr, "usage: gf-bench-dem [--n N]... [--threads T]... [--steps S] [--settle T_nd] "
                        "[--friction MU] [--lammps-data PATH] [--bed PREFIX] [--scene settled_bed|column_collapse] "
                        "[--dump PATH] [--sort-every K] [--sort-bed PREFIX] [--near-skin F]\n");
        return 2;
    }
    gf_ctx ctx = {0};
    for (int k = 0; k < a.n_n; ++k) {
        gf_sim *sim = NULL;
        char ck[256];
        if (a.bed)
            snprintf(ck, sizeof ck, "%s_%s%ld.h5", a.bed, a.collapse ? "collapse_" : "", a.collapse ? 1L : a.n[k]);
        else
            snprintf(ck, sizeof ck, "/tmp/gf_bench_dem_%d.h5", (int)getpid());
        if ((!a.bed || access(ck, R_OK) != 0) && !settle_bed(&ctx, &a, a.n[k], ck))
            return 1;
        gf_run_spec again;
        spec_for(&ctx, &again, &a, a.n[k], 0.0); /* no second settling: the checkpoint holds the bed */
        double rate1 = 0.0;
        for (int q = 0; q < a.n_threads; ++q) {
            gf_sim_options o = {.n_threads = a.threads[q], .restart_path = ck, .tuning.sort_every = a.sort_every,
                                 .tuning.near_skin = a.near_skin};
            if (gf_sim_create(&ctx, &again, &o, &sim) != GF_OK) {
                fprintf(stderr, "gf-bench-dem: %s\n", ctx.last_msg);
                return 1;
            }
            if (a.sort_bed) {
                char out[256];
                snprintf(out, sizeof out, "%s_%ld.h5", a.sort_bed, a.collapse ? 1L : a.n[k]);
                if (gf_sim_sort(sim) != GF_OK || gf_sim_checkpoint(sim, out) != GF_OK) {
                    fprintf(stderr, "gf-bench-dem: %s\n", ctx.last_msg);
                    return 1;
                }
                printf("N = %ld: sorted bed written to %s\n", a.n[k], out);
                gf_sim_destroy(&sim);
                break;
            }
            const int export_bed = q == 0 && a.lammps && k == a.n_n - 1; /* the last N's bed */
            if (export_bed && !gf_bench_export_lammps(sim, a.lammps, NULL, NULL, "gf-bench-dem"))
                return 1;
            const gf_timers *t = gf_sim_timers(sim);
            double e0[GF_TIMER_COUNT];
            memcpy(e0, t->elapsed_s, sizeof e0);
            double t0 = gf_wtime(), c0 = gf_bench_cpu_time_s();
            if (gf_sim_advance(sim, a.steps) != GF_OK) {
                fprintf(stderr, "gf-bench-dem: %s\n", ctx.last_msg);
                return 1;
            }
            double wall = gf_wtime() - t0, cpu = gf_bench_cpu_time_s() - c0;
            const gf_sim_list_stats ls = gf_sim_list_counters(sim);
            const long ng = (long)gf_sim_particles(sim)->n_local; /* the collapse sets its own count */
            double rate = (double)ng * a.steps / wall;
            if (q == 0)
                rate1 = rate;
            double tn = t->elapsed_s[GF_T_NEIGHBOUR] - e0[GF_T_NEIGHBOUR], tf = t->elapsed_s[GF_T_FORCE] - e0[GF_T_FORCE],
                   ti = t->elapsed_s[GF_T_INTEGRATE] - e0[GF_T_INTEGRATE];
            printf("N = %ld, %d thread(s): %ld steps in %.3f s wall, %.3f s CPU: %.3e particle-steps/s wall "
                   "(speed-up %.2f), %.3e per CPU-second; neighbour %.1f %%, force %.1f %%, integrate %.1f %%, "
                   "other %.1f %%; list builds %ld, near builds %ld, pairs per grain %.2f (near %.2f); "
                   "state hash %016llx\n",
                   ng, a.threads[q], a.steps, wall, cpu, rate, rate / rate1, (double)ng * a.steps / cpu,
                   100 * tn / wall, 100 * tf / wall, 100 * ti / wall, 100 * (wall - tn - tf - ti) / wall,
                   ls.builds, ls.near_builds, (double)ls.pairs / ng, (double)ls.near_pairs / ng, state_hash(sim));
            fflush(stdout);
            if (q == 0 && a.dump && !gf_bench_write_dump(sim, a.dump, 0)) {
                fprintf(stderr, "gf-bench-dem: cannot write %s\n", a.dump);
                return 1;
            }
            gf_sim_destroy(&sim);
        }
        if (!a.bed)
            remove(ck);
    }
    return 0;
}
