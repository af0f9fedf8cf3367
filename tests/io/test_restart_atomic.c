/*
 * Checkpoint files are committed whole or not at all (io/gf_restart.h):
 * - a complete write replaces the previous file;
 * - a write in which a dataset fails (here: the same name twice) is not
 *   committed: gf_restart_close returns GF_ERR_IO and the previous file is
 *   read back unchanged;
 * - gf_restart_abort (the caller's own part failed) leaves the previous
 *   file too;
 * and no temporary file is left in the directory in any of the three cases.
 */
#include <stdio.h>
#include <stdlib.h>

#include "gf_test.h"
#include "gf_test_files.h"
#include "io/gf_restart.h"

static gf_status write_value(gf_ctx *ctx, const char *path, double v, int fail, int abort_it)
{
    gf_restart *r = NULL;
    GF_TRY(gf_restart_create(ctx, path, &r));
    gf_status st = gf_restart_put_f64(r, "value", 1, &v);
    if (fail)
        st = gf_restart_put_f64(r, "value", 1, &v); /* a second dataset of the same name: refused by HDF5 */
    if (abort_it) {
        gf_restart_abort(&r);
        return st;
    }
    gf_status cst = gf_restart_close(&r);
    return st != GF_OK ? st : cst;
}

static double read_value(gf_ctx *ctx, const char *path)
{
    gf_restart *r = NULL;
    double v = -1.0;
    if (gf_restart_open(ctx, path, &r) == GF_OK)
        gf_restart_get_f64(r, "value", 1, &v);
    gf_restart_close(&r);
    return v;
}

int main(void)
{
    char dir[] = "/tmp/gf_restart_atomic_XXXXXX";
    GF_CHECK(mkdtemp(dir) != NULL);
    char path[256], pattern[300];
    snprintf(path, sizeof path, "%s/checkpoint.h5", dir);
    snprintf(pattern, sizeof pattern, "%s/*", dir);
    gf_ctx ctx = {0};

    GF_CHECK_OK(write_value(&ctx, path, 1.0, 0, 0), &ctx);
    GF_CHECK_OK(write_value(&ctx, path, 2.0, 0, 0), &ctx);
    GF_CHECK(read_value(&ctx, path) == 2.0);

    gf_ctx quiet = {0};
    gf_status st = write_value(&quiet, path, 3.0, 1, 0);
    printf("failed dataset: %s (%s)\n", gf_status_str(st), quiet.last_msg);
    GF_CHECK(st == GF_ERR_IO);
    GF_CHECK(read_value(&ctx, path) == 2.0);

    GF_CHECK_OK(write_value(&ctx, path, 4.0, 0, 1), &ctx);
    GF_CHECK(read_value(&ctx, path) == 2.0);

    size_t n_files = gf_test_count_files(pattern);
    gf_test_check(n_files == 1, __FILE__, __LINE__, "%zu files in %s, expected only checkpoint.h5", n_files, dir);
    remove(path);
    remove(dir);
    return gf_test_finish();
}
