/*
 * gf_run_spec: one fully resolved run. The contract between the pipeline
 * (which parses YAML, expands a campaign grid and maps the dimensionless
 * groups to physical values) and the engine (which builds a scene from it).
 *
 * Plain data, SI units, no pointers: printable (`grainflow check`),
 * copyable, hashable (the run id is a hash of its canonical text form).
 * Every field's default lives in gf_run_spec_defaults(); scene-specific
 * parameters (column aspect ratio, incline angle, impact speed, ...) are a
 * key/value list validated against the scene's own parameter table
 * (engine/scenes/gf_scene.h), so a new scene adds no field here.
 */
#ifndef GF_RUN_SPEC_H
#define GF_RUN_SPEC_H

#include <stdint.h>

#include "core/gf_status.h"

#define GF_NAME_LEN 48
#define GF_MAX_SCENE_PARAMS 48

typedef struct gf_param {
    char key[GF_NAME_LEN];
    double value;
} gf_param;

typedef struct gf_grains_spec {
    double diameter_m;        /* mean grain diameter D */
    double polydispersity;    /* radii uniform in [R(1-p), R(1+p)], seeds use 0.05 and 0.10 */
    double density_kg_m3;     /* rho_p */
} gf_grains_spec;

typedef struct gf_contact_spec {
    char law[GF_NAME_LEN];    /* row of the contact table: "linear" (the seeds' spring-dashpot), "hertz" */
    double t_contact_nd;      /* t_c sqrt(g/D): contact duration in grain time units */
    double restitution;       /* eps_max, dry normal restitution */
    double friction;          /* mu_c grain-grain */
    double wall_friction;     /* mu_c grain-wall */
    double kt_over_kn;        /* tangential/normal stiffness, seed 0.2 */
    int allow_attraction;     /* 0: normal force clipped at 0 (Izard §3.1.2.2) */
    double dt_over_tc;        /* DEM step / t_c; 1/50 default (symplectic) */
    double skin_over_D;       /* Verlet skin in units of D */
    double sleep_speed_nd;    /* grains slower than this x sqrt(gD) sleep (gf_sleep.c); 0: off */
    double overlap_target_over_D; /* > 0: t_c from the scene's pressure so that static overlaps stay below
                                     this x D (gf_stiffness_rule.h), replacing t_contact_nd; 0: off */
} gf_contact_spec;

typedef struct gf_fluid_spec {
    char model[GF_NAME_LEN];  /* "none", "unresolved", "resolved", "auto" */
    double density_kg_m3;     /* rho_f; 0 when dry */
    double viscosity_Pa_s;    /* eta_f; 0 when dry */
    char drag[GF_NAME_LEN];   /* "di_felice", "beetstra", "tenneti" */
    double cell_over_D;       /* fluid cell size / D */
    double cfl;               /* advective CFL bound */
    int lubrication;          /* Brenner normal lubrication on/off */
    double roughness_over_R;  /* eta_e / R, seed 1e-4 .. 4e-4 */
    double lub_cutoff_over_R; /* lubrication active for 0 <= gap <= cutoff R, seed 1/2 */
    double d_over_dx;         /* resolved tier: grid cells per grain diameter D/dx (8-20); 0: 16 */
    char lub_overlap[GF_NAME_LEN]; /* lubrication while surfaces overlap (contact/gf_lubrication.h): "clamp" (gap
                                      0: damping 6 pi eta R_eff^2/eta_e), "off" (the contact law alone), "film" (the
                                      elastic film of Izard 2014 eq. (3.28)) */
    char time_scheme[GF_NAME_LEN]; /* resolved tier: "ab2" or "rk3" (fluid/gf_fluid_ns2.h) */
    char advection[GF_NAME_LEN];   /* resolved tier: "advective" or "divergence" form (fluid/gf_fluid_ns2.h) */
    double diffusion_number;  /* resolved tier: the fluid step's nu dt/dx^2 where viscosity bounds it, in (0, 1];
                                 0.5 by default (Izard 2014 ran ~1.2 with RK3) */
    double ibm_retraction_dx; /* resolved tier: the solid fraction's profile (markers: the markers' sphere) centred
                                 on R - this x dx (Breugem, J. Comput. Phys. 2012); 0: on R (Izard 2014) */
    char ibm_forcing[GF_NAME_LEN]; /* resolved tier: "smoothed" (Izard 2014) or "markers" (Uhlmann 2005,
                                      Breugem 2012; coupling/gf_ibm_markers.h) */
    int ibm_contact_correction; /* resolved tier, smoothed forcing: 1 (default) adds rho/(rho_p - rho) x the last fluid
                                   step's mean contact and lubrication force, so that they act in full; 0: Izard 2014
                                   eq. (2.32) alone, under which they act at (rho_p - rho)/rho_p (gf_coupling_resolved.c) */
} gf_fluid_spec;

/* The continuum method (method: continuum; engine/continuum): the mu(I) law and the grid. */
typedef struct gf_continuum_spec {
    double mu_s, mu_2, I0;    /* mu(I) = mu_s + (mu_2 - mu_s)/(I0/I + 1) */
    double phi;               /* solid fraction: the continuum's density is phi rho_p */
    double cell_over_D;       /* cell edge / D */
    double gdot_min_nd;       /* |gdot| floor (Djouwe Meffeja 2012, Annex A) x sqrt(D/g) */
} gf_continuum_spec;

typedef struct gf_output_spec {
    double interval_nd;       /* output interval in sqrt(D/g) */
    int particles, fields, probes, diagnostics;  /* which files to write */
    double checkpoint_interval_nd;               /* 0: no periodic checkpoint */
} gf_output_spec;

typedef struct gf_run_spec {
    char scene[GF_NAME_LEN];
    char run_id[24];          /* set by the pipeline: short hash of the canonical spec */
    uint64_t seed;            /* RNG seed (positions, radii) */
    double gravity_m_s2;
    double end_time_nd;       /* in sqrt(D/g); 0: the scene's default / end condition */
    gf_grains_spec grains;
    gf_contact_spec contact;
    gf_fluid_spec fluid;
    gf_output_spec output;
    char method[GF_NAME_LEN]; /* "dem" (grains) or "continuum" (the mu(I) continuum: column_collapse, avalanche) */
    gf_continuum_spec continuum;
    /* the groups a campaign asked for (NaN when not on the grid); recorded as attributes */
    double stokes_St, density_ratio_r, aspect_ratio_a, phi_initial;
    int n_scene_params;
    gf_param scene_params[GF_MAX_SCENE_PARAMS];
} gf_run_spec;

/* The one place defaults live (printed by `grainflow check`). */
void gf_run_spec_defaults(gf_run_spec *spec);

/* Value of scene parameter key, or fallback when absent. */
double gf_run_spec_param(const gf_run_spec *spec, const char *key, double fallback);
/* Sets (adds or replaces) a scene parameter. GF_ERR_CAPACITY when full. */
gf_status gf_run_spec_set_param(gf_ctx *ctx, gf_run_spec *spec, const char *key, double value);

/* DEM time step t_c * dt_over_tc, and t_c itself, in seconds. */
double gf_run_spec_t_contact_s(const gf_run_spec *spec);
double gf_run_spec_dt_s(const gf_run_spec *spec);

/* Largest accepted dt / t_c (t_c of the mean pair). t_c/5 covers the
 * contact network and up to 10 % polydispersity (gf_sim.c, opening
 * comment); beyond, k_n is still the mean pair's (gf_contact.h) and the
 * smallest pair, of mass (1 - p)^3 times the mean, vibrates (1 - p)^(-3/2)
 * times faster, so the bound shrinks as t_c/5 ((1 - p)/0.9)^(3/2): 0.083 t_c
 * at p = 0.5, the schema's widest distribution. */
#define GF_DT_MAX_OVER_TC 0.2
double gf_run_spec_dt_limit_over_tc(const gf_run_spec *spec);
/* GF_ERR_NUMERIC, naming the limit and what to change, when
 * contact.dt_over_tc exceeds gf_run_spec_dt_limit_over_tc; GF_ERR_CONFIG when
 * it is not a positive number. Called by gf_sim_create and by the campaign
 * loader, so `grainflow check` refuses what the engine would refuse. */
gf_status gf_run_spec_check_time_step(gf_ctx *ctx, const gf_run_spec *spec);
/* GF_ERR_CONFIG when method is continuum and the scene has no continuum form, the run is
 * immersed, or the mu(I) law is not mu_2 > mu_s >= 0, I0 > 0. Called by the campaign loader. */
gf_status gf_run_spec_check_method(gf_ctx *ctx, const gf_run_spec *spec);

#endif
