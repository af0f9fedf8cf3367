/* Slurm job-array script; see gf_slurm.h. */
#include "schedule/gf_slurm.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "schedule/gf_ledger.h"

gf_status gf_slurm_emit(gf_ctx *ctx, const gf_campaign *c, const gf_slurm_opts *opt, char *path_out, size_t n)
{
    char dir[4200];
    snprintf(dir, sizeof dir, "%s/%s", opt->out_dir, c->name);
    GF_TRY(gf_ledger_mkdirs(ctx, dir));
    /* --set entries, single-quoted for the shell (a ' inside becomes '\'') */
    char sets[2048] = "";
    for (int i = 0; i < opt->n_sets; ++i) {
        size_t len = strlen(sets);
        snprintf(sets + len, sizeof sets - len, " --set '");
        for (const char *p = opt->sets[i]; *p && strlen(sets) + 5 < sizeof sets; ++p) {
            len = strlen(sets);
            if (*p == '\'')
                snprintf(sets + len, sizeof sets - len, "'\\''");
            else
                snprintf(sets + len, sizeof sets - len, "%c", *p);
        }
        len = strlen(sets);
        snprintf(sets + len, sizeof sets - len, "'");
    }
    size_t cap = 8192;
    char *text = malloc(cap);
    if (!text)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "out of memory");
    int len = snprintf(
        text, cap,
        "#!/bin/bash\n"
        "# Slurm job array for grainflow campaign '%s' (%d runs), written by\n"
        "#   grainflow campaign %s --emit slurm -o %s\n"
        "# Submit:   sbatch %s/%s.slurm\n"
        "# Then:     sbatch --dependency=afterany:<jobid> --wrap \"%s post %s\"\n"
        "# Task k runs run k of the expanded campaign (grainflow check lists them);\n"
        "# --resume makes a repeated task skip a run whose status is done.\n"
        "#SBATCH --job-name=gf-%s\n"
        "#SBATCH --array=0-%d\n"
        "#SBATCH --ntasks=1\n"
        "#SBATCH --cpus-per-task=%d\n"
        "#SBATCH --time=%s\n"
        "#SBATCH --output=%s/slurm-%%A_%%a.out\n"
        "set -euo pipefail\n"
        "export OMP_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}\n"
        "GRAINFLOW=${GRAINFLOW:-%s}\n"
        "exec \"$GRAINFLOW\" campaign %s -o %s --index \"$SLURM_ARRAY_TASK_ID\" --resume --no-post%s\n",
        c->name, c->n_runs, opt->config_path, opt->out_dir, dir, c->name, opt->executable, dir, c->name,
        c->n_runs - 1, opt->cpus_per_task > 0 ? opt->cpus_per_task : 1, opt->time_limit ? opt->time_limit : "04:00:00",
        dir, opt->executable, opt->config_path, opt->out_dir, sets);
    if (len < 0 || (size_t)len >= cap) {
        free(text);
        return GF_FAIL(ctx, GF_ERR_ARG, "slurm: paths too long");
    }
    snprintf(path_out, n, "%s/%s.slurm", dir, c->name);
    gf_status st = gf_ledger_write_atomic(ctx, path_out, text, (size_t)len);
    free(text);
    return st;
}
