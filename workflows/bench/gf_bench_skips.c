/*
 * gf-bench-skips: what each skip of issue #6 saves and what it changes,
 * measured side by side (engine/sim/gf_skips.c, engine/gf_stiffness_rule.h).
 * Every case runs the same scene with the skip off and on, alternating
 * off/on pairs back to back (the machine may be shared), one thread; the
 * cost is the process CPU time of gf_sim_create + the run (best of the
 * repeats per side), the observable is the mean over the repeats (and seeds).
 *
 *   tangential   mu_c = 0: the elastic gas (1000 grains, phi 0.30, eps 1) and a
 *                frictionless settled bed; off = gf_sim_tuning.keep_all_work.
 *                Observable: largest kinetic-energy excursion over 8 sqrt(D/g)
 *                (energy stored in the springs included) / bed height, and the largest
 *                position difference between the two runs (0: bitwise).
 *   lubrication  dry collapse (R0 = 8 D, a = 0.5, W = 3 D) of glass beads in
 *                air, fluid: auto (chooses none) with lubrication asked for;
 *                off = the air's lubrication evaluated anyway. Observable:
 *                run-out (R_inf - R0)/R0 and H_inf/R0, seeds 1-4 (the front
 *                is measured in bins of D: one bin is 0.125 in run-out).
 *   output       the same dry collapse through gf_sim_run with every file at
 *                0.05 sqrt(D/g) (off) against diagnostics only (on).
 *   stiffness    the same dry collapse at the default t_c sqrt(g/D) = 1e-2
 *                (off) against contact.overlap_target_over_D = 0.01 (on);
 *                also the largest overlap seen during the run.
 *
 *   fluid_share  (not a pair) the wall-time share of the fluid step in an
 *                immersed collapse (glass in water, R0 = 16 D, a = 1): the
 *                most that skipping fluid work in idle cells could save.
 *
 *   gf-bench-skips [--case NAME]... [--repeat R]      (default: all, R = 2)
 * A case runs R x (its seeds) off/on pairs; the cost of a side is the sum over
 * the seeds of one repeat, best repeat; the observables are means over all.
 * Prints one markdown row per case (docs/notes/benchmarks.md).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "gf_bench_clock.h"
#include "gf_sim.h"
#include "scenes/gf_scene.h"

#define MAX_OBS 3

typedef struct result {
    double cpu_s, obs[MAX_OBS];
    double *x; /* final positions (x, y, z per grain), for the bitwise comparison */
    size_t n;
} result;

static double load1(void)
{
    double l = NAN;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &l) != 1)
            l = NAN;
        fclose(f);
    }
    return l;
}

static int fail(gf_ctx *ctx)
{
    fprintf(stderr, "gf-bench-skips: %s\n", ctx->last_msg);
    return 0;
}

static void keep_positions(gf_sim *sim, result *r)
{
    const gf_particles *p = gf_sim_particles(sim);
    free(r->x);
    r->n = p->n_local;
    r->x = malloc(3 * r->n * sizeof(double));
    for (size_t i = 0; r->x && i < r->n; ++i)
        r->x[3 * i] = p->x_m[i], r->x[3 * i + 1] = p->y_m[i], r->x[3 * i + 2] = p->z_m[i];
}

/* ---- tangential: elastic gas and frictionless bed ---- */
/* A frictionless spec of `scene` (grains and walls mu = 0: the tangential skip applies). */
static void frictionless_spec(gf_run_spec *s, const char *scene, double D, double rho, double poly, double eps)
{
    gf_run_spec_defaults(s);
    snprintf(s->scene, sizeof s->scene, "%s", scene);
    s->grains.diameter_m = D, s->grains.density_kg_m3 = rho, s->grains.polydispersity = poly;
    s->contact.restitution = eps, s->contact.friction = s->contact.wall_friction = 0.0;
}

/* Creates the run with the skips on (or all work kept) and starts the CPU clock. */
static int create_timed(gf_ctx *ctx, const gf_run_spec *s, int on, gf_sim **sim, double *c0)
{
    gf_sim_options o = {.n_threads = 1, .tuning.keep_all_work = !on};
    *c0 = gf_bench_cpu_time_s();
    return gf_sim_create(ctx, s, &o, sim) == GF_OK;
}
static int run_gas(int on, result *r)
{
    gf_ctx ctx = {0};
    gf_run_spec s;
    frictionless_spec(&s, "elastic_gas", 3e-3, 1319.0, 0.0, 1.0);
    gf_run_spec_set_param(&ctx, &s, "n_grains", 1000);
    gf_run_spec_set_param(&ctx, &s, "box_over_D", 12.05); /* phi = 0.30 */
    gf_sim *sim = NULL;
    double c0;
    if (!create_timed(&ctx, &s, on, &sim, &c0))
        return fail(&ctx);
    const double tg = sqrt(s.grains.diameter_m / s.gravity_m_s2);
    const long n = (long)ceil(8.0 * tg / gf_sim_dt_s(sim)), chunk = n / 100;
    double e0 = gf_particles_kinetic_energy(gf_sim_particles(sim)), de = 0.0;
    for (long k = 0; k < n; k += chunk) {
        if (gf_sim_advance(sim, chunk) != GF_OK)
            return fail(&ctx);
        de = fmax(de, fabs(gf_particles_kinetic_energy(gf_sim_particles(sim)) / e0 - 1.0));
    }
    r->cpu_s = gf_bench_cpu_time_s() - c0;
    r->obs[0] = de;
    keep_positions(sim, r);
    gf_sim_destroy(&sim);
    return 1;
}

static int run_bed(int on, result *r)
{
    gf_ctx ctx = {0};
    gf_run_spec s;
    frictionless_spec(&s, "settled_bed", 1e-3, 2500.0, 0.1, 0.5);
    gf_run_spec_set_param(&ctx, &s, "n_grains", 4000);
    gf_run_spec_set_param(&ctx, &s, "settle_time_nd", 2.0);
    gf_sim *sim = NULL;
    double c0;
    if (!create_timed(&ctx, &s, on, &sim, &c0) || gf_sim_advance(sim, 5000) != GF_OK)
        return fail(&ctx);
    r->cpu_s = gf_bench_cpu_time_s() - c0;
    const gf_particles *p = gf_sim_particles(sim);
    double y = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        y += p->y_m[i] / p->n_local;
    r->obs[0] = y / s.grains.diameter_m; /* centre-of-mass height / D */
    keep_positions(sim, r);
    gf_sim_destroy(&sim);
    return 1;
}

/* ---- the dry collapse of the lubrication, output and stiffness cases ---- */
typedef enum { COLLAPSE_LUB, COLLAPSE_OUTPUT, COLLAPSE_STIFF } collapse_kind;

static void collapse_spec(gf_ctx *ctx, gf_run_spec *s, unsigned seed)
{
    gf_run_spec_defaults(s);
    snprintf(s->scene, sizeof s->scene, "column_collapse");
    s->seed = seed;
    gf_run_spec_set_param(ctx, s, "column_length_over_D", 8.0);
    gf_run_spec_set_param(ctx, s, "aspect_ratio", 0.5);
    gf_run_spec_set_param(ctx, s, "width_over_D", 3.0);
    s->end_time_nd = 40.0; /* upper bound; done() stops the run at rest */
    s->output.particles = s->output.fields = s->output.probes = s->output.diagnostics = 0;
}

static void progress(void *user, double t_s, double t_end_s, double steps_per_s)
{
    (void)user;
    fprintf(stderr, "  t = %.4g of %.4g s, %.3g steps/s\n", t_s, t_end_s, steps_per_s);
}

static int run_collapse(collapse_kind kind, int on, unsigned seed, result *r)
{
    gf_ctx ctx = {0};
    gf_run_spec s;
    collapse_spec(&ctx, &s, seed);
    gf_sim_options o = {.n_threads = 1};
    char dir[64] = "";
    if (kind == COLLAPSE_LUB) { /* glass beads in air: fluid: auto picks the dry tier */
        snprintf(s.fluid.model, sizeof s.fluid.model, "auto");
        s.fluid.density_kg_m3 = 1.2, s.fluid.viscosity_Pa_s = 1.8e-5, s.fluid.lubrication = 1;
        o.tuning.keep_all_work = !on;
    } else if (kind == COLLAPSE_OUTPUT) {
        snprintf(dir, sizeof dir, "/tmp/gf_bench_skips_%d", (int)getpid());
        char cmd[128];
        snprintf(cmd, sizeof cmd, "mkdir -p %s", dir);
        if (system(cmd) != 0)
            return 0;
        o.output_dir = dir;
        if (getenv("GF_BENCH_VERBOSE"))
            o.progress = progress;
        s.output.diagnostics = 1;
        s.output.particles = !on;
        s.output.interval_nd = 0.05;
    } else if (on) {
        s.contact.overlap_target_over_D = 0.01;
    }
    const gf_scene_desc *d = gf_scene_find("column_collapse");
    gf_sim *sim = NULL;
    double c0 = gf_bench_cpu_time_s(), ov_max = 0.0;
    if (gf_sim_create(&ctx, &s, &o, &sim) != GF_OK)
        return fail(&ctx);
    if (kind == COLLAPSE_OUTPUT) {
        if (gf_sim_run(sim) != GF_OK)
            return fail(&ctx);
    } else {
        long chunk = (long)ceil(0.05 * sqrt(s.grains.diameter_m / s.gravity_m_s2) / gf_sim_dt_s(sim));
        while (gf_sim_time_s(sim) < gf_sim_end_time_s(sim) && !(d->done && d->done(sim))) {
            if (gf_sim_advance(sim, chunk) != GF_OK)
                return fail(&ctx);
            double ov;
            gf_sim_contact_stats(sim, NULL, &ov);
            ov_max = fmax(ov_max, ov);
        }
    }
    r->cpu_s = gf_bench_cpu_time_s() - c0;
    const double D = s.grains.diameter_m, R0 = 8.0 * D;
    double v[8];
    if (d->diagnose(sim, v) != GF_OK)
        return fail(&ctx);
    r->obs[0] = (v[0] - R0) / R0, r->obs[1] = v[1] / R0, r->obs[2] = ov_max;
    keep_positions(sim, r);
    gf_sim_destroy(&sim);
    if (dir[0]) {
        char cmd[128];
        snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
        if (system(cmd) != 0)
            return 0;
    }
    return 1;
}

/* ---- the fluid's share of an immersed collapse (what an idle-cell skip could save) ---- */
static int fluid_share(void)
{
    gf_ctx ctx = {0};
    gf_run_spec s;
    collapse_spec(&ctx, &s, 1);
    gf_run_spec_set_param(&ctx, &s, "column_length_over_D", 16.0);
    gf_run_spec_set_param(&ctx, &s, "aspect_ratio", 1.0);
    snprintf(s.fluid.model, sizeof s.fluid.model, "unresolved");
    s.fluid.density_kg_m3 = 1000.0, s.fluid.viscosity_Pa_s = 1e-3; /* glass in water */
    gf_sim_options o = {.n_threads = 1};
    gf_sim *sim = NULL;
    if (gf_sim_create(&ctx, &s, &o, &sim) != GF_OK)
        return fail(&ctx);
    const double tg = sqrt(s.grains.diameter_m / s.gravity_m_s2);
    if (gf_sim_advance(sim, (long)ceil(5.0 * tg / gf_sim_dt_s(sim))) != GF_OK)
        return fail(&ctx);
    const double *e = gf_sim_timers(sim)->elapsed_s, tot = e[GF_T_TOTAL];
    printf("| fluid_share | immersed collapse R0 = 16 D, a = 1, water, 5 sqrt(D/g), %zu grains | total %.2f s: "
           "fluid step %.2f s (%.1f %%), fluid forces %.2f s (%.1f %%), contacts %.2f s (%.1f %%) |\n",
           gf_sim_particles(sim)->n_local, tot, e[GF_T_FLUID], 100 * e[GF_T_FLUID] / tot, e[GF_T_COUPLING],
           100 * e[GF_T_COUPLING] / tot, e[GF_T_FORCE], 100 * e[GF_T_FORCE] / tot);
    gf_sim_destroy(&sim);
    return 1;
}

/* ---- the side-by-side driver ---- */
typedef struct bench_case {
    const char *name, *obs_names[MAX_OBS];
    int n_obs, n_seeds;
    int (*run)(int which, int on, unsigned seed, result *r);
} bench_case;

static int c_gas(int w, int on, unsigned seed, result *r) { (void)w, (void)seed; return run_gas(on, r); }
static int c_bed(int w, int on, unsigned seed, result *r) { (void)w, (void)seed; return run_bed(on, r); }
static int c_col(int w, int on, unsigned seed, result *r) { return run_collapse((collapse_kind)w, on, seed, r); }

static const bench_case cases[] = {
    {"tangential_gas", {"max |K/K0 - 1|"}, 1, 1, c_gas},
    {"tangential_bed", {"y_cm / D"}, 1, 1, c_bed},
    {"lubrication", {"(R_inf - R0)/R0", "H_inf/R0"}, 2, 4, c_col},
    {"output", {"(R_inf - R0)/R0", "H_inf/R0"}, 2, 1, c_col},
    {"stiffness", {"(R_inf - R0)/R0", "H_inf/R0", "max overlap / D"}, 3, 4, c_col},
};
static const int case_kind[] = {0, 0, COLLAPSE_LUB, COLLAPSE_OUTPUT, COLLAPSE_STIFF};

static double max_diff(const result *a, const result *b)
{
    if (!a->x || !b->x || a->n != b->n)
        return NAN;
    double m = 0.0;
    for (size_t i = 0; i < 3 * a->n; ++i)
        m = fmax(m, fabs(a->x[i] - b->x[i]));
    return m;
}

static int bench_one(int k, int repeat)
{
    const bench_case *c = &cases[k];
    double best[2] = {INFINITY, INFINITY}, obs[2][MAX_OBS] = {{0}}, diff = 0.0, l0 = load1();
    int runs = 0;
    for (int rep = 0; rep < repeat; ++rep) {
        double side[2] = {0.0, 0.0}; /* CPU s of this repeat, summed over the seeds */
        for (int sd = 0; sd < c->n_seeds; ++sd) {
            result r[2];
            memset(r, 0, sizeof r);
            for (int on = 0; on < 2; ++on) { /* off, then on, back to back */
                if (!c->run(case_kind[k], on, 1u + (unsigned)sd, &r[on]))
                    return 0;
                side[on] += r[on].cpu_s;
                for (int q = 0; q < c->n_obs; ++q)
                    obs[on][q] += r[on].obs[q];
                printf("  %s seed %d repeat %d skip %s: %.3f CPU s, %s = %.5g\n", c->name, sd + 1, rep + 1,
                       on ? "on " : "off", r[on].cpu_s, c->obs_names[0], r[on].obs[0]);
                fflush(stdout);
            }
            diff = fmax(diff, max_diff(&r[0], &r[1]));
            free(r[0].x), free(r[1].x);
            runs++;
        }
        best[0] = fmin(best[0], side[0]), best[1] = fmin(best[1], side[1]);
    }
    printf("| %s | %d x %d |", c->name, repeat, c->n_seeds);
    for (int q = 0; q < c->n_obs; ++q) {
        double off = obs[0][q] / runs, on = obs[1][q] / runs;
        printf(" %s: %.4g / %.4g (%+.2f %%) |", c->obs_names[q], off, on, off != 0.0 ? 100.0 * (on - off) / off : 0.0);
    }
    printf(" max position difference %.3g m | CPU s off / on %.2f / %.2f | speed-up %.2fx | load %.1f -> %.1f |\n",
           diff, best[0], best[1], best[0] / best[1], l0, load1());
    fflush(stdout);
    return 1;
}

int main(int argc, char **argv)
{
    int repeat = 2, want[8], n_want = 0;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--repeat") && i + 1 < argc)
            repeat = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--case") && i + 1 < argc && n_want < 8) {
            const char *v = argv[++i];
            if (!strcmp(v, "fluid_share")) {
                if (!fluid_share())
                    return 1;
                if (i + 1 == argc && n_want == 0)
                    return 0;
                continue;
            }
            int f = -1;
            for (int k = 0; k < (int)(sizeof cases / sizeof cases[0]); ++k)
                if (!strcmp(cases[k].name, v))
                    f = k;
            if (f < 0) {
                fprintf(stderr, "gf-bench-skips: unknown case '%s'\n", v);
                return 2;
            }
            want[n_want++] = f;
        } else {
            fprintf(stderr, "usage: gf-bench-skips [--case NAME]... [--repeat R]\n");
            return 2;
        }
    }
    if (!n_want)
        for (int k = 0; k < (int)(sizeof cases / sizeof cases[0]); ++k)
            want[n_want++] = k;
    for (int q = 0; q < n_want; ++q)
        if (!bench_one(want[q], repeat < 1 ? 1 : repeat))
            return 1;
    return 0;
}
