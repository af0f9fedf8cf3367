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

/* The same with a sort period (gf_sim_options.sort_every) and an optional
 * checkpoint to continue from (NULL: fresh start). */
static inline gf_status gf_test_sim_sorted(gf_ctx *ctx, const gf_run_spec *spec, int threads, int sort_every,
                                           const char *restart_path, gf_sim **out)
{
    gf_sim_options opt;
    memset(&opt, 0, sizeof opt);
    opt.n_threads = threads, opt.sort_every = sort_every, opt.restart_path = restart_path;
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
