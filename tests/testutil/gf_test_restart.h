/*
 * The split run of the restart tests: one sim advanced 2N steps in one go,
 * with a checkpoint after N, against a second sim re-created from that
 * checkpoint and advanced N more; and the refusal of a checkpoint written by
 * a run of another kind (dry, another fluid tier).
 */
#ifndef GF_TEST_RESTART_H
#define GF_TEST_RESTART_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gf_sim.h"
#include "gf_test.h"
#include "gf_test_sim.h"

/* path = GF_BINARY_DIR (or /tmp) / stem_<pid>.h5: a checkpoint no other test run writes. */
static inline void gf_test_checkpoint_path(char *path, size_t size, const char *stem)
{
    snprintf(path, size, "%s/%s_%d.h5", getenv("GF_BINARY_DIR") ? getenv("GF_BINARY_DIR") : "/tmp", stem,
             (int)getpid());
}

/* *ref: spec advanced N steps, checkpointed at path, advanced N more; *restarted:
 * re-created from the checkpoint and advanced N (NULL when it failed, checked).
 * Returns 0 when the reference could not be made (checked too). One thread. */
static inline int gf_test_split_run(gf_ctx *ctx, const gf_run_spec *spec, long N, const char *path, gf_sim **ref,
                                    gf_sim **restarted)
{
    *ref = *restarted = NULL;
    GF_CHECK_OK(gf_test_sim(ctx, spec, 1, ref), ctx);
    if (!*ref)
        return 0;
    GF_CHECK_OK(gf_sim_advance(*ref, N), ctx);
    GF_CHECK_OK(gf_sim_checkpoint(*ref, path), ctx);
    GF_CHECK_OK(gf_sim_advance(*ref, N), ctx);
    GF_CHECK_OK(gf_test_sim_restart(ctx, spec, 1, path, restarted), ctx);
    if (*restarted)
        GF_CHECK_OK(gf_sim_advance(*restarted, N), ctx);
    return 1;
}

/* A run of spec `other` advanced `steps` and checkpointed at path; a restart
 * of `spec` from it must be refused as a config error whose message holds
 * `why`. what: the printed line's label. */
static inline void gf_test_restart_refused(gf_ctx *ctx, const gf_run_spec *spec, const gf_run_spec *other, long steps,
                                           const char *path, const char *why, const char *what)
{
    gf_sim *d = NULL, *b = NULL;
    GF_CHECK_OK(gf_test_sim(ctx, other, 1, &d), ctx);
    if (!d)
        return;
    if (steps > 0)
        GF_CHECK_OK(gf_sim_advance(d, steps), ctx);
    GF_CHECK_OK(gf_sim_checkpoint(d, path), ctx);
    gf_sim_destroy(&d);
    gf_status st = gf_test_sim_restart(ctx, spec, 1, path, &b);
    printf("%s: %s\n", what, ctx->last_msg);
    GF_CHECK(st == GF_ERR_CONFIG && strstr(ctx->last_msg, why) != NULL);
    gf_sim_destroy(&b);
}

#endif
