/*
 * gf_build_info: what build of grainflow wrote a file (the netCDF `source`
 * and `history` attributes, the resolved run.yaml, `grainflow --version`,
 * the preparation cache key).
 */
#ifndef GF_BUILD_INFO_H
#define GF_BUILD_INFO_H

/* The source revision compiled in: the short commit hash, with "-dirty"
 * when tracked files differed from it, or "unknown" outside a git checkout.
 * Taken at build time (cmake/gf_revision.cmake), not when the build
 * directory was configured. */
const char *gf_build_revision(void);

#endif
