/*
 * What the configuration reader must do with any input, valid or not: either
 * a campaign of at least one run, or no campaign and a GF_ERR_CONFIG /
 * GF_ERR_PHYSICS (GF_ERR_NOMEM) status whose message is one line starting
 * with the file name and a colon. Shared by the libFuzzer harness
 * (fuzz_cfg.c) and the replay of the corpus it grew (test_cfg_corpus.c).
 * Returns NULL when the outcome is acceptable, else what is wrong.
 */
#ifndef GF_CFG_PROPERTY_H
#define GF_CFG_PROPERTY_H

#include <string.h>

#include "campaign/gf_campaign.h"

static inline const char *gf_cfg_outcome_fault(gf_status st, const gf_campaign *c, const gf_ctx *ctx,
                                               const char *name)
{
    if (st == GF_OK)
        return c && c->n_runs >= 1 ? NULL : "accepted without a run";
    if (c)
        return "refused but returned a campaign";
    if (st != GF_ERR_CONFIG && st != GF_ERR_PHYSICS && st != GF_ERR_NOMEM)
        return "refused with a status other than config / physics / memory";
    const size_t n = strlen(name);
    if (strncmp(ctx->last_msg, name, n) != 0 || ctx->last_msg[n] != ':')
        return "message does not start with the file name";
    if (strchr(ctx->last_msg, '\n'))
        return "message is more than one line";
    return NULL;
}

#endif
