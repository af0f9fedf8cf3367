/*
 * One run, in this process: take the run directory's lock, write run.yaml,
 * build the scene, run it, check its files and record the status. Used by
 * every scheduler (worker pool child, MPI rank, Slurm array task, `grainflow
 * run`) so that a run is the same whatever launched it, and no two of them
 * write one run directory at once: a process that finds the lock held by
 * another writes nothing there and says who holds it (rundir/gf_lock.h).
 */
#ifndef GF_RUN_EXEC_H
#define GF_RUN_EXEC_H

#include "campaign/gf_campaign.h"
#include "core/gf_status.h"

typedef struct gf_run_exec_opts {
    const char *run_dir;       /* NULL: no files at all (benchmarks) */
    const char *campaign;      /* campaign name, for run.yaml */
    int n_threads;             /* 0: library default */
    void (*progress)(void *user, double t_s, double t_end_s, double steps_per_s);
    void *progress_user;
    volatile int *interrupt;
    int resume;                /* continue from run_dir/checkpoint.h5 when gf_ledger_can_continue */
    const char *lock_what;     /* what the lock record says holds the run ("campaign NAME"); NULL: "run" */
    int keep_done;             /* non-zero: a run found done (verified) with a manifest written at or after
                                  keep_done_since (Unix time) is left as it is: another process did it */
    double keep_done_since;
} gf_run_exec_opts;

typedef struct gf_run_result {
    gf_status status;
    char message[640];         /* failure reason, "" on success */
    double wall_s;
    long steps;
    long n_particles;
    double sim_time_s;
    double timers_s[16];       /* gf_sim_timers elapsed_s, GF_TIMER_COUNT entries */
    double continued_from_s;   /* simulated time the run continued from (resume), 0 for a fresh start */
    int held;                  /* another process holds the run directory: nothing done, who in message */
    int already_done;          /* found done and verified (keep_done_since): nothing done */
} gf_run_result;

/* Runs spec; never returns an error for a failed simulation: that is in
 * result->status (and in the status file). Returns non-OK only when the run
 * directory, its lock or run.yaml cannot be written. A run held by another
 * process (result->held) or already done (result->already_done) returns GF_OK
 * with result->status GF_OK and nothing written. */
gf_status gf_run_execute(gf_ctx *ctx, const gf_run_spec *spec, const gf_run_exec_opts *opt, gf_run_result *result);

#endif
