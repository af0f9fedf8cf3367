/* The column collapse by the continuum solver; see gf_continuum_collapse.h. */
#include "continuum/gf_continuum_collapse.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "continuum/gf_continuum.h"
#include "core/gf_groups.h"
#include "continuum/gf_continuum_run.h"
#include "io/gf_nc.h"
#include "scenes/gf_measure.h"
#include "scenes/gf_scene.h"

static const gf_var_info collapse_diag[] = {
    {"front_position", "m", "front position from the back wall", NULL},
    {"deposit_height", "m", "maximum height of the deposit", NULL},
    {"packing_fraction", "1", "solid fraction of the initial column region", NULL},
    {"deposit_extent_1D", "m", "x where the deposit's material height first falls below 1 D", NULL},
    {"deposit_extent_2D", "m", "x where the deposit's material height first falls below 2 D", NULL},
};

typedef struct collapse_geom {
    double D, g, R0, H0, L, top, t_grain;
} collapse_geom;

static gf_status geometry(gf_ctx *ctx, const gf_run_spec *spec, collapse_geom *cg)
{
    const gf_scene_desc *scene = gf_scene_find(spec->scene);
    if (!scene || !scene->column_geometry)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "method: continuum: scene %s is not a column", spec->scene);
    cg->D = spec->grains.diameter_m;
    cg->g = spec->gravity_m_s2;
    scene->column_geometry(spec, &cg->R0, &cg->H0);
    double a = cg->H0 / cg->R0, L_over_R0 = gf_run_spec_param(spec, "domain_length_over_R0", 0.0);
    cg->L = (L_over_R0 > 0.0 ? L_over_R0 : 2.0 + 2.5 * a) * cg->R0;  /* room for (R - R0)/R0 ~ 1.5 a */
    cg->top = 1.3 * cg->H0 + 2.0 * cg->D;
    cg->t_grain = sqrt(cg->D / cg->g);
    return GF_OK;
}

static double end_time_s(const gf_run_spec *spec, const collapse_geom *cg)
{
    return (spec->end_time_nd > 0.0 ? spec->end_time_nd : 6.0 * sqrt(cg->H0 / cg->D) + 10.0) * cg->t_grain;
}

static gf_continuum_params solver_params(const gf_run_spec *spec, const collapse_geom *cg)
{
    const gf_continuum_spec *c = &spec->continuum;
    double h = c->cell_over_D * cg->D, rho = c->phi * spec->grains.density_kg_m3;
    int nx = (int)ceil(cg->L / h), ny = (int)ceil(cg->top / h);
    double u_scale = sqrt(cg->g * cg->H0);  /* free-fall speed of the column's top */
    gf_continuum_params p = {
        .n = {nx, ny, 1},
        .length_m = {nx * h, ny * h, h},
        .side = {{GF_SIDE_WALL, GF_SIDE_WALL}, {GF_SIDE_WALL, GF_SIDE_OUTFLOW}, {GF_SIDE_PERIODIC, GF_SIDE_PERIODIC}},
        .density_kg_m3 = rho,
        .body_accel_m_s2 = {0.0, -cg->g, 0.0},
        .rheology = GF_RHEOLOGY_MU_I,
        .mui = {.law = {.mu_s = c->mu_s, .mu_2 = c->mu_2, .I0 = c->I0}, .diameter_m = cg->D,
                .grain_density_kg_m3 = spec->grains.density_kg_m3, .gdot_min_1_s = c->gdot_min_nd / cg->t_grain},
        .two_phase = 1,
        .density2_kg_m3 = rho / 100.0,
        .viscosity2_Pa_s = 1e-3 * spec->grains.density_kg_m3 * sqrt(cg->g * cg->D) * cg->D,
        .dt_s = 0.1 * h / u_scale,  /* Courant 0.1 at the free-fall speed; measured stable at 0.05-0.1 */
    };
    return p;
}

static double column_height(const gf_continuum *s, int i)
{
    const gf_grid *g = gf_continuum_grid(s);
    const double *c = gf_continuum_fraction((gf_continuum *)s);
    double h = 0.0;
    for (int j = 0; j < g->n[1]; ++j)
        h += c[gf_grid_cell(g, i, j, 0)] * g->h_m[1];
    return h;
}

double gf_continuum_collapse_extent(const gf_continuum *s, double depth_m)
{
    const gf_grid *g = gf_continuum_grid(s);
    double *h = malloc((size_t)g->n[0] * sizeof *h);
    if (!h)
        return NAN;
    for (int i = 0; i < g->n[0]; ++i)
        h[i] = column_height(s, i);
    double x = gf_measure_profile_extent(h, g->n[0], g->h_m[0], depth_m);
    free(h);
    return x;
}

double gf_continuum_collapse_front(const gf_continuum *s, double phi, double D)
{
    return gf_continuum_collapse_extent(s, 0.25 * D / phi);
}

static void measure(const gf_continuum *s, const collapse_geom *cg, double phi, double *front, double *height_back,
                    double *volume, double *height_max)
{
    const gf_grid *g = gf_continuum_grid(s);
    *front = gf_continuum_collapse_front(s, phi, cg->D);
    *height_back = column_height(s, 0);
    *volume = 0.0;
    if (height_max)
        *height_max = 0.0;
    for (int i = 0; i < g->n[0]; ++i) {
        double col = column_height(s, i);
        if (height_max && col > *height_max)
            *height_max = col;
        *volume += col * g->h_m[0];
    }
}

/* The run's state: the geometry, the solid fraction and the deposit's volume per unit width at t = 0. */
typedef struct collapse_run {
    collapse_geom cg;
    double phi, volume0_m2;
} collapse_run;

/* front_position, deposit_height, packing_fraction, deposit_extent_1D and _2D (a gf_continuum_sampler;
 * user: the collapse_run). The material height is the column's: the continuum is at phi throughout. */
static void sample_record(const gf_continuum *s, void *user, double *values)
{
    const collapse_run *cr = user;
    double front, height, volume, height_max;
    measure(s, &cr->cg, cr->phi, &front, &height, &volume, &height_max);
    values[0] = front, values[1] = height_max, values[2] = cr->phi;
    values[3] = gf_continuum_collapse_extent(s, cr->cg.D);
    values[4] = gf_continuum_collapse_extent(s, 2.0 * cr->cg.D);
}

static const gf_continuum_diagnostics collapse_diagnostics = {collapse_diag, 5, sample_record};

/* The column R0 x H0 against the back wall, and its volume (user: the collapse_run). */
static void fill_column(gf_continuum *s, void *user)
{
    collapse_run *cr = user;
    const gf_grid *g = gf_continuum_grid(s);
    double *c = gf_continuum_fraction(s);
    for (int j = 0; j < g->n[1]; ++j)
        for (int i = 0; i < g->n[0]; ++i)
            c[gf_grid_cell(g, i, j, 0)] =
                ((i + 0.5) * g->h_m[0] < cr->cg.R0 && (j + 0.5) * g->h_m[1] < cr->cg.H0) ? 1.0 : 0.0;
    double front0, height0;
    measure(s, &cr->cg, cr->phi, &front0, &height0, &cr->volume0_m2, NULL);
}

/* The column in its box as a continuum scene (a gf_continuum_describe; user: the collapse_run filled).
 * Errors: the spec's scene is not a column. */
static gf_status describe(gf_ctx *ctx, const gf_run_spec *spec, void *user, gf_continuum_scene *sc)
{
    collapse_run *cr = user;
    const collapse_geom *cg = &cr->cg;
    GF_TRY(geometry(ctx, spec, &cr->cg));
    cr->phi = spec->continuum.phi;
    sc->what = "continuum collapse";
    sc->params = solver_params(spec, cg);
    sc->fill = fill_column;
    sc->t_end_s = end_time_s(spec, cg);
    sc->groups = (gf_groups_input){.diameter_m = cg->D, .grain_density_kg_m3 = spec->grains.density_kg_m3,
                                   .gravity_m_s2 = cg->g, .slope_sin = 1.0, .column_height_m = cg->H0,
                                   .column_length_m = cg->R0};
    sc->meta = (gf_nc_meta){.column_length_m = cg->R0, .column_height_m = cg->H0, .incline_deg = 90.0,
                            .phi_initial_measured = cr->phi, .phi_initial_local = cr->phi};
    sc->diagnostics = collapse_diagnostics;
    return GF_OK;
}

gf_status gf_continuum_collapse_run(gf_ctx *ctx, const gf_run_spec *spec, const char *output_dir,
                                    const char *resolved_yaml, volatile int *interrupt,
                                    gf_continuum_collapse_result *r)
{
    memset(r, 0, sizeof *r);
    collapse_run cr;
    const gf_continuum_output out = {output_dir, resolved_yaml, interrupt};
    gf_continuum *s = NULL;
    GF_TRY(gf_continuum_scene_run(ctx, spec, describe, &cr, &out, &s, &r->steps));
    double volume;
    measure(s, &cr.cg, cr.phi, &r->front_m, &r->height_m, &volume, NULL);
    r->mass_drift = volume / cr.volume0_m2 - 1.0;
    r->body_front_m = gf_continuum_collapse_extent(s, 2.0 * cr.cg.D);
    r->column_length_m = cr.cg.R0;
    r->column_height_m = cr.cg.H0;
    r->time_s = gf_continuum_time(s);
    gf_continuum_destroy(&s);
    return GF_OK;
}

gf_status gf_continuum_collapse_size(gf_ctx *ctx, const gf_run_spec *spec, double *cells, double *steps)
{
    collapse_geom cg;
    GF_TRY(geometry(ctx, spec, &cg));
    gf_continuum_params p = solver_params(spec, &cg);
    *cells = (double)p.n[0] * p.n[1] * p.n[2];
    *steps = ceil(end_time_s(spec, &cg) / p.dt_s);
    return GF_OK;
}
