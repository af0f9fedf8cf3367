/*
 * Stage energy: horizontal kinetic energy per grain, E_cx(t) = (1/N_g)
 * Σ ½ m_i u_i² (Izard 2014 §5.3, printed as a sum but described "per grain"),
 * written by the engine as diagnostics ecx_per_grain, scaled by m g D with m
 * the mean mobile-grain mass (ρ_p × mean of π d³/6 over the non-glued grains
 * of particles.nc; ρ_p π D³/6 from the attributes if particles.nc is absent).
 * Reports E_cx^max/(m g D) (Table 5.1: 0.023, 0.082, 0.452 for a = 0.5, 1,
 * 1.5) and the time of the maximum. Writes post_energy.nc: E_cx/(m g D)(t).
 */
#include <math.h>
#include <stdlib.h>

#include "stages/gf_stage_util.h"

gf_status gf_stage_energy(gf_ctx *ctx, const gf_stage_in *in, const gf_stage_opts *opts, gf_stage_out *out)
{
    if (!gf_stage_has_file(in, "diagnostics.nc"))
        return GF_ERR_UNSUPPORTED;
    gf_ncr d;
    GF_TRY(gf_stage_open(ctx, in, "diagnostics.nc", &d));
    double *t = NULL, *e = NULL;
    size_t nt = 0, ne = 0;
    if (!gf_ncr_has_var(&d, "ecx_per_grain") && !gf_stage_has_file(in, "particles.nc")) {
        gf_ncr_close(&d);
        return GF_ERR_UNSUPPORTED;  /* no grains (method: continuum): no grain energy */
    }
    gf_status st = gf_ncr_var_1d(ctx, &d, "time", &t, &nt);
    if (st == GF_OK)
        st = gf_ncr_var_1d(ctx, &d, "ecx_per_grain", &e, &ne);
    if (st == GF_OK && (ne != nt || nt == 0))
        st = GF_FAIL(ctx, GF_ERR_IO, "%s: ecx_per_grain has %zu samples, time %zu", d.path, ne, nt);
    double rho_p = NAN, D = NAN, g = NAN;
    if (st == GF_OK) st = gf_ncr_att_double(ctx, &d, "grain_density_kg_m3", &rho_p);
    if (st == GF_OK) st = gf_ncr_att_double(ctx, &d, "grain_diameter_m", &D);
    if (st == GF_OK) st = gf_ncr_att_double(ctx, &d, "gravity_m_s2", &g);
    gf_ncr_close(&d);
    double vol = M_PI / 6.0 * D * D * D;
    if (st == GF_OK && gf_stage_has_file(in, "particles.nc")) {
        gf_ncr p;
        gf_grains_info gi;
        st = gf_stage_open(ctx, in, "particles.nc", &p);
        if (st == GF_OK) {
            st = gf_stage_grains(ctx, &p, 0, &gi);
            gf_ncr_close(&p);
            if (st == GF_OK)
                vol = gi.mean_volume_m3;
        }
    }
    const double m = rho_p * vol, scale = m * g * D;
    if (st == GF_OK && !(scale > 0.0))
        st = GF_FAIL(ctx, GF_ERR_NUMERIC, "%s: m g D = %g J is not positive", d.path, scale);
    if (st == GF_OK) {
        size_t imax = nt;
        for (size_t k = 0; k < nt; ++k)
            if (isfinite(e[k]) && (imax == nt || e[k] > e[imax]))
                imax = k;
        gf_post_row_set(out->row, "grain_mass_kg", m);
        gf_post_row_set(out->row, "Ecx_max_over_mgD", imax < nt ? e[imax] / scale : NAN);
        gf_post_row_set(out->row, "t_Ecx_max_s", imax < nt ? t[imax] : NAN);
        for (size_t k = 0; k < nt; ++k)
            e[k] /= scale;
    }
    if (st == GF_OK && opts && opts->write_series) {
        const gf_postnc_dimension dims[] = {{"time", nt}};
        const gf_postnc_series vars[] = {
            {"time", 1, {0}, "s since 2000-01-01 00:00:00", "time", "time", t},
            {"ecx_over_mgD", 1, {0}, "1", "horizontal kinetic energy per grain over m g D", NULL, e},
        };
        st = gf_postnc_write(ctx, in, "energy", 1, dims, GF_POSTNC_COUNT(dims), vars, GF_POSTNC_COUNT(vars));
    }
    free(t), free(e);
    return st;
}
