/*
 * The benchmarks' command lines and start: "--name value" pairs read
 * through a table of flags into the fields of the program's arguments (the
 * usage line when refused), and, for the programs that time one sim
 * (gf_bench_main.c), the one-thread sim of the program's run spec, with the
 * error printed as "program: message".
 */
#ifndef GF_BENCH_ARGS_H
#define GF_BENCH_ARGS_H

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_sim.h"

typedef enum gf_bench_flag_kind { GF_BENCH_REAL, GF_BENCH_LONG, GF_BENCH_INT, GF_BENCH_PATH } gf_bench_flag_kind;

/* One flag: its name ("--orifice"), what its value is, and the field of the
 * arguments it sets (double, long, int or const char *), by offset. */
typedef struct gf_bench_flag {
    const char *name;
    gf_bench_flag_kind kind;
    size_t offset;
} gf_bench_flag;

/* The row of flag NAME of kind KIND (REAL, LONG, INT, PATH) setting field
 * FIELD of the arguments' struct TYPE. */
#define GF_BENCH_FLAG(NAME, KIND, TYPE, FIELD) {NAME, GF_BENCH_##KIND, offsetof(TYPE, FIELD)}

/* Defines valid(), the check of a program's arguments of type TYPE: the
 * expression ACCEPTED of the arguments a, after the defaults and the flags. */
#define GF_BENCH_VALID(TYPE, ACCEPTED)                                                                            \
    static int valid(const void *args)                                                                            \
    {                                                                                                             \
        const TYPE *a = args;                                                                                     \
        return ACCEPTED;                                                                                          \
    }

/* Sets the field of args named by the flag name to value, converted by the
 * flag's kind; 0 when none of the n flags has that name. */
static inline int gf_bench_set_flag(const gf_bench_flag *flags, size_t n, void *args, const char *name,
                                    const char *value)
{
    size_t q = 0;
    while (q < n && strcmp(name, flags[q].name) != 0)
        ++q;
    if (q == n)
        return 0;
    char *field = (char *)args + flags[q].offset;
    switch (flags[q].kind) {
    case GF_BENCH_REAL: *(double *)field = atof(value); break;
    case GF_BENCH_LONG: *(long *)field = atol(value); break;
    case GF_BENCH_INT: *(int *)field = atoi(value); break;
    case GF_BENCH_PATH: *(const char **)field = value; break;
    }
    return 1;
}

/* Reads argv[1..] as "--name value" pairs of the n flags into args; 0 on an
 * unknown name or a name without a value. Values are not checked here. */
static inline int gf_bench_parse_flags(int argc, char **argv, const gf_bench_flag *flags, size_t n, void *args)
{
    for (int i = 1; i < argc; i += 2)
        if (i + 1 >= argc || !gf_bench_set_flag(flags, n, args, argv[i], argv[i + 1]))
            return 0;
    return 1;
}

/* "usage: program options" on stderr; the exit status of a refused command line. */
static inline int gf_bench_usage(const char *program, const char *options)
{
    fprintf(stderr, "usage: %s %s\n", program, options);
    return 2;
}

/* A benchmark that times one sim (its main() is gf_bench_main.c): its name
 * and options (the usage line); its arguments (a struct of args_size bytes,
 * the defaults, then the flags of the command line, accepted when valid says
 * so); the run spec it makes of them; and what it does with the sim, which
 * returns the exit status and prints "name: message" on a failure. */
typedef struct gf_bench_program {
    const char *name, *options;
    size_t args_size;
    const void *defaults;
    const gf_bench_flag *flags;
    size_t n_flags;
    int (*valid)(const void *args);
    gf_status (*make_spec)(gf_ctx *ctx, const void *args, gf_run_spec *spec);
    int (*run)(gf_ctx *ctx, gf_sim *sim, const void *args);
} gf_bench_program;

/* The program gf_bench_main.c runs: each such benchmark defines it. */
extern const gf_bench_program gf_bench_main_program;

#endif
