/*
 * Post-processing of a campaign directory: run every stage (or one) on every
 * run directory, then write summary.nc and summary.csv (one row per run,
 * failed runs included with their status) and the figures (SVG) from the
 * summary. Reads netCDF only (docs/output.md), so runs made yesterday, on
 * another machine or by another version are post-processed the same way.
 */
#ifndef GF_POST_H
#define GF_POST_H

#include "core/gf_status.h"

typedef struct gf_post_options {
    const char *stage;   /* NULL: all stages; else one stage name */
    int n_jobs;          /* runs processed in parallel; 0 or 1: serial */
    int figures;         /* non-zero: write figures/ */
    int quiet;
} gf_post_options;

/* What a post found, by the status of each summary row. */
typedef struct gf_post_report {
    int n_campaigns, n_runs;
    int n_ok, n_failed, n_corrupt, n_incomplete, n_error;
} gf_post_report;

/* Post-processes every run directory below campaign_dir (or campaign_dir itself
 * when it is a single run directory). A broken run gives a per-run message and a
 * marked summary row; the others are still summarised. A run marked done is
 * first verified against its manifest (rundir/gf_manifest.h): one that fails
 * is "corrupt". The stages of a run run under its lock (a run being written is
 * "incomplete", naming its writer), and the summary and figures under the
 * campaign's (.summary.lock; a second post waits for the first). Returns GF_OK
 * unless the directory cannot be read or the summary cannot be written; the
 * rows' statuses are counted into *rep (may be NULL). */
gf_status gf_post_campaign_report(gf_ctx *ctx, const char *campaign_dir, const gf_post_options *opt,
                                  gf_post_report *rep);
gf_status gf_post_campaign(gf_ctx *ctx, const char *campaign_dir, const gf_post_options *opt);

/* dir itself when it is a run or campaign directory, else every campaign
 * directory found below it (up to 4 levels, named on stderr), each
 * post-processed as above; counts summed into *rep. GF_ERR_IO, writing
 * nothing, when there is no run directory in or below dir. */
gf_status gf_post_tree(gf_ctx *ctx, const char *dir, const gf_post_options *opt, gf_post_report *rep);

#endif
