/*
 * The unresolved coupling's state, shared by the files of that tier only
 * (gf_coupling_unresolved.c: set-up, fluid step, forces;
 * gf_coupling_checkpoint.c: save and restore). Not a public header: the step
 * loop uses gf_coupling.h.
 */
#ifndef GF_COUPLING_UNRESOLVED_H
#define GF_COUPLING_UNRESOLVED_H

#include "coupling/gf_average.h"
#include "coupling/gf_coupling.h"
#include "coupling/gf_coupling_diag.h"
#include "coupling/gf_coupling_tier.h"
#include "coupling/gf_drag.h"
#include "fluid/gf_fluid.h"

#define OSEEN_N 96
#define MEAN_SLIP_F64 4

enum { FLD_EPS, FLD_U, FLD_V, FLD_W, FLD_P, FLD_N };

/* What one fluid step leaves for the DEM substeps that follow, per grain. */
typedef struct held_grain {
    int64_t id;
    double K_kg_s, uf[3], f_other_N[3], eps, mass_kg;
    /* phi1(x) = (1 - exp(-x))/x of the substeps' drag relaxation, for the
     * x = K dt/m it was evaluated at (NaN: not yet): x is the same in every
     * substep between two fluid steps, so expm1 runs once per fluid step */
    double phi1, phi1_x;
} held_grain;

struct gf_unresolved {
    gf_coupling base;             /* first member: the tier row (gf_coupling_tier.h) */
    gf_ctx *ctx;
    gf_run_spec spec;
    gf_coupling_setup setup;
    gf_fluid *fluid;
    const gf_drag_info *law;
    double *mean_v;               /* mean-slip closures: <v>[3] and 1 - K'/K per grain (gf_coupling_mean_slip.c) */
    size_t mean_cap;
    double sigma_m, self_mobility, dt_dem_s;
    double sigma_eff_m;           /* Gaussian width whose continuum Stokes self-mobility is self_mobility */
    double oseen[OSEEN_N];        /* Oseen reduction of the self-mobility on a log grid of Re_sigma */
    double rho_f, mu;
    int user_gradp;
    double mean_gradp[3];
    int ref_axis, ref_side;       /* pressure reference: mean p' = 0 over this face's cell layer (-1: domain mean) */
    int first_step;
    int n_threads;                /* for the per-grain loops of the fluid step (gf_coupling_set_threads) */
    gf_kernel *kern;
    held_grain *held;
    size_t cap, n_held;
    uint64_t held_epoch;          /* the store's order_epoch that held[] follows (gf_coupling_forces_in_order) */
    int held_epoch_known;
    double *uc[3], *gp[3];        /* cell-centred velocity and excess-pressure gradient */
    double *fields[FLD_N];
    double *lanes;                /* cell fields interleaved for the per-grain transfers (gf_average.h) */
    gf_coupling_stats stats;
};

typedef struct gf_unresolved gf_unresolved;

/* The tier's checkpoint (gf_coupling_checkpoint.c): gf_coupling_save and gf_coupling_load for this tier. */
gf_status gf_unresolved_save(const gf_coupling *c, gf_restart *r);
gf_status gf_unresolved_load(gf_coupling *c, gf_restart *r);

/* Mean-slip closures (gf_coupling_mean_slip.c; no-ops or NULL for per-grain closures). */
/* <v> at every grain from the grains' current velocities and the cached kernels; uses c->lanes. */
gf_status gf_mean_slip_prepare(gf_unresolved *c, const gf_particles *p);
/* <v> at grain i, or NULL for a per-grain closure. */
const double *gf_mean_slip_velocity(const gf_unresolved *c, size_t i);
/* The coefficient to hold for grain i over a fluid step of dt_s (K_mean itself); remembers r. */
double gf_mean_slip_hold(gf_unresolved *c, const gf_particles *p, size_t i, double K_mean, double eps_closure,
                         double dt_s);
/* u* = u_f + r (v - <v>): the velocity the held K relaxes grain i towards. */
void gf_mean_slip_target(const gf_unresolved *c, const gf_particles *p, size_t i, const double uf[3], double target[3]);
/* What grain i spreads to the fluid's beta and beta v: K, K ((1 - r) v + r <v>) (K, K v for a per-grain closure). */
void gf_mean_slip_exchange(const gf_unresolved *c, const gf_particles *p, size_t i, double K_held,
                           double value[GF_AVERAGE_LANES]);

/* Per-grain arrays (kernels, held values) for n grains, kept on shrink. */
gf_status gf_unresolved_reserve(gf_unresolved *c, size_t n);

#endif
