/*
 * The key=value arguments of the validation programs (resolved_settling,
 * resolved_bounce): each program lists its keys once, in a table that points
 * at the fields they set, instead of one strcmp branch per key.
 */
#ifndef GF_TEST_ARGS_H
#define GF_TEST_ARGS_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One key: exactly one of number (read with atof), integer (atoi) or text
 * (copied, at most text_size - 1 characters) is set. */
typedef struct gf_test_arg {
    const char *key;
    double *number;
    int *integer;
    char *text;
    size_t text_size;
} gf_test_arg;

/* Sets, for each word key=value of argv[1..argc-1] whose key is in the n rows
 * of table, that row's field; words without '=' and unknown keys are ignored.
 * Modifies argv (the '=' becomes a terminator). */
static inline void gf_test_parse_args(int argc, char **argv, const gf_test_arg *table, size_t n)
{
    for (int i = 1; i < argc; ++i) {
        char *eq = strchr(argv[i], '=');
        if (!eq)
            continue;
        *eq = '\0';
        const char *v = eq + 1;
        for (size_t k = 0; k < n; ++k) {
            if (strcmp(argv[i], table[k].key) != 0)
                continue;
            if (table[k].number)
                *table[k].number = atof(v);
            else if (table[k].integer)
                *table[k].integer = atoi(v);
            else
                snprintf(table[k].text, table[k].text_size, "%s", v);
        }
    }
}

#endif
