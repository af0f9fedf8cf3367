/*
 * Deposits shared between the runs of a campaign.
 *
 * A (St, r) grid at fixed (a, Phi_i) asks for the same column again and
 * again: St and r change the fluid, not the dry preparation, whose deposits
 * (gf_packing_build, 1-4 of them per column) are a third to a half of a small
 * run's time. The preparation is deterministic, so a deposit built once for a
 * spec is, bit for bit, the one any later run with that spec would build; it
 * is kept in a directory (the campaign's "preparations/") and read back.
 *
 * What identifies a deposit: every field of gf_packing_spec written out as
 * text ("key", %.17g for reals), the obstacles' positions and radii, the
 * preparation protocol's version (GF_PACKING_PROTOCOL, raised whenever
 * gf_packing.c changes what it builds) and the source (GF_VERSION and the
 * revision gf_build_revision(): the commit, and for uncommitted code a hash
 * of its diff, so an edit is another source while a rebuild of the same
 * source, e.g. a fresh build directory, keeps the deposits).
 * The file name is a 64-bit FNV-1a hash of all of it; on reading, the key
 * text and the obstacles are compared in full, so a hash collision is a
 * miss, never a wrong deposit. A file that cannot be read (cut short,
 * foreign) is a miss too: the deposit is rebuilt and the file replaced.
 * Files are written under a per-process temporary name and renamed, so runs
 * preparing the same column at the same time never see half a file.
 */
#ifndef GF_PACKING_CACHE_H
#define GF_PACKING_CACHE_H

#include "particles/gf_packing.h"

/* Version of the preparation protocol in the cache key. */
#define GF_PACKING_PROTOCOL 2

/* gf_packing_build through the cache in dir (created when missing; NULL:
 * no cache, plain gf_packing_build). res->reused tells whether the deposit
 * was read back; res->cpu_s is then the time of the original preparation.
 * Errors: those of gf_packing_build; a cache that cannot be written is
 * logged and does not fail the preparation. */
gf_status gf_packing_build_cached(gf_ctx *ctx, const gf_packing_spec *spec, const char *dir, gf_particles *out,
                                  gf_packing_result *res);

#endif
