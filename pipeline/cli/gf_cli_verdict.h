/* The closing line of a post-processing: how many runs are not ok, and why. */
#ifndef GF_CLI_VERDICT_H
#define GF_CLI_VERDICT_H

#include "gf_post.h"

/* Prints, on stderr, one line counting the runs that are not ok (failed,
 * corrupt, incomplete, post-processing error) when there are any. Returns 1
 * then (the command exits non-zero), 0 when every run is ok. */
int gf_cli_post_verdict(const char *cmd, const gf_post_report *rep);

#endif
