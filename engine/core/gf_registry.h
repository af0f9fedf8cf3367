/*
 * Lookup by name in the project's registries (contact laws, drag closures,
 * coupling tiers, scenes): each is a table of rows chosen by a name from the
 * run spec. The helpers see a table only through name_of(i), the name of its
 * row i, so that one search and one message serve every kind of row while
 * each table keeps its own row type.
 */
#ifndef GF_REGISTRY_H
#define GF_REGISTRY_H

#include <stddef.h>

/* The name of row i of a table, 0 <= i < its length. */
typedef const char *gf_registry_name_fn(size_t i);

/* Index of the row named name among the n rows, -1 when none is (or name is NULL). */
long gf_registry_index(size_t n, gf_registry_name_fn *name_of, const char *name);

/* names[0..n) the rows' names in the table's order, names[n] = NULL. */
void gf_registry_fill_names(size_t n, gf_registry_name_fn *name_of, const char **names);

/* The names joined for a message into buf (size bytes, truncated to fit):
 * each between quote and quote, separated by ", " and, before the last, by
 * last_sep: ("", ", ") gives "a, b, c"; ("'", " or ") gives "'a', 'b' or 'c'".
 * Returns buf. */
const char *gf_registry_join(size_t n, gf_registry_name_fn *name_of, const char *quote, const char *last_sep,
                             char *buf, size_t size);

#endif
