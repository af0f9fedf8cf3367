/*
 * The run ledger: a campaign's state lives in its directory, nowhere else.
 *
 *   <out>/<campaign>/<run-id>/run.yaml   resolved spec (input of `grainflow run`)
 *   <out>/<campaign>/<run-id>/status     "done" or "failed: <reason>"
 *   <out>/<campaign>/<run-id>/checkpoint.h5, *.nc.partial
 *                                        what an interrupted dry run leaves
 *                                        for --resume to continue from
 *
 * Both are written to a temporary name and renamed (rename(2) is atomic
 * within a file system), so a killed run never leaves a status that looks
 * finished, and --resume trusts "done" alone. Keeping the state in files
 * rather than in a database means a campaign can be resumed by another
 * process, another node of a Slurm array, or after a crash, with no lock
 * beyond one directory per run.
 */
#ifndef GF_LEDGER_H
#define GF_LEDGER_H

#include <stddef.h>

#include "core/gf_status.h"
#include "gf_run_spec.h"

typedef enum gf_run_state { GF_RUN_NEW = 0, GF_RUN_DONE, GF_RUN_FAILED } gf_run_state;

/* mkdir -p. */
gf_status gf_ledger_mkdirs(gf_ctx *ctx, const char *path);
/* Writes text to path via path.tmp + rename. */
gf_status gf_ledger_write_atomic(gf_ctx *ctx, const char *path, const char *text, size_t len);
/* <out>/<campaign>/<run-id> into buf. */
void gf_ledger_run_dir(const char *out_dir, const char *campaign, const char *run_id, char *buf, size_t n);
/* State of a run directory; the failure reason (if any) into reason. */
gf_run_state gf_ledger_state(const char *run_dir, char *reason, size_t n);
/* 1 when the run in run_dir can continue from its checkpoint instead of
 * starting again: its status says it was interrupted after writing
 * checkpoint.h5 (engine/gf_sim_run.c), that file is there, and its run.yaml
 * is yaml (len bytes) exactly, i.e. the spec did not change since. */
int gf_ledger_can_continue(const char *run_dir, const char *yaml, size_t len);
/* status file: "done" or "failed: <reason>". */
gf_status gf_ledger_set_done(gf_ctx *ctx, const char *run_dir);
gf_status gf_ledger_set_failed(gf_ctx *ctx, const char *run_dir, const char *reason);
/* The run.yaml text (header comments, campaign name, canonical spec) into a
 * malloc'ed string, *len its length. NULL when out of memory. */
char *gf_ledger_run_yaml(const gf_run_spec *spec, const char *campaign, size_t *len);

#endif
