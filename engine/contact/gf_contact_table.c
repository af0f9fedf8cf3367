/*
 * The contact-law registry (docs/architecture.md): one row per law, selected by
 * spec.contact.law. A new law is one kernel file and one row here.
 * Also: derivation of the law parameters from the run spec, and the closed
 * form of the clipped linear law used by the tests (Schäfer, Dippel & Wolf 1996).
 */
#include "contact/gf_contact.h"
#include "core/gf_registry.h"

#include <math.h>

/* The registry: one row per law, defined in the law's own file. */
static const gf_contact_info *const gf_contact_table[] = {
    &gf_contact_law_linear,
    &gf_contact_law_hertz,
    &gf_contact_law_hertz_kk,
};
enum { N_LAWS = sizeof gf_contact_table / sizeof gf_contact_table[0] };

static const char *law_name(size_t i) { return gf_contact_table[i]->name; }

const gf_contact_info *gf_contact_find(const char *law)
{
    long i = gf_registry_index(N_LAWS, law_name, law);
    return i < 0 ? NULL : gf_contact_table[i];
}

const gf_contact_info *const *gf_contact_all(int *n)
{
    *n = N_LAWS;
    return gf_contact_table;
}

const char *const *gf_contact_law_names(void)
{
    static const char *names[N_LAWS + 1];
    gf_registry_fill_names(N_LAWS, law_name, names);
    return names;
}

double gf_contact_damping_ratio(double eps)
{
    double l = log(eps);
    return -l / sqrt(M_PI * M_PI + l * l);
}

gf_status gf_contact_params_from_spec(gf_ctx *ctx, const gf_run_spec *spec, gf_contact_params *out)
{
    const gf_contact_spec *c = &spec->contact;
    double eps = c->restitution;
    const gf_contact_info *law = gf_contact_find(c->law);
    char known[256];
    if (!law)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "contact.law: unknown law '%s' (known: %s)", c->law,
                       gf_registry_join(N_LAWS, law_name, "", ", ", known, sizeof known));
    if (!(eps > 0.0 && eps <= 1.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "contact.restitution: must be in (0, 1] (got %g)", eps);
    if (!(c->t_contact_nd > 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "contact.t_contact_nd: must be > 0 (got %g)", c->t_contact_nd);
    if (!(c->friction >= 0.0) || !(c->wall_friction >= 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "contact.friction/wall_friction: must be >= 0 (got %g, %g)",
                       c->friction, c->wall_friction);
    if (!(c->kt_over_kn > 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "contact.kt_over_kn: must be > 0 (got %g)", c->kt_over_kn);
    double D = spec->grains.diameter_m, rho = spec->grains.density_kg_m3;
    if (!(D > 0.0) || !(rho > 0.0) || !(spec->gravity_m_s2 > 0.0))
        return GF_FAIL(ctx, GF_ERR_PHYSICS, "grains: diameter, density and gravity must be > 0 (got %g m, %g kg/m3, %g m/s2)",
                       D, rho, spec->gravity_m_s2);
    double t_c = gf_run_spec_t_contact_s(spec);
    double m = rho * M_PI * D * D * D / 6.0;
    double m_eff = 0.5 * m; /* mean pair: two grains of diameter D */
    double gamma_n = -(2.0 * m_eff / t_c) * log(eps);                               /* (3.16) */
    double k_n = m_eff * M_PI * M_PI / (t_c * t_c) + gamma_n * gamma_n / (4.0 * m_eff); /* (3.17) */
    *out = (gf_contact_params){.k_n_N_m = k_n,
                               .zeta = gf_contact_damping_ratio(eps),
                               .kt_over_kn = c->kt_over_kn,
                               .mu_grain = c->friction,
                               .mu_wall = c->wall_friction,
                               .allow_attraction = c->allow_attraction,
                               .t_contact_s = t_c,
                               .m_eff_mean_kg = m_eff};
    if (law->derive)
        law->derive(spec, out);
    return GF_OK;
}

void gf_contact_clipped_restitution(double eps_max, double *eps_eff, double *duration_over_tc)
{
    /* Unit mass, damped frequency w = pi (t_c = 1), decay b = -ln(eps):
     * delta = e^{-bt} sin(wt)/w; the clipped force k delta + gamma delta'
     * first vanishes where tan(wt) = -2 b w / (w^2 - b^2), in (t_c/2, t_c]. */
    double w = M_PI, b = -log(eps_max);
    double ts = atan2(2.0 * b * w, b * b - w * w) / w; /* sin > 0, cos < 0 branch */
    double ddot = exp(-b * ts) * (cos(w * ts) - b / w * sin(w * ts));
    *eps_eff = -ddot;
    *duration_over_tc = ts;
}
