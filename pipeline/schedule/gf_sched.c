/* Worker pool, MPI task farm and progress display; see gf_sched.h. */
#include "schedule/gf_sched.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "campaign/gf_spec_schema.h"
#include "core/gf_timer.h"
#include "schedule/gf_comm.h"
#include "schedule/gf_eta.h"
#include "schedule/gf_ledger.h"
#include "schedule/gf_run_exec.h"
#include "rundir/gf_lock.h"
#include "rundir/gf_manifest.h"

void gf_sched_describe(const gf_campaign_run *r, char *buf, size_t n)
{
    size_t len = 0;
    buf[0] = '\0';
    for (int g = 0; g < 4; ++g) {
        double v = *gf_spec_group((gf_run_spec *)&r->spec, g);
        if (!isnan(v) && len < n)
            len += (size_t)snprintf(buf + len, n - len, "%s%s=%g", len ? " " : "", gf_group_names[g], v);
    }
    if (r->label[0] && len < n)
        len += (size_t)snprintf(buf + len, n - len, "%s[%s]", len ? " " : "", r->label);
    if (!len)
        snprintf(buf, n, "%s", r->spec.scene);
}

static void format_duration(double s, char *buf, size_t n)
{
    if (!isfinite(s) || s < 0) {
        snprintf(buf, n, "--:--");
        return;
    }
    long t = (long)(s + 0.5);
    if (t >= 3600)
        snprintf(buf, n, "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
    else
        snprintf(buf, n, "%ld:%02ld", t / 60, t % 60);
}

void gf_progress_update(gf_progress *p, double t_s, double t_end_s, double steps_per_s)
{
    if (t_s > 0.0 && !(p->wall0_s > 0.0)) {
        p->wall0_s = gf_wtime();
        p->t0_s = t_s;
    }
    p->t_s = t_s;
    p->t_end_s = t_end_s;
    p->steps_per_s = steps_per_s;
}

void gf_sched_progress_text(const gf_progress *p, char *buf, size_t n)
{
    char eta[32];
    const double now = gf_wtime();
    if (!(p->wall0_s > 0.0)) {
        format_duration(now - p->started_s, eta, sizeof eta);
        snprintf(buf, n, "preparing the scene (packing, settling)  %s", eta);
        return;
    }
    const double frac = p->t_end_s > 0 ? p->t_s / p->t_end_s : 0.0;
    double rate = p->t_s > p->t0_s ? (p->t_s - p->t0_s) / (now - p->wall0_s) : 0.0; /* sim s per wall s */
    if (!(rate > 0.0)) /* one report so far: its own speed */
        rate = p->steps_per_s * p->dt_s;
    format_duration(rate > 0 ? (p->t_end_s - p->t_s) / rate : NAN, eta, sizeof eta);
    snprintf(buf, n, "t = %.3g/%.3g s (%3.0f%%)  %.3g steps/s  ETA %s", p->t_s, p->t_end_s, 100.0 * frac,
             p->steps_per_s, eta);
}

/* --- shared progress table between the pool and its workers --- */

/* What a worker did with its run, beyond its status file. */
enum { OUTCOME_RAN = 0, OUTCOME_HELD, OUTCOME_DONE_ELSEWHERE };

typedef struct slot {
    volatile int run;           /* run index, -1: free */
    volatile int outcome;       /* OUTCOME_*, written by the worker */
    char message[640];          /* the holder, for OUTCOME_HELD */
    gf_progress progress;       /* written by the worker, read by the parent (a torn read only blurs one frame) */
    pid_t pid;
    volatile double continued_from_s; /* written by the worker before it exits: > 0 when it continued a checkpoint */
} slot;

static void on_progress(void *user, double t_s, double t_end_s, double steps_per_s)
{
    slot *s = user;
    gf_progress_update(&s->progress, t_s, t_end_s, steps_per_s);
}

static volatile int child_interrupt;
static void child_on_signal(int sig)
{
    (void)sig;
    child_interrupt = 1;
}

/* The worker process: one run, then _exit (the child must not return into
 * the caller's stack, nor run its atexit handlers or flush its stdio twice). */
static void worker(const gf_campaign *c, int index, const char *run_dir, int n_threads, const gf_sched_opts *opt,
                   double started, pid_t parent, slot *s)
{
    struct sigaction sa = {0};
    sa.sa_handler = child_on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    /* A worker never outlives the pool: its parent's end sends it SIGTERM (it
     * stops at its next step and checkpoints). A parent that died before the
     * request was registered shows as a changed parent id. */
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent)
        _exit(1);
    char what[GF_NAME_LEN + 16];
    snprintf(what, sizeof what, "campaign %s", c->name);
    gf_ctx ctx = {.log_level = GF_LOG_WARN};
    gf_run_exec_opts eo = {.run_dir = run_dir,
                           .campaign = c->name,
                           .n_threads = n_threads,
                           .progress = on_progress,
                           .progress_user = s,
                           .interrupt = &child_interrupt,
                           .resume = opt->resume,
                           .lock_what = what,
                           .keep_done = 1,
                           .keep_done_since = opt->resume ? 0.0 : started};
    gf_run_result res;
    gf_status st = gf_run_execute(&ctx, &c->runs[index].spec, &eo, &res);
    s->continued_from_s = res.continued_from_s;
    s->outcome = res.held ? OUTCOME_HELD : res.already_done ? OUTCOME_DONE_ELSEWHERE : OUTCOME_RAN;
    snprintf(s->message, sizeof s->message, "%s", res.held ? res.message : "");
    if (st != GF_OK)
        fprintf(stderr, "grainflow: %s\n", gf_ctx_message(&ctx));
    fflush(stderr);
    _exit(st == GF_OK && res.status == GF_OK ? 0 : 1);
}

typedef struct display {
    int tty, quiet, drawn;      /* drawn: lines of the live block on screen */
    int done, failed, total;
    int held, elsewhere;        /* left to another process; found done by another process */
    int *held_runs;             /* indices of the runs left to another process (held of them) */
    gf_campaign_eta eta;
} display;

static void clear_block(display *d)
{
    if (d->tty && d->drawn) {
        printf("\033[%dA\033[J", d->drawn);
        d->drawn = 0;
    }
}

/* ", continued from t = 12.5 sqrt(D/g)" for a run resumed from its checkpoint, "" otherwise. */
static void continued_text(const gf_run_spec *spec, double t_s, char *buf, size_t n)
{
    buf[0] = '\0';
    if (t_s > 0.0)
        snprintf(buf, n, ", continued from t = %.4g sqrt(D/g)",
                 t_s / sqrt(spec->grains.diameter_m / spec->gravity_m_s2));
}

/* A run this process did not run: another holds it, or finished it meanwhile. */
static void report_not_run(display *d, const gf_campaign *c, int index, int outcome, const char *message)
{
    char what[200];
    if (outcome == OUTCOME_HELD)
        d->held_runs[d->held++] = index;
    else
        ++d->elsewhere;
    if (d->quiet && outcome != OUTCOME_HELD)
        return;
    clear_block(d);
    gf_sched_describe(&c->runs[index], what, sizeof what);
    if (outcome == OUTCOME_HELD)
        printf("[%d/%d] %s skipped: %s  (%s)\n", d->done + d->failed + d->held + d->elsewhere, d->total,
               c->runs[index].spec.run_id, message, what);
    else
        printf("[%d/%d] %s done by another process since this campaign started  (%s)\n",
               d->done + d->failed + d->held + d->elsewhere, d->total, c->runs[index].spec.run_id, what);
    fflush(stdout);
}

static void report_finished(display *d, const gf_campaign *c, int index, const char *dir, double wall_s,
                            double continued_from_s)
{
    char reason[520], what[200], wall[32], cont[96];
    gf_run_state state = gf_ledger_state(dir, reason, sizeof reason);
    gf_campaign_eta_finished(&d->eta, index);
    if (state == GF_RUN_DONE)
        ++d->done;
    else
        ++d->failed;
    if (d->quiet)
        return;
    clear_block(d);
    gf_sched_describe(&c->runs[index], what, sizeof what);
    format_duration(wall_s, wall, sizeof wall);
    continued_text(&c->runs[index].spec, continued_from_s, cont, sizeof cont);
    const int seen = d->done + d->failed + d->held + d->elsewhere;
    if (state == GF_RUN_DONE)
        printf("[%d/%d] %s done    %s  (%s%s)\n", seen, d->total, c->runs[index].spec.run_id, what, wall, cont);
    else
        printf("[%d/%d] %s failed: %s  (%s, %s%s)\n", seen, d->total, c->runs[index].spec.run_id, reason, what, wall,
               cont);
    fflush(stdout);
}

static void draw_block(display *d, const gf_campaign *c, const slot *slots, int n_slots, int remaining)
{
    if (!d->tty || d->quiet)
        return;
    clear_block(d);
    for (int i = 0; i < n_slots; ++i) {
        if (slots[i].run < 0)
            continue;
        char text[160];
        gf_sched_progress_text(&slots[i].progress, text, sizeof text);
        printf("  %s  %s\n", c->runs[slots[i].run].spec.run_id, text);
        ++d->drawn;
    }
    int running = 0;
    double part = 0.0;
    for (int i = 0; i < n_slots; ++i)
        if (slots[i].run >= 0) {
            ++running;
            const gf_progress *p = &slots[i].progress;
            part += gf_campaign_eta_part(&d->eta, slots[i].run, p->t_end_s > 0 ? p->t_s / p->t_end_s : 0.0);
        }
    char eta[32];
    format_duration(gf_campaign_eta_left_s(&d->eta, part, gf_wtime()), eta, sizeof eta);
    printf("campaign %s: %d done, %d failed, %d running, %d remaining  ETA %s\n", c->name, d->done, d->failed,
           running, remaining, eta);
    ++d->drawn;
    fflush(stdout);
}

/* Runs left to another process that it finished (verified) by the end of
 * this campaign count as done elsewhere, not as held. Under MPI each rank
 * rechecks its own before the counts are summed. */
static void recheck_held(const gf_campaign *c, const gf_sched_opts *opt, double started, display *d)
{
    int kept = 0;
    for (int k = 0; d->held_runs && k < d->held; ++k) {
        char dir[4200];
        const int index = d->held_runs[k];
        gf_ledger_run_dir(opt->out_dir, c->name, c->runs[index].spec.run_id, dir, sizeof dir);
        if (gf_ledger_state(dir, NULL, 0) == GF_RUN_DONE && gf_manifest_time(dir) >= started &&
            gf_ledger_verified_state(dir, NULL, 0) == GF_RUN_DONE)
            ++d->elsewhere;
        else
            d->held_runs[kept++] = index;
    }
    d->held = kept;
}

/* Records why a worker ended without a status, unless another process holds
 * the run by now (then its directory is not ours to write). */
static void record_lost_worker(const char *dir, int wstatus)
{
    char why[128], lock_path[4300];
    if (WIFSIGNALED(wstatus))
        snprintf(why, sizeof why, "worker killed by signal %d (%s)", WTERMSIG(wstatus), strsignal(WTERMSIG(wstatus)));
    else
        snprintf(why, sizeof why, "worker exited with code %d before recording a status", WEXITSTATUS(wstatus));
    gf_ctx tmp = {0};
    gf_lock *lock = NULL;
    gf_lock_holder other;
    gf_ledger_lock_path(dir, lock_path, sizeof lock_path);
    if (gf_ledger_mkdirs(&tmp, dir) != GF_OK ||
        gf_lock_take(&tmp, lock_path, "campaign", 0.0, &lock, &other, NULL) != GF_OK || !lock)
        return;
    /* an earlier failure's reason is replaced, but not a checkpoint the run can still continue from */
    char reason[600];
    gf_run_state state = gf_ledger_state(dir, reason, sizeof reason);
    if (state == GF_RUN_NEW || (state == GF_RUN_FAILED && !strstr(reason, "checkpoint written")))
        gf_ledger_set_failed(&tmp, dir, why);
    gf_lock_release(&lock);
}

static gf_status run_pool(gf_ctx *ctx, const gf_campaign *c, const gf_sched_opts *opt, const int *todo, int n_todo,
                          double started, display *d)
{
    const pid_t self = getpid();
    int n_jobs = opt->n_jobs > 0 ? opt->n_jobs : 1;
    if (n_jobs > n_todo)
        n_jobs = n_todo > 0 ? n_todo : 1;
    slot *slots = mmap(NULL, (size_t)n_jobs * sizeof *slots, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1,
                       0);
    if (slots == MAP_FAILED)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "worker pool: cannot map the progress table: %s", strerror(errno));
    for (int i = 0; i < n_jobs; ++i)
        slots[i] = (slot){.run = -1};
    /* One thread per worker when several share the machine; the library
     * default (all cores) for a lone worker. */
    const int n_threads = n_jobs > 1 ? 1 : 0;
    int next = 0, running = 0, forwarded = 0;
    gf_status st = GF_OK;
    double last_draw = 0.0;
    fflush(stdout);
    fflush(stderr);
    while (next < n_todo || running > 0) {
        const int stop = opt->interrupt && *opt->interrupt;
        for (int i = 0; i < n_jobs && next < n_todo && !stop; ++i) {
            if (slots[i].run >= 0)
                continue;
            const int index = todo[next++];
            char dir[4200];
            gf_ledger_run_dir(opt->out_dir, c->name, c->runs[index].spec.run_id, dir, sizeof dir);
            slots[i] = (slot){.run = index,
                              .progress = {.started_s = gf_wtime(), .dt_s = gf_run_spec_dt_s(&c->runs[index].spec)}};
            pid_t pid = fork();
            if (pid == 0)
                worker(c, index, dir, n_threads, opt, started, self, &slots[i]);
            if (pid < 0) {
                st = GF_FAIL(ctx, GF_ERR_IO, "worker pool: fork failed: %s", strerror(errno));
                slots[i].run = -1;
                next = n_todo;
                break;
            }
            slots[i].pid = pid;
            ++running;
        }
        if (stop && next < n_todo)
            next = n_todo, st = GF_ERR_INTERRUPTED;
        if (stop && !forwarded) { /* a signal sent to this process alone (kill PID) reaches the runs too: they
                                     stop at their next step and checkpoint (a terminal's Ctrl-C or Slurm signal
                                     the whole group; a second signal changes nothing) */
            for (int i = 0; i < n_jobs; ++i)
                if (slots[i].run >= 0)
                    kill(slots[i].pid, SIGTERM);
            forwarded = 1;
        }
        int wstatus;
        pid_t pid;
        while (running > 0 && (pid = waitpid(-1, &wstatus, WNOHANG)) > 0) {
            for (int i = 0; i < n_jobs; ++i) {
                if (slots[i].run < 0 || slots[i].pid != pid)
                    continue;
                char dir[4200];
                const int index = slots[i].run;
                gf_ledger_run_dir(opt->out_dir, c->name, c->runs[index].spec.run_id, dir, sizeof dir);
                if (!WIFSIGNALED(wstatus) && slots[i].outcome != OUTCOME_RAN) {
                    report_not_run(d, c, index, slots[i].outcome, slots[i].message);
                } else {
                    if (WIFSIGNALED(wstatus) || gf_ledger_state(dir, NULL, 0) == GF_RUN_NEW)
                        record_lost_worker(dir, wstatus);
                    report_finished(d, c, index, dir, gf_wtime() - slots[i].progress.started_s,
                                    slots[i].continued_from_s);
                }
                slots[i].run = -1;
                --running;
            }
        }
        const double now = gf_wtime();
        if (now - last_draw > 0.5) {
            draw_block(d, c, slots, n_jobs, n_todo - next);
            last_draw = now;
        }
        struct timespec ts = {0, 50 * 1000 * 1000};
        nanosleep(&ts, NULL);
    }
    clear_block(d);
    munmap(slots, (size_t)n_jobs * sizeof *slots);
    recheck_held(c, opt, started, d);
    return st;
}

/* Under MPI: run i on rank i mod K, in this process; one line per run. */
static gf_status run_farm(gf_ctx *ctx, const gf_campaign *c, const gf_sched_opts *opt, const int *todo, int n_todo,
                          double started, display *d)
{
    char lock_what[GF_NAME_LEN + 32];
    snprintf(lock_what, sizeof lock_what, "campaign %s, MPI rank %d", c->name, gf_comm_rank());
    const int rank = gf_comm_rank(), size = gf_comm_size();
    gf_status st = GF_OK;
    for (int k = rank; k < n_todo; k += size) {
        if (opt->interrupt && *opt->interrupt) {
            st = GF_ERR_INTERRUPTED;
            break;
        }
        const int index = todo[k];
        char dir[4200], what[200];
        gf_ledger_run_dir(opt->out_dir, c->name, c->runs[index].spec.run_id, dir, sizeof dir);
        gf_run_exec_opts eo = {.run_dir = dir,
                               .campaign = c->name,
                               .interrupt = opt->interrupt,
                               .resume = opt->resume,
                               .lock_what = lock_what,
                               .keep_done = 1,
                               .keep_done_since = opt->resume ? 0.0 : started};
        gf_run_result res;
        gf_status est = gf_run_execute(ctx, &c->runs[index].spec, &eo, &res);
        if (est != GF_OK)
            gf_log(ctx, GF_LOG_WARN, "rank %d: %s", rank, gf_ctx_message(ctx));
        if (est == GF_OK && (res.held || res.already_done)) {
            if (res.held)
                d->held_runs[d->held++] = index;
            else
                ++d->elsewhere;
            printf("[rank %d] %s %s\n", rank, c->runs[index].spec.run_id,
                   res.held ? res.message : "done by another process since this campaign started");
            fflush(stdout);
            continue;
        }
        if (res.status == GF_OK && est == GF_OK)
            ++d->done;
        else
            ++d->failed;
        gf_sched_describe(&c->runs[index], what, sizeof what);
        char cont[96];
        continued_text(&c->runs[index].spec, res.continued_from_s, cont, sizeof cont);
        if (!opt->quiet)
            printf("[rank %d] %s %s %s  (%s%s%.1f s%s)\n", rank, c->runs[index].spec.run_id,
                   res.status == GF_OK ? "done   " : "failed:", res.status == GF_OK ? what : res.message,
                   res.status == GF_OK ? "" : what, res.status == GF_OK ? "" : ", ", res.wall_s, cont);
        fflush(stdout);
    }
    recheck_held(c, opt, started, d);
    d->done = (int)gf_comm_sum(d->done);
    d->failed = (int)gf_comm_sum(d->failed);
    d->held = (int)gf_comm_sum(d->held);
    d->elsewhere = (int)gf_comm_sum(d->elsewhere);
    int interrupted = (int)gf_comm_sum(st == GF_ERR_INTERRUPTED);
    return interrupted ? GF_ERR_INTERRUPTED : GF_OK;
}

gf_status gf_sched_run(gf_ctx *ctx, const gf_campaign *c, const gf_sched_opts *opt, gf_sched_counts *counts)
{
    memset(counts, 0, sizeof *counts);
    const int n_sel = opt->selected ? opt->n_selected : c->n_runs;
    int *todo = malloc((size_t)(n_sel > 0 ? n_sel : 1) * sizeof *todo);
    if (!todo)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "out of memory");
    int n_todo = 0;
    const double started = (double)time(NULL);
    for (int k = 0; k < n_sel; ++k) {
        const int index = opt->selected ? opt->selected[k] : k;
        char dir[4200], reason[600];
        gf_ledger_run_dir(opt->out_dir, c->name, c->runs[index].spec.run_id, dir, sizeof dir);
        gf_run_state state = opt->resume ? gf_ledger_verified_state(dir, reason, sizeof reason) : GF_RUN_NEW;
        if (state == GF_RUN_DONE) {
            ++counts->n_skipped;
            continue;
        }
        if (state == GF_RUN_CORRUPT) {
            ++counts->n_rerun;
            if (gf_comm_rank() == 0) {
                printf("run %s: marked done, but %s: running it again\n", c->runs[index].spec.run_id, reason);
                fflush(stdout);
            }
        }
        todo[n_todo++] = index;
    }
    counts->n_total = n_sel;
    char cdir[4200];
    snprintf(cdir, sizeof cdir, "%s/%s", opt->out_dir, c->name);
    gf_status st = gf_ledger_mkdirs(ctx, cdir);
    display d = {.tty = opt->tty && gf_comm_size() == 1, .quiet = opt->quiet, .total = n_todo,
                 .held_runs = malloc((size_t)(n_todo > 0 ? n_todo : 1) * sizeof(int))};
    if (!d.held_runs)
        st = GF_FAIL(ctx, GF_ERR_NOMEM, "out of memory");
    gf_campaign_eta_init(&d.eta, c, todo, n_todo, opt->n_jobs);
    d.eta.started_s = gf_wtime();
    if (st == GF_OK)
        st = gf_comm_size() > 1 ? run_farm(ctx, c, opt, todo, n_todo, started, &d)
                                : run_pool(ctx, c, opt, todo, n_todo, started, &d);
    free(d.held_runs);
    counts->n_done = d.done;
    counts->n_failed = d.failed;
    counts->n_held = d.held;
    counts->n_skipped += d.elsewhere;
    gf_campaign_eta_free(&d.eta);
    free(todo);
    if (st == GF_ERR_INTERRUPTED)
        return GF_FAIL(ctx, GF_ERR_INTERRUPTED, "campaign %s interrupted: %d done, %d failed, %d not started",
                       c->name, d.done, d.failed, n_todo - d.done - d.failed - d.held - d.elsewhere);
    return st;
}
