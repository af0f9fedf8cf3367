/*
 * Replicate sets of a campaign's runs (gf_post_replicates.h).
 */
#include "stages/gf_post_replicates.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* run.yaml without its comment lines and its top-level "seed:" line, or NULL. */
static char *spec_without_seed(const char *run_dir)
{
    char p[1200], line[1024];
    snprintf(p, sizeof p, "%s/run.yaml", run_dir);
    FILE *f = fopen(p, "r");
    if (!f)
        return NULL;
    size_t len = 0, cap = 4096;
    char *s = malloc(cap);
    while (s && fgets(line, sizeof line, f)) {
        if (line[0] == '#' || strncmp(line, "seed:", 5) == 0)
            continue;
        size_t k = strlen(line);
        if (len + k + 1 > cap) {
            char *t = realloc(s, cap = 2 * (len + k + 1));
            if (!t)
                free(s);
            s = t;
            if (!s)
                break;
        }
        memcpy(s + len, line, k + 1);
        len += k;
    }
    fclose(f);
    if (s && len == 0)
        free(s), s = NULL;
    return s;
}

int gf_post_replicate_groups(const gf_post_row *rows, int n, int *group)
{
    char **spec = calloc((size_t)n + 1, sizeof *spec);
    if (!spec)
        return -1;
    int n_sets = 0;
    for (int i = 0; i < n; ++i) {
        spec[i] = spec_without_seed(rows[i].run_dir);
        group[i] = i;
        for (int j = 0; j < i && spec[i]; ++j)
            if (group[j] == j && spec[j] && strcmp(spec[i], spec[j]) == 0) {
                group[i] = j;
                break;
            }
        n_sets += group[i] == i;
    }
    for (int i = 0; i < n; ++i)
        free(spec[i]);
    free(spec);
    return n_sets;
}
