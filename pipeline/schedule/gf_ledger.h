/*
 * The run ledger: a campaign's state lives in its directory, nowhere else.
 *
 *   <out>/<campaign>/<run-id>/run.yaml   resolved spec (input of `grainflow run`)
 *   <out>/<campaign>/<run-id>/status     "done" or "failed: <reason>"
 *   <out>/<campaign>/<run-id>/manifest   size and CRC-32 of every file the
 *                                        run wrote (rundir/gf_manifest.h)
 *   <out>/<campaign>/<run-id>/.lock      held by the one process writing the
 *                                        run (rundir/gf_lock.h)
 *   <out>/<campaign>/<run-id>/checkpoint.h5, *.nc.partial
 *                                        what an interrupted dry run leaves
 *                                        for --resume to continue from
 *
 * Status and manifest are written to a temporary name and renamed (rename(2)
 * is atomic within a file system), so a killed run never leaves a status that
 * looks finished. "done" is written only after the manifest, and a run that
 * starts again first removes both, so "done" always comes with the list of
 * files it vouches for; --resume and post verify it before trusting it
 * (gf_ledger_verified_state). Keeping the state in files rather than in a
 * database means a campaign can be resumed by another process, another node
 * of a Slurm array, or after a crash; the run's lock file keeps two of them
 * from writing one run at once.
 */
#ifndef GF_LEDGER_H
#define GF_LEDGER_H

#include <stddef.h>

#include "core/gf_status.h"
#include "gf_run_spec.h"

/* GF_RUN_CORRUPT: the status says done but the files fail their manifest. */
typedef enum gf_run_state { GF_RUN_NEW = 0, GF_RUN_DONE, GF_RUN_FAILED, GF_RUN_CORRUPT } gf_run_state;

/* mkdir -p. */
gf_status gf_ledger_mkdirs(gf_ctx *ctx, const char *path);
/* Writes text to path via path.tmp + rename. */
gf_status gf_ledger_write_atomic(gf_ctx *ctx, const char *path, const char *text, size_t len);
/* <out>/<campaign>/<run-id> into buf. */
void gf_ledger_run_dir(const char *out_dir, const char *campaign, const char *run_id, char *buf, size_t n);
/* State of a run directory; the failure reason (if any) into reason. */
gf_run_state gf_ledger_state(const char *run_dir, char *reason, size_t n);
/* As gf_ledger_state, with a done run verified against its manifest: a
 * failed check gives GF_RUN_CORRUPT and the difference in reason. */
gf_run_state gf_ledger_verified_state(const char *run_dir, char *reason, size_t n);
/* <run_dir>/.lock into buf. */
void gf_ledger_lock_path(const char *run_dir, char *buf, size_t n);
/* Removes the manifest and a done status: a run that starts again is
 * unfinished until it ends, whatever its directory said before (a failed
 * status stays, for gf_ledger_can_continue). */
void gf_ledger_clear(const char *run_dir);
/* 1 when the run in run_dir can continue from its checkpoint instead of
 * starting again: its status says it was interrupted after writing
 * checkpoint.h5 (engine/sim/gf_run.c), that file is there, and its run.yaml
 * is yaml (len bytes) exactly, i.e. neither the spec nor the build that
 * wrote it (run.yaml's first line) changed since: a continued run's files
 * then come from one code. When a checkpoint is there but cannot be
 * continued, why (n bytes, may be NULL) names the first line that differs. */
int gf_ledger_can_continue(const char *run_dir, const char *yaml, size_t len, char *why, size_t n);
/* status file: "done" or "failed: <reason>". set_done first checks every file
 * of the run and writes the manifest; a file that does not reopen fails it
 * (and nothing says done). */
gf_status gf_ledger_set_done(gf_ctx *ctx, const char *run_dir);
gf_status gf_ledger_set_failed(gf_ctx *ctx, const char *run_dir, const char *reason);
/* The run.yaml text (header comments, campaign name, canonical spec) into a
 * malloc'ed string, *len its length. NULL when out of memory. */
char *gf_ledger_run_yaml(const gf_run_spec *spec, const char *campaign, size_t *len);

#endif
