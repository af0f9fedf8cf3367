/*
 * The coupling-tier registry (gf_coupling_tier.h). A new tier is its own
 * files defining `const gf_coupling_tier gf_coupling_tier_<name>` and TWO
 * lines here: its extern declaration and its row. The rows are in the order
 * `fluid: auto` asks them, cheapest first.
 */
#include <stdio.h>
#include <string.h>

#include "coupling/gf_coupling_tier.h"

/* --- declarations (one per tier) --- */
extern const gf_coupling_tier gf_coupling_tier_unresolved;
extern const gf_coupling_tier gf_coupling_tier_resolved;

/* --- rows (one per tier) --- */
static const gf_coupling_tier *const gf_coupling_tier_table[] = {
    &gf_coupling_tier_unresolved,
    &gf_coupling_tier_resolved,
};

const gf_coupling_tier *const *gf_coupling_tier_all(int *n)
{
    *n = (int)(sizeof gf_coupling_tier_table / sizeof gf_coupling_tier_table[0]);
    return gf_coupling_tier_table;
}

const gf_coupling_tier *gf_coupling_tier_find(const char *name)
{
    int n = 0;
    const gf_coupling_tier *const *all = gf_coupling_tier_all(&n);
    for (int i = 0; i < n; ++i)
        if (name && strcmp(all[i]->name, name) == 0)
            return all[i];
    return NULL;
}

void gf_coupling_tier_names(char *buf, size_t n)
{
    int nt = 0;
    const gf_coupling_tier *const *all = gf_coupling_tier_all(&nt);
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < nt && used < n; ++i) {
        const char *sep = i == 0 ? "" : (i == nt - 1 ? " or " : ", ");
        int w = snprintf(buf + used, n - used, "%s'%s'", sep, all[i]->name);
        used += w > 0 ? (size_t)w : 0;
    }
}
