/*
 * Restart is bitwise: a frictional bed flowing down a 30 degree tilt
 * (tangential history on every contact, wall history, neighbour-list rebuilds
 * in between) advanced 2N steps in one go, and advanced N steps, checkpointed
 * (HDF5), re-created from the checkpoint and advanced N more, hold identical
 * bytes in every position, velocity and spin (memcmp). Checked with 1 and 2 threads (each against a
 * reference with the same thread count: the per-thread force sums are
 * ordered, so a fixed thread count is deterministic).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dem_testutil.h"

static int same(const double *a, const double *b, size_t n) { return memcmp(a, b, n * sizeof(double)) == 0; }

static gf_status from_checkpoint(gf_ctx *ctx, const gf_run_spec *spec, int threads, const char *path, gf_sim **out)
{
    gf_sim_options opt;
    memset(&opt, 0, sizeof opt);
    opt.n_threads = threads;
    opt.restart_path = path;
    return gf_sim_create(ctx, spec, &opt, out);
}

/* A settled frictional bed (1200 grains, mu = 0.5, ~4 contacts per grain),
 * checkpointed once; then tilted by 30 degrees so that it flows (tan 30 >
 * mu_eff), which exercises sliding contacts, new and broken contacts,
 * neighbour rebuilds and wall history. */
static void check_threads(gf_ctx *ctx, gf_run_spec *spec, const char *bed, int threads)
{
    const long N = 800;
    char path[512];
    snprintf(path, sizeof path, "%s.%d", bed, threads);
    const double g = spec->gravity_m_s2, tilt[3] = {g * sin(M_PI / 6), -g * cos(M_PI / 6), 0.0};
    gf_sim *ref = NULL, *a = NULL, *b = NULL;
    GF_CHECK_OK(from_checkpoint(ctx, spec, threads, bed, &ref), ctx);
    GF_CHECK_OK(from_checkpoint(ctx, spec, threads, bed, &a), ctx);
    if (!ref || !a)
        return;
    gf_sim_set_gravity(ref, tilt);
    gf_sim_set_gravity(a, tilt);
    GF_CHECK_OK(gf_sim_advance(ref, 2 * N), ctx);
    GF_CHECK_OK(gf_sim_advance(a, N), ctx);
    GF_CHECK_OK(gf_sim_checkpoint(a, path), ctx);
    gf_sim_destroy(&a);
    GF_CHECK_OK(from_checkpoint(ctx, spec, threads, path, &b), ctx);
    if (!b)
        return;
    GF_CHECK_OK(gf_sim_advance(b, N), ctx);
    gf_particles *p = gf_sim_particles(ref), *q = gf_sim_particles(b);
    size_t n = p->n_local, nc_ref, nc_b;
    GF_CHECK(q->n_local == n);
    int ok = same(p->x_m, q->x_m, n) && same(p->y_m, q->y_m, n) && same(p->z_m, q->z_m, n) &&
             same(p->vx_m_s, q->vx_m_s, n) && same(p->vy_m_s, q->vy_m_s, n) && same(p->vz_m_s, q->vz_m_s, n) &&
             same(p->wx_rad_s, q->wx_rad_s, n) && same(p->wy_rad_s, q->wy_rad_s, n) && same(p->wz_rad_s, q->wz_rad_s, n);
    gf_sim_contact_stats(ref, &nc_ref, NULL);
    gf_sim_contact_stats(b, &nc_b, NULL);
    double P[3];
    gf_particles_momentum(p, P);
    printf("%d thread(s): %zu grains, %ld + %ld steps, %zu contacts, downslope momentum %.3g kg m/s: "
           "bitwise identical = %d\n",
           threads, n, N, N, nc_ref, P[0], ok);
    GF_CHECK(ok);
    GF_CHECK(nc_ref == nc_b && nc_ref > n); /* contact-rich state */
    GF_CHECK(P[0] > 0.0);                   /* it flowed */
    GF_CHECK(gf_sim_time_s(ref) == gf_sim_time_s(b));
    gf_sim_destroy(&ref);
    gf_sim_destroy(&b);
    remove(path);
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_run_spec bed = gf_test_spec("settled_bed");
    bed.grains.polydispersity = 0.1;
    bed.contact.friction = 0.5;
    gf_run_spec_set_param(&ctx, &bed, "n_grains", 1200); /* above the serial threshold: threads really run */
    gf_run_spec_set_param(&ctx, &bed, "settle_time_nd", 3.0);
    char path[512];
    snprintf(path, sizeof path, "%s/dem_restart_bed_%d.h5", getenv("GF_BINARY_DIR") ? getenv("GF_BINARY_DIR") : "/tmp",
             (int)getpid());
    gf_sim *s0 = NULL;
    GF_CHECK_OK(gf_test_sim(&ctx, &bed, 1, &s0), &ctx);
    if (s0)
        GF_CHECK_OK(gf_sim_checkpoint(s0, path), &ctx);
    gf_sim_destroy(&s0);
    gf_run_spec_set_param(&ctx, &bed, "settle_time_nd", 0.0); /* restarts overwrite the bed: skip settling */
    check_threads(&ctx, &bed, path, 1);
    check_threads(&ctx, &bed, path, 2);
    remove(path);
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
