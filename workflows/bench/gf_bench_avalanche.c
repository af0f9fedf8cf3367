/*
 * gf-bench-avalanche: the dry chute flows of test_avalanche (rows 7-8,
 * Izard 2014 §2.1.3.3), for the side-by-side comparison with LAMMPS
 * (workflows/bench/lammps_avalanche.sh).
 *
 *   gf-bench-avalanche [--angle DEG] [--seed S] [--bed H_over_D] [--length L_over_D] [--width W_over_D]
 *                      [--tc TC_ND] [--eps E] [--spin T_ND] [--avg T_ND] [--every T_ND] [--window K]
 *                      [--lammps-data PATH] [--measure-dump PATH]
 *
 * The grains and contacts of test_avalanche's steady mode: D = 1 cm +- 10 %,
 * rho_p = 2500, mu_c = 0.25 on grains and walls, eps 0.5, t_c = 3.1e-3
 * sqrt(D/g) (the thesis' 1e-4 s), dt = t_c/50; the avalanche scene (rough
 * base of glued half-grains on y = 0, periodic in x and z, lid at bed + 10 D),
 * its bed prepared at theta = 0 and gravity tilted at t = 0 (gf_sim_create
 * runs all of it). Defaults: 27.5 deg, packing seed 31, a 12 D bed on a
 * 6 D x 6 D footprint, 200 sqrt(D/g) of spin-up, then one sample per
 * sqrt(D/g) for 50 (--every sets the interval).
 *
 * --lammps-data writes that t = 0 state (gf_lammps_data.h) and PATH.params,
 * to which the chute's geometry and schedule are appended: the floor y = 0
 * and lid y = TOP, the tilt, the steps of the spin-up and between samples,
 * the sample count. The run then samples the slab profiles of phi and the
 * downslope velocity (gf_measure_profile_y, slabs of D) and Q_g, and prints
 * the seed's reading of the averaged profile (gf_measure_chute_bagnold: I from
 * the Bagnold amplitude, the slip length, the fit's rms). --window K reports
 * instead every K samples, for a transient (row 7: --angle 40 --bed 34 --seed
 * 21 --spin 0 --avg 76 --every 0.5 --window 4, test_avalanche's unsteady
 * set-up and windows): the window's end time, Q_g, the surface speed (slab
 * below the top), the bed height and the bulk I from the velocity profile
 * with hydrostatic pressure, |du/dy| D / sqrt(phi g cos(theta) (h - y)),
 * averaged over the slabs from 2 D above the floor to 3 D below the top.
 *
 * --measure-dump PATH skips the run: it reads the snapshots of a LAMMPS text
 * dump (columns x y z vx vy vz radius, mobile grains) and applies the same
 * sampling and reading to them, in the box of the same scene (recreated, so
 * pass the same options), so that both codes' flows are measured by one
 * definition.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_bench_args.h"
#include "gf_bench_clock.h"
#include "gf_lammps_data.h"
#include "gf_sim.h"
#include "particles/gf_particles.h"
#include "scenes/gf_measure.h"
#include "scenes/gf_scene.h"

enum { N_SLABS = 64 };

typedef struct chute_args {
    long seed;
    double angle_deg, bed_D, length_D, width_D, tc_nd, eps, spin_nd, avg_nd, every_nd;
    int window; /* samples per report; 0: one report of all */
    const char *lammps, *dump;
} chute_args;

/* Time-averaged slab profiles and flow rate over the samples. */
typedef struct chute_window {
    double phi[N_SLABS], u[N_SLABS], q;
    int n;
} chute_window;

static const chute_args defaults = {.seed = 31, .angle_deg = 27.5, .bed_D = 12.0, .length_D = 6.0, .width_D = 6.0,
                                    .tc_nd = 3.1e-3, .eps = 0.5, .spin_nd = 200.0, .avg_nd = 50.0, .every_nd = 1.0};

static const gf_bench_flag flags[] = {
    GF_BENCH_FLAG("--angle", REAL, chute_args, angle_deg),   GF_BENCH_FLAG("--seed", LONG, chute_args, seed),
    GF_BENCH_FLAG("--bed", REAL, chute_args, bed_D),         GF_BENCH_FLAG("--length", REAL, chute_args, length_D),
    GF_BENCH_FLAG("--width", REAL, chute_args, width_D),     GF_BENCH_FLAG("--tc", REAL, chute_args, tc_nd),
    GF_BENCH_FLAG("--eps", REAL, chute_args, eps),           GF_BENCH_FLAG("--spin", REAL, chute_args, spin_nd),
    GF_BENCH_FLAG("--avg", REAL, chute_args, avg_nd),        GF_BENCH_FLAG("--every", REAL, chute_args, every_nd),
    GF_BENCH_FLAG("--window", INT, chute_args, window),      GF_BENCH_FLAG("--lammps-data", PATH, chute_args, lammps),
    GF_BENCH_FLAG("--measure-dump", PATH, chute_args, dump),
};

GF_BENCH_VALID(chute_args, a->seed > 0 && a->bed_D > 0.0 && a->length_D > 0.0 && a->width_D > 0.0 &&
               a->tc_nd > 0.0 && a->spin_nd >= 0.0 && a->every_nd > 0.0 && a->avg_nd >= a->every_nd &&
               a->window >= 0)

static gf_status make_spec(gf_ctx *ctx, const void *args, gf_run_spec *s)
{
    const chute_args *a = args;
    gf_run_spec_defaults(s);
    snprintf(s->scene, sizeof s->scene, "avalanche");
    snprintf(s->fluid.model, sizeof s->fluid.model, "none");
    s->output.particles = s->output.fields = s->output.probes = s->output.diagnostics = 0;
    s->seed = (uint64_t)a->seed;
    s->grains.diameter_m = 0.01;
    s->grains.polydispersity = 0.10;
    s->grains.density_kg_m3 = 2500.0;
    s->contact.restitution = a->eps;
    s->contact.friction = s->contact.wall_friction = 0.25;
    s->contact.t_contact_nd = a->tc_nd;
    GF_TRY(gf_run_spec_set_param(ctx, s, "incline_deg", a->angle_deg));
    GF_TRY(gf_run_spec_set_param(ctx, s, "length_over_D", a->length_D));
    GF_TRY(gf_run_spec_set_param(ctx, s, "width_over_D", a->width_D));
    GF_TRY(gf_run_spec_set_param(ctx, s, "bed_height_over_D", a->bed_D));
    return gf_run_spec_set_param(ctx, s, "height_over_D", a->bed_D + 10.0);
}

/* Steps of one advance of t_nd sqrt(D/g), as test_avalanche's flow_advance. */
static long steps_of(gf_sim *sim, double t_nd)
{
    const gf_run_spec *s = gf_sim_spec(sim);
    return (long)ceil(t_nd * sqrt(s->grains.diameter_m / s->gravity_m_s2) / gf_sim_dt_s(sim));
}

static int n_samples(const chute_args *a)
{
    return (int)floor(a->avg_nd / a->every_nd + 1e-9);
}

/* Steps of the spin-up, advanced in pieces of 25 sqrt(D/g) as test_avalanche does. */
static long spin_steps(gf_sim *sim, double spin_nd)
{
    long n = 0;
    for (double t = 0.0; t < spin_nd - 1e-9; t += 25.0)
        n += steps_of(sim, fmin(25.0, spin_nd - t));
    return n;
}

/* The geometry and schedule the LAMMPS input needs besides the law
 * (gf_bench_params_fn). */
static void append_chute(FILE *f, gf_sim *sim, const double lo[3], const double hi[3], const void *args)
{
    const chute_args *a = args;
    double th = a->angle_deg * M_PI / 180.0;
    (void)lo;
    fprintf(f, "TOP=%.17g\nGX_UNIT=%.17g\nGY_UNIT=%.17g\nSPIN_STEPS=%ld\nSAMPLE_STEPS=%ld\nSAMPLES=%d\n", hi[1],
            sin(th), -cos(th), spin_steps(sim, a->spin_nd), steps_of(sim, a->every_nd), n_samples(a));
}

/* Adds one sample of the mobile grains p (domain dom) to the window. */
static gf_status sample(gf_ctx *ctx, const gf_particles *p, const gf_measure_domain *dom, double D, chute_window *w)
{
    double phi[N_SLABS], u[3 * N_SLABS];
    GF_TRY(gf_measure_profile_y(ctx, p, dom, 0.0, D, N_SLABS, phi, u));
    for (int k = 0; k < N_SLABS; ++k)
        w->phi[k] += phi[k], w->u[k] += isnan(u[3 * k]) ? 0.0 : u[3 * k];
    w->q += gf_measure_grain_flow_rate(p, dom);
    w->n++;
    return GF_OK;
}

/* The window's sums to means. */
static void window_mean(chute_window *w)
{
    for (int k = 0; k < N_SLABS; ++k)
        w->phi[k] /= w->n, w->u[k] /= w->n;
    w->q /= w->n;
}

/* The surface speed / sqrt(gD): the slab just below the one holding the bed's top (half-plateau of phi),
 * the test's reading (the top slab holds the dilute grains above the surface). */
static double surface_speed(const chute_window *w, double D, double g)
{
    int top = (int)floor(gf_measure_bed_height_m(w->phi, N_SLABS, 0.0, D, 0.5) / D);
    return top > 0 && top <= N_SLABS ? w->u[top - 1] / sqrt(g * D) : NAN;
}

/* The averaged window read the seed's way; one line. */
static int report(gf_ctx *ctx, const char *who, gf_sim *sim, const chute_args *a, chute_window *w, double cpu_s)
{
    const gf_run_spec *s = gf_sim_spec(sim);
    const double D = s->grains.diameter_m, g = s->gravity_m_s2;
    window_mean(w);
    gf_measure_chute c;
    if (gf_measure_chute_bagnold(ctx, w->phi, w->u, N_SLABS, D, g, a->angle_deg * M_PI / 180.0, &c) != GF_OK)
        return 0;
    int top = (int)floor(c.h_m / D + 0.5);
    printf("%s: %.1f deg, %d samples: I from the Bagnold fit %.4f, Q_g %.4e m3/s, h %.2f D, phi_bulk %.4f, "
           "surface u %.3f sqrt(gD), Bagnold rms %.4f, lambda/h %.4f, %.1f s CPU\n",
           who, a->angle_deg, w->n, c.I, w->q, c.h_m / D, c.phi_bulk, surface_speed(w, D, g),
           c.rel_rms, c.slip_over_h, cpu_s);
    printf("%s: u/sqrt(gD) by slab:", who);
    for (int k = 0; k <= top + 1 && k < N_SLABS; ++k)
        printf(" %.3f", w->u[k] / sqrt(g * D));
    printf("\n");
    return 1;
}

/* One code's samples on their way to the reports. */
typedef struct chute_reader {
    gf_ctx *ctx;
    const char *who;
    gf_sim *sim; /* the scene: grain size, gravity, box */
    const chute_args *a;
    const gf_measure_domain *dom;
    chute_window w;
    int taken;
} chute_reader;

/* A window of a transient: one line (see the head of the file). */
static void report_window(chute_reader *r)
{
    const gf_run_spec *s = gf_sim_spec(r->sim);
    const double D = s->grains.diameter_m, g = s->gravity_m_s2, th = r->a->angle_deg * M_PI / 180.0;
    chute_window *w = &r->w;
    window_mean(w);
    double bed = gf_measure_bed_height_m(w->phi, N_SLABS, 0.0, D, 0.5), ib = 0.0;
    int top = (int)floor(bed / D), nb = 0;
    for (int k = 2; k <= top - 3 && k < N_SLABS - 1; ++k) {
        double depth = bed - (k + 0.5) * D;
        if (w->phi[k] > 0.0 && depth > 0.0)
            ib += fabs(w->u[k + 1] - w->u[k - 1]) / 2.0 / sqrt(w->phi[k] * g * cos(th) * depth), ++nb;
    }
    printf("%s: t %.1f sqrt(D/g): Q_g %.4e m3/s, surface u %.3f sqrt(gD), bed %.2f D, bulk I (hydrostatic) %.4f\n",
           r->who, r->a->spin_nd + r->taken * r->a->every_nd, w->q, surface_speed(w, D, g),
           bed / D, nb > 0 ? ib / nb : NAN);
    *w = (chute_window){0};
}

/* Adds the sample p; reports a full window. */
static int take_sample(chute_reader *r, const gf_particles *p)
{
    if (sample(r->ctx, p, r->dom, gf_sim_spec(r->sim)->grains.diameter_m, &r->w) != GF_OK)
        return 0;
    r->taken++;
    if (r->a->window > 0 && r->w.n == r->a->window)
        report_window(r);
    return 1;
}

/* The closing report: the steady reading of all samples, unless windows were reported. */
static int finish(chute_reader *r, double cpu_s)
{
    if (r->taken == 0)
        return 0;
    if (r->a->window > 0) {
        printf("%s: %d samples, %.1f s CPU\n", r->who, r->taken, cpu_s);
        return 1;
    }
    return report(r->ctx, r->who, r->sim, r->a, &r->w, cpu_s);
}

/* grainflow's own run: spin-up, then one sample per --every. */
static int run_grainflow(gf_ctx *ctx, gf_sim *sim, const chute_args *a, const gf_measure_domain *dom)
{
    chute_reader r = {.ctx = ctx, .who = "grainflow", .sim = sim, .a = a, .dom = dom};
    double c0 = gf_bench_cpu_time_s();
    for (double t = 0.0; t < a->spin_nd - 1e-9; t += 25.0)
        if (gf_sim_advance(sim, steps_of(sim, fmin(25.0, a->spin_nd - t))) != GF_OK)
            return 0;
    for (int k = 0; k < n_samples(a); ++k)
        if (gf_sim_advance(sim, steps_of(sim, a->every_nd)) != GF_OK || !take_sample(&r, gf_sim_particles(sim)))
            return 0;
    return finish(&r, gf_bench_cpu_time_s() - c0);
}

/* Reads one snapshot of a LAMMPS text dump (ITEM: TIMESTEP ... ITEM: ATOMS x y z vx vy vz radius) into p;
 * 0 at the end of the file, -1 on a malformed snapshot. */
static int read_snapshot(gf_ctx *ctx, FILE *f, double rho, gf_particles *p)
{
    char line[512];
    long n = -1;
    while (fgets(line, sizeof line, f)) {
        if (!strncmp(line, "ITEM: NUMBER OF ATOMS", 21) && fgets(line, sizeof line, f))
            n = atol(line);
        else if (!strncmp(line, "ITEM: ATOMS", 11))
            break;
    }
    if (feof(f) || n < 0)
        return n < 0 ? 0 : -1;
    while (p->n_local > 0)
        gf_particles_remove(p, p->n_local - 1);
    for (long i = 0; i < n; ++i) {
        double x, y, z, vx, vy, vz, r;
        size_t at;
        if (!fgets(line, sizeof line, f) || sscanf(line, "%lf %lf %lf %lf %lf %lf %lf", &x, &y, &z, &vx, &vy, &vz, &r) != 7 ||
            gf_particles_add(ctx, p, x, y, z, r, rho, 0, &at) != GF_OK)
            return -1;
        p->vx_m_s[at] = vx, p->vy_m_s[at] = vy, p->vz_m_s[at] = vz;
    }
    return 1;
}

/* The LAMMPS run's snapshots, measured as grainflow's samples. */
static int measure_dump(gf_ctx *ctx, gf_sim *sim, const chute_args *a, const gf_measure_domain *dom)
{
    FILE *f = fopen(a->dump, "r");
    if (!f) {
        fprintf(stderr, "gf-bench-avalanche: cannot read %s\n", a->dump);
        return 0;
    }
    gf_particles *p = NULL;
    chute_reader rd = {.ctx = ctx, .who = "LAMMPS", .sim = sim, .a = a, .dom = dom};
    int r = gf_particles_create(ctx, 1024, &p) == GF_OK ? 1 : -1;
    const gf_run_spec *s = gf_sim_spec(sim);
    while (r > 0 && (r = read_snapshot(ctx, f, s->grains.density_kg_m3, p)) > 0)
        if (!take_sample(&rd, p))
            r = -1;
    fclose(f);
    gf_particles_destroy(&p);
    if (r < 0 || rd.taken == 0) {
        fprintf(stderr, "gf-bench-avalanche: %s: no readable snapshot (%s)\n", a->dump, ctx->last_msg);
        return 0;
    }
    return finish(&rd, 0.0);
}

/* The LAMMPS run's snapshots measured (--measure-dump), or grainflow's own
 * run after the export. */
static int run(gf_ctx *ctx, gf_sim *sim, const void *args)
{
    const chute_args *a = args;
    gf_measure_domain dom;
    gf_sim_box(sim, dom.lo_m, dom.hi_m, dom.periodic);
    if (a->dump)
        return measure_dump(ctx, sim, a, &dom) ? 0 : 1;
    if (a->lammps && !gf_bench_export_lammps(sim, a->lammps, append_chute, a, gf_bench_main_program.name))
        return 1;
    if (run_grainflow(ctx, sim, a, &dom))
        return 0;
    fprintf(stderr, "%s: %s\n", gf_bench_main_program.name, ctx->last_msg);
    return 1;
}

const gf_bench_program gf_bench_main_program = {
    "gf-bench-avalanche",
    "[--angle DEG] [--seed S] [--bed H_over_D] [--length L_over_D] [--width W_over_D] [--tc TC_ND] [--eps E] "
    "[--spin T_ND] [--avg T_ND] [--every T_ND] [--window K] [--lammps-data PATH] [--measure-dump PATH]",
    sizeof(chute_args), &defaults, flags, sizeof flags / sizeof *flags, valid, make_spec, run};
