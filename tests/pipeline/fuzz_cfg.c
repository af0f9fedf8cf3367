/*
 * libFuzzer entry for the configuration reader: any byte string is parsed
 * and expanded as a campaign, and must meet gf_cfg_outcome_fault's property
 * (cfg_property.h) with no sanitizer report and no leak. Built with every
 * library instrumented (GF_FUZZ, workflows/fuzz.sh), so that the fuzzer
 * steers by the reader's branches; the corpus it grows is committed in
 * tests/pipeline/fuzz_corpus and replayed by test_cfg_corpus.
 */
#include <stdint.h>
#include <stdlib.h>

#include "cfg_property.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    gf_ctx ctx = {0};
    gf_campaign *c = NULL;
    gf_status st = gf_campaign_load_string(&ctx, "fuzz.yaml", (const char *)data, size, NULL, 0, &c);
    if (gf_cfg_outcome_fault(st, c, &ctx, "fuzz.yaml"))
        abort();
    gf_campaign_destroy(&c);
    return 0;
}
