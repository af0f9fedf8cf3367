/* The grainflow executable: everything is in the grainflow_pipeline library
 * (pipeline/cli/gf_cli.c dispatches to one gf_cmd_<name>.c per subcommand),
 * so tests can drive the same code without a process. */
#include <hdf5.h>

#include "cli/gf_cli.h"

int main(int argc, char **argv)
{
    /* No HDF5 shutdown at exit: every file grainflow writes is closed (or
     * abandoned) before the command returns, and HDF5 1.10 crashes in its exit
     * handler (H5F__close_cb) on a file whose close failed on a full disk,
     * turning exit status 1 into a segmentation fault. */
    H5dont_atexit();
    return gf_cli_main(argc, argv);
}
