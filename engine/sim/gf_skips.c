/*
 * Skipping the work a run does not need (issue #6), decided once at
 * gf_sim_create from the spec and the scene, recorded (gf_sim_skips, the
 * `skipped_work` attribute of every output file) and measured side by side
 * with the skip off (gf_sim_tuning.keep_all_work; workflows/bench/skips.sh,
 * docs/notes/benchmarks.md).
 *
 *  - Tangential (GF_SKIP_TANGENTIAL), when mu_c = 0 between grains and on
 *    every wall. The Coulomb cap |F_t| <= mu |F_n| (Cundall & Strack 1979;
 *    gf_contact_tangential.c step 3) is then 0: the tangential spring is
 *    reset to zero at every step and F_t = 0 exactly, so there is no torque
 *    and the spin of a sphere never changes (gf_integrate.h). The pair loop
 *    evaluates the normal law only, keeps no history, accumulates no torque,
 *    and the kick leaves the angular velocities alone. The trajectories are
 *    bitwise those of the full evaluation (F_t = +-0 added to F_n n).
 *  - Lubrication (GF_SKIP_LUBRICATION), when the spec names a viscous fluid
 *    and asks for Brenner lubrication but the run is dry: the scene has no
 *    fluid, fluid.model is none, or `fluid: auto` chose none because free
 *    fall dominates (St >= 10 and r >= 10, coupling/gf_tier.h). The dry tier
 *    drops the fluid as a whole, lubrication included; with keep_all_work
 *    the lubrication of that fluid is evaluated anyway, which measures both
 *    the cost saved and the physics left out (the observable change is the
 *    lubrication's own effect, not a numerical error).
 * Output nobody asked for is not a decision here: gf_sim_run opens only the
 * files spec.output asks for, and computes a record only for them.
 */
#include <stdio.h>
#include <string.h>

#include "gf_sim_internal.h"

static int wants_lubrication(const gf_sim *s)
{
    const gf_fluid_spec *f = &s->spec.fluid;
    return f->lubrication && f->viscosity_Pa_s > 0.0 && f->density_kg_m3 > 0.0;
}

gf_status gf_sim_decide_skips(gf_sim *s)
{
    s->skips = 0;
    if (!s->immersed && wants_lubrication(s)) {
        if (s->opt.tuning.keep_all_work)
            return gf_sim_setup_lubrication(s);
        s->skips |= GF_SKIP_LUBRICATION;
    }
    if (!s->opt.tuning.keep_all_work && s->cp.mu_grain == 0.0) /* walls: gf_sim_skips_wall_added */
        s->skips |= GF_SKIP_TANGENTIAL;
    return GF_OK;
}

void gf_sim_skips_wall_added(gf_sim *s, double friction)
{
    if (friction > 0.0)
        s->skips &= ~(unsigned)GF_SKIP_TANGENTIAL;
}

unsigned gf_sim_skips(const gf_sim *s, char *text, size_t n)
{
    static const struct {
        unsigned bit;
        const char *name;
    } names[] = {{GF_SKIP_TANGENTIAL, "tangential+rotation (mu_c = 0)"},
                 {GF_SKIP_LUBRICATION, "lubrication (dry tier)"}};
    if (text && n > 0) {
        size_t len = 0;
        text[0] = '\0';
        for (size_t k = 0; k < sizeof names / sizeof names[0]; ++k)
            if ((s->skips & names[k].bit) && len < n)
                len += (size_t)snprintf(text + len, n - len, "%s%s", len ? ", " : "", names[k].name);
    }
    return s->skips;
}
