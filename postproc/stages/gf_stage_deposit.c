/*
 * Stage deposit: final heap of a column collapse and the front history
 * (Izard 2014 §5.3–5.5), from the grains of particles.nc.
 *
 * Final frame -> gf_deposit_envelope (method in gf_deposit.h): R_inf from
 * the back wall, H_inf, (R_inf − R0)/R0 and H_inf/R0 with R0 the
 * column_length_m attribute, the height at the back wall over H0 (whether
 * the column's top survived), the shape (triangle / trapezoid), the flank
 * angle and the heap's cross-section, also over R0 H0 (Phi_i / Phi_deposit).
 * Every frame -> the heap front x_front(t) (same binning, so a grain that
 * rolls ahead does not count); if particles.nc holds a single frame,
 * diagnostics front_position is used instead. The maximum front speed is
 * the steepest least-squares line over the shortest windows that resolve
 * it to 10 % given the toe's frame-to-frame scatter (gf_post_rate.h; a
 * single-frame file's front_position is in bins of D, which the estimate
 * allows for), with its uncertainty, NaN when unresolved; the time to rest is the earliest time after which the front stays
 * within D/2 of its final position.
 * Writes post_deposit.nc: time, front_position, (x_front − R0)/R0, and the
 * final envelope deposit_height(x_bin).
 * Both methods (grains and continuum): the last record of the diagnostics'
 * front_position, deposit_extent_1D and deposit_extent_2D, as (x − R0)/R0,
 * the measures the engine makes the same way for the two (solid height at
 * least D/4; material height, the solid height over the column's packing, at
 * least 1 D and 2 D: gf_scene_column_collapse.c), so that a campaign of
 * `method: dem` and `method: continuum` runs compares them column by column.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stages/gf_deposit.h"
#include "stages/gf_post_rate.h"
#include "stages/gf_post_stats.h"
#include "stages/gf_stage_util.h"

/*
 * A run without grains (method: continuum, engine/continuum/gf_continuum_collapse.h)
 * has its heap only as the diagnostics' front_position and deposit_height: the
 * run-out, the height and the front's history come from those; the shape columns
 * stay empty.
 */
static gf_status deposit_from_diagnostics(gf_ctx *ctx, const gf_stage_in *in, gf_stage_out *out)
{
    gf_ncr d;
    GF_TRY(gf_stage_open(ctx, in, "diagnostics.nc", &d));
    double R0, H0, D = gf_ncr_att_double_or(&d, "grain_diameter_m", NAN);
    gf_stage_column(&d, &R0, &H0);
    double *t = NULL, *x = NULL, *h = NULL;
    size_t nt = 0, nx = 0, nh = 0;
    gf_status st = gf_ncr_var_1d(ctx, &d, "time", &t, &nt);
    if (st == GF_OK) st = gf_ncr_var_1d(ctx, &d, "front_position", &x, &nx);
    if (st == GF_OK) st = gf_ncr_var_1d(ctx, &d, "deposit_height", &h, &nh);
    if (st == GF_OK && (nx != nt || nh != nt || nt == 0))
        st = GF_FAIL(ctx, GF_ERR_IO, "%s: front_position, deposit_height and time differ in length", d.path);
    gf_ncr_close(&d);
    if (st == GF_OK) {
        gf_post_row *row = out->row;
        double R = x[nt - 1], H = h[nt - 1];
        gf_post_row_set(row, "R_inf_m", R);
        gf_post_row_set(row, "H_inf_m", H);
        if (R0 > 0.0) {
            gf_post_row_set(row, "R_inf_over_R0", R / R0);
            gf_post_row_set(row, "runout_norm", (R - R0) / R0);
            gf_post_row_set(row, "H_inf_over_R0", H / R0);
        }
        if (nt >= 3) {
            /* the continuum's front is interpolated in the volume fraction: a continuous series (q = 0) */
            gf_rate_estimate u = gf_rate_max_resolved(t, x, nt, 0.0, 0.1);
            gf_post_row_set(row, "Ufront_particles_max_m_s", u.rate);
            gf_post_row_set(row, "Ufront_particles_max_err_m_s", u.sigma);
            gf_post_row_set(row, "t_front_max_speed_s", u.t_at);
            if (D > 0.0)
                gf_post_row_set(row, "t_rest_s", gf_stats_settle_time(t, x, nt, 0.5 * D));
            if (R0 > 0.0 && R > R0)
                gf_post_row_set(row, "t_half_runout_s", gf_stats_first_reaching(t, x, nt, R0 + 0.5 * (R - R0)));
        }
    }
    free(t), free(x), free(h);
    return st;
}

/* front_D4_norm, extent_1D_norm, extent_2D_norm from the diagnostics' last record, when it has them. */
static void extents_from_diagnostics(const gf_stage_in *in, gf_post_row *row)
{
    static const char *const var[3] = {"front_position", "deposit_extent_1D", "deposit_extent_2D"};
    static const char *const col[3] = {"front_D4_norm", "extent_1D_norm", "extent_2D_norm"};
    gf_ctx c = {0};
    gf_ncr d;
    if (!gf_stage_has_file(in, "diagnostics.nc") || gf_stage_open(&c, in, "diagnostics.nc", &d) != GF_OK)
        return;
    double R0, H0;
    gf_stage_column(&d, &R0, &H0);
    for (int k = 0; k < 3 && R0 > 0.0; ++k) {
        double *x = NULL;
        size_t n = 0;
        if (gf_ncr_has_var(&d, var[k]) && gf_ncr_var_1d(&c, &d, var[k], &x, &n) == GF_OK && n > 0)
            gf_post_row_set(row, col[k], (x[n - 1] - R0) / R0);
        free(x);
    }
    gf_ncr_close(&d);
}

/* 1 when diagnostics.nc says it was written by the continuum (its "stages"
 * attribute): the heap is then its deposit_height and front_position. A grain
 * run without particles.nc (output.particles: false) is not one: its heap's
 * shape is not computed, and the note says why. */
static int heap_in_diagnostics(const gf_stage_in *in)
{
    if (!gf_stage_has_file(in, "diagnostics.nc"))
        return 0;
    gf_ctx c = {0};
    gf_ncr d;
    if (gf_stage_open(&c, in, "diagnostics.nc", &d) != GF_OK)
        return 0;
    char stages[64] = "";
    gf_ncr_att_text(NULL, &d, "stages", stages, sizeof stages);
    const int continuum = strcmp(stages, "continuum") == 0 && gf_ncr_has_var(&d, "deposit_height");
    gf_ncr_close(&d);
    return continuum;
}

gf_status gf_stage_deposit(gf_ctx *ctx, const gf_stage_in *in, const gf_stage_opts *opts, gf_stage_out *out)
{
    if (!gf_stage_is_column(in))
        return GF_ERR_UNSUPPORTED;   /* only a released column leaves a heap against a back wall */
    extents_from_diagnostics(in, out->row);
    if (!gf_stage_has_file(in, "particles.nc") && heap_in_diagnostics(in))
        return deposit_from_diagnostics(ctx, in, out);
    gf_ncr p;
    gf_grains_info g;
    double D;
    GF_TRY(gf_stage_open_grains(ctx, in, &p, &g, &D));
    gf_status st = GF_OK;
    double R0, H0;
    gf_stage_column(&p, &R0, &H0);
    const size_t n = g.n_all, nt = g.n_time;
    double *x = malloc((n ? n : 1) * sizeof *x), *y = malloc((n ? n : 1) * sizeof *y);
    double *t = NULL, *front = calloc(nt ? nt : 1, sizeof *front);
    size_t ntt = 0;
    gf_deposit dep = {0};
    if (!x || !y || !front)
        st = GF_FAIL(ctx, GF_ERR_NOMEM, "deposit: out of memory");
    if (st == GF_OK && nt == 0)
        st = GF_FAIL(ctx, GF_ERR_IO, "%s: no frame", p.path);
    if (st == GF_OK)
        st = gf_ncr_var_1d(ctx, &p, "time", &t, &ntt);
    for (size_t k = 0; st == GF_OK && k < nt; ++k) {
        st = gf_ncr_var_2d_col(ctx, &p, "x", k, x, n);
        if (st == GF_OK)
            st = gf_ncr_var_2d_col(ctx, &p, "y", k, y, n);
        if (st == GF_OK)
            front[k] = gf_deposit_front(x, y, g.radius, g.mobile, n, D);
    }
    if (st == GF_OK)   /* x, y hold the final frame */
        st = gf_deposit_envelope(ctx, x, y, g.radius, g.mobile, n, D, &dep);
    gf_ncr_close(&p);
    const double *ft = t, *fx = front;
    size_t fn = nt;
    double *dt = NULL, *dx = NULL;
    if (st == GF_OK && nt < 2 && gf_stage_has_file(in, "diagnostics.nc")) {
        gf_ncr d;
        size_t n1 = 0, n2 = 0;
        if (gf_stage_open(ctx, in, "diagnostics.nc", &d) == GF_OK) {
            if (gf_ncr_has_var(&d, "front_position") && gf_ncr_var_1d(ctx, &d, "time", &dt, &n1) == GF_OK &&
                gf_ncr_var_1d(ctx, &d, "front_position", &dx, &n2) == GF_OK && n1 == n2) {
                ft = dt;
                fx = dx;
                fn = n1;
            }
            gf_ncr_close(&d);
        }
    }
    if (st == GF_OK) {
        gf_post_row *row = out->row;
        gf_post_row_set(row, "R_inf_m", dep.runout_m);
        gf_post_row_set(row, "H_inf_m", dep.height_m);
        if (R0 > 0.0) {
            gf_post_row_set(row, "R_inf_over_R0", dep.runout_m / R0);
            gf_post_row_set(row, "runout_norm", (dep.runout_m - R0) / R0);
            gf_post_row_set(row, "H_inf_over_R0", dep.height_m / R0);
        }
        if (H0 > 0.0)
            gf_post_row_set(row, "H_back_over_H0", dep.back_height_m / H0);
        gf_post_row_set(row, "deposit_area_m2", dep.area_m2);
        if (R0 > 0.0 && H0 > 0.0)
            gf_post_row_set(row, "deposit_area_over_column", dep.area_m2 / (R0 * H0));
        gf_post_row_set_text(row, "deposit_shape",
                             dep.trapezoid < 0 ? "undetermined" : dep.trapezoid ? "trapezoid" : "triangle");
        gf_post_row_set(row, "flank_angle_deg", dep.flank_angle_deg);
        gf_post_row_set(row, "plateau_length_m", dep.plateau_length_m);
        if (fn >= 3) {
            gf_rate_estimate u = gf_rate_max_resolved(ft, fx, fn, ft == t ? 0.0 : D, 0.1);
            gf_post_row_set(row, "Ufront_particles_max_m_s", u.rate);
            gf_post_row_set(row, "Ufront_particles_max_err_m_s", u.sigma);
            gf_post_row_set(row, "t_front_max_speed_s", u.t_at);
            gf_post_row_set(row, "t_rest_s", gf_stats_settle_time(ft, fx, fn, 0.5 * D));
            if (R0 > 0.0 && dep.runout_m > R0)
                gf_post_row_set(row, "t_half_runout_s",
                                gf_stats_first_reaching(ft, fx, fn, R0 + 0.5 * (dep.runout_m - R0)));
        }
    }
    if (st == GF_OK && opts && opts->write_series) {
        double *fnorm = malloc((fn ? fn : 1) * sizeof *fnorm), *xb = malloc((dep.n_bins + 1) * sizeof *xb);
        for (size_t k = 0; fnorm && k < fn; ++k)
            fnorm[k] = R0 > 0.0 ? (fx[k] - R0) / R0 : NAN;
        for (size_t b = 0; xb && b < dep.n_bins; ++b)
            xb[b] = (b + 0.5) * dep.bin_m;
        const gf_postnc_dimension dims[] = {{"time", fn}, {"x_bin", dep.n_bins}};
        const gf_postnc_series vars[] = {
            {"time", 1, {0}, "s since 2000-01-01 00:00:00", "time", "time", ft},
            {"front_position", 1, {0}, "m", "front position from the back wall", NULL, fx},
            {"front_position_norm", 1, {0}, "1", "(x_front - R0)/R0", NULL, fnorm},
            {"x_bin", 1, {1}, "m", "bin centre from the back wall", NULL, xb},
            {"deposit_height", 1, {1}, "m", "final deposit surface height", NULL, dep.bin_height_m},
        };
        if (fnorm && xb)
            st = gf_postnc_write(ctx, in, "deposit", 1, dims, GF_POSTNC_COUNT(dims), vars, GF_POSTNC_COUNT(vars));
        else
            st = GF_FAIL(ctx, GF_ERR_NOMEM, "deposit: out of memory");
        free(fnorm);
        free(xb);
    }
    gf_deposit_free(&dep);
    gf_stage_grains_free(&g);
    free(x), free(y), free(t), free(front), free(dt), free(dx);
    return st;
}
