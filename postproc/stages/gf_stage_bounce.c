/*
 * Stage bounce: the rebound of a sphere falling onto a wall in a viscous fluid
 * (Gondret, Lance & Petit, Phys. Fluids 14, 2002; Izard 2014 §3.1.3), from the
 * diagnostics a bounce writes: sphere_velocity_y (m s-1, positive upward, away
 * from the wall), gap_over_D (surface-to-wall gap / D) and time.
 *
 * Definitions of V_T, V_I, V_R, e = -V_R/V_I, eps = -V_R/V_T and the contact
 * time: stages/gf_bounce_measure.h. Two Stokes numbers, as the literature
 * uses both:
 *   bounce_St    = rho_p V_I D / (9 eta_f), the impact Stokes number of
 *                  Gondret et al. (2002) (also Breugem 2010; Kempe & Fröhlich 2012);
 *   bounce_St_T  = (rho_p + rho_f/2) V_T D / (9 eta_f), Izard 2014 eq. (3.19)
 *                  (terminal velocity, added mass C_M = 1/2).
 * bounce_V_m is the speed of the linear near-wall approach u_p = V_m delta_n/R
 * (Mongruel et al. 2010; gf_bounce_measure_approach), from records dense
 * enough near the wall (configs/approach_mongruel.yaml).
 * eps/eps_max uses the run's restitution attribute (the dry ε_max of the
 * contact law) and the contact time over t_c its t_contact_s attribute.
 *
 * The diagnostics are records every output.interval_nd: a contact shorter
 * than that interval is missed or unresolved, so a bounce campaign sets the
 * interval well below t_c (docs/resolved.md). A record where the sphere never
 * touched, did not rebound (below St ~ 10 it does not: physics, not an error)
 * or whose contact falls between two records keeps what was determined
 * (e = 0 when there was no rebound) and returns GF_ERR_UNSUPPORTED with a
 * "not determined: ..." message for the row's notes.
 */
#include <math.h>
#include <stdlib.h>

#include "stages/gf_bounce_measure.h"
#include "stages/gf_stage_util.h"

typedef struct bounce_series {
    double *t, *v, *gap;
    size_t n;
} bounce_series;

static gf_status read_series(gf_ctx *ctx, gf_ncr *f, double D, bounce_series *s)
{
    size_t nv = 0, ng = 0;
    GF_TRY(gf_ncr_var_1d(ctx, f, "time", &s->t, &s->n));
    GF_TRY(gf_ncr_var_1d(ctx, f, "sphere_velocity_y", &s->v, &nv));
    GF_TRY(gf_ncr_var_1d(ctx, f, "gap_over_D", &s->gap, &ng));
    if (nv != s->n || ng != s->n)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: sphere_velocity_y has %zu samples, gap_over_D %zu, time %zu", f->path,
                       nv, ng, s->n);
    for (size_t k = 0; k < s->n; ++k)
        s->gap[k] *= D;
    return GF_OK;
}

static void set_if(gf_post_row *row, const char *name, double x)
{
    if (isfinite(x))
        gf_post_row_set(row, name, x);
}

/* V_m of the linear near-wall approach (gf_bounce_measure_approach): gaps below 0.06 R, window 5 % flat,
 * the settings of Mongruel et al.'s (2010) comparison in docs/resolved.md. */
static void report_approach(const bounce_series *s, double R, gf_post_row *row)
{
    gf_bounce_approach a;
    gf_bounce_measure_approach(s->v, s->gap, s->n, R, 0.06, 0.05, &a);
    set_if(row, "bounce_V_m", a.V_m);
}

static gf_status report(gf_ctx *ctx, const gf_bounce *b, const double *att, gf_post_row *row, size_t n)
{
    const double D = att[0], rho_p = att[1], rho_f = att[2], eta = att[3], eps_max = att[4], tc = att[5];
    set_if(row, "bounce_V_T", b->V_T);
    set_if(row, "bounce_St_T", (rho_p + 0.5 * rho_f) * b->V_T * D / (9.0 * eta));
    if (!b->touched)
        return GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "not determined: the sphere never touched the wall in %zu records "
                                                "(a contact shorter than output.interval_nd may fall between two)", n);
    set_if(row, "bounce_V_I", b->V_I);
    set_if(row, "bounce_V_R", b->V_R);
    set_if(row, "bounce_e", b->e);
    set_if(row, "bounce_eps", b->eps);
    if (eps_max > 0.0)
        set_if(row, "bounce_eps_over_eps_max", b->eps / eps_max);
    set_if(row, "bounce_St", rho_p * b->V_I * D / (9.0 * eta));
    set_if(row, "bounce_t_impact_s", b->t_in_s);
    set_if(row, "bounce_contact_s", b->contact_s);
    if (tc > 0.0)
        set_if(row, "bounce_contact_over_tc", b->contact_s / tc);
    if (!b->rebounded)
        return GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "not determined: no rebound (e = 0), the sphere stayed on the wall");
    if (!b->left)
        return GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "not determined: contact time, the sphere had not left the wall by "
                                                "the last record");
    return GF_OK;
}

/* The oblique numbers (gf_bounce_measure_oblique) when the diagnostics carry
 * the tangential motion; runs written before it have none and get no such row. */
static gf_status report_oblique(gf_ctx *ctx, const gf_stage_in *in, const gf_bounce *b, double R, size_t n,
                                gf_post_row *row)
{
    if (!gf_stage_has_var(in, "diagnostics.nc", "sphere_velocity_x") ||
        !gf_stage_has_var(in, "diagnostics.nc", "sphere_spin_z"))
        return GF_OK;
    gf_ncr f;
    GF_TRY(gf_stage_open(ctx, in, "diagnostics.nc", &f));
    double *vx = NULL, *wz = NULL;
    size_t nx = 0, nw = 0;
    gf_status st = gf_ncr_var_1d(ctx, &f, "sphere_velocity_x", &vx, &nx);
    if (st == GF_OK) st = gf_ncr_var_1d(ctx, &f, "sphere_spin_z", &wz, &nw);
    gf_ncr_close(&f);
    if (st == GF_OK && (nx != n || nw != n))
        st = GF_FAIL(ctx, GF_ERR_IO, "diagnostics.nc: sphere_velocity_x has %zu samples, sphere_spin_z %zu, time %zu",
                     nx, nw, n);
    static const char *const names[2][5] = {
        {"bounce_psi_in", "bounce_psi_out", "bounce_beta", "bounce_mu_f", "bounce_xi_out_deg"},
        {"bounce_psi_in_T", "bounce_psi_out_T", "bounce_beta_T", "bounce_mu_f_T", "bounce_xi_out_deg_T"}};
    for (int r = 0; r < 2 && st == GF_OK; ++r) {
        gf_bounce_oblique o;
        gf_bounce_measure_oblique(b, vx, wz, R, r ? GF_BOUNCE_AT_APPROACH : GF_BOUNCE_AT_IMPACT, &o);
        const double x[5] = {o.psi_in, o.psi_out, o.beta, o.mu_f, o.xi_out_deg};
        for (int c = 0; c < 5; ++c)
            set_if(row, names[r][c], x[c]);
    }
    free(vx);
    free(wz);
    return st;
}

gf_status gf_stage_bounce(gf_ctx *ctx, const gf_stage_in *in, const gf_stage_opts *opts, gf_stage_out *out)
{
    (void)opts;
    if (!gf_stage_has_var(in, "diagnostics.nc", "gap_over_D") ||
        !gf_stage_has_var(in, "diagnostics.nc", "sphere_velocity_y"))
        return GF_ERR_UNSUPPORTED;   /* no sphere above a wall */
    gf_ncr f;
    GF_TRY(gf_stage_open(ctx, in, "diagnostics.nc", &f));
    double att[6] = {NAN, NAN, NAN, NAN, NAN, NAN};
    gf_status st = gf_ncr_att_double(ctx, &f, "grain_diameter_m", &att[0]);
    if (st == GF_OK) st = gf_ncr_att_double(ctx, &f, "grain_density_kg_m3", &att[1]);
    if (st == GF_OK) st = gf_ncr_att_double(ctx, &f, "fluid_density_kg_m3", &att[2]);
    if (st == GF_OK) st = gf_ncr_att_double(ctx, &f, "fluid_viscosity_Pa_s", &att[3]);
    att[4] = gf_ncr_att_double_or(&f, "restitution", NAN);
    att[5] = gf_ncr_att_double_or(&f, "t_contact_s", NAN);
    bounce_series s = {0};
    if (st == GF_OK)
        st = read_series(ctx, &f, att[0], &s);
    gf_ncr_close(&f);
    if (st == GF_OK) {
        gf_bounce b;
        gf_bounce_measure(s.t, s.v, s.gap, s.n, 0.5 * att[0], &b);
        report_approach(&s, 0.5 * att[0], out->row);
        st = report(ctx, &b, att, out->row, s.n);
        if (b.rebounded) {
            gf_status so = report_oblique(ctx, in, &b, 0.5 * att[0], s.n, out->row);
            st = so != GF_OK ? so : st;
        }
    }
    free(s.t);
    free(s.v);
    free(s.gap);
    return st;
}
