/*
 * How figures name a campaign's runs: by their variant and the groups that
 * tell them apart, never by run hash ("immersed, a=1, Phi_i=0.58").
 *
 * The variant is read from the run's fluid model, the one thing a run
 * directory records that separates a campaign's variants here: "dry" for
 * fluid_model none, "immersed" otherwise ("immersed (<model>)" when the
 * immersed runs use more than one tier).
 */
#ifndef GF_POST_LABEL_H
#define GF_POST_LABEL_H

#include "stages/gf_stage.h"

enum { GF_POST_LABEL_LEN = 96, GF_POST_MAX_VARIANTS = 8 };

typedef struct gf_post_variants {
    int n;                                               /* distinct variants among the runs */
    char names[GF_POST_MAX_VARIANTS][GF_POST_LABEL_LEN]; /* "dry", "immersed", ... */
} gf_post_variants;

/* variant[i] for each of the n rows (index into out->names). */
void gf_post_run_variants(const gf_post_row *rows, int n, int *variant, gf_post_variants *out);

/* labels[i]: the variant when the runs hold more than one, then each group
 * (St, r, a, Phi_i) that takes more than one value across the runs, as
 * "name=value" (%g). Two runs that would share a label get their run id
 * appended (e.g. seeds of one point); a single run is named by its groups. */
void gf_post_run_labels(const gf_post_row *rows, int n, char (*labels)[GF_POST_LABEL_LEN]);

#endif
