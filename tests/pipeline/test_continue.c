/*
 * --resume continues an interrupted run from its checkpoint, and its files
 * are then those of an uninterrupted run.
 *
 * Scene: a dissipative, frictional granular gas (2200 grains, eps 0.8,
 * mu 0.5: tangential history in every collision; above the 2048 grains from
 * which the store is sorted in space at neighbour rebuilds, so the restored
 * store is not in the order particles.nc was opened with).
 *
 * - reference: one uninterrupted run (gf_run_execute, as every scheduler);
 * - the same run interrupted by a timer at ~40 % of the reference's wall
 *   time (as SIGTERM from a batch system would): status "failed:
 *   interrupted ... checkpoint written", checkpoint.h5 and the .nc.partial
 *   files present, no diagnostics.nc;
 * - a plain retry without resume would start again; with resume it
 *   continues from the checkpoint's time (> 0), ends done, leaves no
 *   .partial, and every variable of diagnostics.nc and particles.nc (time
 *   included) is bitwise that of the reference;
 * - a changed spec (run.yaml differs) is not continued: it starts at t = 0,
 *   and gf_ledger_can_continue names the line that differs (the spec's, or
 *   the first line when another build wrote the checkpoint);
 * - the same interrupt and resume for an immersed run (a column collapsing
 *   in a viscous fluid, unresolved tier: the checkpoint holds the fluid too),
 *   whose diagnostics.nc, probes.nc (basal pore pressure) and fields.nc
 *   (fluid fraction, velocity, pressure) are then bitwise the reference's.
 */
#include <netcdf.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <unistd.h>

#include "core/gf_timer.h"
#include "gf_test.h"
#include "gf_test_sim.h"
#include "schedule/gf_ledger.h"
#include "schedule/gf_run_exec.h"

static volatile int interrupt_flag;
static void on_alarm(int sig)
{
    (void)sig;
    interrupt_flag = 1;
}

static void gas_spec(gf_ctx *ctx, gf_run_spec *s)
{
    gf_run_spec_defaults(s);
    snprintf(s->scene, sizeof s->scene, "elastic_gas");
    snprintf(s->run_id, sizeof s->run_id, "gas");
    s->grains.diameter_m = 5e-3;
    s->grains.density_kg_m3 = 2500.0;
    s->grains.polydispersity = 0.05;
    s->contact.restitution = 0.8;
    s->contact.friction = 0.5;
    s->end_time_nd = 4.0;
    s->output.interval_nd = 0.25;
    GF_CHECK_OK(gf_run_spec_set_param(ctx, s, "n_grains", 2200), ctx);
    GF_CHECK_OK(gf_run_spec_set_param(ctx, s, "box_over_D", 16), ctx);
}

/* A dense column (a = 0.5, R0 = 12 D) collapsing in a viscous fluid, every output file. */
static void immersed_spec(gf_ctx *ctx, gf_run_spec *s)
{
    GF_CHECK_OK(gf_test_viscous_collapse_spec(ctx, "unresolved", s), ctx);
    snprintf(s->run_id, sizeof s->run_id, "immersed");
    s->end_time_nd = 3.0;
    s->output.interval_nd = 0.1;
    s->output.particles = s->output.fields = s->output.probes = s->output.diagnostics = 1;
}

static int exists(const char *dir, const char *name)
{
    char path[4300];
    struct stat sb;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return stat(path, &sb) == 0;
}

/* Every variable of a/name equals that of b/name bitwise (same names, types, sizes). */
static void same_file(const char *a, const char *b, const char *name)
{
    char pa[4300], pb[4300];
    snprintf(pa, sizeof pa, "%s/%s", a, name);
    snprintf(pb, sizeof pb, "%s/%s", b, name);
    int fa, fb, nv;
    if (nc_open(pa, NC_NOWRITE, &fa) != NC_NOERR || nc_open(pb, NC_NOWRITE, &fb) != NC_NOERR) {
        gf_test_check(0, __FILE__, __LINE__, "cannot open %s or %s", pa, pb);
        return;
    }
    GF_CHECK(nc_inq_nvars(fa, &nv) == NC_NOERR && nv > 1);
    int n_same = 0;
    for (int v = 0; v < nv; ++v) {
        char vn[NC_MAX_NAME + 1];
        nc_type t;
        int nd, dims[NC_MAX_VAR_DIMS], vb;
        size_t len = 1, size = 0;
        nc_inq_var(fa, v, vn, &t, &nd, dims, NULL);
        nc_inq_type(fa, t, NULL, &size);
        for (int d = 0; d < nd; ++d) {
            size_t l;
            nc_inq_dimlen(fa, dims[d], &l);
            len *= l;
        }
        size_t len_b = 1;
        int nd_b, dims_b[NC_MAX_VAR_DIMS];
        nc_type tb;
        if (nc_inq_varid(fb, vn, &vb) != NC_NOERR) {
            gf_test_check(0, __FILE__, __LINE__, "%s: variable %s missing after the restart", name, vn);
            continue;
        }
        nc_inq_var(fb, vb, NULL, &tb, &nd_b, dims_b, NULL);
        for (int d = 0; d < nd_b; ++d) {
            size_t l;
            nc_inq_dimlen(fb, dims_b[d], &l);
            len_b *= l;
        }
        if (tb != t || len_b != len) {
            gf_test_check(0, __FILE__, __LINE__, "%s: %s has %zu values of type %d, reference %zu of type %d", name, vn,
                          len_b, (int)tb, len, (int)t);
            continue;
        }
        void *x = malloc(len * size + 1), *y = malloc(len * size + 1);
        int ok = x && y && nc_get_var(fa, v, x) == NC_NOERR && nc_get_var(fb, vb, y) == NC_NOERR &&
                 memcmp(x, y, len * size) == 0;
        gf_test_check(ok, __FILE__, __LINE__, "%s: variable %s (%zu values) bitwise as the uninterrupted run", name,
                      vn, len);
        n_same += ok;
        free(x);
        free(y);
    }
    printf("%s: %d of %d variables bitwise equal to the uninterrupted run\n", name, n_same, nv);
    nc_close(fa);
    nc_close(fb);
}

/* Runs spec into co->run_dir and interrupts it after delay_s of wall time
 * (as SIGTERM from a batch system would): a shorter delay again if a faster
 * moment of a shared machine finished the run first, a longer one if the cut
 * came before the first step (nothing to continue yet); once both have
 * happened, the delay halfway between the latest of each (the stepping can
 * be a short window after a long preparation, which doubling and halving
 * would step over). Ends with *res of the last attempt. */
static void interrupt_at(gf_ctx *ctx, const gf_run_spec *spec, const gf_run_exec_opts *co, double delay_s,
                         gf_run_result *res)
{
    const char *dir = co->run_dir;
    double too_early = 0.0, too_late = 0.0; /* latest delays that cut before the first step / finished first */
    for (int attempt = 0; attempt < 16; ++attempt) {
        /* each attempt in a clean directory: a run that finished first
         * leaves its diagnostics.nc, which an interrupted fresh run keeps
         * (its own files stay .partial) */
        GF_CHECK(gf_test_remove_tree(dir));
        long usec = (long)(delay_s * 1e6) + 1;
        struct itimerval it = {{0, 0}, {usec / 1000000, usec % 1000000}};
        interrupt_flag = 0;
        setitimer(ITIMER_REAL, &it, NULL);
        GF_CHECK_OK(gf_run_execute(ctx, spec, co, res), ctx);
        /* a cut before the first step (in the preparation, or with a checkpoint at t = 0) leaves nothing to
         * tell a continued run from a fresh one */
        int early = res->status == GF_ERR_INTERRUPTED && (!exists(dir, "checkpoint.h5") || !(res->sim_time_s > 0.0));
        printf("%s: cut after %.3f s: %s\n", spec->run_id, delay_s,
               res->status == GF_OK ? "finished first" : early ? "interrupted before the first step" : "interrupted");
        if (res->status == GF_OK)
            too_late = delay_s;
        else if (early)
            too_early = delay_s;
        else
            return;
        if (too_early > 0.0 && too_late > 0.0)
            delay_s = 0.5 * (too_early + too_late);
        else
            delay_s *= res->status == GF_OK ? 0.5 : 2.0;
    }
}

/* Reference run, the same run interrupted at first_cut of its wall time
 * (past the scene's preparation) and resumed: the resumed run continues from the checkpoint and its files
 * `names` are bitwise the reference's. */
static void interrupt_and_resume(gf_ctx *ctx, gf_run_spec *spec, const char *out, const char *const *names, int n_names,
                                 double first_cut)
{
    char ref[4200], cut[4200], reason[600];
    snprintf(ref, sizeof ref, "%s/%s_reference", out, spec->run_id);
    snprintf(cut, sizeof cut, "%s/%s_interrupted", out, spec->run_id);
    gf_run_result res;
    gf_run_exec_opts ro = {.run_dir = ref, .campaign = "continue", .n_threads = 1};
    GF_CHECK_OK(gf_run_execute(ctx, spec, &ro, &res), ctx);
    GF_CHECK(res.status == GF_OK && res.continued_from_s == 0.0);
    printf("%s, reference: %ld steps, %.2f s wall\n", spec->run_id, res.steps, res.wall_s);
    const double ref_wall_s = res.wall_s;

    gf_run_exec_opts co = {.run_dir = cut, .campaign = "continue", .n_threads = 1, .interrupt = &interrupt_flag};
    interrupt_at(ctx, spec, &co, first_cut * ref_wall_s, &res);
    GF_CHECK(res.status == GF_ERR_INTERRUPTED);
    GF_CHECK(gf_ledger_state(cut, reason, sizeof reason) == GF_RUN_FAILED);
    gf_test_check(strstr(reason, "checkpoint written") != NULL, __FILE__, __LINE__, "status: %s", reason);
    GF_CHECK(exists(cut, "checkpoint.h5") && exists(cut, "diagnostics.nc.partial") && !exists(cut, "diagnostics.nc"));
    const double t_cut = res.sim_time_s;
    printf("%s: interrupted at t = %.4g s\n", spec->run_id, t_cut);

    /* resumed: continues from the checkpoint, same files as the reference */
    interrupt_flag = 0;
    co.resume = 1;
    GF_CHECK_OK(gf_run_execute(ctx, spec, &co, &res), ctx);
    GF_CHECK(res.status == GF_OK);
    gf_test_check(res.continued_from_s > 0.0 && res.continued_from_s == t_cut, __FILE__, __LINE__,
                  "continued from t = %.17g s (interrupted at %.17g s)", res.continued_from_s, t_cut);
    GF_CHECK(gf_ledger_state(cut, NULL, 0) == GF_RUN_DONE);
    for (int k = 0; k < n_names; ++k) {
        char partial[64];
        snprintf(partial, sizeof partial, "%s.partial", names[k]);
        GF_CHECK(!exists(cut, partial));
        same_file(ref, cut, names[k]);
    }
}

/* A checkpoint that --resume will not use says why: another build wrote its
 * run.yaml (the first line), or the spec changed (end_time here). */
static void check_not_continued(gf_run_spec *spec, const char *dir)
{
    size_t len = 0;
    char *yaml = gf_ledger_run_yaml(spec, "continue", &len), why[600];
    GF_CHECK(yaml && gf_ledger_can_continue(dir, yaml, len, why, sizeof why) == 1 && why[0] == '\0');
    char path[4400];
    snprintf(path, sizeof path, "%s/run.yaml", dir);
    FILE *f = fopen(path, "wb");   /* the same spec, written by another build */
    GF_CHECK(f != NULL);
    fprintf(f, "# grainflow 0.0.1 (an older build)%s", strchr(yaml, '\n'));
    fclose(f);
    GF_CHECK(gf_ledger_can_continue(dir, yaml, len, why, sizeof why) == 0);
    gf_test_check(strstr(why, "line 1 reads \"# grainflow 0.0.1") != NULL, __FILE__, __LINE__, "why: %s", why);
    f = fopen(path, "wb");
    GF_CHECK(f != NULL);
    fwrite(yaml, 1, len, f);
    fclose(f);
    free(yaml);
    const double end = spec->end_time_nd;
    spec->end_time_nd = 2.0;
    yaml = gf_ledger_run_yaml(spec, "continue", &len);
    GF_CHECK(yaml && gf_ledger_can_continue(dir, yaml, len, why, sizeof why) == 0);
    gf_test_check(strstr(why, "end_time") != NULL, __FILE__, __LINE__, "why: %s", why);
    free(yaml);
    spec->end_time_nd = end;
}

int main(void)
{
    char out[] = "/tmp/gf_continue_XXXXXX";
    GF_CHECK(mkdtemp(out) != NULL);
    gf_ctx ctx = {0};
    gf_run_spec spec;
    gas_spec(&ctx, &spec);
    struct sigaction sa = {0};
    sa.sa_handler = on_alarm;
    sigaction(SIGALRM, &sa, NULL);
    static const char *const gas_files[] = {"diagnostics.nc", "particles.nc"};
    interrupt_and_resume(&ctx, &spec, out, gas_files, 2, 0.4);

    /* a changed spec is not continued from an old checkpoint */
    gf_run_result res;
    char changed[4300];
    snprintf(changed, sizeof changed, "%s/changed", out);
    gf_run_exec_opts co = {.run_dir = changed, .campaign = "continue", .n_threads = 1, .interrupt = &interrupt_flag};
    spec.end_time_nd = 3.0;
    interrupt_at(&ctx, &spec, &co, 0.02, &res);
    GF_CHECK(res.status == GF_ERR_INTERRUPTED && res.sim_time_s > 0.0);
    check_not_continued(&spec, changed);
    interrupt_flag = 0;
    co.resume = 1;
    spec.end_time_nd = 2.0;
    GF_CHECK_OK(gf_run_execute(&ctx, &spec, &co, &res), &ctx);
    GF_CHECK(res.status == GF_OK && res.continued_from_s == 0.0);

    /* an immersed run: the checkpoint carries the fluid */
    gf_run_spec imm;
    immersed_spec(&ctx, &imm);
    static const char *const imm_files[] = {"diagnostics.nc", "probes.nc", "fields.nc", "particles.nc"};
    interrupt_and_resume(&ctx, &imm, out, imm_files, 4, 0.75);

    if (!gf_test_remove_tree(out))
        fprintf(stderr, "could not remove %s\n", out);
    return gf_test_finish();
}
