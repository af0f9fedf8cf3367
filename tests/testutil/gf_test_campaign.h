/*
 * Campaigns for the pipeline tests: a campaign file's text loaded as the
 * CLI would load the file, with no --set overrides.
 */
#ifndef GF_TEST_CAMPAIGN_H
#define GF_TEST_CAMPAIGN_H

#include <string.h>

#include "campaign/gf_campaign.h"
#include "gf_test.h"

/* text loaded as the campaign file `name` (the name its messages give),
 * checked; NULL when refused. Owner: the caller (gf_campaign_destroy). */
static inline gf_campaign *gf_test_campaign(gf_ctx *ctx, const char *name, const char *text)
{
    gf_campaign *c = NULL;
    GF_CHECK_OK(gf_campaign_load_string(ctx, name, text, strlen(text), NULL, 0, &c), ctx);
    return c;
}

#endif
