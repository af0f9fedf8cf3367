/*
 * Extra calls of the unresolved coupling for tests, benchmarks and the
 * validation generator (not part of the step-loop contract gf_coupling.h).
 */
#ifndef GF_COUPLING_DIAG_H
#define GF_COUPLING_DIAG_H

#include "coupling/gf_coupling.h"

typedef struct gf_coupling_stats {
    int n_cells[3];
    double cell_m[3], kernel_sigma_m;
    double self_mobility_s_kg;      /* G0: self-induced velocity per unit force of a kernel-spread grain */
    long n_steps;
    double fluid_s;                 /* wall time in gf_coupling_fluid_step */
    double poisson_s;               /* of which pressure solves */
    long poisson_iterations;        /* summed */
    double last_mass_residual;      /* max |dt div(eps u) + eps^{n+1} - eps^n| of the last step */
    double solid_volume_grid_m3;    /* sum_cells (1 - eps) V_cell, before clipping */
    double solid_volume_grains_m3;  /* sum_i V_i of the grains inside */
    long eps_clipped_cells;         /* cells where eps was raised to the floor in the last step */
    double mean_gradp_Pa_m[3];      /* applied mean pressure gradient -<grad p'> (periodic weight balance) */
} gf_coupling_stats;

void gf_coupling_get_stats(const gf_coupling *c, gf_coupling_stats *s);

/* Imposes a mean pressure gradient G = -<grad p> (Pa/m) on fluid and grains
 * (a pressure-driven flow through a periodic bed), replacing the automatic
 * weight balance. */
void gf_coupling_set_mean_pressure_gradient(gf_coupling *c, const double G_Pa_m[3]);

/* DEM substep length used by the exponential drag factor of gf_coupling_add_forces
 * (default gf_run_spec_dt_s(spec)); for drivers whose substep differs. */
void gf_coupling_set_dem_step(gf_coupling *c, double dt_s);

/* Held quantities of grain i after the last fluid step: drag coefficient K (kg/s, self-correction included),
 * fluid velocity at the grain (m/s), local fluid fraction. Returns 0 if i is out of range. */
int gf_coupling_grain_state(const gf_coupling *c, size_t i, double *K_kg_s, double uf_m_s[3], double *eps);

/* Mean fluid velocity sum eps u V / sum eps V (m/s) and fluid-volume fraction of the box. */
void gf_coupling_mean_fluid_velocity(const gf_coupling *c, double u_m_s[3]);

#endif
