/*
 * The accuracy cases: each runs one validation scene through gf_sim with the
 * knobs of a setting and compares its observable with a reference.
 *
 *  restitution      binary_collision, clipped linear law, eps_max = 0.5:
 *                   restitution against the closed form of the clipped
 *                   oscillator (Schäfer et al. 1996: 0.550), tolerance 1 %
 *                   (Izard 2014 (3.16)). The dashpot switches on inside a step
 *                   at a random phase; the error quoted is the WORST over
 *                   n onset phases (4 quick, 8 full), what a user may get.
 *  contact_duration binary_collision, unclipped law (attraction allowed),
 *                   eps = 0.87: the overlap lasts exactly t_c = pi/omega_d
 *                   (k_n of Izard (3.17)); error |T/t_c - 1|, worst over the
 *                   phases, tolerance 3 % (row 2). Times are taken from the
 *                   free flight after separation, so they are not quantised
 *                   by dt.
 *  gas_energy       elastic_gas, eps = 1, mu = 0, 216 equal grains in a
 *                   periodic 7.5 D cube (solid fraction 0.27), rms speed
 *                   2 sqrt(gD): total energy (kinetic + (1/2) k_n delta^2) is
 *                   conserved by the ODE; error = max |E(t)/E(0) - 1| over 100
 *                   samples in 4 sqrt(D/g) (quick) or 20 sqrt(D/g) (full).
 *                   Tolerance 1e-3: a thousandth of the energy, small against
 *                   the 25 % a dissipative collision (eps 0.87) removes. The
 *                   Verlet skin changes only the cost (rebuild frequency
 *                   against list length), so it is swept too.
 *  fluid_cell_order the complete fluid step (gf_fluid, no grains) on the
 *                   decaying Taylor-Green vortex, Re 10 (gf_fluid_exact.h):
 *                   rms velocity error at t = 1/(U k); knob: cell size in a
 *                   nominal D = period/32 (4, 2, 1, 0.5 D: n = 8 ... 64);
 *                   tolerance 5 %, half the 10 % of the coupled cases.
 *  fluid_wall_order the same on start-up plane Poiseuille flow (viscous step
 *                   and no-slip walls; D = channel width/32).
 *  immersed_collapse (--full) the immersed dense collapse of
 *                   tests/fluid/validate_collapse.c: R_inf/R0 of seed 1
 *                   against the mean of 3 seeds of the finest setting (cell
 *                   1 D, dt = t_c/50); knobs cell/D in {4, 2, 1.5, 1}, dt/t_c
 *                   in {1/20, 1/50}; tolerance 10 % (row 33). The dominant
 *                   basal excess pressure at x = R0/2 is recorded too.
 *  hindered_settling  settling scene (unresolved tier chosen by `fluid: auto`),
 *                   suspension at phi = 0.2, Re_t = 0.05: U/U_t against
 *                   Richardson & Zaki (1954) (1 - phi)^4.65; tolerance 10 %
 *                   (issue #4). Knobs: fluid cell / D and dt/t_c.
 *  collapse_runout  (--full) dry column_collapse, R0 = 8 D, a = 0.5, W = 3 D:
 *                   final front position, mean over 3 seeds (the packing
 *                   and the collapse are chaotic: one run's front scatters
 *                   by several D between seeds or dt, and the front is
 *                   measured in bins of D), against the same mean for the
 *                   finest setting (dt = t_c/200, t_c sqrt(g/D) = 5e-3);
 *                   tolerance 10 % (row 33, resolution A vs B). The seed
 *                   scatter of the reference is printed: below it, a
 *                   difference is noise, not a discretisation error.
 *  settling_sphere  (bench_sphere.c) settling scene mode 0, one sphere at
 *                   Re_t = 0.01 in a periodic 60 D box, closure tenneti:
 *                   U/U_St against Stokes with Hasimoto's (1959) periodic
 *                   correction, tolerance 3 % (issue #4); knob: cell / D in
 *                   {4, 3, 2.5, 2} (the kernel width follows the cell).
 *  resolved_early_acceleration (bench_resolved.c) the resolved tier's
 *                   settling sphere, rho_p/rho = 4, Ar = 800, 4 D x 6 D
 *                   free-slip box: a/g as t -> 0 from the force fit over
 *                   0.02-0.15 sqrt(D/g), against the added-mass value 2/3
 *                   (Izard 2014 eq. (2.34)), tolerance 5 %; knobs D/dx in
 *                   {8, 12, 16} (--quick: 8, 12) and the solid fraction's
 *                   retraction in {0, 0.3} dx (Breugem 2012).
 *  settling_terminal_tiers (bench_tiers.c) the same sphere in a 6 D x 16 D
 *                   box: u_T/sqrt(gD) against Schiller-Naumann 1.244
 *                   (Izard 2014 eq. (2.35)), tolerance 3 %; the cell knob
 *                   picks the tier: unresolved at cell/D in {3, 2, 1.5},
 *                   resolved at D/dx = 8 (cell/D = 1/8); the unresolved
 *                   tier's default closure (di_felice). Its twin
 *                   settling_terminal_tenneti: the unresolved cells with the
 *                   closure tenneti (isolated limit Schiller-Naumann).
 *  settling_terminal_step, settling_terminal_step_markers (bench_tiers.c)
 *                   the resolved sphere at D/dx 8 in a 4 D x 12 D box to
 *                   8 sqrt(D/g), u_T against Schiller-Naumann, knob: the
 *                   fluid step fluid.cfl in {0.3, 0.15, 0.075}, with the
 *                   smoothed forcing (r_d 0) or the surface markers (r_d 0.3).
 *  hindered_settling_tiers (bench_suspension.c) a random suspension, phi
 *                   0.1, 41 grains in a 6 D periodic cube, rho_p/rho 2,
 *                   Ar 20: U/U_T against Richardson & Zaki (1954),
 *                   n = 4.4 Re_T^-0.03, tolerance 10 %; the cell knob picks
 *                   the tier as in settling_terminal_tiers (unresolved
 *                   di_felice at 3, 2, 1.5 D; resolved at D/dx = 8).
 *  janssen_saturation (--full, bench_janssen.c) the 6 D x 30 D Janssen
 *                   column of test_janssen: saturation stress (lower-half
 *                   mean), mean of 3 seeds, against the same at dt = t_c/100,
 *                   t_c sqrt(g/D) = 5e-3; knobs dt/t_c in {1/20, 1/50, 1/100},
 *                   t_c sqrt(g/D) in {2e-2, 1e-2, 5e-3}; tolerance 10 %.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "bench_accuracy.h"
#include "contact/gf_contact.h"
#include "coupling/gf_tier.h"
#include "fluid/gf_fluid_exact.h"
#include "coupling/gf_coupling.h"
#include "gf_sim.h"
#include "scenes/gf_scene.h"
#include "gf_test_energy.h" /* the tests' minimum-image spring energy, one definition */

/* CPU time of the process, s: the cost of a one-thread run, insensitive to
 * the other processes sharing the machine (its wall time on an idle one). */
static double bench_cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static gf_run_spec base_spec(const char *scene, const bench_knobs *k)
{
    gf_run_spec s;
    gf_run_spec_defaults(&s);
    snprintf(s.scene, sizeof s.scene, "%s", scene);
    /* acetate-like grains of the seeds' collision tests (Foerster et al. 1994) */
    s.grains.diameter_m = 3e-3;
    s.grains.density_kg_m3 = 1319.0;
    s.grains.polydispersity = 0.0;
    s.contact.dt_over_tc = k->dt_over_tc;
    s.contact.skin_over_D = k->skin_over_D;
    s.contact.t_contact_nd = k->t_contact_nd;
    s.fluid.cell_over_D = k->cell_over_D;
    return s;
}

static gf_status make_sim(gf_ctx *ctx, const gf_run_spec *spec, gf_sim **out)
{
    gf_sim_options opt;
    memset(&opt, 0, sizeof opt);
    opt.output_dir = NULL;
    opt.n_threads = 1;
    return gf_sim_create(ctx, spec, &opt, out);
}

static int always(const char **why)
{
    *why = "";
    return 1;
}

/* ---------------------------------------------------------------- collisions */

typedef struct collision_out {
    double restitution, overlap_over_tc, wall_s;
} collision_out;

/* One head-on collision of two equal grains at V = sqrt(gD), the overlap
 * opening at a fraction `phase` of a step (as tests/engine/test_dem_restitution.c). */
static gf_status collide(gf_ctx *ctx, const bench_knobs *k, double eps, int attraction, double phase,
                         collision_out *o)
{
    gf_run_spec spec = base_spec("binary_collision", k);
    spec.contact.restitution = eps;
    spec.contact.allow_attraction = attraction;
    spec.contact.friction = 0.0;
    double D = spec.grains.diameter_m, V = sqrt(spec.gravity_m_s2 * D), dt = gf_run_spec_dt_s(&spec);
    double gap_over_D = (floor(0.01 * D / (V * dt)) + phase) * V * dt / D;
    GF_TRY(gf_run_spec_set_param(ctx, &spec, "gap_over_D", gap_over_D));
    gf_sim *sim = NULL;
    double t0 = bench_cpu_s();
    GF_TRY(make_sim(ctx, &spec, &sim));
    double tc = gf_run_spec_t_contact_s(&spec);
    long n = (long)ceil((gap_over_D * D / V + 1.5 * tc) / gf_sim_dt_s(sim));
    gf_status st = gf_sim_advance(sim, n);
    o->wall_s = bench_cpu_s() - t0;
    if (st == GF_OK) {
        gf_particles *p = gf_sim_particles(sim);
        double v_sep = p->vx_m_s[1] - p->vx_m_s[0], dist = p->x_m[1] - p->x_m[0];
        double t_end = gf_sim_time_s(sim) - (dist - D) / v_sep; /* free flight, back-extrapolated */
        o->restitution = v_sep / V;
        o->overlap_over_tc = (t_end - gap_over_D * D / V) / tc;
    }
    gf_sim_destroy(&sim);
    return st;
}

static gf_status measure_restitution(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out)
{
    const double eps_max = 0.5;
    double closed, force_duration;
    gf_contact_clipped_restitution(eps_max, &closed, &force_duration);
    int n_phase = full ? 8 : 4;
    double worst = 0.0, mean = 0.0, wall = 0.0;
    for (int ph = 0; ph < n_phase; ++ph) {
        collision_out o;
        GF_TRY(collide(ctx, k, eps_max, 0, (ph + 0.5) / n_phase, &o));
        mean += o.restitution / n_phase;
        worst = fmax(worst, fabs(o.restitution / closed - 1.0));
        wall += o.wall_s;
    }
    *out = (bench_result){mean, closed, worst, wall, NAN};
    return GF_OK;
}

static gf_status measure_duration(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out)
{
    int n_phase = full ? 8 : 4;
    double worst = 0.0, mean = 0.0, wall = 0.0;
    for (int ph = 0; ph < n_phase; ++ph) {
        collision_out o;
        GF_TRY(collide(ctx, k, 0.87, 1, (ph + 0.5) / n_phase, &o));
        mean += o.overlap_over_tc / n_phase;
        worst = fmax(worst, fabs(o.overlap_over_tc - 1.0));
        wall += o.wall_s;
    }
    *out = (bench_result){mean, 1.0, worst, wall, NAN};
    return GF_OK;
}

/* ---------------------------------------------------------------- elastic gas */

static gf_status measure_gas(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out)
{
    gf_run_spec spec = base_spec("elastic_gas", k);
    spec.contact.restitution = 1.0;
    spec.contact.friction = 0.0;
    GF_TRY(gf_run_spec_set_param(ctx, &spec, "n_grains", 216));
    GF_TRY(gf_run_spec_set_param(ctx, &spec, "box_over_D", 7.5));
    GF_TRY(gf_run_spec_set_param(ctx, &spec, "speed_nd", 2.0));
    gf_sim *sim = NULL;
    double wall = 0.0, t0 = bench_cpu_s();
    GF_TRY(make_sim(ctx, &spec, &sim));
    wall += bench_cpu_s() - t0;
    gf_particles *p = gf_sim_particles(sim);
    double e0 = gf_particles_kinetic_energy(p) + gf_test_spring_energy(sim), worst = 0.0;
    double t_total = (full ? 20.0 : 4.0) * sqrt(spec.grains.diameter_m / spec.gravity_m_s2);
    long n_total = (long)ceil(t_total / gf_sim_dt_s(sim)), done = 0;
    gf_status st = GF_OK;
    for (int smp = 1; smp <= 100 && st == GF_OK; ++smp) {
        long target = n_total * smp / 100;
        t0 = bench_cpu_s();
        st = gf_sim_advance(sim, target - done);
        wall += bench_cpu_s() - t0;
        done = target;
        if (st == GF_OK)
            worst = fmax(worst, fabs((gf_particles_kinetic_energy(p) + gf_test_spring_energy(sim)) / e0 - 1.0));
    }
    gf_sim_destroy(&sim);
    GF_TRY(st);
    *out = (bench_result){worst, 0.0, worst, wall, NAN};
    return GF_OK;
}

/* ---------------------------------------------------------------- dry collapse */

#define COLLAPSE_SEEDS 3
static double collapse_reference_m = NAN, collapse_reference_sd_m = NAN;

static int collapse_available(const char **why)
{
    const gf_scene_desc *d = gf_scene_find("column_collapse");
    if (!d || !d->diagnose || d->n_diag < 1) {
        *why = "scene column_collapse (with front_position diagnostic) not in this build";
        return 0;
    }
    *why = "";
    return 1;
}

/* Final front position of a small dry collapse (run to the scene's end condition). */
static gf_status collapse_front(gf_ctx *ctx, const bench_knobs *k, uint64_t seed, double *front_m, double *wall_s)
{
    gf_run_spec spec = base_spec("column_collapse", k);
    spec.seed = seed;
    spec.grains.diameter_m = 7.6e-3; /* Izard 2014 §5.2 grains, defaults of the run spec */
    spec.grains.density_kg_m3 = 2500.0;
    spec.grains.polydispersity = 0.05;
    GF_TRY(gf_run_spec_set_param(ctx, &spec, "column_length_over_D", 8.0));
    GF_TRY(gf_run_spec_set_param(ctx, &spec, "aspect_ratio", 0.5));
    GF_TRY(gf_run_spec_set_param(ctx, &spec, "width_over_D", 3.0));
    spec.end_time_nd = 40.0; /* upper bound; done() stops the run at rest */
    const gf_scene_desc *d = gf_scene_find("column_collapse");
    gf_sim *sim = NULL;
    double t0 = bench_cpu_s();
    GF_TRY(make_sim(ctx, &spec, &sim));
    long chunk = (long)ceil(0.25 * sqrt(spec.grains.diameter_m / spec.gravity_m_s2) / gf_sim_dt_s(sim));
    gf_status st = GF_OK;
    while (st == GF_OK && gf_sim_time_s(sim) < gf_sim_end_time_s(sim) && !(d->done && d->done(sim)))
        st = gf_sim_advance(sim, chunk);
    *wall_s = bench_cpu_s() - t0;
    double v[16];
    if (st == GF_OK && d->n_diag <= 16)
        st = d->diagnose(sim, v);
    *front_m = v[0]; /* front_position, docs/output.md */
    gf_sim_destroy(&sim);
    return st;
}

static gf_status collapse_mean(gf_ctx *ctx, const bench_knobs *k, double *mean_m, double *sd_m, double *wall_s)
{
    double sum = 0.0, sum2 = 0.0;
    *wall_s = 0.0;
    for (int seed = 1; seed <= COLLAPSE_SEEDS; ++seed) {
        double f, w;
        GF_TRY(collapse_front(ctx, k, (uint64_t)seed, &f, &w));
        sum += f, sum2 += f * f, *wall_s += w;
    }
    *mean_m = sum / COLLAPSE_SEEDS;
    *sd_m = sqrt(fmax(0.0, sum2 / COLLAPSE_SEEDS - *mean_m * *mean_m));
    return GF_OK;
}

static gf_status measure_collapse(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out)
{
    if (isnan(collapse_reference_m)) {
        bench_knobs fine = *k;
        fine.dt_over_tc = 1.0 / 200.0;
        fine.t_contact_nd = 5e-3;
        double w;
        GF_TRY(collapse_mean(ctx, &fine, &collapse_reference_m, &collapse_reference_sd_m, &w));
        printf("collapse_runout   reference (dt = t_c/200, t_c sqrt(g/D) = 5e-3, %d seeds): front %.3g D, seed "
               "scatter (sd) %.3g D = %.1f %%\n",
               COLLAPSE_SEEDS, collapse_reference_m / 7.6e-3, collapse_reference_sd_m / 7.6e-3,
               100.0 * collapse_reference_sd_m / collapse_reference_m);
    }
    double front, sd, wall;
    GF_TRY(collapse_mean(ctx, k, &front, &sd, &wall));
    double D = 7.6e-3; /* observables are dimensionless: front / D */
    *out = (bench_result){front / D, collapse_reference_m / D, fabs(front / collapse_reference_m - 1.0), wall, NAN};
    return GF_OK;
}

/* ---------------------------------------------------------------- fluid, cell size */

/* The complete fluid step (gf_fluid, no grains) on exact solutions
 * (engine/fluid/gf_fluid_exact.h, tests/fluid/test_fluid_order.c). These
 * problems have no grain, so the cell knob is measured in a nominal
 * D = L/32 (L: the Taylor-Green period 2 pi/k, the Poiseuille channel
 * width): cell/D in {4, 2, 1, 0.5} is n = 8, 16, 32, 64 cells across L.
 * dt = 0.25 h^2 (Taylor-Green, units 1/(U k)) and 0.1 h^2 (Poiseuille,
 * units L^2/nu): the spatial error dominates (test_fluid_order). */
static const double fluid_cell_list[] = {4.0, 2.0, 1.0, 0.5};

static gf_status measure_fluid(gf_ctx *ctx, gf_fluid_exact_problem pb, const bench_knobs *k, bench_result *out)
{
    int tg = pb == GF_EXACT_TAYLOR_GREEN, n = (int)lround(32.0 / k->cell_over_D);
    double h = (tg ? 2.0 * M_PI : 1.0) / n;
    gf_fluid_exact_case c = {.problem = pb, .n = n, .dt = (tg ? 0.25 : 0.1) * h * h, .t_end = tg ? 1.0 : 0.1, .re = 10.0};
    gf_fluid_exact_result r;
    double t0 = bench_cpu_s();
    GF_TRY(gf_fluid_exact_run(ctx, &c, &r));
    *out = (bench_result){r.err_rms, 0.0, r.err_rms, bench_cpu_s() - t0, NAN};
    return GF_OK;
}

/* Taylor-Green vortex, Re 10, t = 1/(U k): advection + viscous step + projection. */
static gf_status measure_fluid_tgv(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out)
{
    return measure_fluid(ctx, GF_EXACT_TAYLOR_GREEN, k, out);
}

/* Start-up plane Poiseuille flow, t = 0.1 L^2/nu: viscous step + no-slip walls. */
static gf_status measure_fluid_poiseuille(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out)
{
    return measure_fluid(ctx, GF_EXACT_POISEUILLE, k, out);
}

/* ---------------------------------------------------------------- immersed collapse */

/* The immersed dense collapse of tests/fluid/validate_collapse.c (Rondon et
 * al. 2011; Izard 2014 ch. 5): column_collapse, R0 = 16 D, a = 0.5, W = 3 D,
 * D = 7.6 mm, rho_p/rho_f = 8, eta_f = 1 Pa s (viscous regime), phi_i 0.60
 * prepared with rotations locked, unresolved tier, no lubrication, run to
 * 10 000 T_visq, T_visq = eta_f / (drho g H0) (Izard (5.2)). */
#define IMM_D 7.6e-3
#define IMM_RHO_P 8000.0
#define IMM_RHO_F 1000.0
#define IMM_ETA 1.0
#define IMM_R0_OVER_D 16.0
#define IMM_END_T_VISQ 1.0e4
#define IMM_SEEDS 3
static const double imm_dt_list[] = {1.0 / 20, 1.0 / 50};
static const double imm_cell_list[] = {4.0, 2.0, 1.5, 1.0};

typedef struct imm_run {
    double runout, pb8, cpu_s; /* R_inf/R0, dominant basal extremum at x = R0/2 / (drho g H0), CPU s */
} imm_run;

/* Reference: the finest setting (cell 1 D, dt = t_c/50), IMM_SEEDS seeds. */
static imm_run imm_ref_runs[IMM_SEEDS];
static double imm_ref_mean = NAN, imm_ref_sd = NAN;

static int immersed_available(const char **why)
{
    const gf_scene_desc *d = gf_scene_find("column_collapse");
    if (!d || !d->diagnose || d->n_diag < 1) {
        *why = "scene column_collapse (with front_position diagnostic) not in this build";
        return 0;
    }
    *why = "";
    return 1;
}

static gf_status immersed_spec(gf_ctx *ctx, const bench_knobs *k, uint64_t seed, gf_run_spec *s)
{
    gf_run_spec_defaults(s);
    snprintf(s->scene, sizeof s->scene, "column_collapse");
    s->seed = seed;
    s->grains.diameter_m = IMM_D;
    s->grains.density_kg_m3 = IMM_RHO_P;
    snprintf(s->fluid.model, sizeof s->fluid.model, "unresolved");
    s->fluid.density_kg_m3 = IMM_RHO_F;
    s->fluid.viscosity_Pa_s = IMM_ETA;
    s->fluid.lubrication = 0;
    s->fluid.cell_over_D = k->cell_over_D;
    s->contact.dt_over_tc = k->dt_over_tc;
    s->phi_initial = 0.60;
    s->aspect_ratio_a = 0.5;
    GF_TRY(gf_run_spec_set_param(ctx, s, "column_length_over_D", IMM_R0_OVER_D));
    /* the preparation's blocked rotations are kept until t = 0 (scene notes) */
    return gf_run_spec_set_param(ctx, s, "settle_rotation_locked", 1.0);
}

/* Excess pressure at the scene's basal gauge `name` (Pa), 0 when absent. */
static double gauge_Pa(gf_sim *sim, const char *name)
{
    double x_m[3];
    return gf_sim_gauge_position(sim, name, x_m) && gf_sim_coupling(sim) ? gf_sim_excess_pressure_Pa(sim, x_m) : 0.0;
}

/* One collapse to IMM_END_T_VISQ; the gauge is read every 50 T_visq (as validate_collapse). */
static gf_status immersed_run(gf_ctx *ctx, const bench_knobs *k, uint64_t seed, imm_run *r)
{
    gf_run_spec spec;
    GF_TRY(immersed_spec(ctx, k, seed, &spec));
    double H0 = 0.5 * IMM_R0_OVER_D * IMM_D, drho_g_H0 = (IMM_RHO_P - IMM_RHO_F) * spec.gravity_m_s2 * H0;
    double t_visq = IMM_ETA / drho_g_H0, pmin = 0.0, pmax = 0.0, v[16] = {NAN};
    const gf_scene_desc *d = gf_scene_find("column_collapse");
    gf_sim *sim = NULL;
    double t0 = bench_cpu_s();
    GF_TRY(make_sim(ctx, &spec, &sim));
    long chunk = (long)ceil(50.0 * t_visq / gf_sim_dt_s(sim));
    gf_status st = GF_OK;
    while (st == GF_OK && gf_sim_time_s(sim) < IMM_END_T_VISQ * t_visq) {
        st = gf_sim_advance(sim, chunk);
        double pb = gauge_Pa(sim, "base_x8_16R0");
        pmin = fmin(pmin, pb), pmax = fmax(pmax, pb);
    }
    r->cpu_s = bench_cpu_s() - t0;
    if (st == GF_OK && d->n_diag <= 16)
        st = d->diagnose(sim, v);
    gf_sim_destroy(&sim);
    GF_TRY(st);
    r->runout = v[0] / (IMM_R0_OVER_D * IMM_D);
    r->pb8 = (fabs(pmin) > fabs(pmax) ? pmin : pmax) / drho_g_H0;
    return GF_OK;
}

static int imm_is_reference(const bench_knobs *k)
{
    return fabs(k->cell_over_D - 1.0) < 1e-12 && fabs(k->dt_over_tc - 1.0 / 50) < 1e-12;
}

static gf_status immersed_reference(gf_ctx *ctx)
{
    const bench_knobs fine = {1.0 / 50, BENCH_DEFAULT_SKIN_OVER_D, BENCH_DEFAULT_TC_ND, 1.0, BENCH_DEFAULT_RETRACT_DX,
                              BENCH_DEFAULT_FLUID_CFL};
    double sum = 0.0, sum2 = 0.0;
    for (int s = 0; s < IMM_SEEDS; ++s) {
        GF_TRY(immersed_run(ctx, &fine, (uint64_t)(s + 1), &imm_ref_runs[s]));
        double R = imm_ref_runs[s].runout;
        sum += R, sum2 += R * R;
        printf("immersed_collapse reference seed %d (cell 1 D, dt = t_c/50): R_inf/R0 %.4f, Pb(R0/2) %+.4f drho g H0, "
               "%.1f CPU s\n", s + 1, R, imm_ref_runs[s].pb8, imm_ref_runs[s].cpu_s);
        fflush(stdout);
    }
    imm_ref_mean = sum / IMM_SEEDS;
    imm_ref_sd = sqrt(fmax(0.0, sum2 / IMM_SEEDS - imm_ref_mean * imm_ref_mean));
    printf("immersed_collapse reference: R_inf/R0 mean %.4f, seed scatter (sd) %.4f = %.1f %%\n", imm_ref_mean,
           imm_ref_sd, 100.0 * imm_ref_sd / imm_ref_mean);
    fflush(stdout);
    return GF_OK;
}

/* Seed 1 at setting k against the mean run-out of the reference seeds. */
static gf_status measure_immersed(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out)
{
    if (isnan(imm_ref_mean))
        GF_TRY(immersed_reference(ctx));
    imm_run r;
    if (imm_is_reference(k))
        r = imm_ref_runs[0]; /* the reference's seed 1 is this setting's run */
    else
        GF_TRY(immersed_run(ctx, k, 1, &r));
    *out = (bench_result){r.runout, imm_ref_mean, fabs(r.runout / imm_ref_mean - 1.0), r.cpu_s, r.pb8};
    return GF_OK;
}

/* ---------------------------------------------------------------- hindered settling */

static int settling_available(const char **why)
{
    const gf_scene_desc *d = gf_scene_find("settling");
    if (!d || !d->diagnose || d->n_diag < 3) {
        *why = "scene settling (with settling_velocity_ratio) not in this build";
        return 0;
    }
    *why = "";
    return 1;
}

/* Homogeneous suspension at phi = 0.2 in a periodic ~16 D cube, Re_t = 0.05
 * (tests/fluid/test_hindered_settling.c set-up, run through gf_sim): U/U_t
 * after 3 sqrt(D/g) (the grains' Stokes relaxation time is 0.1 sqrt(D/g))
 * against Richardson & Zaki (1954), (1 - phi)^4.65. The tier comes from the
 * `fluid: auto` rule (gf_tier.h), which must pick "unresolved" here. */
static gf_status measure_settling(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out)
{
    gf_run_spec spec = base_spec("settling", k);
    const double D = 1e-3, rho_p = 2500.0, rho_f = 1000.0, g = 9.81, phi = 0.2;
    spec.grains.diameter_m = D;
    spec.grains.density_kg_m3 = rho_p;
    spec.fluid.density_kg_m3 = rho_f;
    spec.fluid.viscosity_Pa_s = sqrt(rho_f * (rho_p - rho_f) * g * D * D * D / (18.0 * 0.05)); /* Re_t = 0.05 */
    gf_groups_input in = {.diameter_m = D, .grain_density_kg_m3 = rho_p, .fluid_density_kg_m3 = rho_f,
                          .viscosity_Pa_s = spec.fluid.viscosity_Pa_s, .gravity_m_s2 = g, .slope_sin = 1.0};
    gf_scales sc;
    GF_TRY(gf_groups_compute(ctx, &in, &sc));
    gf_tier_choice tier;
    GF_TRY(gf_tier_from_scales(ctx, &sc, &tier));
    snprintf(spec.fluid.model, sizeof spec.fluid.model, "%s", tier.model);
    if (tier.tier != GF_TIER_UNRESOLVED)
        return GF_FAIL(ctx, GF_ERR_PHYSICS, "settling: fluid: auto chose '%s' (%s)", tier.model, tier.reason);
    /* Richardson-Zaki is a drag law of the suspension: lubrication between the
     * rare close pairs is not part of it, and at St = 0.06 its explicit
     * damping would need dt < t_c/230 (gf_sim refuses the default dt) */
    spec.fluid.lubrication = 0;
    GF_TRY(gf_run_spec_set_param(ctx, &spec, "mode", 1.0));
    GF_TRY(gf_run_spec_set_param(ctx, &spec, "phi_suspension", phi));
    GF_TRY(gf_run_spec_set_param(ctx, &spec, "box_over_D", 16.0));
    const gf_scene_desc *d = gf_scene_find("settling");
    gf_sim *sim = NULL;
    double t0 = bench_cpu_s();
    GF_TRY(make_sim(ctx, &spec, &sim));
    long n = (long)ceil((full ? 5.0 : 3.0) * sqrt(D / g) / gf_sim_dt_s(sim));
    gf_status st = gf_sim_advance(sim, n);
    double wall = bench_cpu_s() - t0, v[8] = {NAN, NAN, NAN};
    if (st == GF_OK)
        st = d->diagnose(sim, v);
    gf_sim_destroy(&sim);
    GF_TRY(st);
    double rz = pow(1.0 - phi, 4.65);
    *out = (bench_result){v[2], rz, fabs(v[2] / rz - 1.0), wall, NAN};
    return GF_OK;
}

/* ---------------------------------------------------------------- table */

/* The settling sphere's terminal velocity, measured by both tiers against one reference. */
#define SETTLING_TERMINAL_REFERENCE \
    "Schiller & Naumann 1933 with C_D Re^2 = (4/3) Ar: 1.244 (Izard 2014 eq. (2.35))", "|u_T/u_SN - 1| (1)", 0.03
#define SETTLING_TERMINAL_AUX "time of the largest speed, sqrt(D/g) (1)"
/* The resolved sphere against the fluid step (bench_tiers.c), one forcing per case. */
#define SETTLING_STEP_CASE(name, forcing, measure)                                                                    \
    {name, "terminal velocity u_T/sqrt(gD), resolved D/dx 8, 4 D x 12 D box, " forcing " (1)",                         \
     SETTLING_TERMINAL_REFERENCE, BENCH_KNOB_FLUID_CFL, 0, bench_resolved_available, measure, NULL, NULL, 0, 0,       \
     SETTLING_TERMINAL_AUX, NULL, 0, 0, 1, NULL, 0, bench_step_cfl, 3}

/* The avalanche at one Table 4.2 point through both tiers, drive (4.6), 100 sqrt(D/g) (bench_regime_tiers.c). */
#define REGIME_CASE(name, point, t_thesis, fn, scale)                                                               \
    {name, "T/T_thesis, immersed avalanche, " point ", drive (4.6), both tiers (1)",                              \
     "Izard (2014) Table 4.2: T = " t_thesis, "max(T/T_th, T_th/T) - 1 (1)", 1.0, BENCH_KNOB_CELL, 1,             \
     bench_regime_available, fn, NULL, bench_regime_cells, 0, 2, scale " of the thesis' regime (1)", NULL, 0, 0, 2, \
     NULL, 0, NULL, 0}

static const bench_case cases[] = {
    {"restitution", "restitution of a normal collision, clipped law, eps_max 0.5 (1)",
     "closed form of the clipped oscillator, 0.550 (Schaefer et al. 1996)", "worst |e/e_closed - 1| over onset phases (1)",
     0.01, BENCH_KNOB_DT, 0, always, measure_restitution, NULL, NULL, 0, 0, NULL, NULL, 0, 0, 0, NULL, 0, NULL, 0},
    {"contact_duration", "overlap duration / t_c, unclipped law, eps 0.87 (1)", "t_c exactly (Izard (3.17))",
     "worst |T/t_c - 1| over onset phases (1)", 0.03, BENCH_KNOB_DT, 0, always, measure_duration, NULL, NULL, 0, 0, NULL, NULL, 0, 0, 0, NULL, 0, NULL, 0},
    {"gas_energy", "max relative energy error, elastic frictionless gas (1)", "0 (energy conserved by the ODE)",
     "max |E/E0 - 1| (1)", 1e-3, BENCH_KNOB_DT | BENCH_KNOB_SKIN, 0, always, measure_gas, NULL, NULL, 0, 0, NULL, NULL, 0, 0, 0, NULL, 0, NULL, 0},
    {"collapse_runout", "final front position / D, dry collapse R0 = 8 D, a = 0.5 (1)",
     "finest run: dt = t_c/200, t_c sqrt(g/D) = 5e-3, mean of 3 seeds", "|R/R_finest - 1| (1)", 0.10, BENCH_KNOB_DT | BENCH_KNOB_TC,
     1, collapse_available, measure_collapse, NULL, NULL, 0, 0, NULL, NULL, 0, 0, 0, NULL, 0, NULL, 0},
    {"hindered_settling", "settling velocity / Stokes velocity, suspension phi = 0.2, Re_t = 0.05 (1)",
     "Richardson & Zaki 1954: (1 - phi)^4.65", "|U/U_RZ - 1| (1)", 0.10, BENCH_KNOB_DT | BENCH_KNOB_CELL, 0,
     settling_available, measure_settling, NULL, NULL, 0, 0, NULL, NULL, 0, 0, 0, NULL, 0, NULL, 0},
    {"fluid_cell_order", "rms velocity error / U F(t), Taylor-Green vortex Re 10, t = 1/(U k) (1)",
     "exact decay exp(-2 nu k^2 t) (Taylor & Green 1937)", "rms |u - u_exact| / (U F) (1)", 0.05, BENCH_KNOB_CELL, 0,
     always, measure_fluid_tgv, NULL, fluid_cell_list, 0, 4, NULL, NULL, 0, 0, 0, NULL, 0, NULL, 0},
    {"fluid_wall_order", "rms velocity error / u_max, start-up plane Poiseuille, t = 0.1 L^2/nu (1)",
     "exact series solution (gf_fluid_exact.h)", "rms |u - u_exact| / u_max (1)", 0.05, BENCH_KNOB_CELL, 0, always,
     measure_fluid_poiseuille, NULL, fluid_cell_list, 0, 4, NULL, NULL, 0, 0, 0, NULL, 0, NULL, 0},
    {"immersed_collapse", "run-out R_inf/R0, immersed dense collapse R0 = 16 D, a = 0.5, phi_i 0.60 (1)",
     "finest run: cell 1 D, dt = t_c/50, mean of 3 seeds", "|R_inf/R_ref - 1| (1)", 0.10,
     BENCH_KNOB_DT | BENCH_KNOB_CELL, 1, immersed_available, measure_immersed, imm_dt_list, imm_cell_list, 2, 4,
     "dominant basal excess pressure at x = R0/2 / (drho g H0)", NULL, 0, 0, 0, NULL, 0, NULL, 0},
    {"settling_sphere", "terminal velocity U/U_Stokes, single sphere Re_t = 0.01, periodic 60 D box (1)",
     "Stokes with Hasimoto's (1959) periodic correction, 1 - 1.7601 c^(1/3) + c", "|U/U_Hasimoto - 1| (1)", 0.03,
     BENCH_KNOB_CELL, 0, bench_sphere_available, bench_sphere_measure, NULL, bench_sphere_cells, 0, 4,
     "drift of U over the last 20 % of the run (1)", NULL, 0, 0, 0, NULL, 0, NULL, 0},
    {"janssen_saturation", "saturation stress / (rho_e g D), Janssen column 6 D x 30 D, lower-half mean (1)",
     "finest run: dt = t_c/100, t_c sqrt(g/D) = 5e-3, same seed (packing)", "|sigma/sigma_finest - 1| (1)", 0.10,
     BENCH_KNOB_DT | BENCH_KNOB_TC, 1, bench_janssen_available, bench_janssen_measure, bench_janssen_dt, NULL, 3, 0,
     "f_p K from the lambda fit (1)", bench_janssen_tc, 3, 0, 0, NULL, 0, NULL, 0},
    {"resolved_early_acceleration", "early acceleration a/g, settling sphere rho_p/rho 4, Ar 800, resolved tier (1)",
     "added mass C_M = 1/2: (2/3) g (Izard 2014 eq. (2.34))", "|a/a_added_mass - 1| (1)", 0.05,
     BENCH_KNOB_CELL | BENCH_KNOB_RETRACT, 0, bench_resolved_available, bench_resolved_measure, NULL,
     bench_resolved_cells, 0, 3, NULL, NULL, 0, 2, 1, bench_resolved_retract, 2, NULL, 0},
    {"settling_terminal_tiers", "terminal velocity u_T/sqrt(gD), the same sphere in a 6 D x 16 D box, both tiers (1)",
     SETTLING_TERMINAL_REFERENCE,
     BENCH_KNOB_CELL, 0, bench_resolved_available, bench_tiers_measure, NULL, bench_tiers_cells, 0, 4,
     SETTLING_TERMINAL_AUX, NULL, 0, 0, 2, NULL, 0, NULL, 0},
    {"settling_terminal_tenneti", "terminal velocity u_T/sqrt(gD), the same, unresolved tier, closure tenneti (1)",
     SETTLING_TERMINAL_REFERENCE,
     BENCH_KNOB_CELL, 0, bench_resolved_available, bench_tiers_measure_tenneti, NULL, bench_tiers_unresolved_cells, 0,
     3, SETTLING_TERMINAL_AUX, NULL, 0, 0, 2, NULL, 0, NULL, 0},
    SETTLING_STEP_CASE("settling_terminal_step", "smoothed forcing", bench_step_measure_smoothed),
    SETTLING_STEP_CASE("settling_terminal_step_markers", "surface markers, r_d 0.3", bench_step_measure_markers),
    {"hindered_settling_tiers", "settling velocity U/U_T, random suspension phi 0.1, Ar 20, 6 D cube, both tiers (1)",
     "Richardson & Zaki 1954: (1 - phi)^n, n = 4.4 Re_T^-0.03, U_T Schiller-Naumann", "|U/U_RZ - 1| (1)", 0.10,
     BENCH_KNOB_CELL, 0, bench_resolved_available, bench_suspension_measure, NULL, bench_suspension_cells, 0, 4, NULL,
     NULL, 0, 0, 2, NULL, 0, NULL, 0},
    REGIME_CASE("avalanche_viscous_tiers", "viscous, rho_p/rho 4, St 0.05", "605 ms", bench_regime_viscous, "T/T_v"),
    REGIME_CASE("avalanche_inertial_tiers", "inertial, rho_p/rho 3, St 28", "24 ms", bench_regime_inertial, "T/T_i"),
    REGIME_CASE("avalanche_free_fall_tiers", "free fall, rho_p/rho 20, St 220", "32 ms", bench_regime_free_fall,
                "T/T_ff"),
    {"collapse_case_a_tiers",
     "E_cx^max/(m g D), immersed collapse case A (a 0.5, R0 16 D, W 2 D, L 50 D), both tiers (1)",
     "Izard (2014) Table 5.1: 0.023", "|E/0.023 - 1| (1)", 0.30, BENCH_KNOB_CELL, 1, bench_regime_available,
     bench_collapse_tiers, NULL, bench_collapse_cells, 0, 2, "dominant P_b at x = 13/16 R0 / (drho g H0) (1)", NULL, 0,
     0, 2, NULL, 0, NULL, 0},
};

const bench_case *bench_cases(int *n)
{
    *n = (int)(sizeof cases / sizeof cases[0]);
    return cases;
}
