/*
 * The run-directory primitives alone (postproc/rundir): the lock and the manifest.
 *
 * Lock: a child process takes a lock; the parent then finds it held, with the
 * child's pid and this host in the record; after kill -9 of the child the
 * parent takes it at once and reports it stale (the child's record); after a
 * clean release the next holder sees no stale record; a wait of 5 s for a
 * lock released after 0.3 s succeeds in between.
 *
 * Manifest: a run directory with two netCDF files and run.yaml is listed
 * (post_*.nc, checkpoint.h5, *.partial and *.tmp left out); it verifies; it
 * fails, naming the file, on one flipped byte (same size: the CRC-32 sees it),
 * on a truncation, on a missing file; without a manifest (an older run) a
 * truncated netCDF file still fails because it no longer opens.
 */
#include <netcdf.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/gf_timer.h"
#include "gf_test.h"
#include "rundir/gf_lock.h"
#include "rundir/gf_manifest.h"

static char dir[256];

static void path_of(const char *name, char *buf, size_t n)
{
    snprintf(buf, n, "%s/%s", dir, name);
}

/* A small netCDF-4 file with one series. */
static void write_nc(const char *name, int n_values)
{
    char p[512];
    path_of(name, p, sizeof p);
    int id, dim, var;
    double *v = malloc((size_t)n_values * sizeof *v);
    for (int i = 0; i < n_values; ++i)
        v[i] = 0.5 * i;
    GF_CHECK(nc_create(p, NC_NETCDF4 | NC_CLOBBER, &id) == NC_NOERR);
    nc_def_dim(id, "time", (size_t)n_values, &dim);
    nc_def_var(id, "x", NC_DOUBLE, 1, &dim, &var);
    nc_enddef(id);
    nc_put_var_double(id, var, v);
    GF_CHECK(nc_close(id) == NC_NOERR);
    free(v);
}

static void write_text(const char *name, const char *text)
{
    char p[512];
    path_of(name, p, sizeof p);
    FILE *f = fopen(p, "w");
    fputs(text, f);
    fclose(f);
}

static void test_lock(void)
{
    char lock_path[512];
    path_of(".lock", lock_path, sizeof lock_path);
    int ready[2];
    GF_CHECK(pipe(ready) == 0);
    pid_t child = fork();
    if (child == 0) {
        gf_lock *l = NULL;
        gf_lock_holder h;
        gf_lock_take(NULL, lock_path, "test holder", 0.0, &l, &h, NULL);
        char c = l ? 'y' : 'n';
        if (write(ready[1], &c, 1) != 1)
            _exit(2);
        pause(); /* holds until killed */
        _exit(0);
    }
    char c = 0;
    GF_CHECK(read(ready[0], &c, 1) == 1 && c == 'y');
    gf_ctx ctx = {0};
    gf_lock *l = NULL;
    gf_lock_holder h;
    int stale = -1;
    GF_CHECK_OK(gf_lock_take(&ctx, lock_path, "test", 0.0, &l, &h, &stale), &ctx);
    char who[300];
    gf_lock_describe(&h, who, sizeof who);
    printf("held: %s\n", who);
    char host[64] = "";
    gethostname(host, sizeof host - 1);
    GF_CHECK(l == NULL && h.pid == child && strcmp(h.host, host) == 0 && strcmp(h.what, "test holder") == 0);
    kill(child, SIGKILL);
    waitpid(child, NULL, 0);
    GF_CHECK_OK(gf_lock_take(&ctx, lock_path, "test", 0.0, &l, &h, &stale), &ctx);
    GF_CHECK(l != NULL && stale == 1 && h.pid == child);
    gf_lock_release(&l);
    GF_CHECK_OK(gf_lock_take(&ctx, lock_path, "test", 0.0, &l, &h, &stale), &ctx);
    GF_CHECK(l != NULL && stale == 0);
    gf_lock_release(&l);

    /* waiting for a holder that releases */
    child = fork();
    if (child == 0) {
        gf_lock *cl = NULL;
        gf_lock_holder ch;
        gf_lock_take(NULL, lock_path, "brief holder", 0.0, &cl, &ch, NULL);
        char y = 'y';
        if (write(ready[1], &y, 1) != 1)
            _exit(2);
        usleep(300000);
        gf_lock_release(&cl);
        _exit(0);
    }
    GF_CHECK(read(ready[0], &c, 1) == 1);
    const double t0 = gf_wtime();
    GF_CHECK_OK(gf_lock_take(&ctx, lock_path, "test", 5.0, &l, &h, &stale), &ctx);
    const double waited = gf_wtime() - t0;
    printf("waited %.2f s for a lock released after 0.3 s\n", waited);
    GF_CHECK(l != NULL && stale == 0 && waited > 0.2 && waited < 4.0);
    gf_lock_release(&l);
    waitpid(child, NULL, 0);
}

static void flip_byte(const char *name, long offset)
{
    char p[512];
    path_of(name, p, sizeof p);
    FILE *f = fopen(p, "r+b");
    fseek(f, offset, SEEK_SET);
    int b = fgetc(f);
    fseek(f, offset, SEEK_SET);
    fputc(b ^ 0x01, f);
    fclose(f);
}

static long file_size(const char *name)
{
    char p[512];
    struct stat sb;
    path_of(name, p, sizeof p);
    return stat(p, &sb) == 0 ? (long)sb.st_size : -1;
}

static void test_manifest(void)
{
    write_nc("diagnostics.nc", 100);
    write_nc("particles.nc", 5000);
    write_text("run.yaml", "name: t\n");
    write_nc("post_deposit.nc", 10);
    write_text("checkpoint.h5", "x");
    write_text("fields.nc.partial", "x");
    write_text("status.tmp.12", "x");
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_manifest_write(&ctx, dir), &ctx);
    char p[512], line[256], why[600];
    path_of("manifest", p, sizeof p);
    FILE *f = fopen(p, "r");
    int n_files = 0, others = 0;
    while (f && fgets(line, sizeof line, f)) {
        if (strncmp(line, "file ", 5) != 0)
            continue;
        ++n_files;
        others += strstr(line, "post_") || strstr(line, "checkpoint") || strstr(line, "partial") ||
                  strstr(line, ".tmp");
    }
    if (f)
        fclose(f);
    GF_CHECK(n_files == 3 && others == 0);
    GF_CHECK(gf_manifest_time(dir) > 1e9);
    GF_CHECK(gf_manifest_verify(dir, why, sizeof why));

    /* one bit of the last byte: same size, the CRC-32 differs */
    const long size = file_size("particles.nc");
    flip_byte("particles.nc", size - 1);
    GF_CHECK(!gf_manifest_verify(dir, why, sizeof why) && strstr(why, "particles.nc") && strstr(why, "CRC-32"));
    printf("flipped bit: %s\n", why);
    flip_byte("particles.nc", size - 1);
    GF_CHECK(gf_manifest_verify(dir, why, sizeof why));

    path_of("particles.nc", p, sizeof p);
    GF_CHECK(truncate(p, size / 2) == 0);
    GF_CHECK(!gf_manifest_verify(dir, why, sizeof why) && strstr(why, "particles.nc") && strstr(why, "bytes"));
    printf("truncated: %s\n", why);

    /* an older run: no manifest, the truncated file does not open */
    path_of("manifest", p, sizeof p);
    remove(p);
    GF_CHECK(!gf_manifest_verify(dir, why, sizeof why) && strstr(why, "particles.nc"));
    printf("no manifest: %s\n", why);
    write_nc("particles.nc", 5000);
    GF_CHECK(gf_manifest_verify(dir, why, sizeof why));

    GF_CHECK_OK(gf_manifest_write(&ctx, dir), &ctx);
    path_of("diagnostics.nc", p, sizeof p);
    remove(p);
    GF_CHECK(!gf_manifest_verify(dir, why, sizeof why) && strstr(why, "diagnostics.nc is missing"));
    printf("missing: %s\n", why);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/gf_rundir_XXXXXX");
    GF_CHECK(mkdtemp(dir) != NULL);
    test_lock();
    test_manifest();
    return gf_test_finish_removing(dir);
}
