/* Subcommand dispatch and helpers of the grainflow command line; see gf_cli.h. */
#include "cli/gf_cli.h"

#include <limits.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/gf_build_info.h"
#include "schedule/gf_comm.h"

static const char usage_text[] =
    "usage: grainflow <command> [options]\n"
    "\n"
    "Simulation campaigns of dense granular flows, dry or immersed.\n"
    "\n"
    "commands:\n"
    "  run SCENE.yaml        one run (of a campaign: --index K) [-o DIR] [--set key.path=value ...]\n"
    "  campaign FILE.yaml    expand a grid and run it [-o DIR] [--jobs N] [--resume] [--dry-run]\n"
    "                                                [--emit slurm] [--no-post] [--only ID] [--index K]\n"
    "  check FILE.yaml...    validate; print every resolved run, its groups, time scales and cost\n"
    "  demo                  the embedded default campaign [-o DIR] [--jobs N]\n"
    "  post DIR              post-process a campaign directory [--stage NAME] [--jobs N]\n"
    "  bench FILE.yaml       time each run without output, write bench.csv [-o DIR]\n"
    "\n"
    "  grainflow <command> --help   options of a command\n"
    "  grainflow --version\n"
    "\n"
    "exit status: 0 success, 1 a run failed, 2 usage or configuration error\n";

int gf_cli_opt_value(int argc, char **argv, int *i, const char *short_name, const char *long_name,
                     const char **value)
{
    const char *a = argv[*i];
    size_t ll = long_name ? strlen(long_name) : 0;
    if (long_name && strncmp(a, long_name, ll) == 0 && a[ll] == '=') {
        *value = a + ll + 1;
        return 1;
    }
    if ((short_name && strcmp(a, short_name) == 0) || (long_name && strcmp(a, long_name) == 0)) {
        if (*i + 1 >= argc)
            return -1;
        *value = argv[++*i];
        return 1;
    }
    return 0;
}

int gf_cli_usage_error(const char *cmd, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (gf_comm_rank() == 0)
        fprintf(stderr, "grainflow %s: %s (see grainflow %s --help)\n", cmd, msg, cmd);
    return GF_EXIT_USAGE;
}

int gf_cli_parse_count(const char *cmd, const char *opt, const char *text, int max)
{
    char *end = NULL;
    long v = strtol(text, &end, 10);
    if (!*text || *end || v < 1 || v > max) {
        gf_cli_usage_error(cmd, "%s: expected an integer in [1, %d], got '%s'", opt, max, text);
        return -1;
    }
    return (int)v;
}

int gf_cli_shared_option(const gf_cli_shared *o, int argc, char **argv, int *i)
{
    const char *v;
    int m;
    if (!strcmp(argv[*i], "--help") || !strcmp(argv[*i], "-h")) {
        fputs(o->help, stdout);
        return GF_EXIT_OK;
    }
    if (o->out_dir && (m = gf_cli_opt_value(argc, argv, i, "-o", "--output", o->out_dir)))
        return m < 0 ? gf_cli_usage_error(o->cmd, "-o needs a directory") : GF_CLI_NEXT;
    if (o->sets && (m = gf_cli_opt_value(argc, argv, i, NULL, "--set", &v))) {
        if (m < 0 || *o->n_sets == GF_CLI_MAX_SETS)
            return gf_cli_usage_error(o->cmd, "--set needs KEY=VALUE (at most %d)", GF_CLI_MAX_SETS);
        o->sets[(*o->n_sets)++] = v;
        return GF_CLI_NEXT;
    }
    return GF_CLI_OTHER;
}

int gf_cli_operand(const char *cmd, const char *arg, const char **operand)
{
    if (arg[0] == '-' && arg[1])
        return gf_cli_usage_error(cmd, "unknown option '%s'", arg);
    if (*operand)
        return gf_cli_usage_error(cmd, "unexpected argument '%s'", arg);
    *operand = arg;
    return GF_CLI_NEXT;
}

int gf_cli_load_campaign(gf_ctx *ctx, const char *cmd, const char *file, const char *what, const char **sets,
                         int n_sets, gf_campaign **c)
{
    if (!file)
        return gf_cli_usage_error(cmd, "missing %s", what);
    if (gf_campaign_load_file(ctx, file, sets, n_sets, c) != GF_OK) {
        gf_cli_print_error(ctx);
        return GF_EXIT_USAGE;
    }
    return GF_EXIT_OK;
}

void gf_cli_print_error(const gf_ctx *ctx)
{
    if (gf_comm_rank() == 0)
        fprintf(stderr, "%s\n", ctx->last_msg[0] ? ctx->last_msg : gf_status_str(ctx->last_code));
}

int gf_cli_is_tty(void)
{
    return isatty(STDOUT_FILENO) && getenv("TERM") && strcmp(getenv("TERM"), "dumb") != 0;
}

static volatile int interrupt_flag;
static void on_signal(int sig)
{
    (void)sig;
    interrupt_flag = 1;
}

volatile int *gf_cli_catch_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    return &interrupt_flag;
}

void gf_cli_self_path(const char *argv0, char *buf, size_t n)
{
    ssize_t k = readlink("/proc/self/exe", buf, n - 1);
    if (k > 0) {
        buf[k] = '\0';
        return;
    }
    char *r = realpath(argv0, NULL);
    snprintf(buf, n, "%s", r ? r : argv0);
    free(r);
}

int gf_cli_main(int argc, char **argv)
{
    if (gf_comm_init(&argc, &argv) != 0) {
        fprintf(stderr, "grainflow: MPI initialisation failed\n");
        return GF_EXIT_RUN_FAILED;
    }
    int code;
    if (argc < 2) {
        fputs(usage_text, stderr);
        code = GF_EXIT_USAGE;
    } else if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        fputs(usage_text, stdout);
        code = GF_EXIT_OK;
    } else if (strcmp(argv[1], "--version") == 0 || strcmp(argv[1], "version") == 0) {
        printf("grainflow %s (%s)\n", GF_VERSION, gf_build_revision());
        code = GF_EXIT_OK;
    } else {
        static const struct {
            const char *name;
            int (*fn)(int, char **);
        } cmds[] = {{"run", gf_cmd_run},   {"campaign", gf_cmd_campaign}, {"check", gf_cmd_check},
                    {"demo", gf_cmd_demo}, {"post", gf_cmd_post},         {"bench", gf_cmd_bench}};
        code = -1;
        for (size_t i = 0; i < sizeof cmds / sizeof *cmds; ++i)
            if (strcmp(argv[1], cmds[i].name) == 0)
                code = cmds[i].fn(argc - 1, argv + 1);
        if (code < 0) {
            if (gf_comm_rank() == 0)
                fprintf(stderr, "grainflow: unknown command '%s' (run grainflow --help)\n", argv[1]);
            code = GF_EXIT_USAGE;
        }
    }
    fflush(stdout);
    gf_comm_finalize();
    return code;
}
