/*
 * gf-bench-silo: the discharge of the thesis' silo (scene silo; Djouwe
 * Meffeja 2012 §3.3) from its t = 0 state (column settled, orifice just
 * opened), for the side-by-side comparison with LAMMPS
 * (workflows/bench/lammps_silo.sh) and for the speed figure of the thesis
 * (16 000 grains for 1.005 s in 18 h, §3.6).
 *
 *   gf-bench-silo [--orifice D_over_d] [--fill H_over_d] [--width L_over_d]
 *                 [--transient T_nd] [--window T_nd] [--lammps-data PATH]
 *
 * The thesis' contact set (§3.3: e_n = 0.885, mu = mu_wall = 0.5,
 * k_t = 2 k_n / 7) at Silbert et al. (2001)'s stiffness, t_n = 4.97e-3
 * sqrt(d/g), dt = t_n / 50, d = 0.5 mm, 2500 kg m-3; box width x width x 50 d
 * (default 25 d), fill H (default 25.4 d), reinjection at 45 d, square
 * orifice D x D. --lammps-data writes the t = 0 state (gf_lammps_data.h)
 * and PATH.params with the silo's geometry (box LXB, LZB, HB, orifice
 * OX0..OX1, OZ0..OZ1, the exit level EXIT_Y = -d). The run then discharges
 * for transient + window (sqrt(d/g)) and prints the grains that left during
 * the window over its length (Q, grains/s and sqrt(g/d)), the CPU time of the
 * stepping (scene upkeep included, preparation not) and the microseconds per
 * grain-step.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_bench_args.h"
#include "gf_bench_clock.h"
#include "gf_lammps_data.h"
#include "gf_sim.h"
#include "scenes/gf_scene.h"
#include "scenes/gf_silo_thesis.h"

typedef struct silo_args {
    double orifice, fill, width, transient, window;
    const char *lammps;
} silo_args;

static const silo_args defaults = {.orifice = 6.0, .fill = 25.4, .width = 25.0, .transient = 5.0, .window = 20.0};

static const gf_bench_flag flags[] = {
    GF_BENCH_FLAG("--orifice", REAL, silo_args, orifice), GF_BENCH_FLAG("--fill", REAL, silo_args, fill),
    GF_BENCH_FLAG("--width", REAL, silo_args, width),     GF_BENCH_FLAG("--transient", REAL, silo_args, transient),
    GF_BENCH_FLAG("--window", REAL, silo_args, window),   GF_BENCH_FLAG("--lammps-data", PATH, silo_args, lammps),
};

GF_BENCH_VALID(silo_args, a->orifice >= 2.0 && a->fill > 0.0 && a->width > a->orifice && a->transient >= 0.0 &&
               a->window > 0.0)

static gf_status make_spec(gf_ctx *ctx, const void *args, gf_run_spec *s)
{
    const silo_args *a = args;
    gf_silo_thesis_spec(s);
    GF_TRY(gf_run_spec_set_param(ctx, s, "width_x_over_d", a->width));
    GF_TRY(gf_run_spec_set_param(ctx, s, "width_z_over_d", a->width));
    GF_TRY(gf_run_spec_set_param(ctx, s, "orifice_x_over_d", a->orifice));
    GF_TRY(gf_run_spec_set_param(ctx, s, "orifice_z_over_d", a->orifice));
    GF_TRY(gf_run_spec_set_param(ctx, s, "fill_height_over_d", a->fill));
    return gf_run_spec_set_param(ctx, s, "settle_time_nd", 10.0);
}

/* The silo's geometry for the LAMMPS input (gf_bench_params_fn). */
static void append_geometry(FILE *f, gf_sim *sim, const double lo[3], const double hi[3], const void *args)
{
    const silo_args *a = args;
    const double d = gf_sim_spec(sim)->grains.diameter_m, L = a->width * d, o = a->orifice * d;
    (void)lo;
    fprintf(f, "LXB=%.17g\nLZB=%.17g\nHB=%.17g\nOX0=%.17g\nOX1=%.17g\nOZ0=%.17g\nOZ1=%.17g\nEXIT_Y=%.17g\n", L, L,
            hi[1], 0.5 * (L - o), 0.5 * (L + o), 0.5 * (L - o), 0.5 * (L + o), -d);
}

/* Discharges for t_nd sqrt(d/g) with the scene's upkeep; adds the CPU time. */
static gf_status discharge(gf_sim *sim, const gf_scene_desc *desc, double t_nd, double *cpu_s)
{
    const gf_run_spec *s = gf_sim_spec(sim);
    long n = (long)ceil(t_nd * sqrt(s->grains.diameter_m / s->gravity_m_s2) / gf_sim_dt_s(sim) /
                        GF_SCENE_MAINTAIN_EVERY);
    double c0 = gf_bench_cpu_time_s();
    for (long k = 0; k < n; ++k) {
        GF_TRY(gf_sim_advance(sim, GF_SCENE_MAINTAIN_EVERY));
        GF_TRY(desc->maintain(sim));
    }
    *cpu_s += gf_bench_cpu_time_s() - c0;
    return GF_OK;
}

/* The export, the transient, then the window's count; one line. */
static int run(gf_ctx *ctx, gf_sim *sim, const void *args)
{
    const silo_args *a = args;
    if (a->lammps && !gf_bench_export_lammps(sim, a->lammps, append_geometry, a, gf_bench_main_program.name))
        return 1;
    const gf_scene_desc *desc = gf_scene_find("silo");
    double cpu = 0.0, v[8], out0, t0;
    long s0 = gf_sim_step_count(sim);
    gf_status st = discharge(sim, desc, a->transient, &cpu);
    if (st == GF_OK)
        st = desc->diagnose(sim, v);
    out0 = v[0], t0 = gf_sim_time_s(sim);
    if (st == GF_OK)
        st = discharge(sim, desc, a->window, &cpu);
    if (st == GF_OK)
        st = desc->diagnose(sim, v);
    if (st != GF_OK) {
        fprintf(stderr, "%s: %s\n", gf_bench_main_program.name, ctx->last_msg);
        return 1;
    }
    const gf_run_spec *spec = gf_sim_spec(sim);
    const double tg = sqrt(spec->grains.diameter_m / spec->gravity_m_s2), T = gf_sim_time_s(sim) - t0;
    const size_t n = gf_sim_particles(sim)->n_local;
    const long steps = gf_sim_step_count(sim) - s0;
    printf("silo D = %.3g d, %zu grains: %.0f grains left in %.3f sqrt(d/g), Q = %.6g grains/s = %.5g sqrt(g/d); "
           "%ld steps in %.2f s CPU = %.4f us per grain-step\n",
           a->orifice, n, v[0] - out0, T / tg, (v[0] - out0) / T, (v[0] - out0) / T * tg, steps, cpu,
           1e6 * cpu / ((double)n * (double)steps));
    return 0;
}

const gf_bench_program gf_bench_main_program = {
    "gf-bench-silo",
    "[--orifice D_over_d] [--fill H_over_d] [--width L_over_d] [--transient T_nd] [--window T_nd] [--lammps-data PATH]",
    sizeof(silo_args), &defaults, flags, sizeof flags / sizeof *flags, valid, make_spec, run};
