/* See gf_cli_verdict.h. */
#include "cli/gf_cli_verdict.h"

#include <stdio.h>

int gf_cli_post_verdict(const char *cmd, const gf_post_report *rep)
{
    const int bad = rep->n_runs - rep->n_ok;
    if (rep->n_runs > 0 && bad == 0)
        return 0;
    fprintf(stderr,
            "grainflow %s: %d of %d run(s) not ok (%d failed, %d corrupt, %d incomplete, %d post-processing "
            "error): the summary's status and error columns say why\n",
            cmd, bad, rep->n_runs, rep->n_failed, rep->n_corrupt, rep->n_incomplete, rep->n_error);
    return 1;
}
