/* Campaign ETA from the estimated cost of its runs; see gf_eta.h. */
#include "schedule/gf_eta.h"

#include <math.h>
#include <stdlib.h>

#include "campaign/gf_cost.h"

void gf_campaign_eta_init(gf_campaign_eta *e, const gf_campaign *c, const int *todo, int n_todo, int n_jobs)
{
    *e = (gf_campaign_eta){.n_jobs = n_jobs > 0 ? n_jobs : 1};
    e->weight = calloc((size_t)(c->n_runs > 0 ? c->n_runs : 1), sizeof *e->weight);
    if (!e->weight)
        return;
    for (int k = 0; k < n_todo; ++k) {
        gf_run_cost cost;
        gf_cost_estimate(&c->runs[todo[k]].spec, &cost);
        /* a run the scene cannot estimate weighs the mean of the others (1 s when none can) */
        e->weight[todo[k]] = isfinite(cost.cpu_s) && cost.cpu_s > 0 ? cost.cpu_s : NAN;
    }
    double sum = 0.0;
    int n = 0;
    for (int k = 0; k < n_todo; ++k)
        if (!isnan(e->weight[todo[k]]))
            sum += e->weight[todo[k]], ++n;
    for (int k = 0; k < n_todo; ++k) {
        if (isnan(e->weight[todo[k]]))
            e->weight[todo[k]] = n ? sum / n : 1.0;
        e->total += e->weight[todo[k]];
    }
}

void gf_campaign_eta_finished(gf_campaign_eta *e, int index)
{
    if (e->weight)
        e->done += e->weight[index];
}

double gf_campaign_eta_part(const gf_campaign_eta *e, int index, double fraction)
{
    if (!e->weight || !(fraction > 0.0))
        return 0.0;
    return e->weight[index] * fmin(fraction, 1.0);
}

double gf_campaign_eta_left_s(const gf_campaign_eta *e, double running, double now_s)
{
    if (!e->weight || !(e->total > 0.0))
        return NAN;
    const double done = e->done + running, left = fmax(e->total - done, 0.0), elapsed = now_s - e->started_s;
    if (e->done > 0.0 && elapsed > 0.0) /* a run has finished: its preparation is in the pace too */
        return left / (done / elapsed);
    return left / e->n_jobs; /* nothing finished yet: the estimate, one core per worker */
}

void gf_campaign_eta_free(gf_campaign_eta *e)
{
    free(e->weight);
    e->weight = NULL;
}
