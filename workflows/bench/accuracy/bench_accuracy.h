/*
 * gf-bench-accuracy: shared types of the accuracy benchmark.
 *
 * A case is one validation scene with a reference value (closed form,
 * conservation law, or the finest affordable run) and a tolerance taken from
 * the published validations (docs/accuracy.md). A setting is one
 * choice of the accuracy knobs; measuring it runs the scene through gf_sim
 * (no output files) and returns the observable, its error against the
 * reference, and the CPU time of the simulation calls (gf_sim_create +
 * gf_sim_advance, one thread; the benchmark's own bookkeeping is not timed).
 * CPU time, not wall time, is the cost the fronts use: on a shared machine
 * it does not count the time other processes hold the core, and for a
 * one-thread run it is the wall time of an idle machine. The wall time of
 * each setting is recorded next to it.
 */
#ifndef BENCH_ACCURACY_H
#define BENCH_ACCURACY_H

#include "core/gf_status.h"

enum {
    BENCH_KNOB_DT = 1u << 0,
    BENCH_KNOB_SKIN = 1u << 1,
    BENCH_KNOB_TC = 1u << 2,
    BENCH_KNOB_CELL = 1u << 3,
    BENCH_KNOB_RETRACT = 1u << 4, /* resolved tier: fluid.ibm_retraction_dx */
    BENCH_KNOB_FLUID_CFL = 1u << 5 /* resolved tier: fluid.cfl, the fluid step's advective bound */
};

/* Defaults of the knobs a case does not sweep: the run-spec defaults. */
#define BENCH_DEFAULT_DT_OVER_TC 0.02
#define BENCH_DEFAULT_SKIN_OVER_D 0.1
#define BENCH_DEFAULT_TC_ND 1e-2
#define BENCH_DEFAULT_CELL_OVER_D 2.0
#define BENCH_DEFAULT_RETRACT_DX 0.0
#define BENCH_DEFAULT_FLUID_CFL 0.3

typedef struct bench_knobs {
    double dt_over_tc, skin_over_D, t_contact_nd, cell_over_D;
    double retract_dx; /* resolved tier: the solid fraction's profile centred on R - retract_dx dx */
    double fluid_cfl;  /* resolved tier: fluid.cfl */
} bench_knobs;

typedef struct bench_result {
    double observable, reference, error, cpu_s;
    double aux;                 /* second observable of the case (bench_case.aux), recorded, not judged */
} bench_result;

typedef struct bench_case {
    const char *name;           /* scene-level name: "restitution", ... */
    const char *observable;     /* what is measured, with units */
    const char *reference;      /* where the reference comes from */
    const char *error_label;    /* y-axis label of the Pareto plot */
    double tolerance;           /* error accepted for the recommended default */
    unsigned knobs;             /* BENCH_KNOB_* swept */
    int full_only;              /* 1: only under --full (long runs) */
    /* 1 when the case can run in this build (scene present, tier working), else 0 and *why set */
    int (*available)(const char **why);
    /* Measures one setting. The reference may be computed lazily on the first call (finest run). */
    gf_status (*measure)(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out);
    /* Optional: the case's own values of a swept knob (NULL: the common sweep of gf_bench_accuracy.c) */
    const double *dt_list, *cell_list;
    int n_dt, n_cell;
    const char *aux;            /* name and units of bench_result.aux; NULL when the case has none */
    const double *tc_list;      /* optional: the case's own t_c sqrt(g/D) values (NULL: the common sweep) */
    int n_tc;
    int n_cell_quick;           /* --quick runs only the first n_cell_quick of cell_list (0: all of them) */
    int cell_as_resolution;     /* labels: 0 cell/D; 1 D/dx = 1/cell_over_D (the resolved tier's grid);
                                   2 the tier by the cell: below one D, resolved at D/dx, else unresolved */
    const double *retract_list; /* the case's fluid.ibm_retraction_dx values (BENCH_KNOB_RETRACT) */
    int n_retract;
    const double *cfl_list;     /* the case's fluid.cfl values (BENCH_KNOB_FLUID_CFL) */
    int n_cfl;
} bench_case;

const bench_case *bench_cases(int *n);

/* settling_sphere (bench_sphere.c): single sphere, Stokes with Hasimoto's periodic correction */
extern const double bench_sphere_cells[];
int bench_sphere_available(const char **why);
gf_status bench_sphere_measure(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out);

/* janssen_saturation (bench_janssen.c): plateau of the Janssen column against the finest setting */
extern const double bench_janssen_dt[], bench_janssen_tc[];
int bench_janssen_available(const char **why);
gf_status bench_janssen_measure(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out);

/* resolved_early_acceleration (bench_resolved.c): early acceleration of the settling sphere, resolved tier */
extern const double bench_resolved_cells[], bench_resolved_retract[];
int bench_resolved_available(const char **why);
gf_status bench_resolved_measure(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out);
/* The sphere of both: rho_p/rho 4, Ar 800, D = 10 mm, scene bounce with free-slip walls, released 2.5 D
 * below the top of a box_over_D x height_over_D box; tier and its knobs left to the caller. */
struct gf_run_spec;
gf_status bench_settling_sphere_spec(gf_ctx *ctx, double box_over_D, double height_over_D, struct gf_run_spec *s);

/* settling_terminal_tiers (bench_tiers.c): the same sphere's terminal velocity, unresolved and resolved tiers */
extern const double bench_tiers_cells[], bench_tiers_unresolved_cells[];
gf_status bench_tiers_measure(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out);
gf_status bench_tiers_measure_tenneti(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out);
/* settling_terminal_step[_markers] (bench_tiers.c): the resolved sphere at D/dx 8 against the fluid step */
extern const double bench_step_cfl[];
gf_status bench_step_measure_smoothed(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out);
gf_status bench_step_measure_markers(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out);

/* hindered_settling_tiers (bench_suspension.c): a random suspension at phi 0.1, Ar 20, unresolved and resolved tiers */
extern const double bench_suspension_cells[];
gf_status bench_suspension_measure(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out);

/* avalanche_{viscous,inertial,free_fall}_tiers and collapse_case_a_tiers (bench_regime_tiers.c): the thesis'
 * resolved scenes (Table 4.2's three regimes, Table 5.1's case A) through both tiers */
extern const double bench_regime_cells[];
extern const double bench_collapse_cells[];
int bench_regime_available(const char **why);
gf_status bench_regime_viscous(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out);
gf_status bench_regime_inertial(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out);
gf_status bench_regime_free_fall(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out);
gf_status bench_collapse_tiers(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out);

/* Default of a knob for case c: the common default, or the first of the
 * case's own list when that list does not hold the common default. */
double bench_case_default(const bench_case *c, unsigned knob);

/* One measured point. */
typedef struct bench_point {
    int case_index;
    bench_knobs k;
    bench_result r;
    double wall_s;              /* best wall time of the repeats (includes the case's bookkeeping) */
    gf_status status;
    char message[512];          /* ctx message when status != GF_OK */
    char label[64];             /* "dt=tc/50 skin=0.1" */
    unsigned char on_front, recommended, within_tolerance;
} bench_point;

/* Front and recommendation of every case (cheapest within tolerance). */
void bench_analyse(bench_point *pts, int n, const bench_case *cases, int n_cases);
/* Writes <dir>/bench_accuracy.csv, <dir>/bench_accuracy.nc and <dir>/pareto_<case>.svg. */
gf_status bench_write(gf_ctx *ctx, const char *dir, const bench_point *pts, int n, const bench_case *cases,
                      int n_cases, int full);
/* Prints the measured order in dt of each case (error ratio when dt halves). */
void bench_print_orders(const bench_point *pts, int n, const bench_case *cases, int n_cases);
/* Prints the measured order in cell size of each case that sweeps it. */
void bench_print_cell_orders(const bench_point *pts, int n, const bench_case *cases, int n_cases);

#endif
