/*
 * Campaign scheduling: which run goes where, and the progress display.
 *
 * Local: a fork-based worker pool of n_jobs processes. Each run gets its own
 * process, so a crash (a signal, an abort inside a library) fails one run and
 * not the campaign, and runs share no state (no global in any library can
 * leak between runs). Workers report simulated time and steps/s through a
 * small shared-memory table that the parent reads to draw the progress.
 *
 * MPI (`mpirun -n K grainflow campaign ...`): a static cyclic task farm, run
 * i on rank i mod K, each run in its rank's process. Runs of a campaign are
 * independent and no message is needed until the final counts; cyclic order
 * interleaves the grid so that the cheap and the dear corners spread over the
 * ranks. Forking inside an MPI process is avoided (not all transports allow it).
 *
 * In both, runs whose status is done are skipped with resume once their files
 * pass their manifest (a run that fails it is run again, saying so), and a
 * failed run is recorded in its status file while the campaign goes on. Each
 * run takes its directory's lock (gf_run_exec.h): a run another process holds
 * is left to it and reported with its holder, and a run another process
 * finished since this campaign started is not run again, so two campaigns on
 * one directory share its runs. Workers die with the pool: each asks for
 * SIGTERM when its parent ends (prctl PR_SET_PDEATHSIG), which makes it stop
 * and checkpoint like an interrupt.
 */
#ifndef GF_SCHED_H
#define GF_SCHED_H

#include "campaign/gf_campaign.h"

typedef struct gf_sched_opts {
    const char *out_dir;          /* runs go to <out_dir>/<campaign>/<run-id> */
    int n_jobs;                   /* local workers; <= 0: 1 */
    int resume;                   /* skip runs whose status is done; continue interrupted ones from their checkpoint */
    const int *selected;          /* run indices to consider; NULL: all */
    int n_selected;
    int tty;                      /* draw updating progress lines */
    int quiet;                    /* no per-run lines */
    volatile int *interrupt;      /* set by a signal handler: stop launching, let runs checkpoint */
} gf_sched_opts;

typedef struct gf_sched_counts {
    int n_total, n_done, n_failed, n_skipped;
    int n_held;        /* left to another process that holds the run directory */
    int n_rerun;       /* marked done but failing their manifest, run again (resume) */
} gf_sched_counts;

/* Runs the selected runs of c. Returns GF_OK when every run was attempted
 * (failed runs are counted, not errors), GF_ERR_INTERRUPTED when stopped by
 * *interrupt, GF_ERR_IO when the campaign directory cannot be written.
 * Under MPI: collective; counts are summed over ranks. */
gf_status gf_sched_run(gf_ctx *ctx, const gf_campaign *c, const gf_sched_opts *opt, gf_sched_counts *counts);

/* One line describing run r's groups ("St=0.6 r=3.65 a=0.5 Phi_i=0.6 [immersed]"). */
void gf_sched_describe(const gf_campaign_run *r, char *buf, size_t n);
/* Progress of one run as the engine reports it. The ETA extrapolates the
 * simulated-time rate measured since the clock first moved, so the scene
 * preparation (packing, settling: before t = 0) does not distort it; until
 * a second report gives that rate, the reported steps/s times the step dt_s. */
typedef struct gf_progress {
    double t_s, t_end_s, steps_per_s;
    double dt_s;              /* the run's DEM step (set by whoever starts the run); 0: unknown */
    double wall0_s, t0_s;     /* wall time and simulated time at the first report with t > 0 */
    double started_s;         /* wall time the run started */
} gf_progress;
/* Records a report (engine progress callback arguments). */
void gf_progress_update(gf_progress *p, double t_s, double t_end_s, double steps_per_s);
/* "t = 12.3/40.0 s (31%)  1.2e+04 steps/s  ETA 0:45", or "preparing ... 0:12" before t = 0. */
void gf_sched_progress_text(const gf_progress *p, char *buf, size_t n);

#endif
