/* The mu(I) law and its regularised viscosity; see gf_mui.h. */
#include "continuum/gf_mui.h"

#include <math.h>

gf_mui_params gf_mui_glass_beads(void)
{
    const double deg = M_PI / 180.0;
    return (gf_mui_params){.mu_s = tan(20.9 * deg), .mu_2 = tan(32.76 * deg), .I0 = 0.279};
}

gf_mui_params gf_mui_thesis_maxima(void)
{
    return (gf_mui_params){.mu_s = 0.381, .mu_2 = 0.643, .I0 = 0.279};
}

gf_mui_params gf_mui_thesis_matlab(void)
{
    return (gf_mui_params){.mu_s = 0.3819, .mu_2 = 0.6435, .I0 = 0.279};
}

gf_status gf_mui_check(gf_ctx *ctx, const gf_mui_params *p, const char *where)
{
    if (!(isfinite(p->mu_s) && p->mu_s >= 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: mu_s must be >= 0 (got %g)", where, p->mu_s);
    if (!(isfinite(p->mu_2) && p->mu_2 > p->mu_s))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: mu_2 must be > mu_s (got mu_2 = %g, mu_s = %g)", where, p->mu_2,
                       p->mu_s);
    if (!(isfinite(p->I0) && p->I0 > 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: I0 must be > 0 (got %g)", where, p->I0);
    return GF_OK;
}

double gf_mui_friction(const gf_mui_params *p, double I)
{
    /* Written as mu_s + dmu I/(I + I0): exact at I = 0 and finite at I = inf. */
    if (isinf(I))
        return p->mu_2;
    return p->mu_s + (p->mu_2 - p->mu_s) * I / (I + p->I0);
}

double gf_mui_inertial_number(const gf_mui_params *p, double mu)
{
    if (mu <= p->mu_s)
        return 0.0;
    if (mu >= p->mu_2)
        return INFINITY;
    return p->I0 * (mu - p->mu_s) / (p->mu_2 - mu);
}

gf_status gf_mui_material_check(gf_ctx *ctx, const gf_mui_material *m, const char *where)
{
    GF_TRY(gf_mui_check(ctx, &m->law, where));
    if (!(m->diameter_m > 0.0 && isfinite(m->diameter_m)))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: grain diameter must be > 0 (got %g m)", where, m->diameter_m);
    if (!(m->grain_density_kg_m3 > 0.0 && isfinite(m->grain_density_kg_m3)))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: grain density must be > 0 (got %g kg/m3)", where,
                       m->grain_density_kg_m3);
    if (!(m->gdot_min_1_s > 0.0 && isfinite(m->gdot_min_1_s)))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s: gdot_min must be > 0 (got %g 1/s)", where, m->gdot_min_1_s);
    return GF_OK;
}

double gf_mui_viscosity(const gf_mui_material *m, double gdot_1_s, double pressure_Pa)
{
    if (!(pressure_Pa > 0.0))
        return 0.0;  /* Annex A: no confinement, no strength */
    double gdot = fabs(gdot_1_s) > m->gdot_min_1_s ? fabs(gdot_1_s) : m->gdot_min_1_s;
    double I = gdot * m->diameter_m / sqrt(pressure_Pa / m->grain_density_kg_m3);
    double mu = gf_mui_friction(&m->law, I);
    if (m->rate_part_only)
        mu -= m->law.mu_s;
    return mu * pressure_Pa / gdot;
}

double gf_mui_newtonian_viscosity(const gf_mui_material *m, double pressure_Pa)
{
    return m->diameter_m * sqrt(m->grain_density_kg_m3 * pressure_Pa) * (m->law.mu_2 - m->law.mu_s) / m->law.I0;
}
