/* `grainflow post DIR`: post-processing of a campaign (or run) directory. */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/gf_cli.h"
#include "cli/gf_cli_verdict.h"
#include "gf_post.h"

static const char help[] =
    "usage: grainflow post DIR [--stage NAME] [--jobs N] [--no-figures] [-q]\n"
    "\n"
    "Runs the post-processing stages on every run directory below DIR (a campaign\n"
    "directory, or one run directory), then writes DIR/summary.csv, DIR/summary.nc\n"
    "(one row per run, failed runs included) and DIR/figures/*.svg. Reads only the\n"
    "netCDF files, so runs made elsewhere or by another version are treated alike.\n"
    "A DIR holding no run (e.g. the -o directory of campaigns) is searched for the\n"
    "campaigns below it, each summarised in its own directory. A run marked done\n"
    "is verified against its manifest first (sizes, CRC-32): one that fails is\n"
    "'corrupt' in the summary.\n"
    "\n"
    "options:\n"
    "      --stage NAME   run only this stage\n"
    "  -j, --jobs N       runs processed in parallel (default: 1)\n"
    "      --no-figures   skip the SVG figures\n"
    "  -q, --quiet        no per-run lines\n"
    "\n"
    "exit status: 0 every run ok; 1 a run failed, corrupt, incomplete or its\n"
    "post-processing failed (the summary is still written, with the reasons), or no\n"
    "run found; 2 usage error\n";

int gf_cmd_post(int argc, char **argv)
{
    const char *dir = NULL, *stage = NULL, *v;
    int n_jobs = 1, figures = 1, quiet = 0;
    const gf_cli_shared shared = {"post", help, NULL, NULL, NULL};
    for (int i = 1; i < argc; ++i) {
        int m, r = gf_cli_shared_option(&shared, argc, argv, &i);
        if (r != GF_CLI_OTHER) {
            if (r != GF_CLI_NEXT)
                return r;
        } else if ((m = gf_cli_opt_value(argc, argv, &i, NULL, "--stage", &stage))) {
            if (m < 0)
                return gf_cli_usage_error("post", "--stage needs a name");
        } else if ((m = gf_cli_opt_value(argc, argv, &i, "-j", "--jobs", &v))) {
            if (m < 0 || (n_jobs = gf_cli_parse_count("post", "--jobs", v, 4096)) < 0)
                return GF_EXIT_USAGE;
        } else if (!strcmp(argv[i], "--no-figures")) {
            figures = 0;
        } else if (!strcmp(argv[i], "-q") || !strcmp(argv[i], "--quiet")) {
            quiet = 1;
        } else if ((r = gf_cli_operand("post", argv[i], &dir)) != GF_CLI_NEXT) {
            return r;
        }
    }
    if (!dir)
        return gf_cli_usage_error("post", "missing DIR");
    struct stat sb;
    if (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode))
        return gf_cli_usage_error("post", "%s: not a directory", dir);
    gf_ctx ctx = {.log_level = GF_LOG_WARN};
    gf_post_options po = {.stage = stage, .n_jobs = n_jobs, .figures = figures, .quiet = quiet};
    gf_post_report rep;
    gf_status st = gf_post_tree(&ctx, dir, &po, &rep);
    if (st != GF_OK) {
        gf_cli_print_error(&ctx);
        return st == GF_ERR_CONFIG || st == GF_ERR_ARG ? GF_EXIT_USAGE : GF_EXIT_RUN_FAILED;
    }
    return gf_cli_post_verdict("post", &rep) ? GF_EXIT_RUN_FAILED : GF_EXIT_OK;
}
