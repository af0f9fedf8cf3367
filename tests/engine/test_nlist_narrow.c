/*
 * A periodic axis narrower than two contact ranges (the thesis' 2 D wide
 * column, Izard 2014 Table 5.1 cases A, B, D-F): one pair of grains can touch
 * through two images at once, one on each side, and each image is a contact
 * of its own (gf_nlist.h).
 *
 * 1. Two grains of radius 0.525 D in a periodic cube of 2 D, one above the
 *    other along z at half a period: each touches the other through both
 *    images, overlap 0.05 D in each. The two linear springs (eps = 1, no
 *    damping) act in parallel on the relative motion: it oscillates about
 *    half a period at omega = sqrt(2 k_n / m_eff), the period sqrt(2) times
 *    the contact time's 2 t_c of a single spring. Asserted within 0.5 %,
 *    and the mean separation at half a period within 1e-4 of the overlap
 *    (the two forces cancel there). A list that kept one image would push
 *    the grains apart for good.
 * 2. A frictional column collapsing in a 2 D wide periodic slot (a = 1,
 *    R0 = 8 D, mu = 0.5, 10 % polydisperse), where pairs touch through both
 *    images with distinct tangential springs: 300 forced rebuilds leave the trajectory
 *    equal to the run without them (1e-9 D), so each image's history
 *    follows it across rebuilds and wraps; a forced rebuild keeps every
 *    history bit for bit, pair by pair and image by image.
 * 3. A grain reaching its own image (a period shorter than the contact
 *    range) is refused with the axis and the length needed.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dem_testutil.h"
#include "contact/gf_contact.h"

static void squeezed_pair(gf_ctx *ctx)
{
    gf_run_spec spec = gf_test_elastic_gas_spec(ctx, 2, 2.0, 0.02);
    gf_run_spec_set_param(ctx, &spec, "speed_nd", 0.0);
    gf_sim *s = NULL;
    GF_CHECK_OK(gf_test_sim(ctx, &spec, 1, &s), ctx);
    if (!s)
        return;
    gf_particles *p = gf_sim_particles(s);
    const double D = spec.grains.diameter_m, L = 2.0 * D;
    GF_CHECK(p->n_local == 2);
    /* one above the other along z at half a period; the masses are kept, so
     * the springs act on m_eff = m / 2 */
    for (size_t i = 0; i < 2; ++i) {
        p->radius_m[i] = 0.525 * D;
        p->x_m[i] = 0.5 * D, p->y_m[i] = 0.5 * D, p->z_m[i] = 0.5 * D + (double)i * 0.5 * L;
        p->vx_m_s[i] = p->vy_m_s[i] = p->vz_m_s[i] = 0.0;
        p->wx_rad_s[i] = p->wy_rad_s[i] = p->wz_rad_s[i] = 0.0;
    }
    const double k = gf_sim_contact_params(s)->k_n_N_m, m_eff = p->mass_kg[0] * p->mass_kg[1] / (p->mass_kg[0] + p->mass_kg[1]);
    const double omega = sqrt(2.0 * k / m_eff), amplitude = 0.01 * D;
    p->vz_m_s[0] = -0.5 * amplitude * omega, p->vz_m_s[1] = 0.5 * amplitude * omega;
    GF_CHECK_OK(gf_sim_rebuild_neighbours(s), ctx);
    const gf_sim_list_stats ls = gf_sim_list_counters(s);
    /* u: the separation along z less half a period */
    double t_prev = 0.0, u_prev = 0.0, first = -1.0, last = -1.0, u_sum = 0.0;
    int crossings = 0;
    long steps = 0;
    const double t_end = 6.0 * 2.0 * M_PI / omega;
    while (gf_sim_time_s(s) < t_end) {
        GF_CHECK_OK(gf_sim_advance(s, 1), ctx);
        double u = fmod(p->z_m[1] - p->z_m[0] + 2.0 * L, L) - 0.5 * L, t = gf_sim_time_s(s);
        if (steps > 0 && u_prev < 0.0 && u >= 0.0) { /* upward zero crossing, interpolated */
            double tc = t_prev + (t - t_prev) * (-u_prev) / (u - u_prev);
            if (first < 0.0)
                first = tc;
            last = tc, ++crossings;
        }
        u_sum += u, t_prev = t, u_prev = u, ++steps;
    }
    size_t n_contacts = 0;
    gf_sim_contact_stats(s, &n_contacts, NULL);
    const double period = crossings > 1 ? (last - first) / (crossings - 1) : NAN, want = 2.0 * M_PI / omega;
    printf("pair through two images of a 2 D period: %zu list pairs, %zu contacts; period %.6g s against "
           "2 pi / sqrt(2 k_n / m_eff) = %.6g s (%+.3f %%, %d crossings); mean offset from half a period %.2e D\n",
           ls.pairs, n_contacts, period, want, 100.0 * (period / want - 1.0), crossings, u_sum / steps / D);
    GF_CHECK(ls.pairs == 2 && n_contacts == 2);
    GF_CHECK(crossings >= 5);
    GF_CHECK_REL(period, want, 0.005);
    GF_CHECK(fabs(u_sum / steps) < 1e-4 * 0.05 * D);
    gf_sim_destroy(&s);
}

/* q's pair and image (branch vector within D / 2, images are 2 D apart) in v with the same history. */
static int kept(const dem_pair_h *v, size_t m, const dem_pair_h *q, double D)
{
    for (size_t k = 0; k < m; ++k)
        if (v[k].a == q->a && v[k].b == q->b && fabs(v[k].branch[0] - q->branch[0]) < 0.5 * D &&
            fabs(v[k].branch[2] - q->branch[2]) < 0.5 * D)
            return memcmp(v[k].h, q->h, sizeof q->h) == 0;
    return 0;
}

/* Pairs of v present through two images. */
static size_t two_images(const dem_pair_h *v, size_t m)
{
    size_t n = 0;
    for (size_t k = 0; k < m; ++k)
        for (size_t q = k + 1; q < m; ++q)
            n += v[k].a == v[q].a && v[k].b == v[q].b;
    return n;
}

static double wrap(double d, double L) { return d - L * round(d / L); }

static void narrow_bed(gf_ctx *ctx)
{
    gf_run_spec spec = gf_test_spec("column_collapse");
    spec.grains.polydispersity = 0.1;
    spec.aspect_ratio_a = 1.0;
    spec.contact.friction = 0.5;
    spec.contact.wall_friction = 0.5;
    gf_run_spec_set_param(ctx, &spec, "column_length_over_D", 8.0);
    gf_run_spec_set_param(ctx, &spec, "width_over_D", 2.0);
    gf_sim *a = NULL, *b = NULL;
    GF_CHECK_OK(gf_test_sim(ctx, &spec, 1, &a), ctx);
    GF_CHECK_OK(gf_test_sim(ctx, &spec, 1, &b), ctx);
    if (!a || !b)
        return;
    const double g = spec.gravity_m_s2, D = spec.grains.diameter_m;
    GF_CHECK_OK(gf_sim_advance(a, 2000), ctx);
    GF_CHECK_OK(gf_sim_advance(b, 2000), ctx);
    dem_pair_h *before, *after;
    size_t m0 = dem_snapshot(ctx, a, &before);
    GF_CHECK_OK(gf_sim_rebuild_neighbours(a), ctx);
    size_t m1 = dem_snapshot(ctx, a, &after), same = 0, doubled = two_images(before, m0);
    for (size_t k = 0; k < m0; ++k)
        same += kept(after, m1, &before[k], D);
    printf("column in a 2 D slot: %zu contacts with history, %zu pairs through two images; after a forced rebuild %zu, "
           "%zu identical\n", m0, doubled, m1, same);
    GF_CHECK(m0 > 60 && doubled > 0 && m1 == m0 && same == m0);
    free(before), free(after);
    gf_particles *pa = gf_sim_particles(a), *pb = gf_sim_particles(b);
    const long builds0 = gf_sim_list_counters(a).builds;
    for (int k = 0; k < 300; ++k) {
        gf_sim_rebuild_at_next_step(a);
        GF_CHECK_OK(gf_sim_advance(a, 10), ctx);
    }
    GF_CHECK_OK(gf_sim_advance(b, 3000), ctx);
    double lo[3], hi[3], dab = 0.0, vmax = 0.0;
    gf_sim_box(a, lo, hi, NULL);
    for (size_t i = 0; i < pa->n_local; ++i) {
        dab = fmax(dab, fmax(fabs(pa->x_m[i] - pb->x_m[i]), fabs(wrap(pa->z_m[i] - pb->z_m[i], hi[2] - lo[2]))) / D);
        vmax = fmax(vmax, fabs(pa->vx_m_s[i]) / sqrt(g * D));
    }
    const long forced = gf_sim_list_counters(a).builds - builds0;
    printf("3000 steps, %ld forced rebuilds: largest difference to the run without them %.3g D (fastest grain %.3g sqrt(gD))\n",
           forced, dab, vmax);
    GF_CHECK(forced >= 300);
    GF_CHECK(dab < 1e-9);
    gf_sim_destroy(&a);
    gf_sim_destroy(&b);
}

static void own_image_refused(gf_ctx *ctx)
{
    gf_run_spec spec = gf_test_elastic_gas_spec(ctx, 1, 2.0, 0.02);
    gf_sim *s = NULL;
    GF_CHECK_OK(gf_test_sim(ctx, &spec, 1, &s), ctx);
    if (!s)
        return;
    gf_sim_particles(s)->radius_m[0] = 1.01 * spec.grains.diameter_m; /* 2.02 D across: touches itself */
    gf_status st = gf_sim_rebuild_neighbours(s);
    printf("a grain wider than the period: %s\n", ctx->last_msg);
    GF_CHECK(st == GF_ERR_CONFIG && strstr(ctx->last_msg, "its own image"));
    gf_sim_destroy(&s);
}

int main(void)
{
    gf_ctx ctx = {0};
    squeezed_pair(&ctx);
    narrow_bed(&ctx);
    own_image_refused(&ctx);
    return gf_test_finish();
}
