/*
 * Slurm job-array script for a campaign (`grainflow campaign FILE --emit slurm`).
 *
 * Array task k runs run k of the expanded campaign (`--index k`), so the
 * mapping from task to run is the campaign's own deterministic order and
 * needs no list file; --resume makes a requeued or repeated task a no-op for
 * finished runs. Post-processing is a separate job that depends on the array
 * (afterany: failed runs are summarised too). Template and MPI example:
 * workflows/slurm/, workflows/mpi/.
 */
#ifndef GF_SLURM_H
#define GF_SLURM_H

#include "campaign/gf_campaign.h"

typedef struct gf_slurm_opts {
    const char *config_path;     /* absolute path of the campaign file */
    const char *out_dir;         /* absolute output directory */
    const char *executable;      /* absolute path of grainflow */
    const char *time_limit;      /* per task, e.g. "02:00:00" */
    int cpus_per_task;
    const char *const *sets;     /* --set entries passed on to every task */
    int n_sets;
} gf_slurm_opts;

/* Writes <out_dir>/<campaign>/<campaign>.slurm; its path into path_out. */
gf_status gf_slurm_emit(gf_ctx *ctx, const gf_campaign *c, const gf_slurm_opts *opt, char *path_out, size_t n);

#endif
