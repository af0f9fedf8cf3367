/*
 * A post-processing stage run on one synthetic run directory, as
 * gf_post_campaign runs it on each run of a campaign.
 */
#ifndef SYNTH_STAGE_H
#define SYNTH_STAGE_H

#include "stages/gf_stage.h"

/* stage on the run in dir (scene: the name its files give) into row, which
 * the caller has initialised (gf_post_row_init); series non-zero: the stage
 * writes <dir>/post_<stage>.nc too. Returns the stage's status. */
static inline gf_status synth_stage(gf_ctx *ctx, gf_stage_fn *stage, const char *dir, const char *scene, int series,
                                    gf_post_row *row)
{
    gf_stage_in in = {dir, scene};
    gf_stage_opts opts = {series};
    gf_stage_out out = {row};
    return stage(ctx, &in, &opts, &out);
}

#endif
