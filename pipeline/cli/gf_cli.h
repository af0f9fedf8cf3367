/*
 * The `grainflow` command line: one executable, one subcommand per file
 * (gf_cmd_<name>.c). main() only calls gf_cli_main; every subcommand returns
 * its exit code:
 *
 *   0  success
 *   1  a run (or post-processing) failed, or the campaign was interrupted
 *   2  usage or configuration error: one line "file:line:column: message"
 *      (or "grainflow <cmd>: message") on stderr, and nothing was started.
 */
#ifndef GF_CLI_H
#define GF_CLI_H

#include "campaign/gf_campaign.h"
#include "core/gf_status.h"

enum { GF_EXIT_OK = 0, GF_EXIT_RUN_FAILED = 1, GF_EXIT_USAGE = 2 };

int gf_cli_main(int argc, char **argv);

int gf_cmd_run(int argc, char **argv);
int gf_cmd_campaign(int argc, char **argv);
int gf_cmd_check(int argc, char **argv);
int gf_cmd_demo(int argc, char **argv);
int gf_cmd_post(int argc, char **argv);
int gf_cmd_bench(int argc, char **argv);

/* The embedded default campaign (configs/demo.yaml, copied in at build time). */
extern const char gf_demo_yaml[];

/* --- helpers shared by the subcommands (gf_cli.c) --- */

/* Matches argv[*i] against a long/short option taking a value ("-o DIR",
 * "--jobs=4", "--jobs 4"); on match stores the value and advances *i.
 * Returns 1 on match, 0 otherwise, -1 when the value is missing. */
int gf_cli_opt_value(int argc, char **argv, int *i, const char *short_name, const char *long_name,
                     const char **value);
/* Parses a positive integer option value; -1 on error. */
int gf_cli_parse_count(const char *cmd, const char *opt, const char *text, int max);
/* Prints "grainflow <cmd>: <msg>" and the usage hint; returns GF_EXIT_USAGE. */
int gf_cli_usage_error(const char *cmd, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* The most --set KEY=VALUE overrides a command takes. */
#define GF_CLI_MAX_SETS 64

/* What gf_cli_shared_option and gf_cli_operand return when the command goes
 * on with its next argument; gf_cli_shared_option's answer for an argument
 * that is not one of the shared options. Any other value is the exit status
 * the command returns at once. */
enum { GF_CLI_NEXT = -1, GF_CLI_OTHER = -2 };

/* The options several subcommands read alike: -h/--help prints help (exit
 * GF_EXIT_OK); -o/--output DIR into *out_dir, --set KEY=VALUE appended to
 * sets (at most GF_CLI_MAX_SETS), each only where the pointer is non-NULL. */
typedef struct gf_cli_shared {
    const char *cmd, *help;
    const char **out_dir;
    const char **sets;
    int *n_sets;
} gf_cli_shared;

/* Reads argv[*i] when it is a shared option (advancing *i past its value):
 * GF_CLI_NEXT, GF_CLI_OTHER, or the exit status (help; a missing value). */
int gf_cli_shared_option(const gf_cli_shared *o, int argc, char **argv, int *i);
/* The command's one operand (the file or directory) into *operand: an
 * unknown option or a second operand is a usage error (GF_EXIT_USAGE), else
 * GF_CLI_NEXT. */
int gf_cli_operand(const char *cmd, const char *arg, const char **operand);
/* The campaign of file (missing: the usage error "missing <what>") with the
 * overrides sets, into *c; GF_EXIT_OK, else GF_EXIT_USAGE after the message. */
int gf_cli_load_campaign(gf_ctx *ctx, const char *cmd, const char *file, const char *what, const char **sets,
                         int n_sets, gf_campaign **c);

/* Prints the context's message (one line) on stderr. */
void gf_cli_print_error(const gf_ctx *ctx);
/* Non-zero when stdout is a terminal. */
int gf_cli_is_tty(void);
/* The interrupt flag set by SIGINT/SIGTERM once gf_cli_catch_signals ran. */
volatile int *gf_cli_catch_signals(void);
/* Absolute path of the running executable into buf. */
void gf_cli_self_path(const char *argv0, char *buf, size_t n);

/* The shared body of `campaign` and `demo` (gf_cmd_campaign.c). */
int gf_cli_campaign_common(const char *cmd, int argc, char **argv, const char *embedded_text,
                           const char *embedded_name);

#endif
