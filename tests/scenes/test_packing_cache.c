/*
 * Deposits shared between the runs of a campaign (io/gf_packing_cache.h).
 *
 * Claim: a deposit read back from the preparations directory is the one the
 * preparation builds, bit for bit (positions, radii, ids, and the measured
 * Phi_i, mu_prep, deposit count), so that a campaign's runs are the same
 * whether or not another run prepared their column first. A spec that
 * differs in one field (the seed), an obstacle that moved, or a file that
 * was cut short is a miss and is built afresh; the cut file is replaced.
 * The column is the rough-based 8D x 6D x 3D box of a small collapse with
 * Phi_i 0.59 requested (its interior control box, 5 D x 2.5 D x 3 D, holds too
 * few grains to reach 0.58 within 0.005: the deposits jump between ~0.565
 * and ~0.595 across mu_prep 0.20-0.22, and the preparation is refused).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/gf_timer.h"
#include "gf_test.h"
#include "gf_test_files.h"
#include "io/gf_packing_cache.h"

static const double D = 7.6e-3;

static gf_packing_spec column(const gf_particles *base, uint64_t seed)
{
    return (gf_packing_spec){.lo_m = {0, 0, 0}, .hi_m = {8 * D, 6 * D, 3 * D}, .periodic = {0, 0, 1}, .walls_x = 1,
                             .phi_target = 0.59, .psd = {D / 2, 0.05}, .density_kg_m3 = 2500,
                             .gravity_m_s2 = 9.81, .obstacles = base, .seed = seed};
}

static gf_particles *prepare(const gf_packing_spec *sp, const char *dir, gf_packing_result *r)
{
    gf_ctx ctx = {0};
    gf_particles *p = NULL;
    GF_CHECK_OK(gf_particles_create(&ctx, 512, &p), &ctx);
    GF_CHECK_OK(gf_packing_build_cached(&ctx, sp, dir, p, r), &ctx);
    return p;
}

static int same_deposit(const gf_particles *a, const gf_packing_result *ra, const gf_particles *b,
                        const gf_packing_result *rb)
{
    if (a->n_local != b->n_local || ra->n_grains != rb->n_grains || ra->iterations != rb->iterations)
        return 0;
    size_t n = a->n_local;
    return memcmp(a->x_m, b->x_m, n * sizeof(double)) == 0 && memcmp(a->y_m, b->y_m, n * sizeof(double)) == 0 &&
           memcmp(a->z_m, b->z_m, n * sizeof(double)) == 0 &&
           memcmp(a->radius_m, b->radius_m, n * sizeof(double)) == 0 &&
           memcmp(a->mass_kg, b->mass_kg, n * sizeof(double)) == 0 &&
           memcmp(a->id, b->id, n * sizeof(int64_t)) == 0 && ra->phi_local == rb->phi_local &&
           ra->phi_global == rb->phi_global && ra->mu_prep == rb->mu_prep && ra->top_m == rb->top_m;
}

int main(void)
{
    char dir[] = "/tmp/gf_packing_cache_XXXXXX";
    GF_CHECK(mkdtemp(dir) != NULL);
    char prep_dir[600];
    snprintf(prep_dir, sizeof prep_dir, "%s/preparations", dir);
    char pattern[700];
    snprintf(pattern, sizeof pattern, "%s/packing-*.h5", prep_dir);
    gf_ctx ctx = {0};
    gf_psd psd = {D / 2, 0.05};
    gf_particles *base = NULL;
    GF_CHECK_OK(gf_particles_create(&ctx, 64, &base), &ctx);
    GF_CHECK_OK(gf_packing_rough_base(&ctx, base, &psd, 2500, 0.0, 0.0, 8 * D, 0.0, 3 * D, (const int[2]){0, 1}, 4),
                &ctx);

    gf_packing_spec sp = column(base, 4);
    gf_packing_result r_plain, r_first, r_again;
    gf_particles *plain = prepare(&sp, NULL, &r_plain);
    gf_particles *first = prepare(&sp, prep_dir, &r_first);
    double t0 = gf_wtime();
    gf_particles *again = prepare(&sp, prep_dir, &r_again);
    double t_read = gf_wtime() - t0;
    printf("built: %zu grains, Phi_i %.4f, %d deposits, %.2f s; read back (reused %d) in %.4f s\n", r_first.n_grains,
           r_first.phi_local, r_first.iterations, r_first.cpu_s, r_again.reused, t_read);
    GF_CHECK(!r_plain.reused && !r_first.reused && r_again.reused);
    GF_CHECK(gf_test_count_files(pattern) == 1);
    GF_CHECK(same_deposit(plain, &r_plain, first, &r_first));
    GF_CHECK(same_deposit(plain, &r_plain, again, &r_again));

    /* another seed is another column */
    gf_packing_spec other = column(base, 5);
    gf_packing_result r_other;
    gf_particles *p_other = prepare(&other, prep_dir, &r_other);
    GF_CHECK(!r_other.reused && gf_test_count_files(pattern) == 2);
    GF_CHECK(!same_deposit(plain, &r_plain, p_other, &r_other));

    /* an obstacle moved by 1 nm: same key text, different base, a miss */
    base->y_m[0] += 1e-9;
    gf_packing_result r_moved;
    gf_particles *p_moved = prepare(&sp, prep_dir, &r_moved);
    GF_CHECK(!r_moved.reused);
    base->y_m[0] -= 1e-9;

    /* a file cut short is rebuilt (same deposit) and replaced */
    char cmd[700];
    snprintf(cmd, sizeof cmd, "for f in %s/packing-*.h5; do head -c 300 \"$f\" > \"$f.cut\" && mv \"$f.cut\" \"$f\"; done",
             prep_dir);
    GF_CHECK(system(cmd) == 0);
    gf_packing_result r_cut, r_after;
    gf_particles *p_cut = prepare(&sp, prep_dir, &r_cut);
    gf_particles *p_after = prepare(&sp, prep_dir, &r_after);
    GF_CHECK(!r_cut.reused && r_after.reused);
    GF_CHECK(same_deposit(plain, &r_plain, p_cut, &r_cut));
    GF_CHECK(same_deposit(plain, &r_plain, p_after, &r_after));

    gf_particles *all[] = {plain, first, again, p_other, p_moved, p_cut, p_after, base};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; ++k)
        gf_particles_destroy(&all[k]);
    GF_CHECK(gf_test_remove_tree(dir));
    return gf_test_finish();
}
