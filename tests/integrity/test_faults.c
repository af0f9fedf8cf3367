/*
 * Fault injection on a real campaign: the `grainflow` command on four small
 * dry column collapses (R0 = 8 D, a in {1, 2}, Phi_i in {0.58, 0.60},
 * end_time 8 sqrt(D/g): about 1 s of CPU each), with one fault per scenario
 * (argv[1]):
 *
 *   kill9_parent    kill -9 of the campaign process while its runs write
 *   kill9_worker    kill -9 of one worker
 *   sigint          SIGINT to the whole process group (a terminal's Ctrl-C)
 *   sigterm         SIGTERM to the campaign process alone (kill PID, a batch system)
 *   concurrent      two campaigns on one output directory at once
 *   resume_orphans  --resume while the killed campaign's workers still hold their runs
 *   truncated       a done run's particles.nc cut to half its size
 *   full_disk       the output on a 400 KiB tmpfs (or, where mount is refused,
 *                   a 100 KiB file size limit, RLIMIT_FSIZE): writes fail mid-run
 *   no_particles    output.particles: false, then post
 *   post_exit       post on an empty directory and on the parent of a campaign
 *
 * After each fault the same invariants are checked: every run whose status
 * says done passes its manifest, and every netCDF file in it opens and every
 * variable reads back in full (netCDF-C, independently of the manifest
 * code); no process of the campaign outlives it (this test is a child
 * subreaper, so an orphaned worker would be reparented here, and must end
 * within 20 s); then `campaign --resume` exits 0 with every run done, and
 * leaves the runs that were done before it untouched (same status file: inode
 * and modification time), unless they failed their check.
 */
#define _GNU_SOURCE
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <netcdf.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "core/gf_timer.h"
#include "gf_test.h"
#include "rundir/gf_manifest.h"

#define N_RUNS 4
#define MAX_DIRS 16

static char grainflow[1024], work[256], config[400], out_dir[400], camp_dir[500];

static const char campaign_text[] = "name: faults\n"
                                    "seed: 1\n"
                                    "end_time: 8\n"
                                    "scene: {name: column_collapse, column_length_over_D: 8, width_over_D: 3}\n"
                                    "grains: {diameter_m: 7.6e-3, polydispersity: 0.05, density_kg_m3: 2500}\n"
                                    "output: {interval_nd: 1.0%s}\n"
                                    "grid: {a: [1.0, 2.0], Phi_i: [0.58, 0.60], combine: product}\n";

/* ---- processes ---- */

typedef struct limits {
    long fsize_bytes;   /* > 0: RLIMIT_FSIZE of the child */
    int own_group;      /* the child leads its own process group */
} limits;

/* Starts `grainflow args...` with stdout and stderr into log. */
static pid_t spawn(const char *log, const limits *lim, const char *const *args)
{
    pid_t pid = fork();
    if (pid != 0)
        return pid;
    if (lim && lim->own_group)
        setpgid(0, 0);
    if (lim && lim->fsize_bytes > 0) {
        struct rlimit rl = {(rlim_t)lim->fsize_bytes, (rlim_t)lim->fsize_bytes};
        signal(SIGXFSZ, SIG_IGN); /* a write past the limit fails with EFBIG, as on a full disk */
        setrlimit(RLIMIT_FSIZE, &rl);
    }
    int fd = open(log, O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) {
        dup2(fd, 1);
        dup2(fd, 2);
        close(fd);
    }
    char *argv[32];
    int n = 0;
    argv[n++] = grainflow;
    for (int i = 0; args[i] && n < 31; ++i)
        argv[n++] = (char *)args[i];
    argv[n] = NULL;
    execv(grainflow, argv);
    _exit(127);
}

static int wait_code(pid_t pid)
{
    int ws;
    while (waitpid(pid, &ws, 0) < 0 && errno == EINTR)
        ;
    return WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + WTERMSIG(ws);
}

static int run_cmd(const char *log, const limits *lim, const char *const *args)
{
    return wait_code(spawn(log, lim, args));
}

/* Child processes of pid (from /proc/<k>/stat), into kids; their count. */
static int children_of(pid_t pid, pid_t *kids, int max)
{
    DIR *d = opendir("/proc");
    int n = 0;
    struct dirent *e;
    while (d && (e = readdir(d)) && n < max) {
        char p[300], buf[512];
        if (e->d_name[0] < '0' || e->d_name[0] > '9')
            continue;
        snprintf(p, sizeof p, "/proc/%s/stat", e->d_name);
        FILE *f = fopen(p, "r");
        if (!f)
            continue;
        size_t got = fread(buf, 1, sizeof buf - 1, f);
        fclose(f);
        buf[got] = '\0';
        const char *rp = strrchr(buf, ')');
        int ppid = 0;
        char state;
        if (rp && sscanf(rp + 1, " %c %d", &state, &ppid) == 2 && ppid == pid && state != 'Z')
            kids[n++] = (pid_t)atoi(e->d_name);
    }
    if (d)
        closedir(d);
    return n;
}

/* Reaps every remaining child (orphans reparented here included); 1 when all
 * ended within timeout_s. */
static int reap_all(double timeout_s, double *took_s)
{
    const double t0 = gf_wtime();
    for (;;) {
        int ws;
        pid_t p = waitpid(-1, &ws, WNOHANG);
        if (p < 0 && errno == ECHILD) {
            *took_s = gf_wtime() - t0;
            return 1;
        }
        if (p > 0)
            continue;
        if (gf_wtime() - t0 > timeout_s) {
            *took_s = gf_wtime() - t0;
            return 0;
        }
        usleep(20000);
    }
}

/* ---- the run directories ---- */

static int run_dirs(char names[MAX_DIRS][64])
{
    DIR *d = opendir(camp_dir);
    int n = 0;
    struct dirent *e;
    while (d && (e = readdir(d)) && n < MAX_DIRS) {
        if (strlen(e->d_name) != 12 || strspn(e->d_name, "0123456789abcdef") != 12)
            continue; /* run ids are 12 hex digits */
        snprintf(names[n++], 64, "%s", e->d_name);
    }
    if (d)
        closedir(d);
    return n;
}

static int status_is(const char *run, const char *prefix)
{
    char p[1000], line[700] = "";
    snprintf(p, sizeof p, "%s/%.63s/status", camp_dir, run);
    FILE *f = fopen(p, "r");
    if (!f)
        return 0;
    if (!fgets(line, sizeof line, f))
        line[0] = '\0';
    fclose(f);
    return strncmp(line, prefix, strlen(prefix)) == 0;
}

/* Every variable of a netCDF file reads back in full. */
static int nc_reads_fully(const char *path, char *why, size_t n)
{
    int id, nvars, rc = nc_open(path, NC_NOWRITE, &id);
    if (rc != NC_NOERR) {
        snprintf(why, n, "%.500s: %s", path, nc_strerror(rc));
        return 0;
    }
    nc_inq_nvars(id, &nvars);
    int ok = 1;
    for (int v = 0; ok && v < nvars; ++v) {
        int ndims, dims[NC_MAX_VAR_DIMS];
        nc_type type;
        size_t count = 1, len, size;
        nc_inq_var(id, v, NULL, &type, &ndims, dims, NULL);
        for (int k = 0; k < ndims; ++k) {
            nc_inq_dimlen(id, dims[k], &len);
            count *= len;
        }
        if (type == NC_STRING || count == 0)
            continue;
        nc_inq_type(id, type, NULL, &size);
        void *buf = malloc(count * size + 1);
        rc = buf ? nc_get_var(id, v, buf) : NC_ENOMEM;
        free(buf);
        if (rc != NC_NOERR) {
            snprintf(why, n, "%.500s: variable %d: %s", path, v, nc_strerror(rc));
            ok = 0;
        }
    }
    nc_close(id);
    return ok;
}

/* Invariant: nothing marked done is corrupt. Returns the number of done runs. */
static int check_done_runs_sound(const char *when)
{
    char names[MAX_DIRS][64];
    int n = run_dirs(names), n_done = 0;
    for (int i = 0; i < n; ++i) {
        if (!status_is(names[i], "done"))
            continue;
        ++n_done;
        char dir[900], why[800] = "";
        snprintf(dir, sizeof dir, "%s/%.63s", camp_dir, names[i]);
        gf_test_check(gf_manifest_verify(dir, why, sizeof why), __FILE__, __LINE__,
                      "%s: run %s is done but fails its manifest: %s", when, names[i], why);
        static const char *const files[] = {"diagnostics.nc", "particles.nc"};
        for (int k = 0; k < 2; ++k) {
            char p[1000];
            snprintf(p, sizeof p, "%s/%s", dir, files[k]);
            gf_test_check(nc_reads_fully(p, why, sizeof why), __FILE__, __LINE__,
                          "%s: run %s is done but %s does not read back: %s", when, names[i], files[k], why);
        }
    }
    return n_done;
}

/* Status files of the done runs (to show they are not rewritten). */
typedef struct snapshot {
    int n;
    char run[MAX_DIRS][64];
    ino_t ino[MAX_DIRS];
    struct timespec mtime[MAX_DIRS];
} snapshot;

static void take_snapshot(snapshot *s)
{
    char names[MAX_DIRS][64];
    int n = run_dirs(names);
    s->n = 0;
    for (int i = 0; i < n; ++i) {
        char p[1000];
        struct stat sb;
        snprintf(p, sizeof p, "%s/%.63s/status", camp_dir, names[i]);
        if (!status_is(names[i], "done") || stat(p, &sb) != 0)
            continue;
        snprintf(s->run[s->n], 64, "%.63s", names[i]);
        s->ino[s->n] = sb.st_ino;
        s->mtime[s->n++] = sb.st_mtim;
    }
}

/* Invariant: nothing finished is redone (except the run named by except). */
static void check_untouched(const snapshot *s, const char *except, const char *when)
{
    for (int i = 0; i < s->n; ++i) {
        if (except && strcmp(s->run[i], except) == 0)
            continue;
        char p[1000];
        struct stat sb;
        snprintf(p, sizeof p, "%s/%.63s/status", camp_dir, s->run[i]);
        int same = stat(p, &sb) == 0 && sb.st_ino == s->ino[i] && sb.st_mtim.tv_sec == s->mtime[i].tv_sec &&
                   sb.st_mtim.tv_nsec == s->mtime[i].tv_nsec;
        gf_test_check(same, __FILE__, __LINE__, "%s: run %s was done before and has been written again", when,
                      s->run[i]);
    }
}

/* Waits until a run writes its netCDF files (a *.nc.tmp in a run directory). */
static int wait_writing(double timeout_s)
{
    const double t0 = gf_wtime();
    while (gf_wtime() - t0 < timeout_s) {
        char names[MAX_DIRS][64];
        int n = run_dirs(names);
        for (int i = 0; i < n; ++i) {
            char p[1000];
            snprintf(p, sizeof p, "%s/%.63s/particles.nc.tmp", camp_dir, names[i]);
            if (access(p, F_OK) == 0)
                return 1;
        }
        usleep(20000);
    }
    return 0;
}

/* Lines of the file at path holding text (0 when it cannot be read). */
static int count_lines_with(const char *path, const char *text)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    char line[2048];
    int n = 0;
    while (fgets(line, sizeof line, f))
        n += strstr(line, text) != NULL;
    fclose(f);
    return n;
}

static int file_contains(const char *path, const char *text) { return count_lines_with(path, text) > 0; }

static void log_path(const char *name, char *buf, size_t n)
{
    snprintf(buf, n, "%s/%s.log", work, name);
}

/* The campaign with --resume (and post) until every run is done: exit 0. */
static void resume_to_completion(const snapshot *before, const char *except, const char *when)
{
    char log[700];
    log_path("resume_final", log, sizeof log);
    const char *args[] = {"campaign", config, "-o", out_dir, "-j", "2", "--resume", "-q", NULL};
    int code = run_cmd(log, NULL, args);
    gf_test_check(code == 0, __FILE__, __LINE__, "%s: campaign --resume exits %d (see %s)", when, code, log);
    char names[MAX_DIRS][64];
    int n = run_dirs(names), n_done = 0;
    for (int i = 0; i < n; ++i)
        n_done += status_is(names[i], "done");
    gf_test_check(n == N_RUNS && n_done == N_RUNS, __FILE__, __LINE__, "%s: %d of %d runs done after --resume", when,
                  n_done, n);
    check_done_runs_sound(when);
    check_untouched(before, except, when);
}

static int start_campaign(const char *name, const limits *lim, const char *extra)
{
    char log[700];
    log_path(name, log, sizeof log);
    const char *args[] = {"campaign", config, "-o", out_dir, "-j", "2", extra ? extra : "-q", NULL};
    return spawn(log, lim, args);
}

/* ---- scenarios ---- */

static void kill_parent(void)
{
    pid_t pid = start_campaign("kill9_parent", NULL, NULL);
    GF_CHECK(wait_writing(120));
    kill(pid, SIGKILL);
    wait_code(pid);
    double took;
    int ended = reap_all(20, &took);
    gf_test_check(ended, __FILE__, __LINE__, "workers still alive %.1f s after kill -9 of the campaign", took);
    /* they stopped because their parent died (SIGTERM: checkpoint), not at the end of their run */
    char names[MAX_DIRS][64];
    int nd = run_dirs(names), n_cut = 0;
    for (int i = 0; i < nd; ++i)
        n_cut += status_is(names[i], "failed: interrupted");
    printf("kill9_parent: every worker ended %.2f s after the campaign was killed, %d interrupted with a "
           "checkpoint\n", took, n_cut);
    gf_test_check(n_cut >= 1, __FILE__, __LINE__, "no run was interrupted by its parent's death (orphans ran on)");
    check_done_runs_sound("after kill -9 of the campaign");
    snapshot s;
    take_snapshot(&s);
    resume_to_completion(&s, NULL, "kill9_parent");
}

static void kill_worker(void)
{
    pid_t pid = start_campaign("kill9_worker", NULL, NULL);
    GF_CHECK(wait_writing(120));
    pid_t kids[8];
    int n = children_of(pid, kids, 8);
    GF_CHECK(n >= 1);
    if (n >= 1)
        kill(kids[0], SIGKILL);
    int code = wait_code(pid);
    gf_test_check(code == 1, __FILE__, __LINE__, "campaign with a killed worker exits %d", code);
    char names[MAX_DIRS][64];
    int nd = run_dirs(names), n_killed = 0;
    for (int i = 0; i < nd; ++i)
        n_killed += status_is(names[i], "failed: worker killed by signal 9");
    gf_test_check(n_killed == 1, __FILE__, __LINE__, "%d runs record the killed worker", n_killed);
    check_done_runs_sound("after kill -9 of a worker");
    snapshot s;
    take_snapshot(&s);
    printf("kill9_worker: campaign exit %d, %d runs done, 1 recorded 'worker killed by signal 9'\n", code, s.n);
    resume_to_completion(&s, NULL, "kill9_worker");
}

static void signal_campaign(int sig, int whole_group)
{
    limits lim = {.own_group = 1};
    const char *name = sig == SIGINT ? "sigint" : "sigterm";
    pid_t pid = start_campaign(name, &lim, NULL);
    GF_CHECK(wait_writing(120));
    kill(whole_group ? -pid : pid, sig);
    int code = wait_code(pid);
    double took;
    gf_test_check(reap_all(20, &took), __FILE__, __LINE__, "a process of the campaign outlived it");
    gf_test_check(code == 1, __FILE__, __LINE__, "interrupted campaign exits %d", code);
    check_done_runs_sound(name);
    char names[MAX_DIRS][64];
    int nd = run_dirs(names), n_cut = 0;
    for (int i = 0; i < nd; ++i)
        n_cut += status_is(names[i], "failed: interrupted");
    snapshot s;
    take_snapshot(&s);
    printf("%s: campaign exit %d, %d runs done, %d interrupted with a checkpoint\n", name, code, s.n, n_cut);
    GF_CHECK(n_cut >= 1);
    resume_to_completion(&s, NULL, name);
}

/* Ctrl-C at the terminal (SIGINT to the whole process group); SIGTERM to the parent alone. */
static void interrupt_group(void) { signal_campaign(SIGINT, 1); }
static void terminate_parent(void) { signal_campaign(SIGTERM, 0); }

static void concurrent(void)
{
    pid_t a = start_campaign("concurrent_a", NULL, "--no-post");
    pid_t b = start_campaign("concurrent_b", NULL, "--no-post");
    int ca = wait_code(a), cb = wait_code(b);
    char la[700], lb[700];
    log_path("concurrent_a", la, sizeof la);
    log_path("concurrent_b", lb, sizeof lb);
    check_done_runs_sound("two campaigns at once");
    char names[MAX_DIRS][64];
    int n = run_dirs(names), n_done = 0;
    for (int i = 0; i < n; ++i)
        n_done += status_is(names[i], "done");
    /* one writer per run: every run completed by exactly one of the two */
    const int ran_a = count_lines_with(la, " done    "), ran_b = count_lines_with(lb, " done    ");
    const int held_a = count_lines_with(la, "held by pid"), held_b = count_lines_with(lb, "held by pid");
    printf("concurrent: exits %d and %d; runs done by each %d and %d, left to the other %d and %d; %d of %d done\n",
           ca, cb, ran_a, ran_b, held_a, held_b, n_done, n);
    gf_test_check(ran_a + ran_b == N_RUNS, __FILE__, __LINE__, "%d + %d runs completed for %d runs", ran_a, ran_b,
                  N_RUNS);
    gf_test_check(ca == 0 || cb == 0, __FILE__, __LINE__, "neither campaign ended with every run done (%d, %d)", ca,
                  cb);
    GF_CHECK(n_done == N_RUNS);
    snapshot s;
    take_snapshot(&s);
    resume_to_completion(&s, NULL, "concurrent");
}

static void resume_orphans(void)
{
    pid_t pid = start_campaign("orphans", NULL, "--no-post");
    GF_CHECK(wait_writing(120));
    pid_t kids[8];
    int n = children_of(pid, kids, 8);
    for (int i = 0; i < n; ++i)
        kill(kids[i], SIGSTOP); /* workers still holding their runs, as if slow to stop */
    kill(pid, SIGKILL);
    wait_code(pid);
    char log[700];
    log_path("orphans_resume", log, sizeof log);
    const char *args[] = {"campaign", config, "-o", out_dir, "-j", "2", "--resume", "--no-post", NULL};
    int code = run_cmd(log, NULL, args);
    int held = count_lines_with(log, "held by pid");
    printf("resume_orphans: %d stopped workers; --resume during them exits %d, %d runs left to them\n", n, code, held);
    gf_test_check(held == n, __FILE__, __LINE__, "--resume reports %d held runs, %d workers hold one", held, n);
    gf_test_check(code == 1, __FILE__, __LINE__, "--resume with held runs exits %d", code);
    check_done_runs_sound("--resume during orphans");
    for (int i = 0; i < n; ++i)
        kill(kids[i], SIGCONT); /* their parent-death SIGTERM is pending: they checkpoint and stop */
    double took;
    gf_test_check(reap_all(20, &took), __FILE__, __LINE__, "orphaned workers still alive");
    check_done_runs_sound("after the orphans ended");
    snapshot s;
    take_snapshot(&s);
    resume_to_completion(&s, NULL, "resume_orphans");
}

static void truncated(void)
{
    char log[700];
    log_path("truncated_first", log, sizeof log);
    const char *args[] = {"campaign", config, "-o", out_dir, "-j", "2", "-q", NULL};
    GF_CHECK(run_cmd(log, NULL, args) == 0);
    char names[MAX_DIRS][64], p[1000];
    int n = run_dirs(names);
    GF_CHECK(n == N_RUNS);
    snapshot s;
    take_snapshot(&s);
    snprintf(p, sizeof p, "%s/%s/particles.nc", camp_dir, names[0]);
    struct stat sb;
    GF_CHECK(stat(p, &sb) == 0 && truncate(p, sb.st_size / 2) == 0);
    log_path("truncated_post", log, sizeof log);
    const char *post[] = {"post", camp_dir, "--no-figures", NULL};
    int code = run_cmd(log, NULL, post);
    gf_test_check(code == 1, __FILE__, __LINE__, "post with a truncated done run exits %d", code);
    snprintf(p, sizeof p, "%s/summary.csv", camp_dir);
    GF_CHECK(file_contains(p, ",corrupt,") && file_contains(p, "particles.nc"));
    log_path("truncated_dry", log, sizeof log);
    const char *dry[] = {"campaign", config, "-o", out_dir, "--dry-run", NULL};
    GF_CHECK(run_cmd(log, NULL, dry) == 0 && count_lines_with(log, "corrupt") == 1);
    log_path("truncated_resume", log, sizeof log);
    const char *res[] = {"campaign", config, "-o", out_dir, "-j", "2", "--resume", "-q", NULL};
    code = run_cmd(log, NULL, res);
    gf_test_check(code == 0 && file_contains(log, "running it again") && file_contains(log, names[0]), __FILE__,
                  __LINE__, "--resume over a truncated run: exit %d, log %s", code, log);
    printf("truncated: post exit 1 with the row corrupt, --dry-run lists it corrupt, --resume reruns it: exit %d\n",
           code);
    resume_to_completion(&s, names[0], "truncated");
}

static void full_disk(void)
{
    limits lim = {0};
    int mounted = mount("tmpfs", out_dir, "tmpfs", 0, "size=400k") == 0;
    if (!mounted)
        lim.fsize_bytes = 100 * 1024;
    char log[700];
    log_path("full_disk", log, sizeof log);
    const char *args[] = {"campaign", config, "-o", out_dir, "-j", "2", "-q", NULL};
    int code = run_cmd(log, &lim, args);
    gf_test_check(code == 1, __FILE__, __LINE__, "campaign on a full disk exits %d", code);
    int n_done = check_done_runs_sound("full disk");
    printf("full_disk (%s): campaign exit %d, %d runs done and sound, the others failed or unfinished\n",
           mounted ? "400 KiB tmpfs" : "RLIMIT_FSIZE 100 KiB", code, n_done);
    GF_CHECK(n_done < N_RUNS);
    snapshot s;
    take_snapshot(&s);
    if (mounted)
        GF_CHECK(mount("tmpfs", out_dir, "tmpfs", MS_REMOUNT, "size=16m") == 0);
    resume_to_completion(&s, NULL, "full_disk");
    if (mounted)
        umount2(out_dir, MNT_DETACH);
}

static void no_particles(void)
{
    char log[700], p[1000];
    log_path("no_particles", log, sizeof log);
    const char *args[] = {"campaign", config, "-o", out_dir, "--index", "0", NULL};
    int code = run_cmd(log, NULL, args);
    snprintf(p, sizeof p, "%s/summary.csv", camp_dir);
    gf_test_check(code == 0, __FILE__, __LINE__, "campaign with output.particles: false exits %d", code);
    char row[4096] = "";
    FILE *f = fopen(p, "r");
    if (f && fgets(row, sizeof row, f) && !fgets(row, sizeof row, f))
        row[0] = '\0';
    if (f)
        fclose(f);
    gf_test_check(strstr(row, ",ok,") != NULL, __FILE__, __LINE__, "summary row: %.300s", row);
    GF_CHECK(file_contains(p, "particles.nc was not written by this run"));
    printf("no_particles: exit %d, summary row ok with the note\n", code);
}

static void post_exit(void)
{
    char log[700], empty[700], p[1000];
    snprintf(empty, sizeof empty, "%s/empty", work);
    mkdir(empty, 0777);
    log_path("post_empty", log, sizeof log);
    const char *post_empty[] = {"post", empty, NULL};
    int code = run_cmd(log, NULL, post_empty);
    gf_test_check(code == 1 && file_contains(log, "no run directory"), __FILE__, __LINE__, "post on an empty "
                  "directory exits %d", code);
    snprintf(p, sizeof p, "%s/summary.csv", empty);
    GF_CHECK(access(p, F_OK) != 0);
    log_path("post_first", log, sizeof log);
    const char *args[] = {"campaign", config, "-o", out_dir, "--index", "0", "--no-post", NULL};
    GF_CHECK(run_cmd(log, NULL, args) == 0);
    log_path("post_parent", log, sizeof log);
    const char *post_parent[] = {"post", out_dir, "--no-figures", NULL};
    int code2 = run_cmd(log, NULL, post_parent);
    snprintf(p, sizeof p, "%s/summary.csv", camp_dir);
    gf_test_check(code2 == 0 && access(p, F_OK) == 0 && file_contains(log, camp_dir), __FILE__, __LINE__,
                  "post on the parent of a campaign exits %d", code2);
    snprintf(p, sizeof p, "%s/summary.csv", out_dir);
    GF_CHECK(access(p, F_OK) != 0);
    printf("post_exit: empty directory exit %d, parent of a campaign exit %d (summary in the campaign)\n", code,
           code2);
}

int main(int argc, char **argv)
{
    const char *scenario = argc > 1 ? argv[1] : "truncated";
    const char *bin = getenv("GF_BINARY_DIR");
    snprintf(grainflow, sizeof grainflow, "%s/grainflow", bin ? bin : ".");
    if (access(grainflow, X_OK) != 0) {
        printf("%s: no grainflow binary: skipped\n", grainflow);
        return 77;
    }
    prctl(PR_SET_CHILD_SUBREAPER, 1);
    snprintf(work, sizeof work, "/tmp/gf_faults_%s_XXXXXX", scenario);
    GF_CHECK(mkdtemp(work) != NULL);
    snprintf(config, sizeof config, "%s/faults.yaml", work);
    snprintf(out_dir, sizeof out_dir, "%s/runs", work);
    snprintf(camp_dir, sizeof camp_dir, "%s/faults", out_dir);
    mkdir(out_dir, 0777);
    FILE *f = fopen(config, "w");
    GF_CHECK(f != NULL);
    if (f) {
        fprintf(f, campaign_text, strcmp(scenario, "no_particles") == 0 ? ", particles: false" : "");
        fclose(f);
    }
    static const gf_test_mode scenarios[] = {
        {"kill9_parent", kill_parent}, {"kill9_worker", kill_worker}, {"sigint", interrupt_group},
        {"sigterm", terminate_parent}, {"concurrent", concurrent}, {"resume_orphans", resume_orphans},
        {"truncated", truncated}, {"full_disk", full_disk}, {"no_particles", no_particles}, {"post_exit", post_exit}};
    const double t0 = gf_wtime();
    if (!gf_test_run_mode(scenarios, (int)(sizeof scenarios / sizeof scenarios[0]), scenario))
        gf_test_check(0, __FILE__, __LINE__, "unknown scenario %s", scenario);
    printf("%s: %.1f s wall (logs in %s)\n", scenario, gf_wtime() - t0, work);
    return gf_test_finish_removing(work);
}
