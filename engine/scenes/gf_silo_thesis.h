/*
 * The run spec of the silo of Djouwe Meffeja (2012) §3.3 without its
 * geometry: scene silo, dry, monodisperse grains d = 0.5 mm of 2500 kg m-3,
 * the thesis' contact set (e_n = 0.885, mu = mu_wall = 0.5, k_t = 2 k_n / 7)
 * at Silbert et al. (2001)'s stiffness (t_n = 4.97e-3 sqrt(d/g)), no output
 * written. The silo tests and gf-bench-silo then set box, orifice and fill.
 */
#ifndef GF_SILO_THESIS_H
#define GF_SILO_THESIS_H

#include <stdio.h>

#include "gf_sim.h"

static inline void gf_silo_thesis_spec(gf_run_spec *s)
{
    gf_run_spec_defaults(s);
    snprintf(s->scene, sizeof s->scene, "silo");
    s->grains = (gf_grains_spec){.diameter_m = 0.5e-3, .polydispersity = 0.0, .density_kg_m3 = 2500.0};
    s->contact.t_contact_nd = 4.97e-3;
    s->contact.restitution = 0.885;
    s->contact.friction = s->contact.wall_friction = 0.5;
    s->contact.kt_over_kn = 2.0 / 7.0;
    s->output.particles = s->output.fields = s->output.probes = s->output.diagnostics = 0;
    snprintf(s->fluid.model, sizeof s->fluid.model, "none");
}

#endif
