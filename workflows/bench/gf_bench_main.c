/*
 * main() of the benchmarks that time one sim (gf-bench-silo,
 * gf-bench-collapse, gf-bench-avalanche): the program's arguments from its
 * defaults and the command line (the usage line and exit status 2 when
 * refused), the one-thread sim of its run spec (status 1 with "name:
 * message" when it cannot be made), then the program's own run, whose
 * status is the exit status. The program is gf_bench_main_program, defined
 * in its own file (gf_bench_args.h).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_bench_args.h"

/* The arguments of prog from its defaults and argv; 0 when refused. */
static int read_args(const gf_bench_program *prog, int argc, char **argv, void *args)
{
    memcpy(args, prog->defaults, prog->args_size);
    return gf_bench_parse_flags(argc, argv, prog->flags, prog->n_flags, args) && prog->valid(args);
}

/* The one-thread sim of the program's run spec; 0 after "name: message". */
static int start(gf_ctx *ctx, const gf_bench_program *prog, const void *args, gf_sim **sim)
{
    gf_run_spec spec;
    gf_sim_options opt = {.n_threads = 1};
    if (prog->make_spec(ctx, args, &spec) != GF_OK || gf_sim_create(ctx, &spec, &opt, sim) != GF_OK) {
        fprintf(stderr, "%s: %s\n", prog->name, ctx->last_msg);
        return 0;
    }
    return 1;
}

int main(int argc, char **argv)
{
    const gf_bench_program *prog = &gf_bench_main_program;
    void *args = malloc(prog->args_size);
    if (!args)
        return 1;
    gf_ctx ctx = {0};
    gf_sim *sim = NULL;
    int status = 2;
    if (!read_args(prog, argc, argv, args))
        gf_bench_usage(prog->name, prog->options);
    else
        status = start(&ctx, prog, args, &sim) ? prog->run(&ctx, sim, args) : 1;
    gf_sim_destroy(&sim);
    free(args);
    return status;
}
