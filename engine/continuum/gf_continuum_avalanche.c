/* The dry avalanche by the continuum solver; see gf_continuum_avalanche.h. */
#include "continuum/gf_continuum_avalanche.h"

#include <math.h>
#include <string.h>

#include "core/gf_groups.h"
#include "continuum/gf_continuum_run.h"
#include "io/gf_nc.h"

gf_continuum_params gf_continuum_layer_params(const gf_continuum_layer *l)
{
    int ny = (int)lround(l->depth_m / l->cell_m);
    if (ny < 1)
        ny = 1;
    double h = l->depth_m / ny;
    /* a uniform layer is one column of cells: the periodic x direction then admits no
     * perturbation, and dt is bounded by nothing but the transient (no advective limit) */
    int nx = 1;
    gf_continuum_params p = {
        .n = {nx, ny, 1},
        .length_m = {nx * h, l->depth_m, h},
        .side = {{GF_SIDE_PERIODIC, GF_SIDE_PERIODIC}, {GF_SIDE_WALL, GF_SIDE_OUTFLOW},
                 {GF_SIDE_PERIODIC, GF_SIDE_PERIODIC}},
        .density_kg_m3 = l->phi * l->mui.grain_density_kg_m3,
        .body_accel_m_s2 = {l->g_m_s2 * sin(l->incline_rad), -l->g_m_s2 * cos(l->incline_rad), 0.0},
        .rheology = GF_RHEOLOGY_MU_I,
        .mui = l->mui,
        .dt_s = l->dt_s,
    };
    return p;
}

double gf_continuum_layer_row_velocity(const gf_continuum *s, int j)
{
    const gf_grid *g = gf_continuum_grid(s);
    const double *u = gf_continuum_velocity(s, 0);
    double sum = 0.0;
    for (int i = 0; i < g->n[0]; ++i)
        sum += u[gf_grid_face(g, 0, i, j, 0)];
    return sum / g->n[0];
}

void gf_continuum_layer_measure(const gf_continuum *s, double *u_surface_m_s, double *flux_m2_s)
{
    const gf_grid *g = gf_continuum_grid(s);
    int n = g->n[1];
    double q = 0.0;
    for (int j = 0; j < n; ++j)
        q += gf_continuum_layer_row_velocity(s, j) * g->h_m[1];
    /* rows at depths h_c/2 and 3h_c/2: u(h) = u_top + (u_top - u_below) (1/2)^{3/2}/((3/2)^{3/2} - (1/2)^{3/2}) */
    double u_top = gf_continuum_layer_row_velocity(s, n - 1), u_below = gf_continuum_layer_row_velocity(s, n - 2);
    double w = pow(0.5, 1.5) / (pow(1.5, 1.5) - pow(0.5, 1.5));
    *u_surface_m_s = u_top + w * (u_top - u_below);
    *flux_m2_s = q;
}

static const gf_var_info avalanche_diag[] = {
    {"grain_flow_rate", "m3 s-1", "grain volume flow rate Q_g = W phi int u dy", NULL},
    {"fluid_flow_rate", "m3 s-1", "fluid volume flow rate Q_f", NULL},
    {"bed_packing_fraction", "1", "solid fraction of the continuum", NULL},
    {"bed_height", "m", "layer depth", NULL},
    {"surface_velocity", "m s-1", "downslope velocity of the top cells", NULL},
};

typedef struct avalanche_geom {
    gf_continuum_layer layer;
    double width_m, t_grain, theta_deg;
} avalanche_geom;

static void geometry(const gf_run_spec *spec, avalanche_geom *ag)
{
    const gf_continuum_spec *c = &spec->continuum;
    double D = spec->grains.diameter_m, g = spec->gravity_m_s2;
    ag->theta_deg = gf_run_spec_param(spec, "incline_deg", 25.0);
    ag->width_m = gf_run_spec_param(spec, "width_over_D", 5.0) * D;
    ag->t_grain = sqrt(D / g);
    ag->layer = (gf_continuum_layer){
        .depth_m = gf_run_spec_param(spec, "bed_height_over_D", 8.0) * D,
        .incline_rad = ag->theta_deg * M_PI / 180.0,
        .phi = c->phi,
        .g_m_s2 = g,
        .mui = {.law = {.mu_s = c->mu_s, .mu_2 = c->mu_2, .I0 = c->I0}, .diameter_m = D,
                .grain_density_kg_m3 = spec->grains.density_kg_m3, .gdot_min_1_s = c->gdot_min_nd / ag->t_grain},
        .cell_m = c->cell_over_D * D,
        /* the viscous step is implicit and a uniform layer has no advection: dt resolves the
         * transient of Q_g(t), not a stability limit */
        .dt_s = 0.05 * ag->t_grain,
    };
}

static double end_time_s(const gf_run_spec *spec, const avalanche_geom *ag)
{
    return (spec->end_time_nd > 0.0 ? spec->end_time_nd : 200.0) * ag->t_grain;
}

/* The record of avalanche_diag (a gf_continuum_sampler; user: the avalanche_geom). */
static void sample(const gf_continuum *s, void *user, double *v)
{
    const avalanche_geom *ag = user;
    double u_top, q;
    gf_continuum_layer_measure(s, &u_top, &q);
    v[0] = ag->width_m * ag->layer.phi * q;
    v[1] = 0.0;
    v[2] = ag->layer.phi;
    v[3] = ag->layer.depth_m;
    v[4] = u_top;
}

static const gf_continuum_diagnostics avalanche_diagnostics = {avalanche_diag, 5, sample};

/* The layer on its incline as a continuum scene (a gf_continuum_describe; user: the avalanche_geom filled). */
static gf_status describe(gf_ctx *ctx, const gf_run_spec *spec, void *user, gf_continuum_scene *sc)
{
    (void)ctx;
    avalanche_geom *ag = user;
    geometry(spec, ag);
    sc->what = "continuum avalanche";
    sc->params = gf_continuum_layer_params(&ag->layer);
    sc->t_end_s = end_time_s(spec, ag);
    sc->groups = (gf_groups_input){.diameter_m = spec->grains.diameter_m,
                                   .grain_density_kg_m3 = spec->grains.density_kg_m3,
                                   .gravity_m_s2 = spec->gravity_m_s2,
                                   .slope_sin = sin(ag->layer.incline_rad)};
    sc->meta = (gf_nc_meta){.incline_deg = ag->theta_deg, .phi_initial_measured = ag->layer.phi,
                            .phi_initial_local = ag->layer.phi};
    sc->diagnostics = avalanche_diagnostics;
    return GF_OK;
}

gf_status gf_continuum_avalanche_run(gf_ctx *ctx, const gf_run_spec *spec, const char *output_dir,
                                     const char *resolved_yaml, volatile int *interrupt,
                                     gf_continuum_avalanche_result *r)
{
    memset(r, 0, sizeof *r);
    avalanche_geom ag;
    const gf_continuum_output out = {output_dir, resolved_yaml, interrupt};
    gf_continuum *s = NULL;
    GF_TRY(gf_continuum_scene_run(ctx, spec, describe, &ag, &out, &s, &r->steps));
    double v[5];
    sample(s, &ag, v);
    r->flow_rate_m3_s = v[0];
    r->surface_velocity_m_s = v[4];
    r->time_s = gf_continuum_time(s);
    gf_continuum_destroy(&s);
    return GF_OK;
}

void gf_continuum_avalanche_size(const gf_run_spec *spec, double *cells, double *steps)
{
    avalanche_geom ag;
    geometry(spec, &ag);
    gf_continuum_params p = gf_continuum_layer_params(&ag.layer);
    *cells = (double)p.n[0] * p.n[1] * p.n[2];
    *steps = ceil(end_time_s(spec, &ag) / ag.layer.dt_s);
}
