/*
 * gf_sim: set-up, accessors, the builder calls of scenes and the validation
 * of a state (docs/architecture.md).
 *
 * Time step. dt = t_c dt_over_tc, never a bare number (t_c = t_contact_nd
 * sqrt(D/g)). Stability bound: velocity Verlet on one linear spring is stable
 * for omega dt < 2, i.e. dt < (2/pi) t_c = 0.64 t_c for the mean pair. In a
 * dense pack the stiffest mode of the contact network is faster: a grain held
 * by z contacts of stiffness k_n vibrates at up to ~sqrt(z/2) times the pair
 * frequency (z ~ 6-12 gives a factor 1.7-2.4), walls (m* = m_i) are slower
 * and the smallest grains of a 10 % polydisperse set are 1.17x faster. We
 * refuse dt > t_c/5 (GF_ERR_NUMERIC): a factor ~3 under the pair bound that
 * covers those network and polydispersity factors (up to 10 %; wider
 * distributions lower it, gf_run_spec_dt_limit_over_tc); accuracy wants t_c/50
 * (the default) anyway. Lubrication adds an explicit damping rate
 * c / m* = 6 pi eta R_eff^2/(eta_e m*); c dt / m* must stay below 1 (Izard 2014 (3.18)).
 * The step loop is gf_step.c.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/gf_soa.h"
#include "coupling/gf_coupling.h"
#ifdef _OPENMP
#include <omp.h>
#endif

#include "gf_sim_internal.h"
#include "gf_stiffness_rule.h"
#include "integrate/gf_integrate.h"

#define GF_OVERLAP_MAX_OVER_D 0.05

gf_status gf_sim_restore(gf_sim *s, const char *path);          /* gf_sim_checkpoint.c */
gf_status gf_sim_restore_coupling(gf_sim *s, const char *path); /* gf_sim_checkpoint.c */

/* ---- accessors ---- */
gf_particles *gf_sim_particles(gf_sim *s) { return s->p; }
const gf_run_spec *gf_sim_spec(const gf_sim *s) { return &s->spec; }
const gf_scales *gf_sim_scales(const gf_sim *s) { return &s->scales; }
gf_ctx *gf_sim_ctx(gf_sim *s) { return s->ctx; }
gf_rng *gf_sim_rng(gf_sim *s) { return &s->rng; }
const gf_timers *gf_sim_timers(const gf_sim *s) { return &s->timers; }
double gf_sim_time_s(const gf_sim *s) { return s->t_s; }
double gf_sim_dt_s(const gf_sim *s) { return s->dt_s; }
double gf_sim_end_time_s(const gf_sim *s) { return s->t_end_s; }
long gf_sim_step_count(const gf_sim *s) { return s->step; }

void gf_sim_box(const gf_sim *s, double lo[3], double hi[3], int periodic[3])
{
    for (int a = 0; a < 3; ++a) {
        if (lo)
            lo[a] = s->lo_m[a];
        if (hi)
            hi[a] = s->hi_m[a];
        if (periodic)
            periodic[a] = s->periodic[a];
    }
}

void gf_sim_contact_stats(const gf_sim *s, size_t *n_contacts, double *max_overlap_over_D)
{
    if (n_contacts)
        *n_contacts = s->n_contacts;
    if (max_overlap_over_D)
        *max_overlap_over_D = s->max_overlap_m / s->spec.grains.diameter_m;
}

void gf_sim_wall_force(const gf_sim *s, int w, double f[3])
{
    for (int c = 0; c < 3; ++c)
        f[c] = (w >= 0 && w < s->n_walls) ? s->walls[w].force_N[c] : 0.0;
}

double gf_sim_excess_pressure_Pa(const gf_sim *s, const double x_m[3])
{
    return s->coupling ? gf_coupling_excess_pressure_Pa(s->coupling, x_m) : NAN;
}

/* ---- builder calls ---- */
gf_status gf_sim_set_box(gf_sim *s, const double lo[3], const double hi[3], const int periodic[3])
{
    for (int a = 0; a < 3; ++a) {
        if (!(hi[a] > lo[a]) || !isfinite(lo[a]) || !isfinite(hi[a]))
            return GF_FAIL(s->ctx, GF_ERR_CONFIG, "scene %s: box axis %d: need lo < hi (got %g, %g m)",
                           s->spec.scene, a, lo[a], hi[a]);
        s->lo_m[a] = lo[a], s->hi_m[a] = hi[a], s->periodic[a] = periodic ? periodic[a] != 0 : 0;
    }
    s->box_set = 1;
    s->nb.need_build = 1;
    return GF_OK;
}

gf_status gf_sim_set_gravity(gf_sim *s, const double g[3])
{
    for (int a = 0; a < 3; ++a) {
        if (!isfinite(g[a]))
            return GF_FAIL(s->ctx, GF_ERR_CONFIG, "scene %s: gravity must be finite", s->spec.scene);
        s->gravity_m_s2[a] = g[a];
    }
    /* a scene that tilts gravity in start() does so after the fluid exists:
     * the hydrostatic reference, buoyancy and drag must follow */
    if (s->coupling)
        return gf_coupling_set_gravity(s->coupling, g);
    return GF_OK;
}

gf_status gf_sim_add_wall(gf_sim *s, const double point[3], const double normal[3], double friction, int *wall_id)
{
    if (s->n_walls >= GF_SIM_MAX_WALLS)
        return GF_FAIL(s->ctx, GF_ERR_CAPACITY, "scene %s: more than %d walls", s->spec.scene, GF_SIM_MAX_WALLS);
    double len = sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    if (!(len > 0.0) || !isfinite(len))
        return GF_FAIL(s->ctx, GF_ERR_CONFIG, "scene %s: wall normal must be a non-zero vector", s->spec.scene);
    if (!(friction >= 0.0))
        return GF_FAIL(s->ctx, GF_ERR_CONFIG, "scene %s: wall friction must be >= 0 (got %g)", s->spec.scene,
                       friction);
    gf_wall *w = &s->walls[s->n_walls];
    memset(w, 0, sizeof *w);
    for (int a = 0; a < 3; ++a)
        w->point_m[a] = point[a], w->normal[a] = normal[a] / len;
    w->friction = friction;
    w->active = 1;
    gf_sim_skips_wall_added(s, friction);
    if (wall_id)
        *wall_id = s->n_walls;
    s->n_walls++;
    GF_TRY(gf_sim_relayout_walls(s, s->n_walls - 1));
    s->stepper.phase = GF_STEP_STALE;
    return GF_OK;
}

gf_status gf_sim_set_wall_active(gf_sim *s, int w, int active)
{
    if (w < 0 || w >= s->n_walls)
        return GF_FAIL(s->ctx, GF_ERR_ARG, "scene %s: no wall %d (have %d)", s->spec.scene, w, s->n_walls);
    if (s->walls[w].active && !active)
        gf_sim_sleep_wake_all(s); /* a removed gate or lid: what rested on it must move again */
    s->walls[w].active = active != 0;
    s->stepper.phase = GF_STEP_STALE;
    return GF_OK;
}

gf_status gf_sim_set_wall_hole(gf_sim *s, int w, const double lo_m[3], const double hi_m[3])
{
    if (w < 0 || w >= s->n_walls)
        return GF_FAIL(s->ctx, GF_ERR_ARG, "scene %s: no wall %d (have %d)", s->spec.scene, w, s->n_walls);
    gf_wall *wl = &s->walls[w];
    int axis = -1;
    for (int a = 0; a < 3; ++a)
        if (fabs(wl->normal[a]) == 1.0)
            axis = a;
    if (axis < 0)
        return GF_FAIL(s->ctx, GF_ERR_ARG, "scene %s: a hole needs a wall normal to a box axis (wall %d)",
                       s->spec.scene, w);
    for (int a = 0; a < 3; ++a)
        if (a != axis && !(hi_m[a] > lo_m[a]))
            return GF_FAIL(s->ctx, GF_ERR_CONFIG, "scene %s: empty hole [%g, %g] m along axis %d", s->spec.scene,
                           lo_m[a], hi_m[a], a);
    wl->has_hole = 1, wl->hole_axis = axis;
    for (int a = 0; a < 3; ++a)
        wl->hole_lo[a] = lo_m[a], wl->hole_hi[a] = hi_m[a];
    s->stepper.phase = GF_STEP_STALE;
    return GF_OK;
}

gf_status gf_sim_grains_moved(gf_sim *s)
{
    s->stepper.phase = GF_STEP_STALE;
    s->nb.need_build = 1;
    return GF_OK;
}

double *gf_sim_scene_counters(gf_sim *s) { return s->scene_counters; }

gf_status gf_sim_set_end_time(gf_sim *s, double t_end_s)
{
    if (!(t_end_s > 0.0) || !isfinite(t_end_s))
        return GF_FAIL(s->ctx, GF_ERR_CONFIG, "scene %s: end time must be > 0 (got %g s)", s->spec.scene, t_end_s);
    s->t_end_s = t_end_s;
    return GF_OK;
}

gf_status gf_sim_add_gauge(gf_sim *s, const char *name, const double x[3])
{
    if (s->n_gauges >= GF_SIM_MAX_GAUGES)
        return GF_FAIL(s->ctx, GF_ERR_CAPACITY, "scene %s: more than %d gauges", s->spec.scene, GF_SIM_MAX_GAUGES);
    if (!name || strlen(name) >= GF_NAME_LEN)
        return GF_FAIL(s->ctx, GF_ERR_ARG, "scene %s: gauge name missing or too long", s->spec.scene);
    gf_gauge *g = &s->gauges[s->n_gauges++];
    snprintf(g->name, sizeof g->name, "%s", name);
    memcpy(g->x_m, x, sizeof g->x_m);
    return GF_OK;
}

gf_status gf_sim_set_fluid_bc(gf_sim *s, int axis, int side, int bc)
{
    if (axis < 0 || axis > 2 || side < 0 || side > 1 || bc < GF_BC_PERIODIC || bc > GF_BC_FREE_SLIP)
        return GF_FAIL(s->ctx, GF_ERR_ARG, "scene %s: bad fluid boundary (axis %d, side %d, bc %d)", s->spec.scene,
                       axis, side, bc);
    s->fluid_bc[axis][side] = bc;
    s->fluid_bc_set[axis][side] = 1;
    return GF_OK;
}

gf_status gf_sim_set_rotation_locked(gf_sim *s, int locked)
{
    s->rotation_locked = locked != 0;
    gf_particles *p = s->p;
    if (s->rotation_locked)
        for (size_t i = 0; i < p->n_local; ++i)
            p->wx_rad_s[i] = p->wy_rad_s[i] = p->wz_rad_s[i] = 0.0;
    s->nb.need_build = 1; /* the integrator factors are refreshed at the next build */
    s->stepper.phase = GF_STEP_STALE;
    return GF_OK;
}

const char *gf_sim_preparation_dir(const gf_sim *s)
{
    return s->opt.preparation_dir;
}

void gf_sim_reset_clock(gf_sim *s)
{
    s->t_s = 0.0;
    s->step = 0;
    s->next_fluid_step = 0;
}

/* ---- validation ---- */
gf_status gf_sim_check_state(gf_sim *s)
{
    gf_particles *p = s->p;
    const double D = s->spec.grains.diameter_m;
    for (size_t i = 0; i < p->n_local; ++i) {
        if (!(p->radius_m[i] > 0.0) || !isfinite(p->radius_m[i]))
            return GF_FAIL(s->ctx, GF_ERR_PHYSICS, "scene %s: grain %lld has radius %g m (must be > 0)",
                           s->spec.scene, (long long)p->id[i], p->radius_m[i]);
        double c[3] = {p->x_m[i], p->y_m[i], p->z_m[i]};
        for (int a = 0; a < 3; ++a)
            if (!s->periodic[a] && (c[a] < s->lo_m[a] - D || c[a] > s->hi_m[a] + D))
                return GF_FAIL(s->ctx, GF_ERR_PHYSICS,
                               "scene %s: grain %lld at (%g, %g, %g) m lies outside the box along axis %d", s->spec.scene,
                               (long long)p->id[i], c[0], c[1], c[2], a);
    }
    GF_TRY(gf_particles_check_finite(s->ctx, p));
    if (p->n_local == 0)
        return GF_OK;
    GF_TRY(gf_sim_rebuild(s));
    const gf_nlist *nl = s->nb.nl;
    for (size_t i = 0; i < p->n_local; ++i)
        for (size_t k = nl->row_start[i]; k < nl->row_start[i + 1]; ++k) {
            size_t j = (size_t)nl->j[k];
            const double *sh = nl->shift_m[nl->image[k]];
            double d[3] = {p->x_m[i] - p->x_m[j] + sh[0], p->y_m[i] - p->y_m[j] + sh[1], p->z_m[i] - p->z_m[j] + sh[2]};
            double ov = p->radius_m[i] + p->radius_m[j] - sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (ov > GF_OVERLAP_MAX_OVER_D * D && !((p->flags[i] & GF_P_GLUED) && (p->flags[j] & GF_P_GLUED)))
                return GF_FAIL(s->ctx, GF_ERR_PHYSICS,
                               "scene %s: grains %lld and %lld overlap by %.3g D (limit %.2g D): impossible initial "
                               "state",
                               s->spec.scene, (long long)p->id[i], (long long)p->id[j], ov / D, GF_OVERLAP_MAX_OVER_D);
        }
    for (int w = 0; w < s->n_walls; ++w) {
        if (!s->walls[w].active)
            continue;
        for (size_t i = 0; i < p->n_local; ++i) {
            double c[3] = {p->x_m[i], p->y_m[i], p->z_m[i]}, n[3];
            double ov = p->radius_m[i] - gf_wall_distance(&s->walls[w], c, n);
            if (ov > GF_OVERLAP_MAX_OVER_D * D && !(p->flags[i] & GF_P_GLUED))
                return GF_FAIL(s->ctx, GF_ERR_PHYSICS,
                               "scene %s: grain %lld overlaps wall %d by %.3g D (limit %.2g D): impossible initial state",
                               s->spec.scene, (long long)p->id[i], w, ov / D, GF_OVERLAP_MAX_OVER_D);
        }
    }
    return GF_OK;
}

static gf_status check_time_step(gf_sim *s) { return gf_run_spec_check_time_step(s->ctx, &s->spec); }

static gf_status compute_scales(gf_sim *s)
{
    const gf_run_spec *sp = &s->spec;
    double incline = gf_run_spec_param(sp, "incline_deg", 90.0);
    double R0_m = 0.0, H0_m = 0.0;
    if (s->scene->column_geometry)
        s->scene->column_geometry(sp, &R0_m, &H0_m);
    gf_groups_input in = {.diameter_m = sp->grains.diameter_m,
                          .grain_density_kg_m3 = sp->grains.density_kg_m3,
                          .fluid_density_kg_m3 = s->immersed ? sp->fluid.density_kg_m3 : 0.0,
                          .viscosity_Pa_s = s->immersed ? sp->fluid.viscosity_Pa_s : 0.0,
                          .gravity_m_s2 = sp->gravity_m_s2,
                          .slope_sin = sin(incline * M_PI / 180.0),
                          .column_height_m = H0_m,
                          .column_length_m = R0_m};
    return gf_groups_compute(s->ctx, &in, &s->scales);
}

/* contact.overlap_target_over_D > 0: t_c from the scene's largest static
 * pressure (gf_stiffness_rule.h), written back into the spec so that every
 * output records the t_c that ran. */
static gf_status apply_stiffness_rule(gf_sim *s)
{
    gf_run_spec *sp = &s->spec;
    double x = sp->contact.overlap_target_over_D;
    if (x == 0.0)
        return GF_OK;
    if (!(x > 0.0 && x <= 0.05))
        return GF_FAIL(s->ctx, GF_ERR_CONFIG, "contact.overlap_target_over_D: must be in (0, 0.05] or 0 (got %g)", x);
    double R0_m = 0.0, H0_m = 0.0;
    if (s->scene->column_geometry)
        s->scene->column_geometry(sp, &R0_m, &H0_m);
    if (!(H0_m > 0.0))
        return GF_FAIL(s->ctx, GF_ERR_CONFIG,
                       "contact.overlap_target_over_D: scene %s states no pressure scale (column height); set "
                       "contact.t_contact_nd instead", sp->scene);
    double phi = isnan(sp->phi_initial) ? gf_run_spec_param(sp, "phi_target", 0.6) : sp->phi_initial;
    double p_Pa = gf_stiffness_column_pressure_Pa(sp, phi, H0_m);
    sp->contact.t_contact_nd = gf_stiffness_t_contact_nd(sp, gf_stiffness_k_n(sp, p_Pa, x));
    return GF_OK;
}

static int pick_threads(const gf_sim_options *opt)
{
    int n = opt && opt->n_threads > 0 ? opt->n_threads : 1;
#ifdef _OPENMP
    if (!(opt && opt->n_threads > 0))
        n = omp_get_max_threads();
#else
    n = 1;
#endif
    return n > GF_SIM_MAX_THREADS ? GF_SIM_MAX_THREADS : n;
}

/* The neighbour upkeep's settings: the Verlet skin, the near list's (only
 * the blocked linear loop scans one, gf_near_list.c), the sort period. */
static gf_status setup_neighbours(gf_sim *s)
{
    const gf_sim_tuning *tu = &s->opt.tuning;
    gf_neighbours *nb = &s->nb;
    if (!(s->spec.contact.skin_over_D > 0.0))
        return GF_FAIL(s->ctx, GF_ERR_CONFIG, "contact.skin_over_D: must be > 0 (got %g)", s->spec.contact.skin_over_D);
    nb->skin_m = s->spec.contact.skin_over_D * s->spec.grains.diameter_m;
    /* the elastic film in overlap (gf_lubrication.h) is in the generic pair loop only (lubrication is set up by now) */
    if (s->lubrication && s->lub_overlap == GF_LUB_OVERLAP_FILM)
        s->opt.tuning.generic_pair_loop = 1;
    const int blocked = s->law->kernel == gf_contact_linear && !tu->generic_pair_loop;
    const double near_skin = tu->near_skin == 0.0 ? GF_SIM_NEAR_SKIN_DEFAULT : fmin(tu->near_skin, 1.0);
    nb->near.skin_m = (tu->near_skin < 0.0 || !blocked) ? 0.0 : near_skin * nb->skin_m;
    nb->sort_every = tu->sort_every == 0 ? GF_SIM_SORT_EVERY_DEFAULT : (tu->sort_every < 0 ? 0 : tu->sort_every);
    nb->store_layout = -1;
    return GF_OK;
}

static gf_status create_inner(gf_sim *s, const gf_run_spec *spec, const gf_sim_options *opt)
{
    s->spec = *spec;
    if (opt)
        s->opt = *opt;
    s->scene = gf_scene_find(spec->scene);
    if (!s->scene)
        return GF_FAIL(s->ctx, GF_ERR_CONFIG, "scene: unknown scene '%s'", spec->scene);
    GF_TRY(gf_scene_resolve_params(s->ctx, &s->spec));
    GF_TRY(apply_stiffness_rule(s));
    GF_TRY(gf_contact_params_from_spec(s->ctx, &s->spec, &s->cp));
    s->law = gf_contact_find(s->spec.contact.law);
    s->dt_s = gf_run_spec_dt_s(&s->spec);
    GF_TRY(gf_sim_setup_fluid(s));
    GF_TRY(gf_sim_decide_skips(s));
    GF_TRY(check_time_step(s));
    GF_TRY(compute_scales(s));
    GF_TRY(setup_neighbours(s));
    if (!(s->spec.contact.sleep_speed_nd >= 0.0 && s->spec.contact.sleep_speed_nd <= 0.05))
        return GF_FAIL(s->ctx, GF_ERR_CONFIG,
                       "contact.sleep_speed_nd: must be in [0, 0.05] (got %g; above 0.05 a grain at the top of a "
                       "hop could be taken for one at rest)", s->spec.contact.sleep_speed_nd);
    s->n_threads = pick_threads(opt);
    s->gravity_m_s2[1] = -s->spec.gravity_m_s2; /* y is vertical (docs/output.md) unless the scene says */
    gf_rng_seed(&s->rng, s->spec.seed);
    GF_TRY(gf_particles_create(s->ctx, 1024, &s->p));
    GF_TRY(gf_nlist_create(s->ctx, &s->nb.nl));
    s->in_build = 1;
    GF_TRY(s->scene->build(s, &s->spec));
    s->in_build = 0;
    if (!s->box_set)
        return GF_FAIL(s->ctx, GF_ERR_CONFIG, "scene %s: build() set no box", s->spec.scene);
    double t_grain = s->scales.t_grain_s;
    if (s->spec.end_time_nd > 0.0)
        s->t_end_s = s->spec.end_time_nd * t_grain;
    else if (!(s->t_end_s > 0.0))
        s->t_end_s = s->scene->default_end_time_nd * t_grain;
    GF_TRY(gf_sim_check_state(s));
    if (s->opt.restart_path) {
        GF_TRY(gf_sim_restore(s, s->opt.restart_path));
    } else {
        if (s->scene->start)
            GF_TRY(s->scene->start(s));
        GF_TRY(gf_sim_rebuild(s));
        GF_TRY(gf_sim_compute_forces(s));
    }
    if (s->immersed)
        GF_TRY(gf_sim_create_coupling(s));
    if (s->immersed && s->opt.restart_path)
        GF_TRY(gf_sim_restore_coupling(s, s->opt.restart_path));
    if (!s->opt.restart_path && s->scene->prelude)
        GF_TRY(s->scene->prelude(s));
    return GF_OK;
}

gf_status gf_sim_create(gf_ctx *ctx, const gf_run_spec *spec, const gf_sim_options *opt, gf_sim **out)
{
    *out = NULL;
    if (!spec)
        return GF_FAIL(ctx, GF_ERR_ARG, "gf_sim_create: spec is NULL");
    /* aligned: the per-chunk accumulators inside are on cache lines of their own */
    size_t bytes = (sizeof(gf_sim) + _Alignof(gf_sim) - 1) / _Alignof(gf_sim) * _Alignof(gf_sim);
    gf_sim *s = aligned_alloc(_Alignof(gf_sim), bytes);
    if (!s)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "gf_sim_create: cannot allocate");
    memset(s, 0, bytes);
    s->ctx = ctx;
    gf_status st = create_inner(s, spec, opt);
    if (st != GF_OK)
        gf_sim_destroy(&s); /* and s = NULL: the caller gets no sim */
    *out = s;
    return st;
}

void gf_sim_destroy(gf_sim **ps)
{
    if (!ps || !*ps)
        return;
    gf_sim *s = *ps;
    gf_coupling_destroy(&s->coupling);
    gf_particles_destroy(&s->p);
    gf_neighbours_free(&s->nb);
    free(s->wall_hist);
    free(s->sleep_quiet_steps);
    for (int t = 0; t < GF_SIM_MAX_THREADS; ++t)
        gf_soa_free(s->acc[t].buf_block);
    free(s);
    *ps = NULL;
}
