/*
 * gf_post_campaign: post-processing of a campaign directory (gf_post.h).
 *
 * 1. Run directories: campaign_dir itself when it holds a run (a status
 *    file, run.yaml or one of the run files), else its sub-directories that
 *    do, in name order.
 * 2. Per run: identity from the status file and the first readable run file
 *    (diagnostics.nc, particles.nc, probes.nc, fields.nc): run_id, scene,
 *    fluid_model and the groups asked for and realised (docs/output.md).
 *    A failed run ("failed: reason") is marked and not analysed; a done run
 *    whose files do not match its manifest is marked corrupt (and still
 *    analysed as far as its files allow); a run another process holds is
 *    marked incomplete and left alone; a corrupt file or a stage failure is
 *    recorded in the row's error column with the stage's name, a stage whose
 *    input the run did not write in its notes, and the other stages and runs
 *    go on.
 * 3. Stages: every stage of the table, or opt->stage alone, each writing its
 *    scalars into the row and its series into <run>/post_<stage>.nc.
 *    With n_jobs > 1, runs are processed by forked workers (netCDF-C is not
 *    thread-safe); each sends its row back through a pipe. Stages are pure,
 *    so the rows do not depend on n_jobs.
 * 4. summary.nc / summary.csv (gf_summary.h), then the SVG files of figures/: the
 *    diagrams from summary.nc alone, the time series from the per-run
 *    post_deposit.nc and probes.nc; all under the campaign's .summary.lock.
 * gf_post_tree finds the campaign directories below a directory that holds
 * no run, and post-processes each.
 */
#include "gf_post.h"

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "figures/gf_figures.h"
#include "gf_ncread.h"
#include "gf_summary.h"
#include "rundir/gf_lock.h"
#include "rundir/gf_manifest.h"
#include "stages/gf_post_label.h"
#include "stages/gf_stage.h"
#include "stages/gf_silo_flow.h"
#include "stages/gf_stage_util.h"

static const char *const run_files[] = {"diagnostics.nc", "particles.nc", "probes.nc", "fields.nc"};

static int file_exists(const char *dir, const char *name)
{
    char p[1200];
    int k = snprintf(p, sizeof p, "%s/%s", dir, name);
    struct stat st;
    return k > 0 && (size_t)k < sizeof p && stat(p, &st) == 0 && S_ISREG(st.st_mode);
}

static int is_run_dir(const char *dir)
{
    if (file_exists(dir, "status") || file_exists(dir, "run.yaml"))
        return 1;
    for (size_t k = 0; k < sizeof run_files / sizeof run_files[0]; ++k)
        if (file_exists(dir, run_files[k]))
            return 1;
    return 0;
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Appends a copy of s to the list (*list, *n entries of *cap allocated),
 * growing it; 0 when out of memory (the list is left as it was). */
static int append_copy(char ***list, int *n, int *cap, const char *s)
{
    if (*n == *cap) {
        const int grown_cap = *cap ? 2 * *cap : 8;
        char **grown = realloc(*list, (size_t)grown_cap * sizeof **list);
        if (!grown)
            return 0;
        *list = grown;
        *cap = grown_cap;
    }
    char *copy = strdup(s);
    if (!copy)
        return 0;
    (*list)[(*n)++] = copy;
    return 1;
}

/* The run directories directly below dir, appended to the list. */
static gf_status list_run_dirs(gf_ctx *ctx, const char *dir, char ***list, int *n, int *cap)
{
    DIR *d = opendir(dir);
    if (!d)
        return GF_FAIL(ctx, GF_ERR_IO, "post: cannot read directory %s (%s)", dir, strerror(errno));
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.' || strcmp(e->d_name, "figures") == 0)
            continue;
        char p[1200];
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        struct stat st;
        if (stat(p, &st) != 0 || !S_ISDIR(st.st_mode) || !is_run_dir(p))
            continue;
        if (!append_copy(list, n, cap, p))
            break;
    }
    closedir(d);
    return GF_OK;
}

/* Run directories (malloc'ed strings, sorted): dir itself when it is one,
 * else those directly below it. */
static gf_status find_runs(gf_ctx *ctx, const char *dir, char ***out, int *n_out)
{
    int n = 0, cap = 16;
    char **list = malloc((size_t)cap * sizeof *list);
    *out = NULL;
    *n_out = 0;
    if (!list || (is_run_dir(dir) && !append_copy(&list, &n, &cap, dir))) {
        free(list);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "post: out of memory");
    }
    if (n == 0) {
        gf_status st = list_run_dirs(ctx, dir, &list, &n, &cap);
        if (st != GF_OK) {
            free(list);
            return st;
        }
    }
    qsort(list, (size_t)n, sizeof *list, cmp_str);
    *out = list;
    *n_out = n;
    return GF_OK;
}

static void read_status(gf_post_row *row)
{
    char p[1200];
    snprintf(p, sizeof p, "%s/status", row->run_dir);
    FILE *f = fopen(p, "r");
    if (!f) {
        snprintf(row->status, sizeof row->status, "incomplete");
        gf_post_row_add_error(row, NULL, "no status file (run not finished?)");
        return;
    }
    char line[600] = "";
    if (!fgets(line, sizeof line, f))
        line[0] = '\0';
    fclose(f);
    line[strcspn(line, "\r\n")] = '\0';
    if (strncmp(line, "done", 4) == 0) {
        char why[600], msg[700];
        if (!gf_manifest_verify(row->run_dir, why, sizeof why)) {
            snprintf(msg, sizeof msg, "marked done, but %s", why);
            gf_post_row_add_error(row, "corrupt", msg);
        }
        return;
    }
    if (strncmp(line, "failed", 6) == 0) {
        const char *why = line + 6;
        while (*why == ':' || *why == ' ')
            ++why;
        char msg[640];
        snprintf(msg, sizeof msg, "run failed: %s", *why ? why : "(no reason given)");
        snprintf(row->status, sizeof row->status, "failed");
        gf_post_row_add_error(row, NULL, msg);
        return;
    }
    snprintf(row->status, sizeof row->status, "incomplete");
    char msg[700];
    snprintf(msg, sizeof msg, "status file says '%.600s'", line);
    gf_post_row_add_error(row, NULL, msg);
}

/* Identity of a run that left no readable netCDF file (e.g. it failed before
 * its first record), from its run.yaml: the scene name, fluid model and the
 * groups asked for. A line scan of the two-level block layout the pipeline
 * writes, not a YAML parser: anything else is left unset. */
static void read_run_yaml(gf_post_row *row)
{
    char p[1200], line[512], block[64] = "";
    snprintf(p, sizeof p, "%s/run.yaml", row->run_dir);
    FILE *f = fopen(p, "r");
    if (!f)
        return;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#' || line[0] == '\n')
            continue;
        if (line[0] != ' ') {
            sscanf(line, "%63[^:]", block);
            continue;
        }
        char key[64], val[128];
        if (sscanf(line, " %63[^:]: %127s", key, val) != 2)
            continue;
        if (strcmp(block, "scene") == 0 && strcmp(key, "name") == 0 && !row->scene[0])
            snprintf(row->scene, sizeof row->scene, "%.47s", val);
        else if (strcmp(block, "fluid") == 0 && strcmp(key, "model") == 0 && !row->fluid_model[0])
            snprintf(row->fluid_model, sizeof row->fluid_model, "%.47s", val);
        else if (strcmp(block, "groups") == 0 &&
                 (!strcmp(key, "St") || !strcmp(key, "r") || !strcmp(key, "a") || !strcmp(key, "Phi_i")))
            gf_post_row_set(row, key, strtod(val, NULL));
    }
    fclose(f);
}

/* Identity and inputs from the first readable run file. */
static void read_identity(gf_post_row *row)
{
    const char *base = strrchr(row->run_dir, '/');
    snprintf(row->run_id, sizeof row->run_id, "%.63s", base ? base + 1 : row->run_dir);
    for (size_t k = 0; k < sizeof run_files / sizeof run_files[0]; ++k) {
        if (!file_exists(row->run_dir, run_files[k]))
            continue;
        char p[1200];
        snprintf(p, sizeof p, "%s/%s", row->run_dir, run_files[k]);
        gf_ctx c = {0};
        gf_ncr f;
        if (gf_ncr_open(&c, p, &f) != GF_OK)
            continue;   /* the stage reading it will report it */
        char buf[GF_ROW_TEXT_LEN];
        if (gf_ncr_att_text(NULL, &f, "run_id", buf, sizeof buf) == GF_OK && buf[0])
            snprintf(row->run_id, sizeof row->run_id, "%s", buf);
        gf_ncr_att_text(NULL, &f, "scene", row->scene, sizeof row->scene);
        gf_ncr_att_text(NULL, &f, "fluid_model", row->fluid_model, sizeof row->fluid_model);
        char stages[64] = "";
        gf_ncr_att_text(NULL, &f, "stages", stages, sizeof stages);
        gf_post_row_set_text(row, "method", strcmp(stages, "continuum") == 0 ? "continuum" : "dem");
        static const char *const map[][2] = {{"stokes_St", "St"},
                                             {"density_ratio_r", "r"},
                                             {"aspect_ratio_a", "a"},
                                             {"phi_initial", "Phi_i"},
                                             {"realised_St", "realised_St"},
                                             {"realised_r", "realised_r"},
                                             {"phi_initial_measured", "phi_initial_measured"},
                                             {"phi_initial_local", "phi_initial_local"},
                                             {"seed", "seed"}};
        for (size_t m = 0; m < sizeof map / sizeof map[0]; ++m)
            gf_post_row_set(row, map[m][1], gf_ncr_att_double_or(&f, map[m][0], NAN));
        if (gf_ncr_att_double_or(&f, "column_length_m", 0.0) > 0.0) { /* a released column */
            double R0, H0;
            gf_stage_column(&f, &R0, &H0);
            gf_post_row_set(row, "R0_m", R0);
            gf_post_row_set(row, "H0_m", H0);
        }
        gf_ncr_close(&f);
        return;
    }
    read_run_yaml(row);
}

static void stage_name_add(gf_post_row *row, const gf_stage_info *s)
{
    size_t len = strlen(row->stages);
    snprintf(row->stages + len, sizeof row->stages - len, "%s%s@%d", len ? "," : "", s->name, s->version);
}

static void add_note(gf_post_row *row, const char *msg)
{
    size_t len = strlen(row->notes);
    if (len + 3 < sizeof row->notes)
        snprintf(row->notes + len, sizeof row->notes - len, "%s%.300s", len ? "; " : "", msg);
}

/* Everything for one run, into *row. The stages write post_<stage>.nc into
 * the run directory, so they run under its lock; a run another process is
 * writing is reported as such and left alone. */
static void post_run(const char *run_dir, const gf_stage_info *only, gf_post_row *row)
{
    gf_post_row_init(row, run_dir);
    read_status(row);
    read_identity(row);
    if (strcmp(row->status, "failed") == 0)
        return;
    char lock_path[1200], who[300], msg[400];
    gf_lock *lock = NULL;
    gf_lock_holder holder;
    snprintf(lock_path, sizeof lock_path, "%s/.lock", run_dir);
    gf_ctx lc = {0};
    if (gf_lock_take(&lc, lock_path, "post", 0.0, &lock, &holder, NULL) == GF_OK && !lock) {
        gf_lock_describe(&holder, who, sizeof who);
        snprintf(msg, sizeof msg, "being written by %s", who);
        gf_post_row_add_error(row, "incomplete", msg);
        return;
    }
    gf_stage_in in = {run_dir, row->scene};
    gf_stage_opts opts = {1};
    gf_stage_out out = {row};
    for (int s = 0; s < gf_stage_count; ++s) {
        const gf_stage_info *si = &gf_stage_table[s];
        if (only && only != si)
            continue;
        gf_ctx c = {0};
        gf_status st = si->fn(&c, &in, &opts, &out);
        char line[700];
        snprintf(line, sizeof line, "stage %s: %s", si->name, c.last_msg[0] ? c.last_msg : gf_status_str(st));
        if (st == GF_OK)
            stage_name_add(row, si);
        else if (st == GF_ERR_UNSUPPORTED && c.last_msg[0]) /* not determined from what the run wrote */
            add_note(row, line);
        else if (st != GF_ERR_UNSUPPORTED)
            gf_post_row_add_error(row, "error", line);
    }
    gf_lock_release(&lock);
}

/* Writes (writing != 0) or reads all n bytes of buf through fd, across
 * short transfers and interrupted calls; -1 on failure or end of file. */
static int transfer_all(int fd, void *buf, size_t n, int writing)
{
    char *p = buf;
    while (n > 0) {
        ssize_t done = writing ? write(fd, p, n) : read(fd, p, n);
        if (done < 0 && errno == EINTR)
            continue;
        if (done <= 0)
            return -1;
        p += done;
        n -= (size_t)done;
    }
    return 0;
}

/* Runs processed by up to n_jobs forked workers; each streams its row back
 * through its own pipe, read by the parent as soon as the worker is started
 * in turn (reads block until the row is complete). */
static void post_parallel(char **runs, int n, const gf_stage_info *only, int n_jobs, gf_post_row *rows)
{
    int next = 0;
    while (next < n) {
        int batch = n - next < n_jobs ? n - next : n_jobs;
        pid_t pids[64];
        int fds[64];
        for (int j = 0; j < batch; ++j) {
            int pfd[2];
            pids[j] = -1;
            fds[j] = -1;
            if (pipe(pfd) != 0)
                continue;
            const pid_t parent = getpid();
            pid_t pid = fork();
            if (pid == 0) {
                /* no post worker outlives post (it would hold a run's lock) */
                prctl(PR_SET_PDEATHSIG, SIGKILL);
                if (getppid() != parent)
                    _exit(1);
                close(pfd[0]);
                gf_post_row *row = malloc(sizeof *row);
                int rc = 1;
                if (row) {
                    post_run(runs[next + j], only, row);
                    rc = transfer_all(pfd[1], row, sizeof *row, 1) == 0 ? 0 : 1;
                }
                close(pfd[1]);
                _exit(rc);
            }
            close(pfd[1]);
            if (pid < 0) {
                close(pfd[0]);
                continue;
            }
            pids[j] = pid;
            fds[j] = pfd[0];
        }
        for (int j = 0; j < batch; ++j) {
            gf_post_row *row = &rows[next + j];
            if (fds[j] < 0 || transfer_all(fds[j], row, sizeof *row, 0) != 0) {
                /* no worker or it died: do the run here, serially */
                post_run(runs[next + j], only, row);
            }
            if (fds[j] >= 0)
                close(fds[j]);
            if (pids[j] > 0)
                waitpid(pids[j], NULL, 0);
        }
        next += batch;
    }
}

/* ---- figures ---- */

static double row_or(const gf_post_row *r, const char *a, const char *b)
{
    double v = gf_post_row_get(r, a);
    return isfinite(v) ? v : gf_post_row_get(r, b);
}

/* Series var(time) of <run>/<file>, NULL when absent. */
static int read_series(const char *run_dir, const char *file, const char *var, size_t row_k, double **t,
                       double **y, size_t *n)
{
    char p[1200];
    snprintf(p, sizeof p, "%s/%s", run_dir, file);
    *t = *y = NULL;
    *n = 0;
    if (!gf_ncr_exists(p))
        return 0;
    gf_ncr f;
    if (gf_ncr_open(NULL, p, &f) != GF_OK)
        return 0;
    size_t nt = 0;
    int ok = gf_ncr_has_var(&f, var) && gf_ncr_var_1d(NULL, &f, "time", t, &nt) == GF_OK;
    if (ok) {
        *y = malloc(nt * sizeof **y + 1);
        double *full = NULL;
        size_t n1 = 0;
        if (!*y)
            ok = 0;
        else if (gf_ncr_var_1d(NULL, &f, var, &full, &n1) == GF_OK && n1 == nt) {
            memcpy(*y, full, nt * sizeof **y);
        } else {
            ok = gf_ncr_var_2d_row(NULL, &f, var, row_k, *y, nt) == GF_OK;
        }
        free(full);
    }
    gf_ncr_close(&f);
    if (!ok) {
        free(*t), free(*y);
        *t = *y = NULL;
        return 0;
    }
    *n = nt;
    return 1;
}

/* Station of probes.nc nearest to the gauge the summary reports (Pb_x_m), 0 if unknown. */
static size_t gauge_index(const gf_post_row *w)
{
    const double xg = gf_post_row_get(w, "Pb_x_m");
    char p[1200];
    snprintf(p, sizeof p, "%s/probes.nc", w->run_dir);
    size_t best = 0;
    gf_ncr f;
    if (!isfinite(xg) || !gf_ncr_exists(p) || gf_ncr_open(NULL, p, &f) != GF_OK)
        return 0;
    double *x = NULL;
    size_t n = 0;
    if (gf_ncr_var_1d(NULL, &f, "x", &x, &n) == GF_OK)
        for (size_t k = 1; k < n; ++k)
            if (fabs(x[k] - xg) < fabs(x[best] - xg))
                best = k;
    free(x);
    gf_ncr_close(&f);
    return best;
}

/* Curves in the order of their labels (dry before immersed, then by group values). */
static int by_label(const void *x, const void *y)
{
    return strcmp(((const gf_fig_series *)x)->label, ((const gf_fig_series *)y)->label);
}

/* Q^(2/5) against D over the campaign's silo runs, with its Beverloo line (figures/gf_fig_beverloo.c). */
static gf_status silo_figure(gf_ctx *ctx, const char *fig, const gf_post_row *rows, int n)
{
    double *D = calloc(2 * (size_t)n + 1, sizeof *D), k = NAN, C = NAN;
    if (!D)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "post: out of memory");
    double *Q = D + n;
    int m = 0;
    for (int i = 0; i < n; ++i)
        if (isfinite(gf_post_row_get(&rows[i], "silo_Q_nd"))) {
            D[m] = gf_post_row_get(&rows[i], "silo_D_over_d");
            Q[m++] = gf_post_row_get(&rows[i], "silo_Q_nd");
            k = gf_post_row_get(&rows[i], "beverloo_k"), C = gf_post_row_get(&rows[i], "beverloo_C");
        }
    gf_status st = GF_OK;
    if (m > 0) {
        char p[1200];
        snprintf(p, sizeof p, "%s/beverloo.svg", fig);
        st = gf_fig_beverloo(ctx, p, NULL, m, D, Q, k, C);
    }
    free(D);
    return st;
}

static gf_status write_figures(gf_ctx *ctx, const char *dir, const gf_post_row *rows, int n)
{
    char fig[1100], p[1200];
    snprintf(fig, sizeof fig, "%s/figures", dir);
    if (mkdir(fig, 0777) != 0 && errno != EEXIST)
        return GF_FAIL(ctx, GF_ERR_IO, "post: cannot create %s (%s)", fig, strerror(errno));
    double *St = calloc((size_t)n + 1, sizeof *St), *r = calloc((size_t)n + 1, sizeof *r);
    double *a = calloc((size_t)n + 1, sizeof *a), *phi = calloc((size_t)n + 1, sizeof *phi);
    double *ro = calloc((size_t)n + 1, sizeof *ro);
    gf_fig_regime *reg = calloc((size_t)n + 1, sizeof *reg);
    gf_fig_shape *shp = calloc((size_t)n + 1, sizeof *shp);
    gf_fig_series *front = calloc((size_t)n + 1, sizeof *front), *pb = calloc((size_t)n + 1, sizeof *pb);
    double **bufs = calloc(4 * (size_t)n + 1, sizeof *bufs);
    /* legends name runs by variant and groups (gf_post_label.h), not by hash */
    char(*label)[GF_POST_LABEL_LEN] = calloc((size_t)n + 1, sizeof *label);
    int *variant = calloc((size_t)n + 1, sizeof *variant);
    gf_post_variants variants;
    const char *variant_names[GF_POST_MAX_VARIANTS];
    gf_status st = GF_OK;
    if (!St || !r || !a || !phi || !ro || !reg || !shp || !front || !pb || !bufs || !label || !variant) {
        st = GF_FAIL(ctx, GF_ERR_NOMEM, "post: out of memory");
        goto done;
    }
    gf_post_run_labels(rows, n, label);
    gf_post_run_variants(rows, n, variant, &variants);
    for (int v = 0; v < variants.n; ++v)
        variant_names[v] = variants.names[v];
    gf_fig_opts by_variant = {.n_variants = variants.n, .variant = variant, .variant_names = variant_names};
    int n_regime = 0, n_coll = 0, n_front = 0, n_pb = 0; /* rows that hold a regime, a run-out */
    for (int i = 0; i < n; ++i) {
        const gf_post_row *w = &rows[i];
        St[i] = row_or(w, "St", "St_groups");
        r[i] = row_or(w, "r", "r_groups");
        a[i] = gf_post_row_get(w, "a");
        phi[i] = row_or(w, "Phi_i", "phi_initial_measured");
        ro[i] = gf_post_row_get(w, "runout_norm");
        reg[i] = gf_fig_regime_from_name(gf_post_row_get_text(w, "regime"));
        shp[i] = gf_fig_shape_from_name(gf_post_row_get_text(w, "deposit_shape"));
        n_regime += reg[i] != GF_FIG_REGIME_UNDETERMINED || isfinite(gf_post_row_get(w, "T_s"));
        n_coll += isfinite(ro[i]);
        size_t m;
        if (read_series(w->run_dir, "post_deposit.nc", "front_position_norm", 0, &bufs[4 * i], &bufs[4 * i + 1], &m))
            front[n_front++] = (gf_fig_series){label[i], (int)m, bufs[4 * i], bufs[4 * i + 1]};
        if (read_series(w->run_dir, "probes.nc", "excess_pore_pressure", gauge_index(w), &bufs[4 * i + 2],
                        &bufs[4 * i + 3], &m))
            pb[n_pb++] = (gf_fig_series){label[i], (int)m, bufs[4 * i + 2], bufs[4 * i + 3]};
    }
    qsort(front, (size_t)n_front, sizeof *front, by_label);
    qsort(pb, (size_t)n_pb, sizeof *pb, by_label);
    if (n_regime > 0) {
        snprintf(p, sizeof p, "%s/regime_diagram.svg", fig);
        st = gf_fig_regime_diagram(ctx, p, NULL, n, St, r, reg);
    }
    if (st == GF_OK && n_coll > 0) {
        snprintf(p, sizeof p, "%s/deposit_shape.svg", fig);
        st = gf_fig_deposit_shape(ctx, p, &by_variant, n, a, phi, shp);
        if (st == GF_OK) {
            snprintf(p, sizeof p, "%s/runout.svg", fig);
            st = gf_fig_runout(ctx, p, &by_variant, n, a, ro, reg);
        }
    }
    if (st == GF_OK)
        st = silo_figure(ctx, fig, rows, n);
    if (st == GF_OK && n_front > 0) {
        snprintf(p, sizeof p, "%s/front_position.svg", fig);
        gf_fig_opts o = {.title = "Front position (x_front - R0)/R0 against time"};
        st = gf_fig_timeseries(ctx, p, &o, "t (s)", "(x_front - R0)/R0 (1)", n_front, front);
    }
    if (st == GF_OK && n_pb > 0) {
        snprintf(p, sizeof p, "%s/pore_pressure.svg", fig);
        gf_fig_opts o = {.title = "Basal excess pore pressure at the summary gauge (Pb_x_m)"};
        st = gf_fig_timeseries(ctx, p, &o, "t (s)", "excess pore pressure (Pa)", n_pb, pb);
    }
done:
    for (int i = 0; bufs && i < 4 * n; ++i)
        free(bufs[i]);
    free(bufs), free(St), free(r), free(a), free(phi), free(ro), free(reg), free(shp), free(front), free(pb);
    free(label), free(variant);
    return st;
}

/* Counts the rows of a summary by status into *rep. */
static void count_rows(const gf_post_row *rows, int n, gf_post_report *rep)
{
    rep->n_runs += n;
    for (int i = 0; i < n; ++i) {
        const char *st = rows[i].status;
        if (!strcmp(st, "ok"))
            ++rep->n_ok;
        else if (!strcmp(st, "failed"))
            ++rep->n_failed;
        else if (!strcmp(st, "corrupt"))
            ++rep->n_corrupt;
        else if (!strcmp(st, "incomplete"))
            ++rep->n_incomplete;
        else
            ++rep->n_error;
    }
}

/* Takes the lock of the campaign's summary and figures, waiting for another
 * post to finish with them. */
static gf_status lock_summary(gf_ctx *ctx, const char *dir, int quiet, gf_lock **lock)
{
    char path[1100], who[300];
    gf_lock_holder holder;
    snprintf(path, sizeof path, "%s/.summary.lock", dir);
    GF_TRY(gf_lock_take(ctx, path, "post", 0.0, lock, &holder, NULL));
    if (*lock)
        return GF_OK;
    gf_lock_describe(&holder, who, sizeof who);
    if (!quiet)
        fprintf(stderr, "grainflow post: %s: summary being written by %s; waiting\n", dir, who);
    const double wait_s = 600.0;
    GF_TRY(gf_lock_take(ctx, path, "post", wait_s, lock, &holder, NULL));
    if (!*lock) {
        gf_lock_describe(&holder, who, sizeof who);
        return GF_FAIL(ctx, GF_ERR_IO, "post: %s: summary still held by %s after %.0f s; not written", dir, who,
                       wait_s);
    }
    return GF_OK;
}

gf_status gf_post_campaign_report(gf_ctx *ctx, const char *campaign_dir, const gf_post_options *opt,
                                  gf_post_report *rep)
{
    gf_post_options defaults = {NULL, 1, 1, 0};
    gf_post_report scratch;
    if (!opt)
        opt = &defaults;
    if (!rep)
        rep = &scratch;
    memset(rep, 0, sizeof *rep);
    if (!campaign_dir)
        return GF_FAIL(ctx, GF_ERR_ARG, "post: no campaign directory");
    const gf_stage_info *only = NULL;
    if (opt->stage && opt->stage[0]) {
        only = gf_stage_find(opt->stage);
        if (!only) {
            char names[256] = "";
            for (int s = 0; s < gf_stage_count; ++s) {
                size_t len = strlen(names);
                snprintf(names + len, sizeof names - len, "%s%s", s ? ", " : "", gf_stage_table[s].name);
            }
            return GF_FAIL(ctx, GF_ERR_CONFIG, "post: unknown stage '%s' (stages: %s)", opt->stage, names);
        }
    }
    char **runs = NULL;
    int n = 0;
    GF_TRY(find_runs(ctx, campaign_dir, &runs, &n));
    gf_lock *lock = NULL;
    gf_status st = lock_summary(ctx, campaign_dir, opt->quiet, &lock);
    /* a single run directory writes its summary next to its files */
    gf_post_row *rows = st == GF_OK ? calloc((size_t)n + 1, sizeof *rows) : NULL;
    if (st == GF_OK && !rows)
        st = GF_FAIL(ctx, GF_ERR_NOMEM, "post: out of memory");
    if (st != GF_OK) {
        for (int i = 0; i < n; ++i)
            free(runs[i]);
        free(runs);
        gf_lock_release(&lock);
        return st;
    }
    int jobs = opt->n_jobs > 1 ? opt->n_jobs : 1;
    if (jobs > 64)
        jobs = 64;
    if (jobs > 1 && n > 1)
        post_parallel(runs, n, only, jobs, rows);
    else
        for (int i = 0; i < n; ++i)
            post_run(runs[i], only, &rows[i]);
    int n_bad = 0;
    for (int i = 0; i < n; ++i) {
        if (strcmp(rows[i].status, "ok") != 0)
            ++n_bad;
        if (!opt->quiet && rows[i].error[0])
            fprintf(stderr, "grainflow post: run %s (%s): %s: %s\n", rows[i].run_id, rows[i].run_dir, rows[i].status,
                    rows[i].error);
    }
    count_rows(rows, n, rep);
    gf_silo_campaign_fits(rows, n); /* the laws over the campaign's silo runs, in their rows */
    st = gf_summary_write(ctx, campaign_dir, rows, n);
    if (st == GF_OK && opt->figures) {
        char p[1100];
        snprintf(p, sizeof p, "%s/summary.nc", campaign_dir);
        gf_post_row *back = NULL;
        int nb = 0;
        st = gf_summary_read(ctx, p, &back, &nb);
        if (st == GF_OK)
            st = write_figures(ctx, campaign_dir, back, nb);
        free(back);
    }
    gf_lock_release(&lock);
    if (!opt->quiet)
        fprintf(stderr, "grainflow post: %d run(s) summarised in %s/summary.{nc,csv}, %d marked\n", n, campaign_dir,
                n_bad);
    for (int i = 0; i < n; ++i)
        free(runs[i]);
    free(runs);
    free(rows);
    return st;
}

gf_status gf_post_campaign(gf_ctx *ctx, const char *campaign_dir, const gf_post_options *opt)
{
    return gf_post_campaign_report(ctx, campaign_dir, opt, NULL);
}

/* Campaign directories (holding run directories) below dir, depth first, in
 * name order, at most max_depth levels down; appended to *list. */
static void find_campaigns(const char *dir, int max_depth, char ***list, int *n, int *cap)
{
    if (max_depth < 0)
        return;
    DIR *d = opendir(dir);
    if (!d)
        return;
    char **names = NULL;
    int nn = 0, nc = 0, has_run = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        char p[1200];
        struct stat sb;
        if (e->d_name[0] == '.' || !strcmp(e->d_name, "figures") || !strcmp(e->d_name, "preparations"))
            continue;
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        if (stat(p, &sb) != 0 || !S_ISDIR(sb.st_mode))
            continue;
        if (is_run_dir(p)) {
            has_run = 1;
            continue;
        }
        if (!append_copy(&names, &nn, &nc, p))
            break;
    }
    closedir(d);
    if (has_run) {
        (void)append_copy(list, n, cap, dir); /* out of memory: this campaign is left out */
    } else {
        if (nn)
            qsort(names, (size_t)nn, sizeof *names, cmp_str);
        for (int i = 0; i < nn; ++i)
            if (names[i])
                find_campaigns(names[i], max_depth - 1, list, n, cap);
    }
    for (int i = 0; i < nn; ++i)
        free(names[i]);
    free(names);
}

gf_status gf_post_tree(gf_ctx *ctx, const char *dir, const gf_post_options *opt, gf_post_report *rep)
{
    gf_post_report one;
    memset(rep, 0, sizeof *rep);
    char **list = NULL;
    int n = 0, cap = 0;
    if (is_run_dir(dir)) {
        rep->n_campaigns = 1;
        return gf_post_campaign_report(ctx, dir, opt, rep);
    }
    find_campaigns(dir, 4, &list, &n, &cap);
    if (n == 0) {
        free(list);
        return GF_FAIL(ctx, GF_ERR_IO, "post: no run directory in or below %s (a run directory holds status, "
                       "run.yaml or the run's .nc files)", dir);
    }
    if (!(n == 1 && strcmp(list[0], dir) == 0) && !(opt && opt->quiet))
        fprintf(stderr, "grainflow post: %s holds %d campaign(s) below it%s\n", dir, n, n ? ":" : "");
    gf_status st = GF_OK;
    for (int i = 0; i < n; ++i) {
        if (!(n == 1 && strcmp(list[i], dir) == 0) && !(opt && opt->quiet))
            fprintf(stderr, "  %s\n", list[i]);
        gf_status s1 = gf_post_campaign_report(ctx, list[i], opt, &one);
        if (s1 != GF_OK && st == GF_OK)
            st = s1;
        rep->n_campaigns += 1;
        rep->n_runs += one.n_runs;
        rep->n_ok += one.n_ok;
        rep->n_failed += one.n_failed;
        rep->n_corrupt += one.n_corrupt;
        rep->n_incomplete += one.n_incomplete;
        rep->n_error += one.n_error;
        free(list[i]);
    }
    free(list);
    return st;
}
