/*
 * Lookup by name in a registry (gf_registry.h). A linear search: the tables
 * hold a handful of rows and are read at configuration, never in a step.
 */
#include "core/gf_registry.h"

#include <stdio.h>
#include <string.h>

long gf_registry_index(size_t n, gf_registry_name_fn *name_of, const char *name)
{
    for (size_t i = 0; name && i < n; ++i)
        if (strcmp(name_of(i), name) == 0)
            return (long)i;
    return -1;
}

void gf_registry_fill_names(size_t n, gf_registry_name_fn *name_of, const char **names)
{
    for (size_t i = 0; i < n; ++i)
        names[i] = name_of(i);
    names[n] = NULL;
}

const char *gf_registry_join(size_t n, gf_registry_name_fn *name_of, const char *quote, const char *last_sep,
                             char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < n && used < size; ++i) {
        const char *sep = i == 0 ? "" : (i + 1 == n ? last_sep : ", ");
        int w = snprintf(buf + used, size - used, "%s%s%s%s", sep, quote, name_of(i), quote);
        used += w > 0 ? (size_t)w : 0;
    }
    return buf;
}
