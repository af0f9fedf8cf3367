/*
 * The fluid side of a run's set-up: which coupling tier (the spec's, or the
 * one the regime asks for with fluid: auto, coupling/gf_tier.h), Brenner
 * lubrication between grains (Brenner 1961; Izard 2014 (2.36)), and the
 * coupling itself, created after the scene's build (the preparation runs
 * dry) with the box's boundary conditions.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "coupling/gf_coupling.h"
#include "coupling/gf_tier.h"
#include "gf_sim_internal.h"

/* fluid: auto — the tier from the regime (St, r) of the run (coupling/gf_tier.h):
 * no fluid in the free-fall regime, else the first registered tier that fits. */
static gf_status choose_tier(gf_sim *s)
{
    gf_fluid_spec *f = &s->spec.fluid;
    gf_scales sc;
    gf_groups_input in = {.diameter_m = s->spec.grains.diameter_m,
                          .grain_density_kg_m3 = s->spec.grains.density_kg_m3,
                          .fluid_density_kg_m3 = f->density_kg_m3,
                          .viscosity_Pa_s = f->viscosity_Pa_s,
                          .gravity_m_s2 = s->spec.gravity_m_s2,
                          .slope_sin = sin(gf_run_spec_param(&s->spec, "incline_deg", 90.0) * M_PI / 180.0)};
    GF_TRY(gf_groups_compute(s->ctx, &in, &sc));
    gf_tier_choice choice;
    GF_TRY(gf_tier_from_scales(s->ctx, &sc, &choice));
    snprintf(f->model, sizeof f->model, "%s", choice.model);
    snprintf(s->fluid_reason, sizeof s->fluid_reason, "fluid: auto: %s", choice.reason);
    return GF_OK;
}

gf_status gf_sim_setup_fluid(gf_sim *s)
{
    gf_fluid_spec *f = &s->spec.fluid;
    s->immersed = 0;
    if (!(s->scene->needs & GF_NEED_FLUID)) {
        snprintf(s->fluid_reason, sizeof s->fluid_reason, "scene %s is dry", s->scene->name);
        return GF_OK;
    }
    snprintf(s->fluid_reason, sizeof s->fluid_reason, "fluid.model = %s in the run spec", f->model);
    if (strcmp(f->model, "auto") == 0)
        GF_TRY(choose_tier(s));
    if (strcmp(f->model, "none") == 0)
        return GF_OK;
    GF_TRY(gf_coupling_check(s->ctx, &s->spec)); /* a registered tier that accepts this spec */
    if (!(f->viscosity_Pa_s > 0.0) || !(f->density_kg_m3 > 0.0))
        return GF_FAIL(s->ctx, GF_ERR_CONFIG, "fluid: density and viscosity must be > 0 when immersed (got %g, %g)",
                       f->density_kg_m3, f->viscosity_Pa_s);
    s->immersed = 1;
    return f->lubrication ? gf_sim_setup_lubrication(s) : GF_OK;
}

gf_status gf_sim_setup_lubrication(gf_sim *s)
{
    const gf_fluid_spec *f = &s->spec.fluid;
    double R = 0.5 * s->spec.grains.diameter_m;
    if (!(f->roughness_over_R > 0.0) || !(f->lub_cutoff_over_R >= 0.0))
        return GF_FAIL(s->ctx, GF_ERR_CONFIG,
                       "fluid: roughness_over_R must be > 0 and lub_cutoff_over_R >= 0 (got %g, %g)",
                       f->roughness_over_R, f->lub_cutoff_over_R);
    s->lubrication = 1;
    s->lub_eta_Pa_s = f->viscosity_Pa_s;
    s->lub_roughness_m = f->roughness_over_R * R;
    s->lub_cutoff_m = f->lub_cutoff_over_R * R;
    if (gf_lub_overlap_from_name(f->lub_overlap, &s->lub_overlap) != 0)
        return GF_FAIL(s->ctx, GF_ERR_CONFIG, "fluid.lub_overlap: unknown mode '%s' (clamp, off or film)", f->lub_overlap);
    s->nb.extra_m = s->lub_cutoff_m; /* the neighbour reach covers the lubrication range */
    return GF_OK;
}

gf_status gf_sim_create_coupling(gf_sim *s)
{
    gf_coupling_setup setup;
    memset(&setup, 0, sizeof setup);
    for (int a = 0; a < 3; ++a) {
        setup.lo_m[a] = s->lo_m[a], setup.hi_m[a] = s->hi_m[a];
        setup.gravity_m_s2[a] = s->gravity_m_s2[a];
        for (int side = 0; side < 2; ++side)
            setup.bc[a][side] = s->fluid_bc_set[a][side] ? (gf_fluid_bc)s->fluid_bc[a][side]
                                : s->periodic[a]           ? GF_BC_PERIODIC
                                                           : GF_BC_NO_SLIP;
    }
    GF_TRY(gf_coupling_create(s->ctx, &s->spec, &setup, &s->coupling));
    gf_coupling_set_threads(s->coupling, s->n_threads);
    gf_sim_choose_substeps(s);
    s->next_fluid_step = s->step;
    return GF_OK;
}
