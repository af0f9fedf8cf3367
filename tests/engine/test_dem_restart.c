/*
 * Restart is bitwise: a frictional bed flowing down a 30 degree tilt
 * (tangential history on every contact, wall history, neighbour-list rebuilds
 * in between) advanced 2N steps in one go, and advanced N steps, checkpointed
 * (HDF5), re-created from the checkpoint and advanced N more, hold identical
 * bytes in every position, velocity and spin (memcmp). Checked with 1 and 2 threads (each against a
 * reference with the same thread count: the per-thread force sums are
 * ordered, so a fixed thread count is deterministic). Also with the spatial
 * sort of the store at every third rebuild (gf_sim_tuning.sort_every): the
 * restart sorts at the same rebuilds, and the sorted run follows the unsorted
 * one grain by grain (by id) to round-off, i.e. ids, history and per-grain
 * data moved together.
 * Then a dry column collapse restarted as it starts to flow, with the scene's own
 * re-equilibration before t = 0 (settle_time_nd at its default): the restart
 * rebuilds the scene, settle included, and the checkpoint's contacts must
 * replace every history that settle left (a stale one once changed the first
 * step after the restart). Again in a 2 D wide slot, where a pair can touch
 * through two images, each with its own history in the checkpoint.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dem_testutil.h"

static gf_status from_checkpoint(gf_ctx *ctx, const gf_run_spec *spec, int threads, int sort_every, const char *path,
                                 gf_sim **out)
{
    return gf_test_sim_sorted(ctx, spec, threads, sort_every, path, out);
}

/* A settled frictional bed (1200 grains, mu = 0.5, ~4 contacts per grain),
 * checkpointed once; then tilted by 30 degrees so that it flows (tan 30 >
 * mu_eff), which exercises sliding contacts, new and broken contacts,
 * neighbour rebuilds and wall history. */
static void check_threads(gf_ctx *ctx, gf_run_spec *spec, const char *bed, int threads, int sort_every)
{
    const long N = 800;
    char path[512];
    snprintf(path, sizeof path, "%s.%d", bed, threads);
    const double g = spec->gravity_m_s2, tilt[3] = {g * sin(M_PI / 6), -g * cos(M_PI / 6), 0.0};
    gf_sim *ref = NULL, *a = NULL, *b = NULL;
    GF_CHECK_OK(from_checkpoint(ctx, spec, threads, sort_every, bed, &ref), ctx);
    GF_CHECK_OK(from_checkpoint(ctx, spec, threads, sort_every, bed, &a), ctx);
    if (!ref || !a)
        return;
    gf_sim_set_gravity(ref, tilt);
    gf_sim_set_gravity(a, tilt);
    GF_CHECK_OK(gf_sim_advance(ref, 2 * N), ctx);
    GF_CHECK_OK(gf_sim_advance(a, N), ctx);
    GF_CHECK_OK(gf_sim_checkpoint(a, path), ctx);
    gf_sim_destroy(&a);
    GF_CHECK_OK(from_checkpoint(ctx, spec, threads, sort_every, path, &b), ctx);
    if (!b)
        return;
    GF_CHECK_OK(gf_sim_advance(b, N), ctx);
    gf_particles *p = gf_sim_particles(ref), *q = gf_sim_particles(b);
    size_t n = p->n_local, nc_ref, nc_b;
    GF_CHECK(q->n_local == n);
    int ok = gf_test_same_motion(p, q);
    gf_sim_contact_stats(ref, &nc_ref, NULL);
    gf_sim_contact_stats(b, &nc_b, NULL);
    double P[3];
    gf_particles_momentum(p, P);
    size_t moved = 0;
    for (size_t i = 0; i < n; ++i)
        moved += p->id[i] != (int64_t)i;
    printf("%d thread(s), sort_every %d: %zu grains, %ld + %ld steps, %zu contacts, downslope momentum %.3g kg m/s, "
           "%zu grains off their insertion index: bitwise identical = %d\n",
           threads, sort_every, n, N, N, nc_ref, P[0], moved, ok);
    if (sort_every > 0) {
        GF_CHECK(moved > 0); /* the store was sorted */
        /* against the unsorted run, grain by grain: round-off only */
        gf_sim *u = NULL;
        GF_CHECK_OK(from_checkpoint(ctx, spec, threads, -1, bed, &u), ctx);
        if (u) {
            gf_sim_set_gravity(u, tilt);
            GF_CHECK_OK(gf_sim_advance(u, 2 * N), ctx);
            gf_particles *w = gf_sim_particles(u);
            double *at = malloc(3 * n * sizeof *at), dmax = 0.0, vmax = 0.0;
            for (size_t i = 0; at && i < n; ++i) {
                size_t k = (size_t)w->id[i];
                at[3 * k] = w->x_m[i], at[3 * k + 1] = w->y_m[i], at[3 * k + 2] = w->vx_m_s[i];
            }
            for (size_t i = 0; at && i < n; ++i) {
                size_t k = (size_t)p->id[i];
                dmax = fmax(dmax, fmax(fabs(p->x_m[i] - at[3 * k]), fabs(p->y_m[i] - at[3 * k + 1])));
                vmax = fmax(vmax, fabs(p->vx_m_s[i] - at[3 * k + 2]));
            }
            double D = spec->grains.diameter_m;
            printf("  sorted vs unsorted run, same grain: max |dx| = %.3g D, max |dv_x| = %.3g sqrt(gD)\n", dmax / D,
                   vmax / sqrt(spec->gravity_m_s2 * D));
            GF_CHECK(at && dmax < 1e-6 * D);
            free(at);
            gf_sim_destroy(&u);
        }
    }
    GF_CHECK(ok);
    GF_CHECK(nc_ref == nc_b && nc_ref > n); /* contact-rich state */
    GF_CHECK(P[0] > 0.0);                   /* it flowed */
    GF_CHECK(gf_sim_time_s(ref) == gf_sim_time_s(b));
    gf_sim_destroy(&ref);
    gf_sim_destroy(&b);
    remove(path);
}

/* Column collapse (a = 1, R0 = 8 D, ~200 grains): 2N steps straight versus N,
 * checkpoint, restart (settle and all), N more; bitwise in every state array.
 * width_over_D > 0: that slot width (2: the thesis', where pairs touch
 * through two images and the checkpoint keeps each image's history). */
static void check_collapse(gf_ctx *ctx, const char *path, double width_over_D)
{
    const long N = 1500;
    gf_run_spec spec = gf_test_spec("column_collapse");
    spec.aspect_ratio_a = 1.0;
    spec.contact.friction = 0.5;
    gf_run_spec_set_param(ctx, &spec, "column_length_over_D", 8.0);
    if (width_over_D > 0.0)
        gf_run_spec_set_param(ctx, &spec, "width_over_D", width_over_D);
    gf_sim *ref = NULL, *b = NULL;
    GF_CHECK_OK(gf_test_sim(ctx, &spec, 1, &ref), ctx);
    if (!ref)
        return;
    GF_CHECK_OK(gf_sim_advance(ref, N), ctx);
    GF_CHECK_OK(gf_sim_checkpoint(ref, path), ctx);
    GF_CHECK_OK(gf_sim_advance(ref, N), ctx);
    GF_CHECK_OK(from_checkpoint(ctx, &spec, 1, 0, path, &b), ctx);
    if (b) {
        GF_CHECK_OK(gf_sim_advance(b, N), ctx);
        gf_particles *p = gf_sim_particles(ref), *q = gf_sim_particles(b);
        size_t n = p->n_local;
        int ok = gf_test_same_motion(p, q);
        double front = 0.0;
        for (size_t i = 0; i < n; ++i)
            if (!(p->flags[i] & GF_P_GLUED))
                front = fmax(front, p->x_m[i]);
        printf("column collapse, a = 1, width %g D: %zu grains, %ld + %ld steps, front at %.2f D: bitwise identical = %d\n",
               width_over_D > 0.0 ? width_over_D : 3.0, n, N, N, front / spec.grains.diameter_m, ok);
        GF_CHECK(ok);
    }
    gf_sim_destroy(&ref);
    gf_sim_destroy(&b);
    remove(path);
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_run_spec bed = gf_test_bed_spec(&ctx, 1200, 3.0); /* 1200: above the serial threshold, threads really run */
    char path[512];
    snprintf(path, sizeof path, "%s/dem_restart_bed_%d.h5", getenv("GF_BINARY_DIR") ? getenv("GF_BINARY_DIR") : "/tmp",
             (int)getpid());
    gf_sim *s0 = NULL;
    GF_CHECK_OK(gf_test_sim(&ctx, &bed, 1, &s0), &ctx);
    if (s0)
        GF_CHECK_OK(gf_sim_checkpoint(s0, path), &ctx);
    gf_sim_destroy(&s0);
    gf_run_spec_set_param(&ctx, &bed, "settle_time_nd", 0.0); /* restarts overwrite the bed: skip settling */
    check_threads(&ctx, &bed, path, 1, 0);
    check_threads(&ctx, &bed, path, 2, 0);
    check_threads(&ctx, &bed, path, 1, 3);
    check_threads(&ctx, &bed, path, 2, 3);
    remove(path);
    check_collapse(&ctx, path, 0.0);
    check_collapse(&ctx, path, 2.0);
    /* a missing checkpoint is an I/O error naming the file */
    gf_run_spec spec = gf_test_spec("binary_collision");
    gf_sim_options opt;
    memset(&opt, 0, sizeof opt);
    opt.restart_path = "/nonexistent/checkpoint.h5";
    gf_sim *s = NULL;
    gf_status st = gf_sim_create(&ctx, &spec, &opt, &s);
    GF_CHECK(st == GF_ERR_IO && strstr(ctx.last_msg, "/nonexistent/checkpoint.h5"));
    return gf_test_finish();
}
