/*
 * Fuzz corpus: every file in tests/pipeline/corpus/ is malformed on purpose
 * (tabs, unclosed quotes and brackets, wrong types, unknown keys, numbers too
 * large for a double, NaN and infinities, an empty file, binary junk, invalid
 * UTF-8, NUL bytes, nesting 200 deep, keys 20000 characters long, ...). Each
 * must give a clean configuration error: status GF_ERR_CONFIG and exactly one
 * line "path:line:column: message" naming a position inside the file, and no
 * campaign. Run under -DGF_SANITIZE=ON this also checks that no input makes
 * the parser read out of bounds or leak.
 *
 * Then every input of tests/pipeline/fuzz_corpus (the corpus libFuzzer grew
 * from these files and the configs, workflows/fuzz.sh: valid campaigns and
 * near misses that reach every branch the fuzzer found) goes through the
 * reader of the ordinary build, which must meet the fuzzer's property
 * (cfg_property.h): a campaign, or a located one-line refusal.
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "campaign/gf_campaign.h"
#include "cfg_property.h"
#include "gf_test.h"

/* "path:L:C: text" with L, C >= 1 and text non-empty. */
static int located(const char *msg, const char *path, int *line, int *col)
{
    size_t n = strlen(path);
    if (strncmp(msg, path, n) != 0 || msg[n] != ':')
        return 0;
    int used = 0;
    if (sscanf(msg + n, ":%d:%d: %n", line, col, &used) != 2 || used == 0)
        return 0;
    return *line >= 1 && *col >= 1 && msg[n + (size_t)used] != '\0';
}

static int lines_in(const char *path)
{
    FILE *f = fopen(path, "rb");
    int n = 1, c;
    while (f && (c = fgetc(f)) != EOF)
        n += c == '\n';
    if (f)
        fclose(f);
    return n;
}

/* One corpus file as the reader left it: its name in dir, its path, the status, the campaign (or NULL) and the context. */
typedef struct corpus_entry {
    const char *dir, *name, *path;
    gf_status st;
    const gf_campaign *c;
    const gf_ctx *ctx;
} corpus_entry;
typedef void (*corpus_check)(const corpus_entry *e, void *arg);

/* Loads each file of dir (dot files aside) as a campaign and hands the outcome to check; returns the number of files. */
static int replay_corpus(const char *dir, corpus_check check, void *arg)
{
    DIR *d = opendir(dir);
    GF_CHECK(d != NULL);
    int n = 0;
    struct dirent *e;
    while (d && (e = readdir(d))) {
        if (e->d_name[0] == '.')
            continue;
        char path[4400];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        gf_ctx ctx = {0};
        gf_campaign *c = NULL;
        gf_status st = gf_campaign_load_file(&ctx, path, NULL, 0, &c);
        const corpus_entry ce = {.dir = dir, .name = e->d_name, .path = path, .st = st, .c = c, .ctx = &ctx};
        check(&ce, arg);
        gf_campaign_destroy(&c);
        ++n;
    }
    if (d)
        closedir(d);
    return n;
}

/* A corpus file is refused as a config error, located file:line:col within the file, on one line, with no campaign. */
static void check_refused(const corpus_entry *e, void *arg)
{
    (void)arg;
    const char *msg = e->ctx->last_msg;
    int line = 0, col = 0;
    gf_test_check(e->st == GF_ERR_CONFIG, __FILE__, __LINE__, "%s: status %s (%s)", e->name, gf_status_str(e->st), msg);
    gf_test_check(located(msg, e->path, &line, &col), __FILE__, __LINE__, "%s: not file:line:col: %s", e->name, msg);
    gf_test_check(line <= lines_in(e->path), __FILE__, __LINE__, "%s: line %d beyond the file", e->name, line);
    gf_test_check(strchr(msg, '\n') == NULL, __FILE__, __LINE__, "%s: one line", e->name);
    gf_test_check(e->c == NULL, __FILE__, __LINE__, "%s: no campaign", e->name);
    printf("%-28s %s\n", e->name, msg + strlen(e->dir) + 1);
}

/* A fuzz input is accepted or refused as the reader must (gf_cfg_outcome_fault); *arg counts the accepted ones. */
static void check_fuzz(const corpus_entry *e, void *arg)
{
    const char *fault = gf_cfg_outcome_fault(e->st, e->c, e->ctx, e->path);
    gf_test_check(fault == NULL, __FILE__, __LINE__, "fuzz_corpus/%s: %s (%s: %s)", e->name, fault ? fault : "",
                  gf_status_str(e->st), e->ctx->last_msg);
    *(int *)arg += e->st == GF_OK;
}

int main(void)
{
    const char *src = getenv("GF_SOURCE_DIR");
    char dir[4096];
    snprintf(dir, sizeof dir, "%s/tests/pipeline/corpus", src ? src : ".");
    int n_files = replay_corpus(dir, check_refused, NULL);
    gf_test_check(n_files >= 40, __FILE__, __LINE__, "corpus has %d files, expected >= 40", n_files);

    snprintf(dir, sizeof dir, "%s/tests/pipeline/fuzz_corpus", src ? src : ".");
    int n_ok = 0, n_fuzz = replay_corpus(dir, check_fuzz, &n_ok);
    printf("fuzz corpus: %d inputs replayed, %d accepted as campaigns, %d refused with a located line\n", n_fuzz, n_ok,
           n_fuzz - n_ok);
    gf_test_check(n_fuzz >= 200, __FILE__, __LINE__, "fuzz corpus has %d files, expected >= 200", n_fuzz);
    return gf_test_finish();
}
