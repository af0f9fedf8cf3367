/*
 * Stage pore_pressure: basal excess pore pressure P_b(t) (pressure minus
 * hydrostatic) at the gauges of probes.nc (Izard 2014 §5.3–5.5;
 * Rondon, Pouliquen & Aussillous 2011).
 *
 * Per station: the minimum and maximum with their times; the dominant
 * extremum P_ext (larger |P|); the relaxation time, the earliest time after
 * the extremum from which |P| stays below 10 % of |P_ext| to the end of the
 * record (NaN if it never does); P normalised by Δρ g H0 (the thesis's
 * pressure scale, H0 = column_height_m). The summary row carries the
 * station the seed uses, x = 13 D under a collapsing column (nearest
 * station), else the first one. A dense column gives a negative P_ext
 * (dilatancy, suction), a loose one a positive P_ext (contraction).
 * Writes post_pore_pressure.nc: P_b/(Δρ g H0) per station and time, and the
 * per-station extrema.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stages/gf_stage_util.h"

typedef struct trace_stats {
    double pmin, pmax, tmin, tmax, pext, trelax;
} trace_stats;

static void trace(const double *t, const double *p, size_t n, trace_stats *s)
{
    size_t imin = 0, imax = 0;
    int any = 0;
    for (size_t k = 0; k < n; ++k) {
        if (!isfinite(p[k]))
            continue;
        if (!any || p[k] < p[imin])
            imin = k;
        if (!any || p[k] > p[imax])
            imax = k;
        any = 1;
    }
    s->pmin = s->pmax = s->tmin = s->tmax = s->pext = s->trelax = NAN;
    if (!any)
        return;
    s->pmin = p[imin], s->tmin = t[imin], s->pmax = p[imax], s->tmax = t[imax];
    const size_t iext = fabs(p[imin]) > fabs(p[imax]) ? imin : imax;
    s->pext = p[iext];
    const double band = 0.1 * fabs(s->pext);
    if (!(band > 0.0))
        return;
    size_t n_end = n;
    while (n_end > 0 && !isfinite(p[n_end - 1]))
        --n_end;
    if (n_end == 0 || fabs(p[n_end - 1]) >= band)
        return;   /* still above 10 % at the end: not relaxed */
    size_t k = n_end - 1;
    while (k > iext + 1 && fabs(p[k - 1]) < band)
        --k;
    s->trelax = t[k];
}

gf_status gf_stage_pore_pressure(gf_ctx *ctx, const gf_stage_in *in, const gf_stage_opts *opts, gf_stage_out *out)
{
    if (!gf_stage_has_file(in, "probes.nc"))
        return GF_ERR_UNSUPPORTED;   /* no gauges (dry run or no fluid tier with probes) */
    gf_ncr f;
    GF_TRY(gf_stage_open(ctx, in, "probes.nc", &f));
    double *t = NULL, *P = NULL, *xs = NULL;
    size_t nt = 0, ns = 0, n1 = 0, nx = 0;
    gf_status st = gf_ncr_var_1d(ctx, &f, "time", &t, &nt);
    if (st == GF_OK)
        st = gf_ncr_var_2d(ctx, &f, "excess_pore_pressure", &P, &ns, &n1);
    if (st == GF_OK && n1 != nt)
        st = GF_FAIL(ctx, GF_ERR_IO, "%s: excess_pore_pressure has %zu times, time %zu", f.path, n1, nt);
    if (st == GF_OK && ns == 0)
        st = GF_FAIL(ctx, GF_ERR_IO, "%s: no station", f.path);
    if (st == GF_OK)
        st = gf_ncr_var_1d(ctx, &f, "x", &xs, &nx);
    if (st == GF_OK && nx != ns)
        st = GF_FAIL(ctx, GF_ERR_IO, "%s: x has %zu stations, excess_pore_pressure %zu", f.path, nx, ns);
    const double D = gf_ncr_att_double_or(&f, "grain_diameter_m", NAN);
    const double rho_p = gf_ncr_att_double_or(&f, "grain_density_kg_m3", NAN);
    const double rho_f = gf_ncr_att_double_or(&f, "fluid_density_kg_m3", NAN);
    const double g = gf_ncr_att_double_or(&f, "gravity_m_s2", NAN);
    double R0, H0;
    gf_stage_column(&f, &R0, &H0);
    const double scale = (rho_p - rho_f) * g * H0;
    trace_stats *ts = NULL;
    size_t main_st = 0;
    if (st == GF_OK) {
        ts = calloc(ns, sizeof *ts);
        if (!ts)
            st = GF_FAIL(ctx, GF_ERR_NOMEM, "pore_pressure: out of memory");
    }
    if (st == GF_OK) {
        for (size_t s = 0; s < ns; ++s)
            trace(t, P + s * nt, nt, &ts[s]);
        if (gf_stage_is_column(in) && D > 0.0)
            for (size_t s = 1; s < ns; ++s)
                if (fabs(xs[s] - 13.0 * D) < fabs(xs[main_st] - 13.0 * D))
                    main_st = s;
        gf_post_row *row = out->row;
        char name[GF_ROW_TEXT_LEN];
        if (gf_ncr_char_row(NULL, &f, "station_name", main_st, name, sizeof name) != GF_OK)
            snprintf(name, sizeof name, "%zu", main_st);
        gf_post_row_set_text(row, "Pb_station", name);
        gf_post_row_set(row, "Pb_x_m", xs[main_st]);
        const trace_stats *m = &ts[main_st];
        gf_post_row_set(row, "Pb_min_Pa", m->pmin);
        gf_post_row_set(row, "Pb_max_Pa", m->pmax);
        gf_post_row_set(row, "t_Pb_min_s", m->tmin);
        gf_post_row_set(row, "t_Pb_max_s", m->tmax);
        gf_post_row_set(row, "Pb_ext_over_drho_g_H0", scale > 0.0 ? m->pext / scale : NAN);
        gf_post_row_set(row, "t_Pb_relax_s", m->trelax);
    }
    gf_ncr_close(&f);
    if (st == GF_OK && opts && opts->write_series) {
        double *pn = malloc(ns * nt * sizeof *pn + 1), *a = malloc(3 * ns * sizeof *a + 1);
        if (!pn || !a)
            st = GF_FAIL(ctx, GF_ERR_NOMEM, "pore_pressure: out of memory");
        for (size_t k = 0; st == GF_OK && k < ns * nt; ++k)
            pn[k] = scale > 0.0 ? P[k] / scale : NAN;
        for (size_t s = 0; st == GF_OK && s < ns; ++s) {
            a[s] = ts[s].pmin;
            a[ns + s] = ts[s].pmax;
            a[2 * ns + s] = ts[s].trelax;
        }
        if (st == GF_OK) {
            const gf_postnc_dimension dims[] = {{"station", ns}, {"time", nt}};
            const gf_postnc_series vars[] = {
                {"time", 1, {1}, "s since 2000-01-01 00:00:00", "time", "time", t},
                {"x", 1, {0}, "m", "gauge position x", NULL, xs},
                {"excess_pore_pressure_norm", 2, {0, 1}, "1", "basal excess pore pressure over drho g H0", NULL, pn},
                {"excess_pore_pressure_min", 1, {0}, "Pa", "minimum excess pore pressure", NULL, a},
                {"excess_pore_pressure_max", 1, {0}, "Pa", "maximum excess pore pressure", NULL, a + ns},
                {"relaxation_time", 1, {0}, "s", "time after which |P| stays below 10 % of its extremum", NULL,
                 a + 2 * ns},
            };
            st = gf_postnc_write(ctx, in, "pore_pressure", 1, dims, GF_POSTNC_COUNT(dims), vars, GF_POSTNC_COUNT(vars));
        }
        free(pn);
        free(a);
    }
    free(ts), free(t), free(P), free(xs);
    return st;
}
