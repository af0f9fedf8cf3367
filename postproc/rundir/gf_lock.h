/*
 * One writer per file set: an advisory lock on a lock file, taken by whoever
 * writes a run directory (<run>/.lock: `campaign` workers, MPI ranks, Slurm
 * array tasks, `run`, `post` for its post_<stage>.nc) or a campaign's summary
 * and figures (<campaign>/.summary.lock: `post`, and `campaign` when it
 * post-processes).
 *
 * The lock is flock(2) on the open file: the kernel drops it when its holder
 * ends in any way (exit, crash, kill -9), so a holder that died cannot block
 * anyone, and two processes cannot both hold it. The holder writes who it is
 * into the file (pid, host, start time, what), which a process that finds the
 * lock held reports; a clean release empties the file, so a non-empty file
 * found unlocked is the trace of a holder that died holding it (a stale lock):
 * the new holder takes it over and says whose it was. On Linux, flock on NFS
 * is carried by the NFS lock manager (fcntl byte-range locks), so the lock
 * also holds between nodes; Lustre needs the `flock` mount option.
 */
#ifndef GF_LOCK_H
#define GF_LOCK_H

#include <stddef.h>

#include "core/gf_status.h"

typedef struct gf_lock gf_lock;

/* Who holds (or held) a lock, as recorded in its file. */
typedef struct gf_lock_holder {
    long pid;
    char host[64];
    long since;          /* Unix time the lock was taken */
    char what[96];       /* "campaign tiny", "run", "post", ... */
} gf_lock_holder;

/* Takes the lock of lock_path (created if absent), waiting at most wait_s
 * seconds (0: one try). On success *out is the lock; when another process
 * holds it past the wait, *out is NULL and *other says who (GF_OK both ways).
 * *stale (may be NULL) is set to 1 when the lock was taken over from a holder
 * that ended without releasing it, whose record is then in *other.
 * Errors: GF_ERR_IO when the file cannot be opened or locked. */
gf_status gf_lock_take(gf_ctx *ctx, const char *lock_path, const char *what, double wait_s, gf_lock **out,
                       gf_lock_holder *other, int *stale);

/* Releases (empties the record, unlocks, closes). Accepts NULL *lock. */
void gf_lock_release(gf_lock **lock);

/* "pid 1234 on node7 (campaign tiny) since 2026-11-26 19:50:02 UTC" into buf. */
void gf_lock_describe(const gf_lock_holder *h, char *buf, size_t n);

#endif
