/*
 * The coupling interface of gf_coupling.h, dispatched to the tier the run
 * spec names (gf_coupling_tier.h). The dispatcher adds no arithmetic: a run
 * through it is bitwise the run the tier would make when called directly.
 */
#include <math.h>
#include <string.h>

#include "coupling/gf_coupling_tier.h"

const gf_coupling_tier *gf_coupling_tier_of(const gf_coupling *c) { return c ? c->tier : NULL; }

/* spec.fluid.model names the tier; "auto" reaching the library directly (a
 * driver that did not resolve it from the regime, as gf_sim does through
 * gf_tier.h) takes the cheapest registered tier, the registry's first row. */
static gf_status find_tier(gf_ctx *ctx, const char *model, const gf_coupling_tier **out)
{
    *out = gf_coupling_tier_find(model);
    if (!*out && strcmp(model, "auto") == 0) {
        int n = 0;
        *out = gf_coupling_tier_all(&n)[0];
    }
    if (*out)
        return GF_OK;
    char names[160];
    gf_coupling_tier_names(names, sizeof names);
    return GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "fluid.model '%s': the coupling tiers are %s", model, names);
}

gf_status gf_coupling_check(gf_ctx *ctx, const gf_run_spec *spec)
{
    const gf_coupling_tier *t;
    GF_TRY(find_tier(ctx, spec->fluid.model, &t));
    return t->check ? t->check(ctx, spec) : GF_OK;
}

gf_status gf_coupling_create(gf_ctx *ctx, const gf_run_spec *spec, const gf_coupling_setup *setup, gf_coupling **out)
{
    *out = NULL;
    const gf_coupling_tier *t;
    GF_TRY(find_tier(ctx, spec->fluid.model, &t));
    if (t->check)
        GF_TRY(t->check(ctx, spec));
    GF_TRY(t->create(ctx, spec, setup, out));
    (*out)->tier = t;
    return GF_OK;
}

void gf_coupling_destroy(gf_coupling **c)
{
    if (!c || !*c)
        return;
    (*c)->tier->destroy(*c);
    *c = NULL;
}

const char *gf_coupling_model(const gf_coupling *c) { return c ? c->tier->name : "none"; }

void gf_coupling_set_threads(gf_coupling *c, int n_threads)
{
    if (c->tier->set_threads)
        c->tier->set_threads(c, n_threads);
}

double gf_coupling_dt_max_s(const gf_coupling *c, const gf_particles *p) { return c->tier->dt_max_s(c, p); }

gf_status gf_coupling_fluid_step(gf_coupling *c, const gf_particles *p, double dt_s)
{
    return c->tier->fluid_step(c, p, dt_s);
}

gf_status gf_coupling_add_forces(gf_coupling *c, gf_particles *p) { return c->tier->add_forces(c, p); }

int gf_coupling_forces_in_order(const gf_coupling *c, const gf_particles *p)
{
    return c->tier->forces_in_order ? c->tier->forces_in_order(c, p) : 0;
}

void gf_coupling_add_forces_range(gf_coupling *c, gf_particles *p, size_t i0, size_t i1)
{
    c->tier->add_forces_range(c, p, i0, i1);
}

double gf_coupling_excess_pressure_Pa(const gf_coupling *c, const double x_m[3])
{
    return c->tier->excess_pressure_Pa ? c->tier->excess_pressure_Pa(c, x_m) : NAN;
}

int gf_coupling_fields(const gf_coupling *c, int n_cells[3], double lo_m[3], double cell_m[3],
                       const gf_var_info **vars, const double *const **fields)
{
    if (!c->tier->fields) {
        *vars = NULL, *fields = NULL;
        return 0;
    }
    return c->tier->fields(c, n_cells, lo_m, cell_m, vars, fields);
}

gf_status gf_coupling_set_gravity(gf_coupling *c, const double gravity_m_s2[3])
{
    return c->tier->set_gravity(c, gravity_m_s2);
}

gf_status gf_coupling_save(const gf_coupling *c, gf_restart *r) { return c->tier->save(c, r); }

gf_status gf_coupling_load(gf_coupling *c, gf_restart *r) { return c->tier->load(c, r); }

double gf_coupling_fluid_flow_rate(const gf_coupling *c)
{
    return c->tier->fluid_flow_rate ? c->tier->fluid_flow_rate(c) : NAN;
}

double gf_coupling_fluid_mass_kg(const gf_coupling *c)
{
    return c->tier->fluid_mass_kg ? c->tier->fluid_mass_kg(c) : NAN;
}

int gf_coupling_grain_force(const gf_coupling *c, const gf_particles *p, size_t i, double f_N[3])
{
    if (c->tier->grain_force && i < p->n_local && c->tier->grain_force(c, p, i, f_N))
        return 1;
    f_N[0] = f_N[1] = f_N[2] = NAN;
    return 0;
}
