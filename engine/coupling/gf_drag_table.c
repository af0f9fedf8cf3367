/*
 * The drag-closure registry (gf_drag.h): one row per closure, each defined in
 * its own file. A new closure is one file and one row here; the schema's
 * allowed values of fluid.drag and the error messages read this list.
 */
#include "coupling/gf_drag.h"
#include "core/gf_registry.h"

static const gf_drag_info *const gf_drag_table[] = {
    &gf_drag_law_di_felice,
    &gf_drag_law_beetstra,
    &gf_drag_law_tenneti,
    &gf_drag_law_mean_slip,
};
enum { N_LAWS = sizeof gf_drag_table / sizeof gf_drag_table[0] };

static const char *closure_name(size_t i) { return gf_drag_table[i]->name; }

const gf_drag_info *gf_drag_lookup(const char *name)
{
    long i = gf_registry_index(N_LAWS, closure_name, name);
    return i < 0 ? NULL : gf_drag_table[i];
}

const char *const *gf_drag_names(void)
{
    static const char *names[N_LAWS + 1];
    gf_registry_fill_names(N_LAWS, closure_name, names);
    return names;
}

gf_status gf_drag_find(gf_ctx *ctx, const char *name, const gf_drag_info **law)
{
    *law = gf_drag_lookup(name);
    if (*law)
        return GF_OK;
    char known[256];
    return GF_FAIL(ctx, GF_ERR_CONFIG, "fluid.drag: unknown closure '%s' (known: %s)", name ? name : "",
                   gf_registry_join(N_LAWS, closure_name, "", ", ", known, sizeof known));
}

static double clip_eps(double eps) { return eps > 1.0 ? 1.0 : eps < 0.2 ? 0.2 : eps; }

double gf_drag_coefficient(const gf_drag_info *law, double D, double eps, double slip, double rho, double mu)
{
    return law->coefficient(D, clip_eps(eps), slip, rho, mu);
}

double gf_drag_fluctuation_coefficient(const gf_drag_info *law, double D, double eps, double slip, double rho,
                                       double mu)
{
    gf_drag_fn f = law->fluctuation ? law->fluctuation : law->coefficient;
    return f(D, clip_eps(eps), slip, rho, mu);
}
