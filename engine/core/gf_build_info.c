#include "core/gf_build_info.h"

#include "gf_build_revision.h" /* generated in the build directory */

const char *gf_build_revision(void)
{
    return GF_BUILD_REVISION;
}
