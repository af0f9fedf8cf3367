/*
 * Sims for tests: a run spec of a scene with the seeds' defaults and small
 * acetate-like grains (D = 3 mm, rho_p = 1319 kg m-3, monodisperse: the
 * Foerster et al. 1994 collision material), a sim that writes no file, and
 * the bitwise comparison of two stores.
 */
#ifndef GF_TEST_SIM_H
#define GF_TEST_SIM_H

#include <stdio.h>
#include <string.h>

#include "gf_sim.h"

static inline gf_run_spec gf_test_spec(const char *scene)
{
    gf_run_spec s;
    gf_run_spec_defaults(&s);
    snprintf(s.scene, sizeof s.scene, "%s", scene);
    s.grains.diameter_m = 3e-3;
    s.grains.density_kg_m3 = 1319.0;
    s.grains.polydispersity = 0.0;
    return s;
}

/* A scene parameter and its value (gf_run_spec_set_param). */
typedef struct gf_test_param {
    const char *key;
    double value;
} gf_test_param;

/* Sets the n scene parameters on s in order, stopping at the first refused
 * (its status, the message in ctx); GF_OK when all were accepted. */
static inline gf_status gf_test_set_params(gf_ctx *ctx, gf_run_spec *s, const gf_test_param *params, size_t n)
{
    for (size_t k = 0; k < n; ++k)
        GF_TRY(gf_run_spec_set_param(ctx, s, params[k].key, params[k].value));
    return GF_OK;
}

/* A frictional (mu_c 0.5), 10 % polydisperse settled_bed of n grains with
 * settle_time_nd = settle_nd: the restart and pair-loop tests' bed. */
static inline gf_run_spec gf_test_bed_spec(gf_ctx *ctx, int n, double settle_nd)
{
    gf_run_spec bed = gf_test_spec("settled_bed");
    bed.grains.polydispersity = 0.1;
    bed.contact.friction = 0.5;
    gf_run_spec_set_param(ctx, &bed, "n_grains", n);
    gf_run_spec_set_param(ctx, &bed, "settle_time_nd", settle_nd);
    return bed;
}

/* An elastic (eps = 1), frictionless gas of n grains at 2 sqrt(gD) in a
 * periodic cube of side box_over_D D, dt = dt_over_tc t_c: the
 * energy-conservation tests' gas. */
static inline gf_run_spec gf_test_elastic_gas_spec(gf_ctx *ctx, int n, double box_over_D, double dt_over_tc)
{
    gf_run_spec gas = gf_test_spec("elastic_gas");
    gas.contact.restitution = 1.0;
    gas.contact.friction = 0.0;
    gas.contact.dt_over_tc = dt_over_tc;
    gf_run_spec_set_param(ctx, &gas, "n_grains", n);
    gf_run_spec_set_param(ctx, &gas, "box_over_D", box_over_D);
    gf_run_spec_set_param(ctx, &gas, "speed_nd", 2.0);
    return gas;
}

/* The viscous collapse of the immersed restart and continuation tests into
 * *s: a dense column (phi 0.6, a = 0.5, R0 = 12 D) of D = 7.6 mm,
 * 2500 kg m-3 grains in a fluid of 1000 kg m-3 and 0.1 Pa s (St ~ 0.3, the
 * viscous regime of Izard 2014 ch. 5), on the fluid tier `model` ("none":
 * dry). The status of setting R0. */
static inline gf_status gf_test_viscous_collapse_spec(gf_ctx *ctx, const char *model, gf_run_spec *s)
{
    gf_run_spec_defaults(s);
    snprintf(s->scene, sizeof s->scene, "column_collapse");
    s->grains.density_kg_m3 = 2500.0;
    s->grains.diameter_m = 7.6e-3;
    snprintf(s->fluid.model, sizeof s->fluid.model, "%s", model);
    s->fluid.density_kg_m3 = 1000.0;
    s->fluid.viscosity_Pa_s = 0.1;
    s->phi_initial = 0.6;
    s->aspect_ratio_a = 0.5;
    return gf_run_spec_set_param(ctx, s, "column_length_over_D", 12.0);
}

/* The small frictional column collapse of the pair-loop tests: a = 1,
 * R0 = 8 D, mu_c 0.5, on the scene's rough base of glued grains. */
static inline gf_run_spec gf_test_small_collapse_spec(gf_ctx *ctx)
{
    gf_run_spec col = gf_test_spec("column_collapse");
    col.aspect_ratio_a = 1.0;
    col.contact.friction = 0.5;
    gf_run_spec_set_param(ctx, &col, "column_length_over_D", 8.0);
    return col;
}

/* The fluid of the immersed collapse (configs/column_collapse_immersed.yaml)
 * on spec s: the unresolved tier, rho_f = rho_p / 8, eta_f 0.05 Pa s, Brenner
 * lubrication closer than R/2 with roughness 2e-4 R. */
static inline void gf_test_immerse(gf_run_spec *s)
{
    snprintf(s->fluid.model, sizeof s->fluid.model, "unresolved");
    s->fluid.density_kg_m3 = 0.125 * s->grains.density_kg_m3, s->fluid.viscosity_Pa_s = 0.05;
    s->fluid.lubrication = 1;
    s->fluid.roughness_over_R = 2e-4, s->fluid.lub_cutoff_over_R = 0.5;
}

/* The scenes on which two variants of the pair loop must give the same bits
 * (compare runs both from the same start and checks): a frictional bed
 * settling from a stack (contacts made and broken, Coulomb slip) on 1 and 2
 * threads, 2000 steps (1200 grains: above the serial threshold, threads
 * really run); the small collapse on its glued base (the scan's flagged
 * path), 3000 steps; the same collapse immersed with Brenner lubrication
 * (candidates in range that do not touch), 1 and 2 threads. */
typedef void (*gf_test_compare_fn)(gf_ctx *ctx, const char *what, const gf_run_spec *spec, int threads, long steps);
static inline void gf_test_pair_loop_scenes(gf_ctx *ctx, gf_test_compare_fn compare)
{
    gf_run_spec bed = gf_test_bed_spec(ctx, 1200, 0.0);
    compare(ctx, "settling bed", &bed, 1, 2000);
    compare(ctx, "settling bed", &bed, 2, 2000);
    gf_run_spec col = gf_test_small_collapse_spec(ctx);
    compare(ctx, "column collapse", &col, 1, 3000);
    gf_run_spec wet = col;
    gf_test_immerse(&wet);
    compare(ctx, "immersed column collapse", &wet, 1, 3000);
    compare(ctx, "immersed column collapse", &wet, 2, 3000);
}

/* Sim with no output directory and `threads` OpenMP threads (0: default). */
static inline gf_status gf_test_sim(gf_ctx *ctx, const gf_run_spec *spec, int threads, gf_sim **out)
{
    gf_sim_options opt;
    memset(&opt, 0, sizeof opt);
    opt.n_threads = threads;
    return gf_sim_create(ctx, spec, &opt, out);
}

/* The same, continued from the HDF5 checkpoint at restart_path. */
static inline gf_status gf_test_sim_restart(gf_ctx *ctx, const gf_run_spec *spec, int threads, const char *restart_path,
                                            gf_sim **out)
{
    gf_sim_options opt;
    memset(&opt, 0, sizeof opt);
    opt.n_threads = threads;
    opt.restart_path = restart_path;
    return gf_sim_create(ctx, spec, &opt, out);
}

/* The same with a sort period (gf_sim_tuning.sort_every) and an optional
 * checkpoint to continue from (NULL: fresh start). */
static inline gf_status gf_test_sim_sorted(gf_ctx *ctx, const gf_run_spec *spec, int threads, int sort_every,
                                           const char *restart_path, gf_sim **out)
{
    gf_sim_options opt;
    memset(&opt, 0, sizeof opt);
    opt.n_threads = threads, opt.tuning.sort_every = sort_every, opt.restart_path = restart_path;
    return gf_sim_create(ctx, spec, &opt, out);
}

/* 1 when two stores hold the same grains, in the same order, with the same
 * bytes in every position, velocity and spin (restart checks). */
static inline int gf_test_same_motion(const gf_particles *a, const gf_particles *b)
{
    const size_t n = a->n_local, z = n * sizeof(double);
    if (b->n_local != n)
        return 0;
    const double *const fa[9] = {a->x_m, a->y_m, a->z_m, a->vx_m_s, a->vy_m_s, a->vz_m_s, a->wx_rad_s, a->wy_rad_s, a->wz_rad_s};
    const double *const fb[9] = {b->x_m, b->y_m, b->z_m, b->vx_m_s, b->vy_m_s, b->vz_m_s, b->wx_rad_s, b->wy_rad_s, b->wz_rad_s};
    for (int k = 0; k < 9; ++k)
        if (memcmp(fa[k], fb[k], z) != 0)
            return 0;
    return memcmp(a->id, b->id, n * sizeof *a->id) == 0;
}

#endif
