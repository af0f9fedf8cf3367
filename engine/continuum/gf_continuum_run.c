/* The continuum scenes' run; see gf_continuum_run.h. */
#include "continuum/gf_continuum_run.h"

#include <math.h>
#include <stdio.h>

/* dir/diagnostics.nc with the scene's variables and attributes, the groups and the method's fluid model. */
static gf_status diagnostics_open(gf_ctx *ctx, const gf_continuum_scene *sc, const char *dir, gf_nc_writer **w)
{
    gf_scales scales;
    GF_TRY(gf_groups_compute(ctx, &sc->groups, &scales));
    gf_nc_meta meta = sc->meta;
    meta.scales = &scales;
    meta.fluid_model = "none";
    meta.fluid_model_reason = "method: continuum (dry)";
    meta.stages = "continuum";
    char path[4200];
    snprintf(path, sizeof path, "%s/diagnostics.nc", dir);
    return gf_nc_diagnostics_open(ctx, path, &meta, sc->diagnostics.vars, sc->diagnostics.n_vars, w);
}

/* Steps s to t_end; with w appends the sampler's record at t = 0, every_s, ... */
static gf_status run_until(gf_ctx *ctx, gf_continuum *s, const gf_continuum_scene *sc, void *user, double every_s,
                           gf_nc_writer *w, volatile int *interrupt, long *steps)
{
    double next = 0.0, values[16];
    while (1) {
        double t = gf_continuum_time(s);
        if (w && t >= next - 1e-9 * every_s) {
            sc->diagnostics.sample(s, user, values);
            GF_TRY(gf_nc_diagnostics_append(w, t, values));
            next += every_s;
        }
        if (t >= sc->t_end_s - 1e-9 * every_s)
            return GF_OK;
        if (interrupt && *interrupt)
            return GF_FAIL(ctx, GF_ERR_INTERRUPTED, "%s interrupted at t = %g s", sc->what, t);
        GF_TRY(gf_continuum_step(s));
        ++*steps;
    }
}

gf_status gf_continuum_scene_run(gf_ctx *ctx, const gf_run_spec *spec, gf_continuum_describe describe, void *user,
                                 const gf_continuum_output *out, gf_continuum **solver, long *steps)
{
    *solver = NULL;
    GF_TRY(gf_run_spec_check_method(ctx, spec));
    gf_continuum_scene sc = {0};
    GF_TRY(describe(ctx, spec, user, &sc));
    sc.meta.spec = spec;
    sc.meta.resolved_yaml = out->resolved_yaml;
    gf_continuum *s = NULL;
    GF_TRY(gf_continuum_create(ctx, &sc.params, &s));
    if (sc.fill)
        sc.fill(s, user);
    gf_nc_writer *w = NULL;
    gf_status st = gf_continuum_init_pressure(s);
    if (st == GF_OK && out->dir)
        st = diagnostics_open(ctx, &sc, out->dir, &w);
    double every_s = spec->output.interval_nd * sqrt(spec->grains.diameter_m / spec->gravity_m_s2);
    if (st == GF_OK)
        st = run_until(ctx, s, &sc, user, every_s, w, out->interrupt, steps);
    if (st == GF_OK)
        st = gf_nc_writer_close(&w);
    gf_nc_writer_abort(&w);
    if (st != GF_OK)
        gf_continuum_destroy(&s);
    *solver = s;
    return st;
}
