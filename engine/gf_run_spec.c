/* Defaults of a run; see gf_run_spec.h. */
#include "gf_run_spec.h"

#include "continuum/gf_mui.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void gf_run_spec_defaults(gf_run_spec *s)
{
    memset(s, 0, sizeof *s);
    snprintf(s->scene, sizeof s->scene, "column_collapse");
    s->seed = 1;
    s->gravity_m_s2 = 9.81;
    s->end_time_nd = 0.0;
    /* Izard 2014 §5.2: D = 7.6 mm (D, not R: Ar ~ 30), 5 % polydispersity. */
    s->grains = (gf_grains_spec){.diameter_m = 7.6e-3, .polydispersity = 0.05, .density_kg_m3 = 2500.0};
    /* Izard 2014 §5.2: eps_max = 0.87, mu_c = 0.25; t_c sqrt(g/D) = 2.5e-3 there; a softer
     * 1e-2 keeps grains rigid (overlap << D at these pressures) at 4x fewer steps. */
    s->contact = (gf_contact_spec){.restitution = 0.87, .friction = 0.25, .wall_friction = 0.25,
                                   .kt_over_kn = 0.2, .allow_attraction = 0, .t_contact_nd = 1e-2,
                                   .dt_over_tc = 0.02, .skin_over_D = 0.1,
                                   .sleep_speed_nd = 0.0};
    snprintf(s->contact.law, sizeof s->contact.law, "linear");
    s->fluid = (gf_fluid_spec){.density_kg_m3 = 0.0, .viscosity_Pa_s = 0.0, .cell_over_D = 2.0, .cfl = 0.3,
                               .diffusion_number = 0.5, .lubrication = 1, .roughness_over_R = 2e-4, .lub_cutoff_over_R = 0.5};
    snprintf(s->fluid.model, sizeof s->fluid.model, "none");
    snprintf(s->fluid.drag, sizeof s->fluid.drag, "di_felice");
    snprintf(s->fluid.time_scheme, sizeof s->fluid.time_scheme, "ab2");
    snprintf(s->fluid.advection, sizeof s->fluid.advection, "divergence");
    snprintf(s->fluid.ibm_forcing, sizeof s->fluid.ibm_forcing, "smoothed");
    snprintf(s->fluid.lub_overlap, sizeof s->fluid.lub_overlap, "clamp");
    s->fluid.ibm_contact_correction = 1;
    s->output = (gf_output_spec){.interval_nd = 1.0, .particles = 1, .fields = 1, .probes = 1,
                                 .diagnostics = 1, .checkpoint_interval_nd = 0.0};
    snprintf(s->method, sizeof s->method, "dem");
    /* mu_s, mu_2: this DEM's own steady chute (docs/notes/validation-dem.md), so that the two methods
     * compare like with like; I0 of Jop et al. 2005. */
    s->continuum = (gf_continuum_spec){.mu_s = 0.280, .mu_2 = 0.703, .I0 = 0.279, .phi = 0.6,
                                       .cell_over_D = 0.5, .gdot_min_nd = 1e-4};
    s->stokes_St = s->density_ratio_r = s->aspect_ratio_a = s->phi_initial = NAN;
}

double gf_run_spec_param(const gf_run_spec *s, const char *key, double fallback)
{
    for (int i = 0; i < s->n_scene_params; ++i)
        if (strcmp(s->scene_params[i].key, key) == 0)
            return s->scene_params[i].value;
    return fallback;
}

gf_status gf_run_spec_set_param(gf_ctx *ctx, gf_run_spec *s, const char *key, double value)
{
    for (int i = 0; i < s->n_scene_params; ++i)
        if (strcmp(s->scene_params[i].key, key) == 0) {
            s->scene_params[i].value = value;
            return GF_OK;
        }
    if (s->n_scene_params >= GF_MAX_SCENE_PARAMS)
        return GF_FAIL(ctx, GF_ERR_CAPACITY, "run spec: more than %d scene parameters", GF_MAX_SCENE_PARAMS);
    if (strlen(key) >= GF_NAME_LEN)
        return GF_FAIL(ctx, GF_ERR_ARG, "run spec: parameter name too long: %s", key);
    gf_param *p = &s->scene_params[s->n_scene_params++];
    snprintf(p->key, sizeof p->key, "%s", key);
    p->value = value;
    return GF_OK;
}

double gf_run_spec_t_contact_s(const gf_run_spec *s)
{
    return s->contact.t_contact_nd * sqrt(s->grains.diameter_m / s->gravity_m_s2);
}

double gf_run_spec_dt_s(const gf_run_spec *s)
{
    return gf_run_spec_t_contact_s(s) * s->contact.dt_over_tc;
}

double gf_run_spec_dt_limit_over_tc(const gf_run_spec *s)
{
    double p = s->grains.polydispersity;
    return p > 0.1 ? GF_DT_MAX_OVER_TC * pow((1.0 - p) / 0.9, 1.5) : GF_DT_MAX_OVER_TC;
}

gf_status gf_run_spec_check_time_step(gf_ctx *ctx, const gf_run_spec *s)
{
    const double r = s->contact.dt_over_tc, limit = gf_run_spec_dt_limit_over_tc(s);
    if (!(r > 0.0) || !isfinite(r))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "contact.dt_over_tc: must be > 0 (got %g)", r);
    if (r <= limit)
        return GF_OK;
    if (limit < GF_DT_MAX_OVER_TC)
        return GF_FAIL(ctx, GF_ERR_NUMERIC,
                       "contact.dt_over_tc = %g exceeds the stability limit t_c/5 x ((1 - p)/0.9)^1.5 = %.3g t_c "
                       "of the smallest grains (grains.polydispersity p = %g: the smallest pair's contact lasts "
                       "%.2g t_c); use dt_over_tc <= %.3g or a narrower size distribution",
                       r, limit, s->grains.polydispersity, pow(1.0 - s->grains.polydispersity, 1.5), limit);
    return GF_FAIL(ctx, GF_ERR_NUMERIC,
                   "contact.dt_over_tc = %g: dt = %g s exceeds the stability limit t_c/5 = %g s "
                   "(velocity Verlet on the contact network; use <= 0.2, 0.02 recommended)",
                   r, gf_run_spec_dt_s(s), gf_run_spec_t_contact_s(s) * GF_DT_MAX_OVER_TC);
}

gf_status gf_run_spec_check_method(gf_ctx *ctx, const gf_run_spec *spec)
{
    if (strcmp(spec->method, "continuum") != 0)
        return GF_OK;
    if (strcmp(spec->scene, "column_collapse") != 0 && strcmp(spec->scene, "avalanche") != 0)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "method: continuum runs the scenes column_collapse and avalanche only (got %s)",
                       spec->scene);
    if (strcmp(spec->fluid.model, "none") != 0)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "method: continuum is dry (fluid.model: none; got %s)", spec->fluid.model);
    gf_mui_params law = {.mu_s = spec->continuum.mu_s, .mu_2 = spec->continuum.mu_2, .I0 = spec->continuum.I0};
    return gf_mui_check(ctx, &law, "continuum");
}
