/*
 * gf_sim_run: the driver loop with outputs. Advances in chunks that end on
 * output instants (spec.output.interval_nd sqrt(D/g)), the end time, or
 * about every 0.1 wall second (progress callback about once per second,
 * interrupt and scene end-condition checks). Writes, only when
 * opt.output_dir is set and only the files the spec asks for:
 *   diagnostics.nc  kinetic_energy, ecx_per_grain, n_contacts,
 *                   max_overlap_over_D + the scene's own variables
 *   particles.nc    trajectories of every grain
 *   probes.nc       excess pore pressure at the scene's gauges (immersed runs)
 *   fields.nc       the coupling's gridded fields (immersed runs)
 *   checkpoint.h5   every checkpoint_interval_nd, and on interrupt.
 * An interrupted run keeps its files as "<name>.partial"; started again
 * from checkpoint.h5 (gf_sim_options.restart_path) it continues them and
 * takes up the original output instants, so its files are those of an
 * uninterrupted run (records and values bitwise; the history attribute notes
 * the restart).
 * Files are written under temporary names and renamed when complete
 * (gf_nc writers); a failed run aborts them so no partial file looks complete.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_sim_internal.h"

#define GF_N_COMMON_DIAG 4
#define GF_MAX_DIAG 64

static const gf_var_info common_diag[GF_N_COMMON_DIAG] = {
    {"kinetic_energy", "J", "total kinetic energy of mobile grains (translation + rotation)", NULL},
    {"ecx_per_grain", "J", "horizontal (x) translational kinetic energy per mobile grain, E_cx (Izard 2014 §5.3)", NULL},
    {"n_contacts", "1", "number of grain-grain and grain-wall contacts", NULL},
    {"max_overlap_over_D", "1", "largest contact overlap / mean diameter", NULL},
};

typedef struct run_out {
    gf_nc_writer *diag, *parts, *probes, *fields;
    gf_var_info vars[GF_MAX_DIAG];
    int n_vars;
    double values[GF_MAX_DIAG];
    double *probe_values;
    int suspend;          /* interrupted with a checkpoint written: keep the files as .partial */
} run_out;

static gf_status write_record(gf_sim *s, run_out *o)
{
    gf_timer_start(&s->timers, GF_T_OUTPUT);
    gf_status st = GF_OK;
    if (o->diag) {
        o->values[0] = gf_particles_kinetic_energy(s->p);
        o->values[1] = gf_particles_ecx_per_grain(s->p);
        o->values[2] = (double)s->n_contacts;
        o->values[3] = s->max_overlap_m / s->spec.grains.diameter_m;
        if (s->scene->diagnose && s->scene->n_diag > 0)
            st = s->scene->diagnose(s, o->values + GF_N_COMMON_DIAG);
        if (st == GF_OK)
            st = gf_nc_diagnostics_append(o->diag, s->t_s, o->values);
    }
    if (st == GF_OK && o->parts)
        st = gf_nc_particles_append(o->parts, s->t_s, s->p);
    if (st == GF_OK && o->probes) {
        for (int k = 0; k < s->n_gauges; ++k)
            o->probe_values[k] = gf_coupling_excess_pressure_Pa(s->coupling, s->gauges[k].x_m);
        st = gf_nc_probes_append(o->probes, s->t_s, o->probe_values);
    }
    if (st == GF_OK && o->fields) {
        int nc[3];
        double lo[3], cell[3];
        const gf_var_info *vars;
        const double *const *f;
        gf_coupling_fields(s->coupling, nc, lo, cell, &vars, &f);
        st = gf_nc_fields_append(o->fields, s->t_s, f);
    }
    gf_timer_stop(&s->timers, GF_T_OUTPUT);
    return st;
}

static gf_status open_outputs(gf_sim *s, run_out *o, gf_nc_meta *meta)
{
    const char *dir = s->opt.output_dir;
    char path[1024];
    const gf_output_spec *os = &s->spec.output;
    if (os->diagnostics) {
        o->n_vars = GF_N_COMMON_DIAG;
        memcpy(o->vars, common_diag, sizeof common_diag);
        if (s->scene->n_diag > GF_MAX_DIAG - GF_N_COMMON_DIAG)
            return GF_FAIL(s->ctx, GF_ERR_CAPACITY, "scene %s: too many diagnostics (%d)", s->scene->name,
                           s->scene->n_diag);
        for (int k = 0; k < s->scene->n_diag; ++k)
            o->vars[o->n_vars++] = s->scene->diag[k];
        snprintf(path, sizeof path, "%s/diagnostics.nc", dir);
        GF_TRY(gf_nc_diagnostics_open(s->ctx, path, meta, o->vars, o->n_vars, &o->diag));
    }
    if (os->particles) {
        snprintf(path, sizeof path, "%s/particles.nc", dir);
        GF_TRY(gf_nc_particles_open(s->ctx, path, meta, s->p, &o->parts));
    }
    if (os->probes && s->coupling && s->n_gauges > 0) {
        static const gf_var_info pv = {"excess_pore_pressure", "Pa", "pore pressure minus hydrostatic", NULL};
        const char *names[GF_SIM_MAX_GAUGES];
        double xyz[3 * GF_SIM_MAX_GAUGES];
        for (int k = 0; k < s->n_gauges; ++k) {
            names[k] = s->gauges[k].name;
            memcpy(&xyz[3 * k], s->gauges[k].x_m, sizeof s->gauges[k].x_m);
        }
        o->probe_values = calloc((size_t)s->n_gauges, sizeof(double));
        if (!o->probe_values)
            return GF_FAIL(s->ctx, GF_ERR_NOMEM, "run: cannot allocate probe values");
        snprintf(path, sizeof path, "%s/probes.nc", dir);
        GF_TRY(gf_nc_probes_open(s->ctx, path, meta, s->n_gauges, names, xyz, &pv, 1, &o->probes));
    }
    if (os->fields && s->coupling) {
        int nc[3];
        double lo[3], cell[3];
        const gf_var_info *vars;
        const double *const *f;
        int nv = gf_coupling_fields(s->coupling, nc, lo, cell, &vars, &f);
        if (nv > 0) {
            snprintf(path, sizeof path, "%s/fields.nc", dir);
            GF_TRY(gf_nc_fields_open(s->ctx, path, meta, nc, lo, cell, vars, nv, &o->fields));
        }
    }
    return GF_OK;
}

/* Closes the files: into place after a complete run, as "<name>.partial"
 * after an interrupt that wrote a checkpoint (o->suspend: the restart
 * continues them), removed after a failure. */
static gf_status close_outputs(run_out *o, gf_status st)
{
    gf_nc_writer **w[4] = {&o->diag, &o->parts, &o->probes, &o->fields};
    for (int k = 0; k < 4; ++k) {
        if (st == GF_OK)
            st = gf_nc_writer_close(w[k]);
        else if (st == GF_ERR_INTERRUPTED && o->suspend) {
            gf_status ss = gf_nc_writer_suspend(w[k]);
            if (ss != GF_OK)
                st = ss;
        } else
            gf_nc_writer_abort(w[k]);
    }
    free(o->probe_values);
    o->probe_values = NULL;
    return st;
}

static gf_status checkpoint_in_dir(gf_sim *s)
{
    if (!s->opt.output_dir)
        return GF_OK;
    char path[1024];
    snprintf(path, sizeof path, "%s/checkpoint.h5", s->opt.output_dir);
    return gf_sim_checkpoint(s, path);
}

/* The first instant of the series t_k = k dt_out (accumulated as the loop
 * below does) that a run stopped at t_s has not reached: a restarted run
 * takes up the original output and checkpoint instants. */
static double next_instant(double every_s, double t_s, double dt_s)
{
    if (!(every_s > 0.0))
        return INFINITY;
    double next = every_s;
    while (t_s >= next - 0.5 * dt_s)
        next += every_s;
    return next;
}

/* Steps from now to the first step whose time passes the test the loop
 * applies, t >= t_stop - dt/2, and never beyond it. The quotient is about
 * k - 1/2 for an instant on the step grid (robust), and where it falls
 * within 1e-3 of an integer (an instant near a half step, or the round-off
 * of the accumulated time) the shorter count is taken: the loop then takes
 * the one step more that the test asks for. The step that records an
 * instant is therefore the same however the run was cut into chunks; with
 * the former ceil((t_stop - t)/dt - 1e-9) it moved by one step with the
 * wall-clock-sized chunks (the time accumulated over thousands of steps
 * differs from k dt by 1e-6 dt and more). */
static long steps_to(const gf_sim *s, double t_stop)
{
    double x = (t_stop - 0.5 * s->dt_s - s->t_s) / s->dt_s, k = floor(x);
    if (!(x < 1e15)) /* no instant ahead (infinite or absurd): the chunk decides */
        return 1L << 50;
    long n = (long)(x - k < 1e-3 ? k : k + 1.0);
    return n > 0 ? n : 1;
}

/* Scenes that end themselves (done()) are asked every GF_DONE_EVERY steps
 * of the clock, at chunk boundaries that do not depend on the wall clock, so
 * that the last step, and the run's last record, are reproducible. */
#define GF_DONE_EVERY 100

static gf_status run_loop(gf_sim *s, run_out *o, int resumed)
{
    const double t_grain = s->scales.t_grain_s;
    double out_dt = s->spec.output.interval_nd * t_grain;
    double ck_dt = s->spec.output.checkpoint_interval_nd * t_grain;
    double next_out = out_dt > 0.0 ? s->t_s + out_dt : INFINITY, next_ck = ck_dt > 0.0 ? s->t_s + ck_dt : INFINITY;
    double wall0 = gf_wtime(), last_progress = wall0;
    long chunk = s->opt.tuning.chunk_steps > 0 ? s->opt.tuning.chunk_steps : 16, steps_at_progress = s->step;
    if (resumed) { /* the records up to now are in the continued files */
        next_out = next_instant(out_dt, s->t_s, s->dt_s);
        next_ck = next_instant(ck_dt, s->t_s, s->dt_s);
    } else {
        GF_TRY(write_record(s, o));
    }
    long written_step = s->step; /* a step count, not a time: steps overshoot an instant by up to dt */
    while (s->t_s < s->t_end_s - 0.5 * s->dt_s) {
        long to_stop = steps_to(s, fmin(fmin(next_out, next_ck), s->t_end_s));
        const long to_check = GF_DONE_EVERY - s->step % GF_DONE_EVERY;
        if (s->scene->done && to_check < to_stop)
            to_stop = to_check;
        const long to_upkeep = GF_SCENE_MAINTAIN_EVERY - s->step % GF_SCENE_MAINTAIN_EVERY;
        if (s->scene->maintain && to_upkeep < to_stop)
            to_stop = to_upkeep;
        long n = to_stop < chunk ? to_stop : chunk;
        double w0 = gf_wtime();
        gf_status st = gf_sim_advance(s, n);
        if (st == GF_ERR_INTERRUPTED) {
            char what[512];
            snprintf(what, sizeof what, "%s", s->ctx->last_msg);
            if (!s->opt.output_dir)
                return GF_FAIL(s->ctx, GF_ERR_INTERRUPTED, "%s; no checkpoint (no output directory)", what);
            gf_status ck = checkpoint_in_dir(s);
            if (ck != GF_OK)
                return ck;
            o->suspend = 1;
            return GF_FAIL(s->ctx, GF_ERR_INTERRUPTED, "%s; checkpoint written", what);
        }
        GF_TRY(st);
        if (s->scene->maintain && s->step % GF_SCENE_MAINTAIN_EVERY == 0)
            GF_TRY(s->scene->maintain(s));
        double w1 = gf_wtime(), took = w1 - w0;
        /* ~0.1 s per chunk; grown only when a whole chunk ran (a chunk cut short by
         * frequent output instants must not double without bound and overflow) */
        if (s->opt.tuning.chunk_steps <= 0) { /* > 0: fixed by the caller */
            if (took < 0.05 && n == chunk)
                chunk *= 2;
            else if (took > 0.2 && chunk > 1)
                chunk /= 2;
        }
        if (s->t_s >= next_out - 0.5 * s->dt_s) {
            GF_TRY(write_record(s, o));
            written_step = s->step;
            next_out += out_dt;
        }
        if (s->t_s >= next_ck - 0.5 * s->dt_s) {
            GF_TRY(checkpoint_in_dir(s));
            next_ck += ck_dt;
        }
        if (s->opt.progress && w1 - last_progress >= 1.0) {
            s->opt.progress(s->opt.progress_user, s->t_s, s->t_end_s, (s->step - steps_at_progress) / (w1 - last_progress));
            last_progress = w1;
            steps_at_progress = s->step;
        }
        if (s->scene->done && s->step % GF_DONE_EVERY == 0 && s->scene->done(s))
            break;
    }
    if ((o->diag || o->parts) && s->step != written_step) /* last state, unless just written */
        GF_TRY(write_record(s, o));
    return GF_OK;
}

/* Column length R0 and height H0 (collapse scenes), incline (avalanche). */
static void scene_geometry(const gf_sim *s, double *R0_m, double *H0_m, double *incline_deg)
{
    *R0_m = *H0_m = 0.0;
    if (s->scene->column_geometry)
        s->scene->column_geometry(&s->spec, R0_m, H0_m);
    *incline_deg = gf_run_spec_param(&s->spec, "incline_deg", 0.0);
}

/* A run restarted from its checkpoint: each file takes up the records its
 * interrupted predecessor left in "<name>.partial" (gf_nc_resume.c). */
static gf_status continue_outputs(gf_sim *s, run_out *o)
{
    gf_nc_writer *w[4] = {o->diag, o->parts, o->probes, o->fields};
    for (int k = 0; k < 4; ++k)
        if (w[k])
            GF_TRY(gf_nc_writer_continue(w[k], s->t_s + 0.5 * s->dt_s));
    return GF_OK;
}

/* The packing the run starts from is measured at t = 0, after the scene has
 * re-equilibrated the prepared deposit with the run's own contacts; that can
 * move it past the tolerance the preparation met (a loose frictional deposit
 * compacts: gf_packing.h, step 3). Said on stderr, naming the run, whenever
 * the realised Phi_i is further from the one asked than phi_tolerance. */
static void warn_packing(const gf_sim *s, double phi_local)
{
    const double asked = isnan(s->spec.phi_initial) ? gf_run_spec_param(&s->spec, "phi_target", NAN)
                                                    : s->spec.phi_initial;
    const double tol = gf_run_spec_param(&s->spec, "phi_tolerance", NAN);
    if (isnan(asked) || isnan(tol) || isnan(phi_local) || gf_run_spec_param(&s->spec, "free_pour", 0.0) > 0.5)
        return;
    if (fabs(phi_local - asked) > tol)
        gf_log(s->ctx, GF_LOG_WARN,
               "warning: run %s starts at Phi_i = %.4f (interior, at t = 0), %.4f from the %.4g asked: more than "
               "phi_tolerance = %.4g",
               s->spec.run_id, phi_local, phi_local - asked, asked, tol);
}

gf_status gf_sim_run(gf_sim *s)
{
    run_out o;
    memset(&o, 0, sizeof o);
    gf_status st = GF_OK;
    const int resumed = s->opt.restart_path != NULL;
    if (s->opt.output_dir) {
        double R0_m, H0_m, incline_deg, phi_measured = NAN, phi_local = NAN;
        scene_geometry(s, &R0_m, &H0_m, &incline_deg);
        if (s->scene->initial_packing && s->step == 0) {
            GF_TRY(s->scene->initial_packing(s, &phi_measured, &phi_local));
            warn_packing(s, phi_local);
        }
        char skipped[256];
        gf_sim_skips(s, skipped, sizeof skipped);
        gf_nc_meta meta = {
            .skipped_work = skipped,
            .spec = &s->spec,
            .scales = &s->scales,
            .resolved_yaml = s->opt.resolved_yaml,
            .fluid_model = s->immersed ? s->spec.fluid.model : "none",
            .fluid_model_reason = s->fluid_reason,
            .stages = s->immersed ? (s->lubrication ? "fluid,contacts,lubrication,coupling,integrate"
                                                    : "fluid,contacts,coupling,integrate")
                                  : (s->lubrication ? "contacts,lubrication,integrate" : "contacts,integrate"),
            .column_length_m = R0_m,
            .column_height_m = H0_m,
            .incline_deg = incline_deg,
            .phi_initial_measured = phi_measured,
            .phi_initial_local = phi_local,
        };
        st = open_outputs(s, &o, &meta);
        if (st == GF_OK && resumed)
            st = continue_outputs(s, &o);
    }
    if (st == GF_OK)
        st = run_loop(s, &o, resumed);
    return close_outputs(&o, st);
}
