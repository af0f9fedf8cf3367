/*
 * libFuzzer entry for the configuration reader: any byte string is parsed
 * and expanded as a campaign. The property checked is the one the corpus
 * test checks on fixed files: no crash, no sanitizer report, no leak, and
 * either a campaign or a GF_ERR_CONFIG / GF_ERR_PHYSICS status with a
 * one-line located message ("fuzz.yaml:line:column: ...").
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "campaign/gf_campaign.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    gf_ctx ctx = {0};
    gf_campaign *c = NULL;
    gf_status st = gf_campaign_load_string(&ctx, "fuzz.yaml", (const char *)data, size, NULL, 0, &c);
    if (st == GF_OK) {
        if (!c || c->n_runs < 1)
            abort();
    } else {
        if (c || strncmp(ctx.last_msg, "fuzz.yaml:", 10) != 0 || strchr(ctx.last_msg, '\n'))
            abort();
        if (st != GF_ERR_CONFIG && st != GF_ERR_PHYSICS && st != GF_ERR_NOMEM)
            abort();
    }
    gf_campaign_destroy(&c);
    return 0;
}
