/*
 * The manifest of a finished run: <run>/manifest lists every file the run
 * wrote (run.yaml, the netCDF files, anything the engine puts beside them),
 * each with its size in bytes and its CRC-32 (zlib), after each netCDF file
 * was reopened and read as netCDF. The run's status says `done` only after
 * the manifest is in place, and whoever trusts a done run (`campaign
 * --resume`, `post`) verifies it first: the files are there, open, and have
 * the recorded sizes and checksums. A file cut short by a full disk, a killed
 * writer or a second writer fails that check, and the run counts as
 * unfinished.
 *
 * Not listed: status, manifest, the lock file, post_<stage>.nc (written later
 * by `post`), checkpoint.h5 and the temporary files of an unfinished write
 * (*.tmp*, *.partial).
 */
#ifndef GF_MANIFEST_H
#define GF_MANIFEST_H

#include <stddef.h>

#include "core/gf_status.h"

/* Checks and records every file of run_dir, into <run_dir>/manifest (written
 * to a temporary name and renamed). Fails, naming the file, when one does not
 * reopen; no manifest is left then. */
gf_status gf_manifest_write(gf_ctx *ctx, const char *run_dir);

/* 1 when the files of run_dir match its manifest (present, same size, same
 * CRC-32, netCDF files open); 0 with the first difference in reason. A run
 * without a manifest (made by an older version) passes when each of its
 * netCDF files opens. */
int gf_manifest_verify(const char *run_dir, char *reason, size_t n);

/* Unix time (s) at which the manifest of run_dir was written, 0 if none. */
double gf_manifest_time(const char *run_dir);

#endif
