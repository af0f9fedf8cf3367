/*
 * Stage flow_rate: grain and fluid flow rates of an avalanche (Izard 2014
 * §4.1.3, eq. 4.11): Q_g(t) = (1/L) ∫ α U dV and
 * Q_f(t) = (1/L) ∫ (1 − α) U dV, written by the engine as diagnostics.nc
 * grain_flow_rate and fluid_flow_rate (m3 s-1).
 *
 * Steady state: MSER-5 truncation (White 1997; gf_post_stats.h) on Q_g(t):
 * t_steady_s is the first time of the window that minimises the marginal
 * standard error, i.e. after which the series fluctuates about one mean with
 * no transient left to bias it. The time average Q̄_g over [t_steady, end]
 * (eq. 4.8) gets its standard error from block averaging (Flyvbjerg &
 * Petersen 1989), which accounts for the correlation of successive samples.
 * Qg_drift_rel (line-fit change over the window / mean) flags a window that
 * still creeps (the thesis notes φ creeps by 1.5 % while Q_g is steady).
 * Q_f is averaged over the same window.
 *
 * Scene silo: the discharge rate Q(t) of the orifice, read the same way
 * (stages/gf_silo_flow.h).
 */
#include <math.h>
#include <stdlib.h>

#include "stages/gf_post_stats.h"
#include "stages/gf_silo_flow.h"
#include "stages/gf_stage_util.h"

gf_status gf_stage_flow_rate(gf_ctx *ctx, const gf_stage_in *in, const gf_stage_opts *opts, gf_stage_out *out)
{
    (void)opts;
    if (gf_stage_has_var(in, "diagnostics.nc", "discharge_rate"))
        return gf_silo_flow_rate(ctx, in, out);   /* a discharge through an orifice */
    /* a flowing layer in a periodic cell: whatever scene wrote Q_g */
    if (!gf_stage_has_file(in, "diagnostics.nc"))
        return GF_ERR_UNSUPPORTED;
    gf_ncr f;
    GF_TRY(gf_stage_open(ctx, in, "diagnostics.nc", &f));
    if (!gf_ncr_has_var(&f, "grain_flow_rate")) {
        gf_ncr_close(&f);
        return GF_ERR_UNSUPPORTED;   /* not a flowing-layer scene */
    }
    double *t = NULL, *qg = NULL, *qf = NULL;
    size_t nt = 0, nq = 0, nf = 0;
    gf_status st = gf_ncr_var_1d(ctx, &f, "time", &t, &nt);
    if (st == GF_OK)
        st = gf_ncr_var_1d(ctx, &f, "grain_flow_rate", &qg, &nq);
    if (st == GF_OK && gf_ncr_has_var(&f, "fluid_flow_rate"))
        st = gf_ncr_var_1d(ctx, &f, "fluid_flow_rate", &qf, &nf);
    if (st == GF_OK && nq != nt)
        st = GF_FAIL(ctx, GF_ERR_IO, "%s: grain_flow_rate has %zu samples, time %zu", f.path, nq, nt);
    gf_steady s;
    if (st == GF_OK) {
        gf_stats_steady(t, qg, nt, &s);
        if (!s.ok)
            st = GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "not determined: %s: grain_flow_rate has %zu samples, at "
                                                  "least 10 needed for a steady window", f.path, nt);
    }
    if (st == GF_OK) {
        gf_post_row *row = out->row;
        gf_post_row_set(row, "Qg_mean", s.mean);
        gf_post_row_set(row, "Qg_std", s.std);
        gf_post_row_set(row, "Qg_sem", s.sem);
        gf_post_row_set(row, "Qg_drift_rel", s.drift_rel);
        gf_post_row_set(row, "t_steady_s", s.t_start_s);
        gf_post_row_set(row, "t_end_s", t[nt - 1]);
        if (qf && nf == nt) {
            double m, sd;
            gf_stats_mean_std(qf + s.i_start, nt - s.i_start, &m, &sd);
            gf_post_row_set(row, "Qf_mean", m);
        }
    }
    free(t);
    free(qg);
    free(qf);
    gf_ncr_close(&f);
    return st;
}
