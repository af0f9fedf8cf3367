/*
 * The split run of the restart tests: one sim advanced 2N steps in one go,
 * with a checkpoint after N, against a second sim re-created from that
 * checkpoint and advanced N more, compared bitwise (grains, pressure); and
 * the refusal of a checkpoint written by a run of another kind (dry, another
 * fluid tier). gf_test_restart runs the whole test.
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

/* The excess pressure of sims a and b at the n points x (Pa, into pa and pb);
 * 1 when each pair holds the same bytes. */
static inline int gf_test_same_pressure(const gf_sim *a, const gf_sim *b, int n, const double (*x)[3], double *pa,
                                        double *pb)
{
    int same = 1;
    for (int k = 0; k < n; ++k) {
        pa[k] = gf_sim_excess_pressure_Pa(a, x[k]);
        pb[k] = gf_sim_excess_pressure_Pa(b, x[k]);
        same = same && memcmp(&pa[k], &pb[k], sizeof(double)) == 0;
    }
    return same;
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

/* What a restart test compares and which checkpoint it must refuse. */
typedef struct gf_test_restart_case {
    const char *stem; /* the checkpoint's file stem (gf_test_checkpoint_path) */
    long N;           /* steps before and after the checkpoint */
    /* the checks on ref (2N steps in one go) and restarted (from the checkpoint, N more) */
    void (*compare)(gf_ctx *ctx, const gf_run_spec *spec, long N, gf_sim *ref, gf_sim *restarted);
    const gf_run_spec *other; /* the run of another kind whose checkpoint (after other_steps) is refused */
    long other_steps;
    const char *why, *what;   /* as in gf_test_restart_refused */
} gf_test_restart_case;

/* The split run of spec compared by c->compare (when both runs were made),
 * then the refusal; removes the checkpoint. Returns gf_test_finish(); early,
 * skipping the rest, when the reference run could not be made. */
static inline int gf_test_restart(gf_ctx *ctx, const gf_run_spec *spec, const gf_test_restart_case *c)
{
    char path[512];
    gf_test_checkpoint_path(path, sizeof path, c->stem);
    gf_sim *ref = NULL, *restarted = NULL;
    if (!gf_test_split_run(ctx, spec, c->N, path, &ref, &restarted))
        return gf_test_finish();
    if (restarted)
        c->compare(ctx, spec, c->N, ref, restarted);
    gf_sim_destroy(&restarted);
    gf_sim_destroy(&ref);
    gf_test_restart_refused(ctx, spec, c->other, c->other_steps, path, c->why, c->what);
    remove(path);
    return gf_test_finish();
}

#endif
