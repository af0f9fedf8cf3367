/* The grainflow executable: everything is in the grainflow_pipeline library
 * (pipeline/cli/gf_cli.c dispatches to one gf_cmd_<name>.c per subcommand),
 * so tests can drive the same code without a process. */
#include "cli/gf_cli.h"

int main(int argc, char **argv)
{
    return gf_cli_main(argc, argv);
}
