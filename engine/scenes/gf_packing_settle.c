/* A settling phase of the packing preparation through the engine; see gf_packing_settle.h. */
#include "scenes/gf_packing_settle.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gf_sim.h"

/* Rest test (gf_packing_settle.h): mean kinetic energy per grain in m g D,
 * earliest rest and longest settling in sqrt(D/g), and the interval between
 * two tests. */
static const double REST_KE = 1e-4, REST_EARLIEST_ND = 5.0, LONGEST_ND = 400.0, TEST_EVERY_ND = 0.5;

/* The engine's box around the container, the grains and the obstacles: the
 * container itself on periodic axes, else everything with a margin of one
 * grain, and room above the grains for the first bounces. */
static void preparation_box(const gf_packing_spec *sp, const gf_particles *grains, double lo[3], double hi[3])
{
    const double D = 2.0 * sp->psd.mean_radius_m, back = sp->wall_setback_m;
    for (int c = 0; c < 3; ++c)
        lo[c] = sp->lo_m[c] - (c == 1 ? 0.0 : back), hi[c] = sp->hi_m[c] + (c == 1 ? 0.0 : back);
    const gf_particles *sets[2] = {grains, sp->obstacles};
    for (int k = 0; k < 2; ++k)
        for (size_t i = 0; sets[k] && i < sets[k]->n_local; ++i) {
            const gf_particles *q = sets[k];
            const double x[3] = {q->x_m[i], q->y_m[i], q->z_m[i]}, r = q->radius_m[i];
            for (int c = 0; c < 3; ++c)
                lo[c] = fmin(lo[c], x[c] - r), hi[c] = fmax(hi[c], x[c] + r);
        }
    for (int c = 0; c < 3; ++c) {
        const int periodic = c != 1 && sp->periodic[c];
        lo[c] = periodic ? sp->lo_m[c] : lo[c] - D;
        hi[c] = periodic ? sp->hi_m[c] : hi[c] + (c == 1 ? 10.0 : 1.0) * D;
    }
}

static gf_status set_params(gf_ctx *ctx, gf_run_spec *rs, const gf_packing_spec *sp, const double lo[3],
                            const double hi[3])
{
    const double back = sp->wall_setback_m;
    const struct {
        const char *key;
        double value;
    } kv[] = {
        {"box_lo_x_m", lo[0]}, {"box_lo_y_m", lo[1]}, {"box_lo_z_m", lo[2]},
        {"box_hi_x_m", hi[0]}, {"box_hi_y_m", hi[1]}, {"box_hi_z_m", hi[2]},
        {"periodic_x", sp->periodic[0] ? 1.0 : 0.0}, {"periodic_z", sp->periodic[2] ? 1.0 : 0.0},
        {"floor_y_m", sp->lo_m[1]},
        {"walls_x", sp->walls_x ? 1.0 : 0.0}, {"wall_x_lo_m", sp->lo_m[0] - back}, {"wall_x_hi_m", sp->hi_m[0] + back},
        {"walls_z", sp->walls_z ? 1.0 : 0.0}, {"wall_z_lo_m", sp->lo_m[2] - back}, {"wall_z_hi_m", sp->hi_m[2] + back},
    };
    for (size_t k = 0; k < sizeof kv / sizeof kv[0]; ++k)
        GF_TRY(gf_run_spec_set_param(ctx, rs, kv[k].key, kv[k].value));
    return GF_OK;
}

/* The run spec of the phase: the spec's grains, the phase's linear contacts, frictionless walls, dry, no output. */
static gf_status phase_spec(gf_ctx *ctx, const gf_packing_spec *sp, const gf_packing_phase *ph,
                            const gf_particles *grains, gf_run_spec *rs)
{
    gf_run_spec_defaults(rs);
    snprintf(rs->scene, sizeof rs->scene, "packing_preparation");
    const double D = 2.0 * sp->psd.mean_radius_m, g = sp->gravity_m_s2;
    rs->seed = sp->seed;
    rs->gravity_m_s2 = g;
    rs->grains = (gf_grains_spec){.diameter_m = D, .polydispersity = sp->psd.polydispersity,
                                  .density_kg_m3 = sp->density_kg_m3};
    rs->contact = (gf_contact_spec){.t_contact_nd = ph->t_contact_s / sqrt(D / g), .restitution = ph->restitution,
                                    .friction = ph->mu, .wall_friction = 0.0, .kt_over_kn = 0.2,
                                    .dt_over_tc = ph->dt_over_tc, .skin_over_D = 0.3};
    snprintf(rs->contact.law, sizeof rs->contact.law, "linear");
    rs->output = (gf_output_spec){0};
    double lo[3], hi[3];
    preparation_box(sp, grains, lo, hi);
    return set_params(ctx, rs, sp, lo, hi);
}

/* The grains (ids from *first_id on, in their order), then the obstacles, glued. */
static gf_status add_grains(gf_ctx *ctx, gf_sim *sim, const gf_packing_spec *sp, const gf_particles *grains,
                            int64_t *first_id)
{
    gf_particles *p = gf_sim_particles(sim);
    *first_id = p->next_id;
    for (size_t k = 0; k < grains->n_local; ++k) {
        size_t i;
        GF_TRY(gf_particles_add(ctx, p, grains->x_m[k], grains->y_m[k], grains->z_m[k], grains->radius_m[k],
                                sp->density_kg_m3, 0, &i));
        p->vx_m_s[i] = grains->vx_m_s[k], p->vy_m_s[i] = grains->vy_m_s[k], p->vz_m_s[i] = grains->vz_m_s[k];
    }
    const gf_particles *o = sp->obstacles;
    for (size_t k = 0; o && k < o->n_local; ++k)
        GF_TRY(gf_particles_add(ctx, p, o->x_m[k], o->y_m[k], o->z_m[k], o->radius_m[k], sp->density_kg_m3,
                                GF_P_GLUED, NULL));
    return GF_OK;
}

static double mobile_kinetic_energy_J(const gf_particles *p)
{
    double ke = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        if (!(p->flags[i] & GF_P_GLUED))
            ke += 0.5 * p->mass_kg[i] *
                  (p->vx_m_s[i] * p->vx_m_s[i] + p->vy_m_s[i] * p->vy_m_s[i] + p->vz_m_s[i] * p->vz_m_s[i]);
    return ke;
}

/* The drag over n steps as an exact decay of the velocities (operator
 * splitting: the linear drag alone integrates to u exp(-t / tau)). */
static void apply_drag(gf_particles *p, double decay)
{
    for (size_t i = 0; i < p->n_local; ++i)
        p->vx_m_s[i] *= decay, p->vy_m_s[i] *= decay, p->vz_m_s[i] *= decay;
}

/* Advances until rest or the longest settling. */
static gf_status settle(gf_ctx *ctx, gf_sim *sim, const gf_packing_spec *sp, const gf_packing_phase *ph,
                        size_t n_mobile)
{
    gf_particles *p = gf_sim_particles(sim);
    const double D = 2.0 * sp->psd.mean_radius_m, g = sp->gravity_m_s2, t_unit = sqrt(D / g);
    const double dt = gf_sim_dt_s(sim), m_mean = sp->density_kg_m3 * gf_psd_mean_volume_m3(&sp->psd);
    /* the drag acts once per contact duration: tau / t_c = 100 for the preparation's, a first-order splitting
     * error of 1 % of the drag, itself a small part of the force on a falling grain */
    const long split = ph->drag_time_s < INFINITY ? lround(fmax(1.0, 1.0 / ph->dt_over_tc)) : 1;
    const double decay = ph->drag_time_s < INFINITY ? exp(-(double)split * dt / ph->drag_time_s) : 1.0;
    const long test_every = split * (long)ceil(TEST_EVERY_ND * t_unit / dt / (double)split);
    const long longest = (long)(LONGEST_ND * t_unit / dt);
    for (long step = 0; step < longest;) {
        for (long k = 0; k < test_every; k += split) {
            GF_TRY(gf_sim_advance(sim, split));
            if (decay < 1.0)
                apply_drag(p, decay);
        }
        step += test_every;
        if (mobile_kinetic_energy_J(p) / (double)n_mobile < REST_KE * m_mean * g * D &&
            step * dt > REST_EARLIEST_ND * t_unit) {
            gf_log(ctx, GF_LOG_DEBUG, "packing: settled after %.1f sqrt(D/g) (%ld steps)", step * dt / t_unit, step);
            return GF_OK;
        }
    }
    return GF_OK; /* the longest settling: the deposit is measured as it is; the Phi check decides */
}

/* The settled grains back into grains, by id (the engine reorders its store). */
static gf_status copy_back(gf_ctx *ctx, const gf_particles *p, int64_t first_id, gf_particles *grains)
{
    size_t found = 0;
    for (size_t i = 0; i < p->n_local; ++i) {
        int64_t k = p->id[i] - first_id;
        if ((p->flags[i] & GF_P_GLUED) || k < 0 || (size_t)k >= grains->n_local)
            continue;
        grains->x_m[k] = p->x_m[i], grains->y_m[k] = p->y_m[i], grains->z_m[k] = p->z_m[i];
        grains->vx_m_s[k] = p->vx_m_s[i], grains->vy_m_s[k] = p->vy_m_s[i], grains->vz_m_s[k] = p->vz_m_s[i];
        ++found;
    }
    if (found != grains->n_local)
        return GF_FAIL(ctx, GF_ERR_PHYSICS, "packing: %zu of %zu grains left the container while settling",
                       grains->n_local - found, grains->n_local);
    return GF_OK;
}

gf_status gf_packing_settle(gf_ctx *ctx, const gf_packing_spec *sp, const gf_packing_phase *ph, gf_particles *grains)
{
    if (grains->n_local == 0)
        return GF_OK;
    gf_run_spec rs;
    GF_TRY(phase_spec(ctx, sp, ph, grains, &rs));
    /* one thread: a deposit is the same whatever the machine, so that a campaign's runs may share it
     * (io/gf_packing_cache.h); the engine's sums over contacts follow its per-thread chunks */
    gf_sim_options opt = {.n_threads = 1};
    gf_sim *sim = NULL;
    GF_TRY(gf_sim_create(ctx, &rs, &opt, &sim));
    int64_t first_id = 0;
    gf_status st = add_grains(ctx, sim, sp, grains, &first_id);
    if (st == GF_OK)
        st = gf_sim_set_rotation_locked(sim, ph->rotation_locked);
    if (st == GF_OK)
        st = gf_sim_check_state(sim);
    if (st == GF_OK)
        st = settle(ctx, sim, sp, ph, grains->n_local);
    if (st == GF_OK)
        st = copy_back(ctx, gf_sim_particles(sim), first_id, grains);
    gf_sim_destroy(&sim);
    return st;
}
