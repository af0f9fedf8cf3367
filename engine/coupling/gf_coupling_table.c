/*
 * The coupling-tier registry (gf_coupling_tier.h). A new tier is its own
 * files defining `const gf_coupling_tier gf_coupling_tier_<name>` and TWO
 * lines here: its extern declaration and its row. The rows are in the order
 * `fluid: auto` asks them, cheapest first.
 */
#include "core/gf_registry.h"
#include "coupling/gf_coupling_tier.h"

/* --- declarations (one per tier) --- */
extern const gf_coupling_tier gf_coupling_tier_unresolved;
extern const gf_coupling_tier gf_coupling_tier_resolved;

/* --- rows (one per tier) --- */
static const gf_coupling_tier *const gf_coupling_tier_table[] = {
    &gf_coupling_tier_unresolved,
    &gf_coupling_tier_resolved,
};

enum { N_TIERS = sizeof gf_coupling_tier_table / sizeof gf_coupling_tier_table[0] };

static const char *tier_name(size_t i) { return gf_coupling_tier_table[i]->name; }

const gf_coupling_tier *const *gf_coupling_tier_all(int *n)
{
    *n = N_TIERS;
    return gf_coupling_tier_table;
}

const gf_coupling_tier *gf_coupling_tier_find(const char *name)
{
    long i = gf_registry_index(N_TIERS, tier_name, name);
    return i < 0 ? NULL : gf_coupling_tier_table[i];
}

void gf_coupling_tier_names(char *buf, size_t n) { gf_registry_join(N_TIERS, tier_name, "'", " or ", buf, n); }
