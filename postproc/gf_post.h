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

/* Post-processes every run directory below campaign_dir (or campaign_dir itself
 * when it is a single run directory). A broken run gives a per-run message and a
 * marked summary row; the others are still summarised. Returns GF_OK unless the
 * directory cannot be read or the summary cannot be written. */
gf_status gf_post_campaign(gf_ctx *ctx, const char *campaign_dir, const gf_post_options *opt);

#endif
