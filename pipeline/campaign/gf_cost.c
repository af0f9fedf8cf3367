/* Cost estimate of a run from its spec; see gf_cost.h. */
#include "campaign/gf_cost.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "campaign/gf_groups_map.h"
#include "continuum/gf_continuum_avalanche.h"
#include "continuum/gf_continuum_collapse.h"
#include "coupling/gf_coupling_tier.h"
#include "core/gf_status.h"
#include "scenes/gf_scene.h"

/*
 * Per grain-step CPU constants (one core, Release build, -O3 -march=x86-64-v2),
 * measured on the dry collapse of configs/demo.yaml (a = 1, Phi_i = 0.6,
 * R0 = 10 D: 404 grains; R0 = 16 D: 960 grains) as the difference of CPU times
 * between end_time 12 and 2 sqrt(D/g) (50 000 steps), which cancels the
 * preparation: 3.2e-8 (404 grains), 3.8e-8 (960 grains) s per grain-step;
 * and the preparation (packing by deposition, gf_packing.h) as what the
 * end_time 2 runs took beyond their steps and settling: 2.2-2.9 ms per grain.
 * The fluid's cost is its tier's (gf_coupling_tier.cost).
 * Re-measure: docs/campaigns.md, "What a campaign costs".
 */
#define COST_DEM_S_PER_GRAIN_STEP 3.5e-8
#define COST_PACK_S_PER_GRAIN 2.5e-3
/* method: continuum, CPU per cell and time step. The implicit mu(I) viscous
 * solve (a sparse LU) dominates and its cost per cell grows with the grid:
 * measured on configs/column_collapse_methods.yaml at cell D/2, quiet
 * machine, one core: a = 0.5, 2 600 cells x 2 263 steps, 26.9 s (4.6 us per
 * cell-step); a = 1, 6 624 cells x 3 200 steps, 147.5 s (7.0 us), i.e.
 * 4.6 us x (cells / 2 600)^0.45. */
#define COST_CONTINUUM_S_PER_CELL_STEP 4.6e-6
#define COST_CONTINUUM_REF_CELLS 2600.0
#define COST_CONTINUUM_CELL_EXPONENT 0.45
/* netCDF-4 (deflated) bytes per grain and output record, same runs:
 * particles.nc 38.7 and 39.9, fields.nc 42 and 34 (the fluid grid follows
 * the domain, which follows the grains); diagnostics and probes ~100 kB. */
#define COST_PARTICLES_B_PER_GRAIN_RECORD 40.0
#define COST_FIELDS_B_PER_GRAIN_RECORD 40.0
#define COST_SMALL_FILES_B 1.1e5
/* a grid tier's fields.nc (the resolved tier: solid fraction, velocity, pressure): 185 MB for 4 records
 * of 2.30 M cells, the collapse at D/dx 8 to 0.3 sqrt(D/g), 20 bytes per cell and record */
#define COST_FIELDS_B_PER_CELL_RECORD 20.0

static int is_immersed(const gf_scene_desc *scene, const gf_run_spec *s)
{
    return scene && (scene->needs & GF_NEED_FLUID) && strcmp(s->fluid.model, "none") != 0 &&
           s->fluid.viscosity_Pa_s > 0.0;
}

static double grain_estimate(const gf_scene_desc *scene, const gf_run_spec *s)
{
    if (scene && scene->grain_count)
        return scene->grain_count(s);
    double n = gf_run_spec_param(s, "n_grains", NAN); /* scenes that take the count as a parameter */
    return n > 0 ? n : NAN;
}

/* method: continuum: the grid's cells and steps; small files only. */
static void continuum_estimate(const gf_run_spec *s, gf_run_cost *out)
{
    double cells = NAN, steps = NAN;
    if (strcmp(s->scene, "avalanche") == 0) {
        gf_continuum_avalanche_size(s, &cells, &steps);
    } else {
        gf_ctx ctx = {.log_level = GF_LOG_QUIET};
        if (gf_continuum_collapse_size(&ctx, s, &cells, &steps) != GF_OK)
            cells = steps = NAN;
    }
    out->n_grains = NAN;
    out->n_cells = cells;
    out->steps = steps;
    out->cpu_s = cells * steps * COST_CONTINUUM_S_PER_CELL_STEP *
                 pow(cells / COST_CONTINUUM_REF_CELLS, COST_CONTINUUM_CELL_EXPONENT);
    out->output_bytes = COST_SMALL_FILES_B;
}

/* The scene's time under the fluid before t = 0 (NaN when the run's scales cannot be computed). */
static double prelude_time_s(const gf_scene_desc *scene, const gf_run_spec *s)
{
    if (!scene->prelude_time_s)
        return 0.0;
    gf_ctx ctx = {.log_level = GF_LOG_QUIET};
    gf_scales scales;
    return gf_groups_map_realised(&ctx, s, &scales) == GF_OK ? scene->prelude_time_s(s, &scales) : NAN;
}

/* The fluid's CPU over fluid_time_s, from the run's tier (an unregistered name: the first, as `fluid: auto`). */
static double fluid_estimate(const gf_scene_desc *scene, const gf_run_spec *s, double fluid_time_s, gf_run_cost *out)
{
    const gf_coupling_tier *tier = gf_coupling_tier_find(s->fluid.model);
    if (!tier) {
        int n;
        tier = gf_coupling_tier_all(&n)[0];
    }
    gf_tier_cost_query q = {.n_grains = out->n_grains, .box_m = {NAN, NAN, NAN}, .fluid_time_s = fluid_time_s};
    if (scene->fluid_box)
        scene->fluid_box(s, q.box_m);
    gf_tier_cost tc = {NAN, NAN, NAN, 0};
    if (tier->cost)
        tier->cost(s, &q, &tc);
    out->fluid_cells = tc.cells;
    out->fluid_steps = tc.fluid_steps;
    out->cpu_at_least = tc.at_least;
    return tc.cpu_s;
}

void gf_cost_estimate(const gf_run_spec *s, gf_run_cost *out)
{
    const gf_scene_desc *scene = gf_scene_find(s->scene);
    memset(out, 0, sizeof *out);
    out->n_cells = out->fluid_cells = out->fluid_steps = NAN;
    if (strcmp(s->method, "continuum") == 0) {
        continuum_estimate(s, out);
        return;
    }
    out->immersed = is_immersed(scene, s);
    out->may_stop_early = scene && scene->done != NULL;
    out->n_grains = grain_estimate(scene, s);
    const double t_grain = sqrt(s->grains.diameter_m / s->gravity_m_s2), dt = gf_run_spec_dt_s(s);
    const double end_nd = s->end_time_nd > 0 ? s->end_time_nd : (scene ? scene->default_end_time_nd : 0.0);
    out->steps = end_nd > 0 && dt > 0 ? ceil(end_nd * t_grain / dt) : NAN;
    /* the preparation's settling runs dry, before the fluid is made; the prelude under the fluid */
    const double settle = dt > 0 ? ceil(gf_run_spec_param(s, "settle_time_nd", 0.0) * t_grain / dt) : 0.0;
    const double prelude_s = out->immersed ? prelude_time_s(scene, s) : 0.0;
    out->prelude_steps = dt > 0 ? ceil(prelude_s / dt) : 0.0;
    const int packs = scene && (scene->needs & GF_NEED_PACKING);
    out->cpu_s = out->n_grains * ((packs ? COST_PACK_S_PER_GRAIN : 0.0) +
                                  (out->steps + settle + out->prelude_steps) * COST_DEM_S_PER_GRAIN_STEP);
    if (out->immersed)
        out->cpu_s += fluid_estimate(scene, s, out->steps * dt + prelude_s, out);
    const double records = s->output.interval_nd > 0 ? floor(end_nd / s->output.interval_nd) + 1.0 : NAN;
    double bytes = COST_SMALL_FILES_B;
    if (s->output.particles)
        bytes += records * out->n_grains * COST_PARTICLES_B_PER_GRAIN_RECORD;
    if (s->output.fields && out->immersed)
        bytes += records * (isnan(out->fluid_cells) ? out->n_grains * COST_FIELDS_B_PER_GRAIN_RECORD
                                                     : out->fluid_cells * COST_FIELDS_B_PER_CELL_RECORD);
    out->output_bytes = bytes;
}

void gf_cost_format_time(double s, char *buf, size_t n)
{
    if (!isfinite(s) || s < 0) {
        snprintf(buf, n, "?");
        return;
    }
    double t = floor(s + 0.5);
    if (t >= 3600.0)
        snprintf(buf, n, "%.0f:%02.0f:%02.0f", floor(t / 3600.0), fmod(floor(t / 60.0), 60.0), fmod(t, 60.0));
    else
        snprintf(buf, n, "%.0f:%02.0f", floor(t / 60.0), fmod(t, 60.0));
}

void gf_cost_format_bytes(double b, char *buf, size_t n)
{
    static const char *const units[] = {"B", "kB", "MB", "GB", "TB", "PB"};
    if (!isfinite(b) || b < 0) {
        snprintf(buf, n, "?");
        return;
    }
    int k = 0;
    while (b >= 1000.0 && k < 5)
        b /= 1000.0, ++k;
    snprintf(buf, n, k ? "%.3g %s" : "%.0f %s", b, units[k]);
}
