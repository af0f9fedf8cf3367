/* Run directories, status files and run.yaml; see gf_ledger.h. */
#include "schedule/gf_ledger.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "campaign/gf_spec_text.h"
#include "core/gf_build_info.h"
#include "rundir/gf_manifest.h"

gf_status gf_ledger_mkdirs(gf_ctx *ctx, const char *path)
{
    char buf[4096];
    if (snprintf(buf, sizeof buf, "%s", path) >= (int)sizeof buf)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: path too long", path);
    for (char *p = buf + 1;; ++p) {
        if (*p == '/' || *p == '\0') {
            char c = *p;
            *p = '\0';
            if (mkdir(buf, 0777) != 0 && errno != EEXIST)
                return GF_FAIL(ctx, GF_ERR_IO, "%s: cannot create directory: %s", buf, strerror(errno));
            *p = c;
            if (!c)
                break;
        }
    }
    struct stat sb;
    if (stat(path, &sb) != 0 || !S_ISDIR(sb.st_mode))
        return GF_FAIL(ctx, GF_ERR_IO, "%s: not a directory", path);
    return GF_OK;
}

gf_status gf_ledger_write_atomic(gf_ctx *ctx, const char *path, const char *text, size_t len)
{
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "wb");
    if (!f)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: cannot write: %s", tmp, strerror(errno));
    int ok = fwrite(text, 1, len, f) == len;
    ok &= fflush(f) == 0;
    ok &= fsync(fileno(f)) == 0 || errno == EINVAL;
    ok &= fclose(f) == 0;
    if (!ok || rename(tmp, path) != 0) {
        int e = errno;
        remove(tmp);
        return GF_FAIL(ctx, GF_ERR_IO, "%s: cannot write: %s", path, strerror(e));
    }
    return GF_OK;
}

void gf_ledger_run_dir(const char *out_dir, const char *campaign, const char *run_id, char *buf, size_t n)
{
    snprintf(buf, n, "%s/%s/%s", out_dir, campaign, run_id);
}

gf_run_state gf_ledger_state(const char *run_dir, char *reason, size_t n)
{
    char path[4200], line[600] = "";
    if (n)
        reason[0] = '\0';
    snprintf(path, sizeof path, "%s/status", run_dir);
    FILE *f = fopen(path, "r");
    if (!f)
        return GF_RUN_NEW;
    if (!fgets(line, sizeof line, f))
        line[0] = '\0';
    fclose(f);
    line[strcspn(line, "\n")] = '\0';
    if (strcmp(line, "done") == 0)
        return GF_RUN_DONE;
    if (n)
        snprintf(reason, n, "%s", strncmp(line, "failed: ", 8) == 0 ? line + 8 : line);
    return GF_RUN_FAILED;
}

gf_run_state gf_ledger_verified_state(const char *run_dir, char *reason, size_t n)
{
    gf_run_state st = gf_ledger_state(run_dir, reason, n);
    if (st == GF_RUN_DONE && !gf_manifest_verify(run_dir, reason, n))
        return GF_RUN_CORRUPT;
    return st;
}

void gf_ledger_lock_path(const char *run_dir, char *buf, size_t n)
{
    snprintf(buf, n, "%s/.lock", run_dir);
}

void gf_ledger_clear(const char *run_dir)
{
    char path[4200];
    /* "failed: interrupted ...; checkpoint written" stays: a continuation
     * killed in turn can still continue from the same checkpoint */
    if (gf_ledger_state(run_dir, NULL, 0) == GF_RUN_DONE) {
        snprintf(path, sizeof path, "%s/status", run_dir);
        remove(path);
    }
    snprintf(path, sizeof path, "%s/manifest", run_dir);
    remove(path);
}

/* The first line at which run.yaml (file f) and yaml (len bytes) differ, both quoted, into why. */
static void first_difference(FILE *f, const char *yaml, size_t len, char *why, size_t n)
{
    char old[400], now[400];
    size_t k = 0;
    for (int no = 1;; ++no) {
        const int has_old = fgets(old, sizeof old, f) != NULL, has_now = k < len;
        old[has_old ? strcspn(old, "\n") : 0] = '\0';
        const char *nl = memchr(yaml + k, '\n', len - k);
        const size_t m = (nl ? (size_t)(nl - yaml) : len) - k;
        snprintf(now, sizeof now, "%.*s", (int)m, yaml + k);
        k += m + (nl != NULL);
        if (strcmp(old, now) != 0) {
            snprintf(why, n, "run.yaml line %d reads \"%.120s\" where this spec has \"%.120s\"", no, old, now);
            return;
        }
        if (!has_old && !has_now)
            break;
    }
    snprintf(why, n, "run.yaml differs from this spec");
}

int gf_ledger_can_continue(const char *run_dir, const char *yaml, size_t len, char *why, size_t n)
{
    char reason[600], path[4200];
    if (why && n)
        why[0] = '\0';
    if (gf_ledger_state(run_dir, reason, sizeof reason) != GF_RUN_FAILED ||
        strncmp(reason, "interrupted", 11) != 0 || !strstr(reason, "checkpoint written"))
        return 0;
    snprintf(path, sizeof path, "%s/checkpoint.h5", run_dir);
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    fclose(f);
    snprintf(path, sizeof path, "%s/run.yaml", run_dir);
    if (!(f = fopen(path, "rb"))) {
        if (why && n)
            snprintf(why, n, "its run.yaml is missing");
        return 0;
    }
    int same = 1;
    for (size_t k = 0; same && k < len; ++k)
        same = fgetc(f) == (unsigned char)yaml[k];
    same = same && fgetc(f) == EOF;
    if (!same && why && n) {
        rewind(f);
        first_difference(f, yaml, len, why, n);
    }
    fclose(f);
    return same;
}

gf_status gf_ledger_set_done(gf_ctx *ctx, const char *run_dir)
{
    char path[4200];
    GF_TRY(gf_manifest_write(ctx, run_dir));
    snprintf(path, sizeof path, "%s/status", run_dir);
    return gf_ledger_write_atomic(ctx, path, "done\n", 5);
}

gf_status gf_ledger_set_failed(gf_ctx *ctx, const char *run_dir, const char *reason)
{
    char path[4200], text[700];
    snprintf(path, sizeof path, "%s/status", run_dir);
    int len = snprintf(text, sizeof text, "failed: %s", reason && *reason ? reason : "unknown");
    if (len >= (int)sizeof text)
        len = (int)sizeof text - 2;
    for (int i = 8; i < len; ++i) /* the status is one line */
        if (text[i] == '\n')
            text[i] = ' ';
    text[len++] = '\n';
    return gf_ledger_write_atomic(ctx, path, text, (size_t)len);
}

char *gf_ledger_run_yaml(const gf_run_spec *spec, const char *campaign, size_t *len)
{
    char body[GF_SPEC_TEXT_MAX];
    size_t nb = gf_spec_text(spec, body, sizeof body);
    size_t cap = nb + 512;
    char *text = malloc(cap);
    if (!text)
        return NULL;
    int nh = snprintf(text, cap,
                      "# grainflow %s (%s): resolved spec of run %s.\n"
                      "# Every value is explicit; `grainflow run run.yaml` reproduces the run (same id).\n"
                      "name: %s\n",
                      GF_VERSION, gf_build_revision(), spec->run_id, campaign);
    memcpy(text + nh, body, nb + 1);
    *len = (size_t)nh + nb;
    return text;
}
