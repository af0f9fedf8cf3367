/* Run manifests: sizes and CRC-32 of a run's files; see gf_manifest.h. */
#include "rundir/gf_manifest.h"

#include <dirent.h>
#include <errno.h>
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <unistd.h>
#include <zlib.h>

#define MANIFEST_NAME "manifest"
#define NAME_MAX_LEN 256

static int ends_with(const char *s, const char *tail)
{
    size_t ls = strlen(s), lt = strlen(tail);
    return ls >= lt && strcmp(s + ls - lt, tail) == 0;
}

/* Files of a run directory that the run wrote and the manifest lists. */
static int is_listed(const char *name)
{
    if (name[0] == '.' || !strcmp(name, "status") || !strcmp(name, MANIFEST_NAME) ||
        !strcmp(name, "checkpoint.h5") || !strncmp(name, "post_", 5))
        return 0;
    return !strstr(name, ".tmp") && !ends_with(name, ".partial") && strlen(name) < NAME_MAX_LEN;
}

/* Size and CRC-32 of a whole file, read back from the file system. */
static int file_crc(const char *path, long long *size, unsigned long *crc)
{
    const size_t chunk = 1 << 20;
    unsigned char *buf = malloc(chunk);
    FILE *f = buf ? fopen(path, "rb") : NULL;
    if (!f) {
        free(buf);
        return -1;
    }
    uLong c = crc32(0L, Z_NULL, 0);
    long long total = 0;
    size_t got;
    while ((got = fread(buf, 1, chunk, f)) > 0) {
        c = crc32(c, buf, (uInt)got);
        total += (long long)got;
    }
    int bad = ferror(f);
    fclose(f);
    free(buf);
    *size = total;
    *crc = c;
    return bad ? -1 : 0;
}

/* A netCDF file reopens and its header reads back. */
static int nc_reopens(const char *path, char *reason, size_t n)
{
    int id, ndims, nvars, natts, unlim;
    int rc = nc_open(path, NC_NOWRITE, &id);
    if (rc == NC_NOERR) {
        rc = nc_inq(id, &ndims, &nvars, &natts, &unlim);
        nc_close(id);
    }
    if (rc != NC_NOERR)
        snprintf(reason, n, "%s does not open as netCDF (%s)", strrchr(path, '/') + 1, nc_strerror(rc));
    return rc == NC_NOERR;
}

static int cmp_name(const void *a, const void *b)
{
    return strcmp((const char *)a, (const char *)b);
}

/* Names of the listed files of dir (sorted) into a malloc'ed array. */
static int list_files(const char *dir, char (**names)[NAME_MAX_LEN])
{
    *names = NULL;
    DIR *d = opendir(dir);
    if (!d)
        return -1;
    int n = 0, cap = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        char p[4400];
        struct stat sb;
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        if (!is_listed(e->d_name) || stat(p, &sb) != 0 || !S_ISREG(sb.st_mode))
            continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 16;
            void *grown = realloc(*names, (size_t)cap * sizeof **names);
            if (!grown) {
                closedir(d);
                return -1;
            }
            *names = grown;
        }
        snprintf((*names)[n++], NAME_MAX_LEN, "%s", e->d_name);
    }
    closedir(d);
    if (n)
        qsort(*names, (size_t)n, sizeof **names, cmp_name);
    return n;
}

gf_status gf_manifest_write(gf_ctx *ctx, const char *run_dir)
{
    char (*names)[NAME_MAX_LEN] = NULL;
    int n = list_files(run_dir, &names);
    if (n < 0)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: cannot list the run's files: %s", run_dir, strerror(errno));
    char path[4400], tmp[4500], reason[600];
    snprintf(path, sizeof path, "%s/%s", run_dir, MANIFEST_NAME);
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "w");
    gf_status st = GF_OK;
    if (!f) {
        free(names);
        return GF_FAIL(ctx, GF_ERR_IO, "%s: cannot write: %s", tmp, strerror(errno));
    }
    struct timeval now;
    gettimeofday(&now, NULL);
    char host[64] = "unknown";
    gethostname(host, sizeof host - 1);
    host[sizeof host - 1] = '\0';
    fprintf(f, "# grainflow run manifest: the files this run wrote, reopened after it ended (size in bytes, CRC-32)\n");
    fprintf(f, "written %.3f pid %ld host %s\n", (double)now.tv_sec + 1e-6 * (double)now.tv_usec, (long)getpid(), host);
    for (int i = 0; i < n && st == GF_OK; ++i) {
        char p[4400];
        long long size;
        unsigned long crc;
        snprintf(p, sizeof p, "%s/%s", run_dir, names[i]);
        if (ends_with(names[i], ".nc") && !nc_reopens(p, reason, sizeof reason))
            st = GF_FAIL(ctx, GF_ERR_IO, "%s: %s", run_dir, reason);
        else if (file_crc(p, &size, &crc) != 0)
            st = GF_FAIL(ctx, GF_ERR_IO, "%s: cannot read back: %s", p, strerror(errno));
        else
            fprintf(f, "file %s %lld %08lx\n", names[i], size, crc);
    }
    free(names);
    int ok = fflush(f) == 0 && (fsync(fileno(f)) == 0 || errno == EINVAL);
    ok &= fclose(f) == 0;
    if (st == GF_OK && (!ok || rename(tmp, path) != 0))
        st = GF_FAIL(ctx, GF_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
    if (st != GF_OK)
        remove(tmp);
    return st;
}

/* A run from before manifests: every netCDF file opens. */
static int verify_without_manifest(const char *run_dir, char *reason, size_t n)
{
    char (*names)[NAME_MAX_LEN] = NULL;
    int count = list_files(run_dir, &names), ok = count >= 0;
    for (int i = 0; ok && i < count; ++i) {
        char p[4400];
        snprintf(p, sizeof p, "%s/%s", run_dir, names[i]);
        ok = !ends_with(names[i], ".nc") || nc_reopens(p, reason, n);
    }
    if (count < 0)
        snprintf(reason, n, "cannot list the run directory");
    free(names);
    return ok;
}

int gf_manifest_verify(const char *run_dir, char *reason, size_t n)
{
    char path[4400], line[600];
    if (n)
        reason[0] = '\0';
    snprintf(path, sizeof path, "%s/%s", run_dir, MANIFEST_NAME);
    FILE *f = fopen(path, "r");
    if (!f)
        return verify_without_manifest(run_dir, reason, n);
    int ok = 1, n_files = 0;
    while (ok && fgets(line, sizeof line, f)) {
        char name[NAME_MAX_LEN], p[4400];
        long long size, got_size;
        unsigned long crc, got_crc;
        if (sscanf(line, "file %255s %lld %lx", name, &size, &crc) != 3)
            continue;
        ++n_files;
        snprintf(p, sizeof p, "%s/%s", run_dir, name);
        struct stat sb;
        if (stat(p, &sb) != 0) {
            snprintf(reason, n, "%s is missing (the manifest lists it)", name);
            ok = 0;
        } else if ((long long)sb.st_size != size) {
            snprintf(reason, n, "%s has %lld bytes, %lld when the run ended", name, (long long)sb.st_size, size);
            ok = 0;
        } else if (file_crc(p, &got_size, &got_crc) != 0 || got_crc != crc) {
            snprintf(reason, n, "%s changed since the run ended (CRC-32 %08lx, recorded %08lx)", name, got_crc, crc);
            ok = 0;
        } else if (ends_with(name, ".nc")) {
            ok = nc_reopens(p, reason, n);
        }
    }
    fclose(f);
    if (ok && n_files == 0) {
        snprintf(reason, n, "the manifest lists no file");
        ok = 0;
    }
    return ok;
}

double gf_manifest_time(const char *run_dir)
{
    char path[4400], line[600];
    double t = 0.0;
    snprintf(path, sizeof path, "%s/%s", run_dir, MANIFEST_NAME);
    FILE *f = fopen(path, "r");
    if (!f)
        return 0.0;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "written %lf", &t) == 1)
            break;
    fclose(f);
    return t;
}
