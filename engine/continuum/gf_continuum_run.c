/* The continuum scenes' diagnostics file and time loop; see gf_continuum_run.h. */
#include "continuum/gf_continuum_run.h"

#include <stdio.h>

gf_status gf_continuum_diagnostics_open(gf_ctx *ctx, const gf_groups_input *in, gf_nc_meta meta, const char *dir,
                                        const gf_var_info *vars, int n_vars, gf_nc_writer **w)
{
    gf_scales scales;
    GF_TRY(gf_groups_compute(ctx, in, &scales));
    meta.scales = &scales;
    meta.fluid_model = "none";
    meta.fluid_model_reason = "method: continuum (dry)";
    meta.stages = "continuum";
    char path[4200];
    snprintf(path, sizeof path, "%s/diagnostics.nc", dir);
    return gf_nc_diagnostics_open(ctx, path, &meta, vars, n_vars, w);
}

gf_status gf_continuum_run_until(gf_ctx *ctx, gf_continuum *s, double t_end_s, double every_s, gf_nc_writer *w,
                                 gf_continuum_sampler sample, void *user, volatile int *interrupt, const char *what,
                                 long *steps)
{
    double next = 0.0, values[16];
    while (1) {
        double t = gf_continuum_time(s);
        if (w && t >= next - 1e-9 * every_s) {
            sample(s, user, values);
            GF_TRY(gf_nc_diagnostics_append(w, t, values));
            next += every_s;
        }
        if (t >= t_end_s - 1e-9 * every_s)
            return GF_OK;
        if (interrupt && *interrupt)
            return GF_FAIL(ctx, GF_ERR_INTERRUPTED, "%s interrupted at t = %g s", what, t);
        GF_TRY(gf_continuum_step(s));
        ++*steps;
    }
}
