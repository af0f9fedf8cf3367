/*
 * gf-bench-collapse: one dry column collapse (scene column_collapse) run to
 * rest, for the side-by-side comparison with LAMMPS
 * (workflows/bench/lammps_collapse.sh).
 *
 *   gf-bench-collapse [--seed S] [--aspect A] [--length R0_over_D] [--width W_over_D]
 *                     [--end-time T_nd] [--lammps-data PATH] [--dump PATH]
 *
 * The run spec's own material and contact parameters (Izard 2014 §5.2 glass
 * beads: D = 7.6 mm, 5 % polydisperse, eps 0.87, mu 0.25 on grains and
 * walls, t_c = 1e-2 sqrt(D/g), dt = t_c/50, skin 0.1 D) and the scene's
 * preparation: packing, 5 sqrt(D/g) of re-equilibration behind the gate,
 * clock reset, gate removed (gf_sim_create runs all of it).
 *
 * --lammps-data writes that t = 0 state (mobile grains type 1, glued base
 * grains type 2; gf_lammps_data.h) and PATH.params, to which the collapse
 * geometry is appended: R0, H0, the walls x = 0 and x = L, floor y = 0, top
 * y = TOP, the slab width W. The run then goes on until the scene's rest
 * test (done(), checked every 0.25 sqrt(D/g), as gf-bench-accuracy does) or
 * the end time (default: the scene's, 10 T0 + 40 sqrt(D/g)), and prints the
 * step count, the CPU time of the stepping calls alone (the preparation is
 * not the comparison's business), and the scene's own front_position and
 * deposit_height. --dump writes the final grains, one "x y z radius type"
 * line each (the columns of the LAMMPS dump of lammps_collapse.sh), so that
 * the script measures both codes' deposits with one definition.
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

typedef struct collapse_args {
    long seed;
    double aspect, length_D, width_D, end_nd;
    const char *lammps, *dump;
} collapse_args;

static const collapse_args defaults = {.seed = 1, .aspect = 1.0, .length_D = 16.0, .width_D = 3.0};

static const gf_bench_flag flags[] = {
    GF_BENCH_FLAG("--seed", LONG, collapse_args, seed),       GF_BENCH_FLAG("--aspect", REAL, collapse_args, aspect),
    GF_BENCH_FLAG("--length", REAL, collapse_args, length_D), GF_BENCH_FLAG("--width", REAL, collapse_args, width_D),
    GF_BENCH_FLAG("--end-time", REAL, collapse_args, end_nd), GF_BENCH_FLAG("--dump", PATH, collapse_args, dump),
    GF_BENCH_FLAG("--lammps-data", PATH, collapse_args, lammps),
};

GF_BENCH_VALID(collapse_args, a->seed > 0 && a->aspect > 0.0 && a->length_D > 0.0 && a->width_D > 0.0)

static gf_status make_spec(gf_ctx *ctx, const void *args, gf_run_spec *s)
{
    const collapse_args *a = args;
    gf_run_spec_defaults(s); /* column_collapse with Izard's grains and contacts */
    s->seed = (uint64_t)a->seed;
    s->end_time_nd = a->end_nd; /* 0: the scene's end time */
    GF_TRY(gf_run_spec_set_param(ctx, s, "aspect_ratio", a->aspect));
    GF_TRY(gf_run_spec_set_param(ctx, s, "column_length_over_D", a->length_D));
    return gf_run_spec_set_param(ctx, s, "width_over_D", a->width_D);
}

/* The geometry the LAMMPS input needs besides the law (column_collapse's
 * walls; gf_bench_params_fn). */
static void append_geometry(FILE *f, gf_sim *sim, const double lo[3], const double hi[3], const void *args)
{
    const collapse_args *a = args;
    const gf_run_spec *s = gf_sim_spec(sim);
    double D = s->grains.diameter_m;
    fprintf(f, "R0=%.17g\nH0=%.17g\nL=%.17g\nTOP=%.17g\nW=%.17g\nRHO=%.17g\n", a->length_D * D,
            a->aspect * a->length_D * D, hi[0], hi[1], hi[2] - lo[2], s->grains.density_kg_m3);
}

/* Steps to rest or to the end time; *cpu_s: CPU time of gf_sim_advance alone. */
static gf_status run_to_rest(gf_sim *sim, const gf_scene_desc *d, double *cpu_s)
{
    const gf_run_spec *s = gf_sim_spec(sim);
    long chunk = (long)ceil(0.25 * sqrt(s->grains.diameter_m / s->gravity_m_s2) / gf_sim_dt_s(sim));
    *cpu_s = 0.0;
    while (gf_sim_time_s(sim) < gf_sim_end_time_s(sim) && !d->done(sim)) {
        double c0 = gf_bench_cpu_time_s();
        GF_TRY(gf_sim_advance(sim, chunk));
        *cpu_s += gf_bench_cpu_time_s() - c0;
    }
    return GF_OK;
}

static int report(gf_sim *sim, const gf_scene_desc *d, const collapse_args *a, double cpu_s)
{
    double v[16];
    if (d->n_diag > 16 || d->diagnose(sim, v) != GF_OK)
        return 0;
    const gf_particles *p = gf_sim_particles(sim);
    size_t n_glued = 0;
    double m_mobile = 0.0; /* the rest test's unit: mean mobile mass x g D */
    for (size_t i = 0; i < p->n_local; ++i) {
        int glued = (p->flags[i] & GF_P_GLUED) != 0;
        n_glued += glued;
        m_mobile += glued ? 0.0 : p->mass_kg[i];
    }
    const double D = gf_sim_spec(sim)->grains.diameter_m, R0 = a->length_D * D, g = gf_sim_spec(sim)->gravity_m_s2;
    long steps = gf_sim_step_count(sim);
    printf("seed %ld: %zu grains (%zu glued), %ld steps to t = %.4f sqrt(D/g), %.3f s CPU, "
           "%.4e particle-steps per CPU-second; front %.4f R0, height %.4f R0, KE %.3e m g D per grain\n",
           a->seed, p->n_local, n_glued, steps, gf_sim_time_s(sim) / sqrt(D / g), cpu_s,
           (double)p->n_local * steps / cpu_s, v[0] / R0, v[1] / R0,
           gf_particles_kinetic_energy(p) / (m_mobile * g * D));
    return 1;
}

/* The export, the collapse to rest, its report and the dump. */
static int run(gf_ctx *ctx, gf_sim *sim, const void *args)
{
    const collapse_args *a = args;
    const char *program = gf_bench_main_program.name;
    const gf_scene_desc *d = gf_scene_find("column_collapse");
    int ok = !a->lammps || gf_bench_export_lammps(sim, a->lammps, append_geometry, a, program);
    double cpu = 0.0;
    if (ok && run_to_rest(sim, d, &cpu) != GF_OK)
        fprintf(stderr, "%s: %s\n", program, ctx->last_msg), ok = 0;
    if (ok && !report(sim, d, a, cpu))
        fprintf(stderr, "%s: diagnostics failed: %s\n", program, ctx->last_msg), ok = 0;
    if (ok && a->dump && !gf_bench_write_dump(sim, a->dump, 1))
        fprintf(stderr, "%s: cannot write %s\n", program, a->dump), ok = 0;
    return ok ? 0 : 1;
}

const gf_bench_program gf_bench_main_program = {
    "gf-bench-collapse",
    "[--seed S] [--aspect A] [--length R0_over_D] [--width W_over_D] [--end-time T_nd] [--lammps-data PATH] "
    "[--dump PATH]",
    sizeof(collapse_args), &defaults, flags, sizeof flags / sizeof *flags, valid, make_spec, run};
