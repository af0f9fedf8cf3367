/* One run in this process; see gf_run_exec.h. */
#include "schedule/gf_run_exec.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "continuum/gf_continuum_avalanche.h"
#include "continuum/gf_continuum_collapse.h"
#include "core/gf_timer.h"
#include "gf_sim.h"
#include "rundir/gf_lock.h"
#include "rundir/gf_manifest.h"
#include "schedule/gf_ledger.h"

/* <campaign dir>/preparations for run_dir = <campaign dir>/<run id>: the
 * deposits one run prepares serve the campaign's other runs
 * (io/gf_packing_cache.h). "" when run_dir has no parent to name. */
static void preparation_dir(const char *run_dir, char *buf, size_t n)
{
    const char *slash = strrchr(run_dir, '/');
    if (!slash || slash == run_dir || (size_t)(slash - run_dir) + 14 >= n) {
        buf[0] = '\0';
        return;
    }
    snprintf(buf, n, "%.*s/preparations", (int)(slash - run_dir), run_dir);
}

/* Takes the run directory's lock. *lock NULL and res->held set when another
 * process holds it; a lock left by a holder that died is taken over, saying so. */
static gf_status lock_run(gf_ctx *ctx, const gf_run_spec *spec, const gf_run_exec_opts *opt, gf_run_result *res,
                          gf_lock **lock)
{
    char path[4200], who[300];
    gf_lock_holder holder;
    int stale = 0;
    gf_ledger_lock_path(opt->run_dir, path, sizeof path);
    GF_TRY(gf_lock_take(ctx, path, opt->lock_what ? opt->lock_what : "run", 0.0, lock, &holder, &stale));
    gf_lock_describe(&holder, who, sizeof who);
    if (!*lock) {
        res->held = 1;
        snprintf(res->message, sizeof res->message, "run directory held by %s: left to it", who);
    } else if (stale) {
        gf_log(ctx, GF_LOG_WARN, "run %s: took over the lock of %s, which ended without releasing it", spec->run_id,
               who);
    }
    return GF_OK;
}

/* A run another process finished since keep_done_since (verified). */
static int done_meanwhile(const gf_run_exec_opts *opt)
{
    if (!opt->keep_done || gf_ledger_state(opt->run_dir, NULL, 0) != GF_RUN_DONE ||
        gf_manifest_time(opt->run_dir) < opt->keep_done_since)
        return 0;
    return gf_ledger_verified_state(opt->run_dir, NULL, 0) == GF_RUN_DONE;
}

gf_status gf_run_execute(gf_ctx *ctx, const gf_run_spec *spec, const gf_run_exec_opts *opt, gf_run_result *res)
{
    memset(res, 0, sizeof *res);
    char *yaml = NULL;
    size_t yaml_len = 0;
    char checkpoint[4200], preparations[4200] = "";
    int cont = 0;
    gf_lock *lock = NULL;
    if (opt->run_dir) {
        GF_TRY(gf_ledger_mkdirs(ctx, opt->run_dir));
        GF_TRY(lock_run(ctx, spec, opt, res, &lock));
        if (!lock)
            return GF_OK;
        if (done_meanwhile(opt)) {
            res->already_done = 1;
            gf_lock_release(&lock);
            return GF_OK;
        }
        yaml = gf_ledger_run_yaml(spec, opt->campaign ? opt->campaign : "run", &yaml_len);
        if (!yaml) {
            gf_lock_release(&lock);
            return GF_FAIL(ctx, GF_ERR_NOMEM, "out of memory");
        }
        char why[600] = "";
        cont = opt->resume && gf_ledger_can_continue(opt->run_dir, yaml, yaml_len, why, sizeof why);
        if (opt->resume && !cont && why[0]) /* a checkpoint is there: say why it is not used */
            gf_log(ctx, GF_LOG_WARN, "warning: run %s: not continued from its checkpoint (%s): starting again from t = 0",
                   spec->run_id, why);
        gf_ledger_clear(opt->run_dir);
        snprintf(checkpoint, sizeof checkpoint, "%s/checkpoint.h5", opt->run_dir);
        preparation_dir(opt->run_dir, preparations, sizeof preparations);
        char path[4200];
        snprintf(path, sizeof path, "%s/run.yaml", opt->run_dir);
        gf_status st = gf_ledger_write_atomic(ctx, path, yaml, yaml_len);
        if (st != GF_OK) {
            gf_lock_release(&lock);
            free(yaml);
            return st;
        }
    }
    gf_ctx run_ctx = {.log_level = ctx->log_level};
    gf_sim_options so = {.output_dir = opt->run_dir,
                         .resolved_yaml = yaml,
                         .n_threads = opt->n_threads,
                         .progress = opt->progress,
                         .progress_user = opt->progress_user,
                         .interrupt = opt->interrupt,
                         .restart_path = cont ? checkpoint : NULL,
                         .preparation_dir = preparations[0] ? preparations : NULL};
    const double t0 = gf_wtime();
    gf_sim *sim = NULL;
    gf_status st = GF_OK;
    if (strcmp(spec->method, "continuum") == 0 && strcmp(spec->scene, "avalanche") == 0) {
        gf_continuum_avalanche_result ar;
        st = gf_continuum_avalanche_run(&run_ctx, spec, opt->run_dir, yaml, opt->interrupt, &ar);
        res->steps = ar.steps;
        res->sim_time_s = ar.time_s;
    } else if (strcmp(spec->method, "continuum") == 0) { /* the mu(I) continuum instead of grains */
        gf_continuum_collapse_result cr;
        st = gf_continuum_collapse_run(&run_ctx, spec, opt->run_dir, yaml, opt->interrupt, &cr);
        res->steps = cr.steps;
        res->sim_time_s = cr.time_s;
    } else {
        st = gf_sim_create(&run_ctx, spec, &so, &sim);
    }
    if (st == GF_OK && sim) {
        res->n_particles = (long)gf_sim_particles(sim)->n_local;
        res->continued_from_s = cont ? gf_sim_time_s(sim) : 0.0;
        st = gf_sim_run(sim);
        res->steps = gf_sim_step_count(sim);
        res->sim_time_s = gf_sim_time_s(sim);
        const gf_timers *t = gf_sim_timers(sim);
        for (int i = 0; i < GF_TIMER_COUNT && i < 16; ++i)
            res->timers_s[i] = t->elapsed_s[i];
    }
    gf_sim_destroy(&sim);
    res->wall_s = gf_wtime() - t0;
    res->status = st;
    free(yaml);
    if (st != GF_OK)
        snprintf(res->message, sizeof res->message, "%s: %s", gf_status_str(st),
                 run_ctx.last_msg[0] ? run_ctx.last_msg : "no message");
    if (!opt->run_dir)
        return GF_OK;
    if (st == GF_OK) {
        gf_ctx check = {0};
        if (gf_ledger_set_done(&check, opt->run_dir) != GF_OK) { /* a file that does not read back: not done */
            res->status = GF_ERR_IO;
            snprintf(res->message, sizeof res->message, "output check failed: %s", check.last_msg);
        }
    }
    gf_status rs = res->status == GF_OK ? GF_OK : gf_ledger_set_failed(ctx, opt->run_dir, res->message);
    gf_lock_release(&lock);
    return rs;
}
