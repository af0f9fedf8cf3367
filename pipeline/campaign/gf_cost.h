/*
 * What a run will cost before it runs: grains, steps, CPU time and output
 * size, estimated from the resolved spec alone (`grainflow check`, and the
 * campaign ETA before any run has reported its speed).
 *
 *   CPU = N (c_pack + (steps + settle_steps + prelude_steps) c_dem) + fluid
 *
 * with N the scene's grain estimate (gf_scene_desc.grain_count), the
 * constants measured on this code (gf_cost.c), the prelude the scene's time
 * under the fluid before t = 0 (gf_scene_desc.prelude_time_s), and fluid, when
 * immersed, what the run's coupling tier says its fluid costs over the prelude
 * and the run (gf_coupling_tier.cost: per grain and step for the unresolved
 * tier, per cell and fluid step for the resolved one, from the scene's box). A run with method: continuum costs its cells times
 * its time steps times a constant per cell-step instead. A scene that stops at its own end condition (a deposit
 * at rest) may finish earlier: its figures are upper bounds.
 */
#ifndef GF_COST_H
#define GF_COST_H

#include <stddef.h>

#include "gf_run_spec.h"

typedef struct gf_run_cost {
    double n_grains;       /* estimated grains, NaN when the scene gives no estimate (and for method: continuum) */
    double n_cells;        /* method: continuum: the grid's cells; NaN for grains */
    double steps;          /* DEM steps from t = 0 to the end time; NaN when the end is the scene's condition only */
    double prelude_steps;  /* DEM steps under the fluid before t = 0 (the scene's prelude); 0 when none */
    double fluid_cells;    /* a grid tier's cells; NaN for the other tiers or when the scene gives no box */
    double fluid_steps;    /* a grid tier's fluid steps over the prelude and the run; NaN as fluid_cells */
    double cpu_s;          /* estimated CPU seconds on one core; NaN when n_grains or steps is */
    double output_bytes;   /* estimated bytes of the netCDF files; NaN when unknown */
    int immersed;          /* the fluid tier runs */
    int may_stop_early;    /* the scene has an end condition: figures are upper bounds */
    int cpu_at_least;      /* the fluid tier sized its step at rest: cpu_s is a lower bound */
} gf_run_cost;

/* Warning thresholds: a run or campaign above these is worth a second look. */
#define GF_COST_WARN_CPU_S 3600.0
#define GF_COST_WARN_BYTES 4.0e9

void gf_cost_estimate(const gf_run_spec *spec, gf_run_cost *out);

/* "1:02:03" (h:mm:ss) or "4:05" (m:ss); "?" for NaN. */
void gf_cost_format_time(double s, char *buf, size_t n);
/* "12 kB", "3.4 MB", "1.2 GB"; "?" for NaN. */
void gf_cost_format_bytes(double b, char *buf, size_t n);

#endif
