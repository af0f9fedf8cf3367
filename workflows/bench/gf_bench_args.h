/*
 * The benchmarks' command lines and start: "--name value" pairs read
 * through a table of flags into the program's arguments, and the one-thread
 * sim of a run spec, with the error printed as "program: message".
 */
#ifndef GF_BENCH_ARGS_H
#define GF_BENCH_ARGS_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_sim.h"

typedef enum gf_bench_flag_kind { GF_BENCH_REAL, GF_BENCH_LONG, GF_BENCH_INT, GF_BENCH_PATH } gf_bench_flag_kind;

/* One flag: its name ("--orifice"), what its value is, and where it goes
 * (double *, long *, int * or const char **). */
typedef struct gf_bench_flag {
    const char *name;
    gf_bench_flag_kind kind;
    void *dest;
} gf_bench_flag;

/* Reads argv[1..] as "--name value" pairs of the n flags; 0 on an unknown
 * name or a name without a value. Values are not checked here. */
static inline int gf_bench_parse_flags(int argc, char **argv, const gf_bench_flag *flags, size_t n)
{
    for (int i = 1; i < argc; i += 2) {
        const char *k = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        size_t q = 0;
        while (q < n && strcmp(k, flags[q].name) != 0)
            ++q;
        if (!v || q == n)
            return 0;
        switch (flags[q].kind) {
        case GF_BENCH_REAL: *(double *)flags[q].dest = atof(v); break;
        case GF_BENCH_LONG: *(long *)flags[q].dest = atol(v); break;
        case GF_BENCH_INT: *(int *)flags[q].dest = atoi(v); break;
        case GF_BENCH_PATH: *(const char **)flags[q].dest = v; break;
        }
    }
    return 1;
}

/* *sim: the one-thread sim of spec, when made (the status of the spec's
 * making) is GF_OK and the sim is created; 0 otherwise, with
 * "program: message" on stderr. */
static inline int gf_bench_start(gf_ctx *ctx, gf_status made, const gf_run_spec *spec, const char *program,
                                 gf_sim **sim)
{
    gf_sim_options opt = {.n_threads = 1};
    if (made != GF_OK || gf_sim_create(ctx, spec, &opt, sim) != GF_OK) {
        fprintf(stderr, "%s: %s\n", program, ctx->last_msg);
        return 0;
    }
    return 1;
}

#endif
