/*
 * The campaign's ETA on its progress line. Each run weighs its estimated
 * CPU time (gf_cost.h); the pace is the weight finished per wall second so
 * far, running runs counted by their simulated fraction, and the time left
 * is the weight left at that pace. Until a run has finished (the pace of
 * running ones leaves out their preparation), the estimate alone, shared by
 * the workers. Runs that stop early (a deposit at rest)
 * finish ahead of their weight, so the ETA errs long, then catches up.
 */
#ifndef GF_ETA_H
#define GF_ETA_H

#include "campaign/gf_campaign.h"

typedef struct gf_campaign_eta {
    double *weight;       /* per run index of the campaign; NULL: no ETA */
    double total, done;   /* weight of the runs to do, and of those finished */
    double started_s;     /* wall time the campaign started */
    int n_jobs;
} gf_campaign_eta;

/* Weights of the runs todo[0..n_todo). Without memory, no ETA (not an error). */
void gf_campaign_eta_init(gf_campaign_eta *e, const gf_campaign *c, const int *todo, int n_todo, int n_jobs);
void gf_campaign_eta_finished(gf_campaign_eta *e, int index);
/* Weight of run index times its finished fraction (0 before t = 0). */
double gf_campaign_eta_part(const gf_campaign_eta *e, int index, double fraction);
/* Wall seconds left; running: the sum of gf_campaign_eta_part of the running runs. NaN when unknown. */
double gf_campaign_eta_left_s(const gf_campaign_eta *e, double running, double now_s);
void gf_campaign_eta_free(gf_campaign_eta *e);

#endif
