/*
 * A minimal grain integrator for the coupling tests: the sub-cycled loop of
 * gf_sim (Izard 2014 §2.3.1) without contacts — per fluid step, M substeps of
 * symplectic Euler with gravity + held fluid force. Grains flagged
 * GF_P_GLUED, or with fixed = 1, keep their velocity.
 */
#ifndef FLUID_TEST_UTIL_H
#define FLUID_TEST_UTIL_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/gf_rng.h"
#include "coupling/gf_coupling.h"
#include "coupling/gf_coupling_diag.h"
#include "gf_run_spec.h"
#include "particles/gf_particles.h"
#include "gf_test.h"
#include "gf_test_drag.h"

typedef struct coupled_loop {
    gf_coupling *c;
    gf_particles *p;
    double g[3], lo[3], hi[3];
    int periodic[3];
    double dt_f_max;   /* requested fluid step (reduced to gf_coupling_dt_max_s) */
    int substeps;      /* DEM substeps per fluid step */
    int fixed;         /* grains keep their velocity (prescribed motion) */
    double t;
} coupled_loop;

static inline void spec_fluid(gf_run_spec *s, double D, double rho_p, double rho_f, double mu, const char *drag,
                              double cell_over_D)
{
    gf_run_spec_defaults(s);
    s->grains.diameter_m = D;
    s->grains.density_kg_m3 = rho_p;
    s->grains.polydispersity = 0.0;
    snprintf(s->fluid.model, sizeof s->fluid.model, "unresolved");
    snprintf(s->fluid.drag, sizeof s->fluid.drag, "%s", drag);
    s->fluid.density_kg_m3 = rho_f;
    s->fluid.viscosity_Pa_s = mu;
    s->fluid.cell_over_D = cell_over_D;
    s->fluid.cfl = 0.3;
}

/* L->c: the coupling of spec over the fully periodic cube [0, Lb]^3, the
 * fluid's body force L->g; L->p: an empty store for 4096 grains (checked). */
static inline void periodic_cube(gf_ctx *ctx, const gf_run_spec *spec, double Lb, coupled_loop *L)
{
    gf_coupling_setup su = {.gravity_m_s2 = {L->g[0], L->g[1], L->g[2]}};
    for (int d = 0; d < 3; ++d) {
        su.hi_m[d] = L->hi[d] = Lb;
        su.bc[d][0] = su.bc[d][1] = GF_BC_PERIODIC;
        L->periodic[d] = 1;
    }
    GF_CHECK_OK(gf_coupling_create(ctx, spec, &su, &L->c), ctx);
    GF_CHECK_OK(gf_particles_create(ctx, 4096, &L->p), ctx);
}

static inline gf_status loop_step(coupled_loop *L)
{
    double dt = fmin(L->dt_f_max, gf_coupling_dt_max_s(L->c, L->p));
    GF_TRY(gf_coupling_fluid_step(L->c, L->p, dt));
    double dts = dt / L->substeps;
    gf_coupling_set_dem_step(L->c, dts);
    gf_particles *p = L->p;
    for (int s = 0; s < L->substeps; ++s) {
        gf_particles_clear_forces(p);
        GF_TRY(gf_coupling_add_forces(L->c, p));
        for (size_t i = 0; i < p->n_local; ++i) {
            if ((p->flags[i] & GF_P_GLUED) || L->fixed)
                continue;
            double m = p->mass_kg[i];
            p->vx_m_s[i] += dts * (p->fx_N[i] / m + L->g[0]);
            p->vy_m_s[i] += dts * (p->fy_N[i] / m + L->g[1]);
            p->vz_m_s[i] += dts * (p->fz_N[i] / m + L->g[2]);
        }
        for (size_t i = 0; i < p->n_local; ++i) {
            double *x[3] = {&p->x_m[i], &p->y_m[i], &p->z_m[i]};
            double v[3] = {p->vx_m_s[i], p->vy_m_s[i], p->vz_m_s[i]};
            for (int d = 0; d < 3; ++d) {
                *x[d] += dts * v[d];
                double Lb = L->hi[d] - L->lo[d];
                if (L->periodic[d]) {
                    while (*x[d] < L->lo[d])
                        *x[d] += Lb;
                    while (*x[d] >= L->hi[d])
                        *x[d] -= Lb;
                }
            }
        }
    }
    L->t += dt;
    return GF_OK;
}

/* Mean grain velocity (mobile grains). */
static inline void grain_mean_velocity(const gf_particles *p, double v[3])
{
    size_t n = 0;
    v[0] = v[1] = v[2] = 0.0;
    for (size_t i = 0; i < p->n_local; ++i) {
        if (p->flags[i] & GF_P_GLUED)
            continue;
        v[0] += p->vx_m_s[i];
        v[1] += p->vy_m_s[i];
        v[2] += p->vz_m_s[i];
        ++n;
    }
    if (n)
        for (int d = 0; d < 3; ++d)
            v[d] /= (double)n;
}

/* n^3 grains of diameter D and density rho_p (flags: GF_P_GLUED or 0) at the
 * nodes (i + 1/2) a of a simple cubic lattice of spacing a > D, each moved by
 * up to 0.45 (a - D) along each axis (uniform, from seed): the lattice's
 * solid fraction without its order, and no two grains touching. */
static inline void jittered_lattice(gf_ctx *ctx, gf_particles *p, int n, double a, double D, double rho_p,
                                    uint8_t flags, uint64_t seed)
{
    gf_rng rng;
    gf_rng_seed(&rng, seed);
    double jit = 0.45 * (a - D);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                gf_particles_add(ctx, p, (i + 0.5) * a + gf_rng_range(&rng, -jit, jit),
                                 (j + 0.5) * a + gf_rng_range(&rng, -jit, jit),
                                 (k + 0.5) * a + gf_rng_range(&rng, -jit, jit), D / 2, rho_p, flags, NULL);
}

/* Schiller–Naumann terminal velocity (m/s) of a sphere of diameter D. */
static inline double schiller_naumann_terminal(double D, double rho_p, double rho_f, double mu, double g)
{
    double ar = rho_f * (rho_p - rho_f) * g * D * D * D / (mu * mu);
    return gf_test_schiller_naumann_Re(ar) * mu / (rho_f * D);
}

#endif
