/*
 * The settling suspension both fluid tiers run side by side
 * (tests/resolved/resolved_suspension.c; gf-bench-accuracy's
 * hindered_settling_tiers): the `settling` scene's fully periodic cube, y up,
 * grains of D = 10 mm at rho_p/rho = 2 in a fluid of 1000 kg/m3 whose
 * viscosity sets the Archimedes number Ar = (rho_p/rho - 1) g D^3 / nu^2,
 * and the volume flux j that defines the zero-volume-flux frame.
 */
#ifndef GF_TEST_SUSPENSION_H
#define GF_TEST_SUSPENSION_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "coupling/gf_coupling.h"
#include "coupling/gf_coupling_diag.h"
#include "gf_sim.h"
#include "gf_test_drag.h"

#define GF_TEST_SUSP_D_M 0.01
#define GF_TEST_SUSP_RHO 1000.0
#define GF_TEST_SUSP_RATIO 2.0
#define GF_TEST_SUSP_G 9.81

typedef struct gf_test_suspension {
    const char *model, *drag;  /* fluid.model; fluid.drag of the unresolved tier (NULL: its default) */
    int mode, arrangement;     /* the scene's mode (0 one sphere, 1 suspension), arrangement (0 lattice, 1 random) */
    double box, phi, ar;       /* box_over_D, phi_suspension, Archimedes number */
    double d_over_dx, retract; /* resolved tier: D/dx, fluid.ibm_retraction_dx */
    double cell_over_D;        /* unresolved tier: the fluid cell / D (0: a third of the box) */
    const char *ibm_forcing;   /* resolved tier: fluid.ibm_forcing (NULL: its default) */
} gf_test_suspension;

/* Dynamic viscosity (Pa s) at Archimedes number ar. */
static inline double gf_test_suspension_viscosity(double ar)
{
    const double D = GF_TEST_SUSP_D_M, rho = GF_TEST_SUSP_RHO;
    return sqrt(rho * (GF_TEST_SUSP_RATIO - 1.0) * rho * GF_TEST_SUSP_G * D * D * D / ar);
}

static inline gf_status gf_test_suspension_spec(gf_ctx *ctx, const gf_test_suspension *s, double t_end_nd,
                                                gf_run_spec *spec)
{
    const double D = GF_TEST_SUSP_D_M;
    gf_run_spec_defaults(spec);
    snprintf(spec->scene, sizeof spec->scene, "settling");
    spec->grains = (gf_grains_spec){.diameter_m = D, .polydispersity = 0.0,
                                    .density_kg_m3 = GF_TEST_SUSP_RATIO * GF_TEST_SUSP_RHO};
    snprintf(spec->fluid.model, sizeof spec->fluid.model, "%s", s->model);
    if (s->drag)
        snprintf(spec->fluid.drag, sizeof spec->fluid.drag, "%s", s->drag);
    spec->fluid.density_kg_m3 = GF_TEST_SUSP_RHO;
    spec->fluid.viscosity_Pa_s = gf_test_suspension_viscosity(s->ar);
    spec->fluid.d_over_dx = s->d_over_dx;
    spec->fluid.ibm_retraction_dx = s->retract;
    if (s->ibm_forcing)
        snprintf(spec->fluid.ibm_forcing, sizeof spec->fluid.ibm_forcing, "%s", s->ibm_forcing);
    spec->fluid.cfl = 0.3;
    spec->contact.t_contact_nd = 0.05;
    spec->end_time_nd = t_end_nd;
    GF_TRY(gf_run_spec_set_param(ctx, spec, "mode", s->mode));
    GF_TRY(gf_run_spec_set_param(ctx, spec, "box_over_D", s->box));
    GF_TRY(gf_run_spec_set_param(ctx, spec, "phi_suspension", s->phi));
    GF_TRY(gf_run_spec_set_param(ctx, spec, "arrangement", s->arrangement));
    if (strcmp(s->model, "unresolved") == 0) { /* the lattice rounds the box to whole lattice cells, L = n a */
        double a = D * cbrt(M_PI / (6.0 * s->phi));
        double L = s->mode && !s->arrangement ? lround(s->box * D / a) * a : s->box * D;
        spec->fluid.cell_over_D = s->cell_over_D > 0.0 ? s->cell_over_D : L / D / 3.0;
    }
    return GF_OK;
}

/* The box's solid fraction and sum_i (m_i - rho V_i), the grains' excess mass. */
static inline double gf_test_suspension_phi(gf_sim *sim, double *excess_kg)
{
    const gf_particles *p = gf_sim_particles(sim);
    double lo[3], hi[3], vs = 0.0;
    int per[3];
    gf_sim_box(sim, lo, hi, per);
    *excess_kg = 0.0;
    for (size_t i = 0; i < p->n_local; ++i) {
        double R = p->radius_m[i], V = 4.0 / 3.0 * M_PI * R * R * R;
        vs += V;
        *excess_kg += p->mass_kg[i] - GF_TEST_SUSP_RHO * V;
    }
    return vs / ((hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]));
}

/* The mean vertical grain velocity vp and the volume flux j (m/s, y up): the box mean of the resolved tier's
 * velocity, inside the grains too; the fast tier's phi vp + (1 - phi) <u_f>. */
static inline void gf_test_suspension_flux(gf_sim *sim, double phi, double *vp, double *j)
{
    const gf_coupling *c = gf_sim_coupling(sim);
    const gf_particles *p = gf_sim_particles(sim);
    *vp = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        *vp += p->vy_m_s[i] / (double)p->n_local;
    if (strcmp(gf_coupling_model(c), "resolved") != 0) {
        double uf[3];
        gf_coupling_mean_fluid_velocity(c, uf);
        *j = phi * *vp + (1.0 - phi) * uf[1];
        return;
    }
    const gf_var_info *vars;
    const double *const *f;
    int n[3];
    double lo[3], h[3], s = 0.0;
    int nv = gf_coupling_fields(c, n, lo, h, &vars, &f);
    size_t nc = (size_t)n[0] * n[1] * n[2];
    for (int v = 0; v < nv; ++v)
        if (strcmp(vars[v].name, "v_fluid") == 0)
            for (size_t q = 0; q < nc; ++q)
                s += f[v][q];
    *j = s / (double)nc;
}

/* Schiller-Naumann terminal velocity (m/s) and Reynolds number re_t of the isolated grain at Archimedes number ar,
 * and Richardson & Zaki's (1954) exponent at that Re_T: 4.65 (< 0.2), 4.4 Re^-0.03 (< 1), 4.4 Re^-0.1 (< 500). */
static inline double gf_test_suspension_terminal(double ar, double *re_t, double *n_rz)
{
    double re = gf_test_schiller_naumann_Re(ar);
    *re_t = re;
    *n_rz = re < 0.2 ? 4.65 : re < 1.0 ? 4.4 * pow(re, -0.03) : re < 500.0 ? 4.4 * pow(re, -0.1) : 2.39;
    return re * gf_test_suspension_viscosity(ar) / (GF_TEST_SUSP_RHO * GF_TEST_SUSP_D_M);
}

#endif
