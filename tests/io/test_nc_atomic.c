/*
 * A killed run leaves no file that looks complete. A child process opens
 * all four writers, appends records and dies by SIGKILL before closing (as
 * a run killed by the scheduler or the OOM killer would): the final names
 * must not exist, only the "*.tmp" files. The same sequence closed normally
 * must produce the four final files and no "*.tmp" left behind.
 */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "gf_test.h"
#include "nc_check.h"

static const char *const files[4] = {"diagnostics.nc", "particles.nc", "probes.nc", "fields.nc"};

static int exists(const char *dir, const char *name, const char *suffix)
{
    char p[1200];
    snprintf(p, sizeof p, "%s/%s%s", dir, name, suffix);
    struct stat sb;
    return stat(p, &sb) == 0;
}

/* Opens the four writers, appends two records; closes them if finish. Returns 0 on success. */
static int write_run(const char *dir, int finish)
{
    nc_test_run run;
    nc_test_run_init(&run);
    gf_ctx ctx = {0};
    gf_particles *p = NULL;
    if (gf_particles_create(&ctx, 8, &p) != GF_OK)
        return 1;
    for (int k = 0; k < 8; ++k)
        gf_particles_add(&ctx, p, 0.01 * k, 0.005, 0.0, 1e-3, 2500.0, 0, NULL);
    gf_var_info diag[1] = {{"kinetic_energy", "J", "kinetic energy", NULL}};
    gf_var_info pv[1] = {{"excess_pore_pressure", "Pa", "excess pore pressure", NULL}};
    gf_var_info fv[1] = {{"fluid_fraction", "1", "fluid fraction", NULL}};
    const char *names[1] = {"g0"};
    double xyz[3] = {0, 0, 0}, lo[3] = {0, 0, 0}, h[3] = {1e-3, 1e-3, 1e-3};
    int nc[3] = {4, 4, 2};
    gf_nc_writer *w[4] = {0};
    char path[4][1200];
    for (int i = 0; i < 4; ++i)
        snprintf(path[i], sizeof path[i], "%s/%s", dir, files[i]);
    if (gf_nc_diagnostics_open(&ctx, path[0], &run.meta, diag, 1, &w[0]) != GF_OK ||
        gf_nc_particles_open(&ctx, path[1], &run.meta, p, &w[1]) != GF_OK ||
        gf_nc_probes_open(&ctx, path[2], &run.meta, 1, names, xyz, pv, 1, &w[2]) != GF_OK ||
        gf_nc_fields_open(&ctx, path[3], &run.meta, nc, lo, h, fv, 1, &w[3]) != GF_OK) {
        fprintf(stderr, "open failed: %s\n", ctx.last_msg);
        return 1;
    }
    static double field[32];
    const double *fp[1] = {field};
    for (int it = 0; it < 2; ++it) {
        double t = 0.1 * it, e = 1.0 * it, pe = -3.0 * it;
        if (gf_nc_diagnostics_append(w[0], t, &e) || gf_nc_particles_append(w[1], t, p) ||
            gf_nc_probes_append(w[2], t, &pe) || gf_nc_fields_append(w[3], t, fp)) {
            fprintf(stderr, "append failed: %s\n", ctx.last_msg);
            return 1;
        }
    }
    if (!finish) {
        fflush(NULL);
        raise(SIGKILL);   /* no close, no atexit, no flush of HDF5 metadata */
    }
    for (int i = 0; i < 4; ++i)
        if (gf_nc_writer_close(&w[i]) != GF_OK)
            return 1;
    gf_particles_destroy(&p);
    return 0;
}

static void test_killed_run_leaves_only_tmp_files(void)
{
    const char *dir = nc_test_dir("atomic-killed");
    pid_t pid = fork();
    if (pid == 0)
        _exit(write_run(dir, 0));
    int status = 0;
    waitpid(pid, &status, 0);
    GF_CHECK(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    for (int i = 0; i < 4; ++i) {
        gf_test_check(!exists(dir, files[i], ""), __FILE__, __LINE__, "killed run: no %s at the final name",
                      files[i]);
        gf_test_check(exists(dir, files[i], ".tmp"), __FILE__, __LINE__, "killed run: %s.tmp left for inspection",
                      files[i]);
    }
}

static void test_closed_run_leaves_final_files(void)
{
    char dir[1100];
    snprintf(dir, sizeof dir, "%s", nc_test_dir("atomic-closed"));
    pid_t pid = fork();
    if (pid == 0)
        _exit(write_run(dir, 1));
    int status = 0;
    waitpid(pid, &status, 0);
    GF_CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    for (int i = 0; i < 4; ++i) {
        gf_test_check(exists(dir, files[i], ""), __FILE__, __LINE__, "closed run: %s present", files[i]);
        gf_test_check(!exists(dir, files[i], ".tmp"), __FILE__, __LINE__, "closed run: no %s.tmp", files[i]);
    }
    /* and the closed files are complete: two records each */
    char p[1200];
    snprintf(p, sizeof p, "%s/particles.nc", dir);
    size_t n;
    double *t = nc_read_doubles(p, "time", &n);
    GF_CHECK(t && n == 2 && t[1] == 0.1);
    free(t);
}

int main(void)
{
    test_killed_run_leaves_only_tmp_files();
    test_closed_run_leaves_final_files();
    return gf_test_finish();
}
