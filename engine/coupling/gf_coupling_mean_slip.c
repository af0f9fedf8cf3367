/*
 * The unresolved tier's side of the mean-slip closures (gf_drag.h, e.g.
 * gf_drag_mean_slip.c): per fluid step, the local mean grain velocity <v> at
 * each grain, then the held values for the DEM substeps. The force
 *   F_d = K (u_f - <v>) + K' (<v> - v)
 * is held as the per-grain form of the other closures plus a correction on
 * the grain-scale velocity v_0 - <v> of the fluid step's start,
 *   F_d = K (u* - v),  u* = u_f + r (v_0 - <v>),
 * so the exact exponential relaxation of gf_coupling_add_forces is unchanged
 * and the mean motion (hindered settling, pore-pressure drag) is the
 * per-grain closure's. Over a fluid step dt the grain-scale velocity is then
 * multiplied by 1 - (1 - e^{-x})(1 - r), x = K dt/m; r is chosen so that this
 * is e^{-x'}, x' = K' dt/m (the exact decay under K'):
 *   r = 1 - (1 - e^{-x'}) / (1 - e^{-x})   (-> 1 - K'/K as dt -> 0; K' capped at K),
 * in [0, 1), so stable at any step, where holding K' with a lagged
 * K (u_f - <v>) term is not (it overshoots by K/K' once K' dt/m > 1:
 * measured, hindered settling diverged at phi 0.3).
 * The fluid feels the opposite force, -sum K (u_f - (1 - r) v_0 - r <v>) delta.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "coupling/gf_coupling_unresolved.h"

static double volume(const gf_particles *p, size_t i)
{
    double r = p->radius_m[i];
    return 4.0 / 3.0 * M_PI * r * r * r;
}

gf_status gf_mean_slip_prepare(gf_unresolved *c, const gf_particles *p)
{
    if (!c->law->fluctuation)
        return GF_OK;
    if (c->mean_cap < p->n_local) {
        size_t cap = p->n_local + p->n_local / 2 + 16;
        double *m = realloc(c->mean_v, cap * MEAN_SLIP_F64 * sizeof *m);
        if (!m)
            return GF_FAIL(c->ctx, GF_ERR_NOMEM, "coupling: out of memory for %zu mean velocities", p->n_local);
        c->mean_v = m, c->mean_cap = cap;
    }
    const gf_grid *g = &c->fluid->grid;
    memset(c->lanes, 0, g->n_cells * GF_AVERAGE_LANES * sizeof(double));
    for (size_t i = 0; i < p->n_local; ++i) {  /* in grain order: the sums do not depend on threads */
        double v = volume(p, i);
        const double value[GF_AVERAGE_LANES] = {v, v * p->vx_m_s[i], v * p->vy_m_s[i], v * p->vz_m_s[i]};
        gf_average_spread_lanes(g, &c->kern[i], value, c->lanes);
    }
    for (size_t i = 0; i < p->n_local; ++i) {
        double s[GF_AVERAGE_LANES];
        gf_average_interpolate_lanes(g, &c->kern[i], c->lanes, s);
        double *m = &c->mean_v[MEAN_SLIP_F64 * i];
        for (int a = 0; a < 3; ++a)
            m[a] = s[0] > 0.0 ? s[1 + a] / s[0] : 0.0;
        m[3] = 0.0;  /* r, set by gf_mean_slip_hold */
    }
    return GF_OK;
}

const double *gf_mean_slip_velocity(const gf_unresolved *c, size_t i)
{
    return c->law->fluctuation ? &c->mean_v[MEAN_SLIP_F64 * i] : NULL;
}

double gf_mean_slip_hold(gf_unresolved *c, const gf_particles *p, size_t i, double K_mean, double eps_closure,
                         double dt_s)
{
    double *m = &c->mean_v[MEAN_SLIP_F64 * i];
    double d[3] = {m[0] - p->vx_m_s[i], m[1] - p->vy_m_s[i], m[2] - p->vz_m_s[i]};
    double w = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double Kf = gf_drag_fluctuation_coefficient(c->law, 2.0 * p->radius_m[i], eps_closure, w, c->rho_f, c->mu);
    double x = K_mean * dt_s / p->mass_kg[i], xf = Kf * dt_s / p->mass_kg[i];
    m[3] = K_mean > Kf ? 1.0 - (x > 1e-8 ? expm1(-xf) / expm1(-x) : Kf / K_mean) : 0.0;
    return K_mean;
}

void gf_mean_slip_target(const gf_unresolved *c, const gf_particles *p, size_t i, const double uf[3], double target[3])
{
    const double *m = &c->mean_v[MEAN_SLIP_F64 * i];
    const double v[3] = {p->vx_m_s[i], p->vy_m_s[i], p->vz_m_s[i]};
    for (int a = 0; a < 3; ++a)
        target[a] = uf[a] + m[3] * (v[a] - m[a]);
}

void gf_mean_slip_exchange(const gf_unresolved *c, const gf_particles *p, size_t i, double K_held,
                           double value[GF_AVERAGE_LANES])
{
    const double *m = c->law->fluctuation ? &c->mean_v[MEAN_SLIP_F64 * i] : NULL;
    const double v[3] = {p->vx_m_s[i], p->vy_m_s[i], p->vz_m_s[i]};
    value[0] = K_held;
    for (int a = 0; a < 3; ++a)
        value[1 + a] = K_held * (m ? v[a] - m[3] * (v[a] - m[a]) : v[a]);
    for (int l = 4; l < GF_AVERAGE_LANES; ++l)
        value[l] = 0.0;
}
