/*
 * Replicates: runs of a campaign that are the same experiment drawn again,
 * i.e. whose resolved specs (run.yaml) differ only by the random seed (the
 * packing, the radii, the reinjection sites). A campaign law is fitted
 * through their mean, one point per experiment, as one longer run would give
 * it: the scatter of single realisations is not a misfit of the law.
 */
#ifndef GF_POST_REPLICATES_H
#define GF_POST_REPLICATES_H

#include "stages/gf_stage.h"

/* group[i] for each of the n rows: the index of the first row of its
 * replicate set (group[i] == i for the first); a row whose run.yaml cannot be
 * read is a set of its own. Returns the number of sets, -1 when out of memory. */
int gf_post_replicate_groups(const gf_post_row *rows, int n, int *group);

#endif
