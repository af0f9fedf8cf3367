/*
 * Stage regime: time scales and flow-regime label of a run.
 *
 * Reference scales T_v, T_i, T_ff, T_visq, T0 come from gf_groups_compute on
 * the run's attributes (never recomputed here). The flow time T and the rule:
 *
 * Avalanche (Izard 2014 §4.1.4.2, eq. 4.1, 4.12):
 *   T = V_g / Q̄_g, with Q̄_g the steady mean of diagnostics grain_flow_rate
 *   (same MSER-5 window as stage flow_rate) and V_g the solid volume of the
 *   mobile grains: the global attribute grain_volume_m3 if the engine writes
 *   one, else Σ π d³/6 over the non-glued grains of particles.nc, else (runs
 *   written without trajectories) φ̄ L W h̄ from the steady means of
 *   diagnostics bed_packing_fraction and bed_height, with L and W from the
 *   scene_param_length_over_D and scene_param_width_over_D attributes (the
 *   thesis's 𝒱_g = L W h̄_g, eq. 4.12, with the solid fraction that Q_g
 *   carries; the bed fraction excludes the base and surface layers, so this
 *   estimate is good to a few percent). Since
 *   Q_g = (1/L) ∫ α U dV, T = L ∫α dV / ∫ αU dV = L / Ū_g: the time the mean
 *   grain takes to cross the periodic cell, as in the thesis. Label by
 *   gf_regime_classify (nearest scale in decades; transitional rule).
 *   T_over_Tv_boyer: the T/T_v that Boyer, Guazzelli & Pouliquen (2011)'s
 *   μ(I_v) gives the run's own steady bed depth and drive (gf_boyer.h), the
 *   dense-suspension reference for the viscous plateau.
 *
 * Column collapse: Bougouin & Lacaze, PRF 3, 064305 (2018) classify immersed
 *   collapses from the collapse duration in units of T_ff, T_v and T_i
 *   (secondary source: verify). Here the duration is the
 *   time to rest t_rest (front within D/2 of its final position, from
 *   diagnostics front_position), and the per-diameter scales of gf_groups
 *   are carried over the column height H0: travel at the limit speed for the
 *   viscous and inertial scales (D/T_v is the Stokes speed Δρ g D²/(18 η),
 *   D/T_i = sqrt(2 Δρ g D / ρ_f) the inertial limit speed of Courrech du Pont
 *   et al. 2003), so T_v,H0 = (H0/D) T_v and T_i,H0 = (H0/D) T_i; uniformly
 *   accelerated fall for the free-fall scale, T_ff,H0 = sqrt(H0/D) T_ff
 *   = sqrt(2 ρ_p H0 / (Δρ g)). T = t_rest is labelled against these three
 *   with gf_regime_classify (g_eff = g: vertical fall). T_over_T* columns
 *   hold t_rest over the H0 scales for a collapse. Also reported: the
 *   maximum front speed and its uncertainty, the steepest least-squares
 *   line over the shortest windows that resolve it to 10 % given that
 *   front_position moves in bins of D (gf_post_rate.h; NaN when the record
 *   cannot resolve it, e.g. a front that advances a few D), also in units of
 *   R0/T_visq (the thesis's viscous master line is ≈ 1e-4, §5.4), and t_rest
 *   in units of T_visq and T0.
 */
#include <math.h>
#include <stdlib.h>

#include "core/gf_boyer.h"
#include "stages/gf_post_rate.h"
#include "stages/gf_post_stats.h"
#include "stages/gf_regime.h"
#include "stages/gf_stage_util.h"

static void put_labels(gf_post_row *row, double T, const gf_scales *sc, const gf_regime_result *res)
{
    gf_post_row_set_text(row, "regime", gf_regime_name(res->label));
    gf_post_row_set_text(row, "regime_nearest", gf_regime_name(res->nearest));
    gf_post_row_set(row, "regime_confidence", res->confidence_decades);
    gf_post_row_set(row, "T_s", T);
    gf_post_row_set(row, "T_over_Tv", sc->t_viscous_s > 0 ? T / sc->t_viscous_s : NAN);
    gf_post_row_set(row, "T_over_Ti", sc->t_inertial_s > 0 ? T / sc->t_inertial_s : NAN);
    gf_post_row_set(row, "T_over_Tff", sc->t_freefall_s > 0 ? T / sc->t_freefall_s : NAN);
}

/* Mean of diagnostics variable `name` over the samples from i0 on; NaN if it is missing or shorter. */
static double steady_mean(gf_ctx *ctx, const gf_ncr *d, const char *name, size_t i0)
{
    double *v = NULL, m = NAN, sd;
    size_t n = 0;
    if (gf_ncr_has_var(d, name) && gf_ncr_var_1d(ctx, d, name, &v, &n) == GF_OK && i0 < n)
        gf_stats_mean_std(v + i0, n - i0, &m, &sd);
    free(v);
    return m;
}

/* T/T_v that Boyer et al. (2011)'s μ(I_v) gives this run's bed (core/gf_boyer.h): its steady mean depth
 * h̄ (bed_height), cell length, incline and the grains' downslope drive (ρ_p/Δρ)^n of the scene's
 * slope_gravity_exponent n (scenes/gf_scene_avalanche.c). NaN for a dry run or when anything is missing. */
static double boyer_T_over_Tv(const gf_ncr *d, double h)
{
    const double D = gf_ncr_att_double_or(d, "grain_diameter_m", NAN);
    const double L = gf_ncr_att_double_or(d, "scene_param_length_over_D", NAN);
    const double th = gf_ncr_att_double_or(d, "incline_deg", NAN) * M_PI / 180.0;
    const double n = gf_ncr_att_double_or(d, "scene_param_slope_gravity_exponent", 0.0);
    const double rp = gf_ncr_att_double_or(d, "grain_density_kg_m3", NAN);
    const double rf = gf_ncr_att_double_or(d, "fluid_density_kg_m3", 0.0);
    if (!(rf > 0.0 && rf < rp && h > 0.0))
        return NAN;
    return gf_boyer_layer_T_over_Tv(&GF_BOYER_2011, tan(th) * pow(rp / (rp - rf), n), tan(th), h / D, L, 0);
}

/* φ̄ L W h̄ (NaN if anything is missing). */
static double bed_volume(const gf_ncr *d, double h, double phi)
{
    const double D = gf_ncr_att_double_or(d, "grain_diameter_m", NAN);
    const double L = gf_ncr_att_double_or(d, "scene_param_length_over_D", NAN) * D;
    const double W = gf_ncr_att_double_or(d, "scene_param_width_over_D", NAN) * D;
    return phi * L * W * h;
}

static gf_status avalanche(gf_ctx *ctx, const gf_stage_in *in, const gf_ncr *d, const gf_scales *sc, gf_post_row *row)
{
    double *t = NULL, *q = NULL;
    size_t nt, nq;
    gf_status st = gf_ncr_var_1d(ctx, d, "time", &t, &nt);
    if (st == GF_OK)
        st = gf_ncr_var_1d(ctx, d, "grain_flow_rate", &q, &nq);
    gf_steady s = {0};
    if (st == GF_OK) {
        gf_stats_steady(t, q, nq < nt ? nq : nt, &s);
        if (!s.ok || !(s.mean > 0.0))
            st = GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "not determined: %s: no steady positive grain flow rate (mean %g m3/s)", d->path,
                         s.mean);
    }
    free(t);
    free(q);
    if (st != GF_OK)
        return st;
    const double h = steady_mean(ctx, d, "bed_height", s.i_start);
    double Vg = gf_ncr_att_double_or(d, "grain_volume_m3", NAN);
    if (!(Vg > 0.0) && !gf_stage_has_file(in, "particles.nc")) {
        Vg = bed_volume(d, h, steady_mean(ctx, d, "bed_packing_fraction", s.i_start));
        if (!(Vg > 0.0))
            return GF_FAIL(ctx, GF_ERR_IO, "%s: no particles.nc, and no bed_height, bed_packing_fraction and "
                                           "scene_param_length_over_D/width_over_D to estimate the grain volume",
                           d->path);
    }
    if (!(Vg > 0.0)) {
        gf_ncr p;
        GF_TRY(gf_stage_open(ctx, in, "particles.nc", &p));
        gf_grains_info g;
        st = gf_stage_grains(ctx, &p, 0, &g);
        gf_ncr_close(&p);
        if (st != GF_OK)
            return st;
        Vg = g.solid_volume_m3;
    }
    const double T = Vg / s.mean;
    gf_regime_result res;
    GF_TRY(gf_regime_classify(ctx, T, sc, &res));
    put_labels(row, T, sc, &res);
    gf_post_row_set(row, "Vg_m3", Vg);
    gf_post_row_set(row, "T_over_Tv_boyer", boyer_T_over_Tv(d, h));
    return GF_OK;
}

static gf_status collapse(gf_ctx *ctx, const gf_ncr *d, const gf_groups_input *gi, const gf_scales *sc,
                          gf_post_row *row)
{
    double *t = NULL, *x = NULL;
    size_t nt, nx;
    gf_status st = gf_ncr_var_1d(ctx, d, "time", &t, &nt);
    if (st == GF_OK)
        st = gf_ncr_var_1d(ctx, d, "front_position", &x, &nx);
    if (st == GF_OK && (nx != nt || nt < 3))
        st = GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "not determined: %s: front_position has %zu samples (time %zu), 3 or more needed", d->path, nx,
                     nt);
    double t_rest = NAN;
    gf_rate_estimate umax = {NAN, NAN, NAN, NAN, 0};
    if (st == GF_OK) {
        umax = gf_rate_max_resolved(t, x, nt, gi->diameter_m, 0.1);
        t_rest = gf_stats_settle_time(t, x, nt, 0.5 * gi->diameter_m);
    }
    free(t);
    free(x);
    if (st != GF_OK)
        return st;
    if (!(gi->column_height_m > 0.0))
        return GF_FAIL(ctx, GF_ERR_IO, "%s: column_height_m (H0) is needed for the collapse scales", d->path);
    if (!(t_rest > 0.0))
        return GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "not determined: %s: no positive time to rest (t_rest = %g s)", d->path, t_rest);
    const double h = gi->column_height_m / gi->diameter_m;
    gf_scales sH = *sc;
    sH.t_viscous_s = sc->t_viscous_s * h;
    sH.t_inertial_s = sc->t_inertial_s * h;
    sH.t_freefall_s = sc->t_freefall_s * sqrt(h);
    gf_regime_result res;
    GF_TRY(gf_regime_classify(ctx, t_rest, &sH, &res));
    put_labels(row, t_rest, &sH, &res);
    gf_post_row_set(row, "Ufront_max_m_s", umax.rate);
    gf_post_row_set(row, "Ufront_max_err_m_s", umax.sigma);
    if (sc->t_visq_s > 0.0 && gi->column_length_m > 0.0) {
        gf_post_row_set(row, "Ufront_max_over_R0_per_Tvisq", umax.rate * sc->t_visq_s / gi->column_length_m);
        gf_post_row_set(row, "t_rest_over_Tvisq", t_rest / sc->t_visq_s);
    }
    if (sc->t0_H_s > 0.0)
        gf_post_row_set(row, "t_rest_over_T0", t_rest / sc->t0_H_s);
    return GF_OK;
}

gf_status gf_stage_regime(gf_ctx *ctx, const gf_stage_in *in, const gf_stage_opts *opts, gf_stage_out *out)
{
    (void)opts;
    if (!gf_stage_has_file(in, "diagnostics.nc"))
        return GF_ERR_UNSUPPORTED;
    gf_ncr d;
    GF_TRY(gf_stage_open(ctx, in, "diagnostics.nc", &d));
    gf_groups_input gi;
    gf_scales sc;
    gf_status st = gf_stage_scales(ctx, &d, in, &gi, &sc);
    if (st == GF_OK) {
        gf_post_row *row = out->row;
        gf_post_row_set(row, "Tv_s", sc.t_viscous_s);
        gf_post_row_set(row, "Ti_s", sc.t_inertial_s);
        gf_post_row_set(row, "Tff_s", sc.t_freefall_s);
        gf_post_row_set(row, "Tvisq_s", sc.t_visq_s);
        gf_post_row_set(row, "St_groups", sc.stokes_St);
        gf_post_row_set(row, "r_groups", sc.density_ratio_r);
        if (gf_ncr_has_var(&d, "grain_flow_rate"))
            st = avalanche(ctx, in, &d, &sc, row);
        else if (gf_ncr_has_var(&d, "front_position"))
            st = collapse(ctx, &d, &gi, &sc, row);
        else
            st = GF_ERR_UNSUPPORTED;
    }
    gf_ncr_close(&d);
    return st;
}
