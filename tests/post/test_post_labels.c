/*
 * Legend labels of a campaign's runs (gf_post_label.h). The demo's eight runs
 * (dry and immersed over a x Phi_i at one St, r) are named by variant and the
 * two groups that vary, never by hash; a group every run shares is left out;
 * two runs that would share a label (seeds of one point) keep their run ids;
 * the variants are numbered in the order met, dry and immersed.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gf_test.h"
#include "stages/gf_post_label.h"

static void make_row(gf_post_row *w, const char *id, const char *fluid, double St, double a, double phi)
{
    gf_post_row_init(w, id);
    snprintf(w->run_id, sizeof w->run_id, "%s", id);
    snprintf(w->fluid_model, sizeof w->fluid_model, "%s", fluid);
    gf_post_row_set(w, "St", St);
    gf_post_row_set(w, "r", isnan(St) ? NAN : 2.04);
    gf_post_row_set(w, "a", a);
    gf_post_row_set(w, "Phi_i", phi);
}

static void test_demo_labels(void)
{
    static gf_post_row rows[8];
    const double a[4] = {1.0, 1.0, 0.5, 0.5}, phi[4] = {0.6, 0.58, 0.6, 0.58};
    for (int k = 0; k < 4; ++k) {
        char id[16];
        snprintf(id, sizeof id, "d%02x", 17 * k);
        make_row(&rows[k], id, "none", NAN, a[k], phi[k]);
        snprintf(id, sizeof id, "i%02x", 17 * k);
        make_row(&rows[4 + k], id, "unresolved", 0.2, a[k], phi[k]);
    }
    char labels[8][GF_POST_LABEL_LEN];
    gf_post_run_labels(rows, 8, labels);
    GF_CHECK(strcmp(labels[0], "dry, a=1, Phi_i=0.6") == 0);
    GF_CHECK(strcmp(labels[3], "dry, a=0.5, Phi_i=0.58") == 0);
    GF_CHECK(strcmp(labels[5], "immersed, a=1, Phi_i=0.58") == 0);
    for (int i = 0; i < 8; ++i)
        gf_test_check(strstr(labels[i], rows[i].run_id) == NULL, __FILE__, __LINE__, "label %d \"%s\" has no hash",
                      i, labels[i]);
    int variant[8];
    gf_post_variants v;
    gf_post_run_variants(rows, 8, variant, &v);
    GF_CHECK(v.n == 2 && strcmp(v.names[0], "dry") == 0 && strcmp(v.names[1], "immersed") == 0);
    GF_CHECK(variant[0] == 0 && variant[3] == 0 && variant[4] == 1 && variant[7] == 1);
}

static void test_shared_label_keeps_ids(void)
{
    static gf_post_row rows[3];
    make_row(&rows[0], "aaa111", "unresolved", 0.2, 0.5, 0.6);
    make_row(&rows[1], "bbb222", "unresolved", 0.2, 0.5, 0.6);   /* a second seed */
    make_row(&rows[2], "ccc333", "unresolved", 0.2, 1.0, 0.6);
    char labels[3][GF_POST_LABEL_LEN];
    gf_post_run_labels(rows, 3, labels);
    GF_CHECK(strcmp(labels[0], "a=0.5 [aaa111]") == 0);
    GF_CHECK(strcmp(labels[1], "a=0.5 [bbb222]") == 0);
    GF_CHECK(strcmp(labels[2], "a=1") == 0);
    /* one run: its groups */
    gf_post_run_labels(rows, 1, labels);
    GF_CHECK(strcmp(labels[0], "St=0.2, r=2.04, a=0.5, Phi_i=0.6") == 0);
    /* two immersed tiers: the variant says which */
    snprintf(rows[2].fluid_model, sizeof rows[2].fluid_model, "resolved");
    gf_post_run_labels(rows, 3, labels);
    GF_CHECK(strcmp(labels[2], "immersed (resolved), a=1") == 0);
}

int main(void)
{
    test_demo_labels();
    test_shared_label_keeps_ids();
    return gf_test_finish();
}
