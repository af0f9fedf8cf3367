/*
 * The particle store's per-grain arrays in one staggered block
 * (core/gf_soa.h): element i of the 19 arrays falls in 19 distinct sets of
 * a 4 KiB-indexed L1 and of a 64 KiB-indexed L2, every array is 64-byte
 * aligned, and growing the store keeps every grain's values (the arrays are
 * moved to a new block, not reallocated one by one).
 */
#include <stdint.h>
#include <stdio.h>

#include "gf_test.h"
#include "particles/gf_particles.h"

/* Number of distinct cache sets that element i of the n arrays falls in,
 * for a cache indexed by the address bits below index_bytes. */
static int distinct_sets(void *const *arr, int n, size_t i, size_t index_bytes)
{
    int distinct = 0;
    for (int a = 0; a < n; ++a) {
        uintptr_t sa = ((uintptr_t)arr[a] + 8 * i) % index_bytes / 64;
        int seen = 0;
        for (int b = 0; b < a; ++b)
            seen |= ((uintptr_t)arr[b] + 8 * i) % index_bytes / 64 == sa;
        distinct += !seen;
    }
    return distinct;
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_particles *p = NULL;
    GF_CHECK_OK(gf_particles_create(&ctx, 16, &p), &ctx);
    /* grow through several reallocations; each grain's values encode its index */
    const size_t n = 70000;
    for (size_t k = 0; k < n; ++k)
        GF_CHECK_OK(gf_particles_add(&ctx, p, (double)k, 2.0 * k, 3.0 * k, 1e-3 * (1.0 + k % 7), 2500, 0, NULL), &ctx);
    for (size_t k = 0; k < n; ++k)
        p->vx_m_s[k] = -(double)k, p->tz_N_m[k] = 0.5 * k;
    GF_CHECK_OK(gf_particles_reserve(&ctx, p, 4 * p->capacity), &ctx);
    size_t bad = 0;
    for (size_t k = 0; k < n; ++k)
        bad += p->x_m[k] != (double)k || p->y_m[k] != 2.0 * k || p->z_m[k] != 3.0 * k || p->id[k] != (int64_t)k ||
               p->radius_m[k] != 1e-3 * (1.0 + k % 7) || p->vx_m_s[k] != -(double)k || p->tz_N_m[k] != 0.5 * k;
    gf_test_check(bad == 0, __FILE__, __LINE__, "%zu of %zu grains changed when the store grew", bad, n);

    void *arr[] = {p->x_m,  p->y_m,  p->z_m,  p->vx_m_s, p->vy_m_s, p->vz_m_s,   p->wx_rad_s,
                   p->wy_rad_s, p->wz_rad_s, p->fx_N,   p->fy_N,   p->fz_N,     p->tx_N_m,
                   p->ty_N_m, p->tz_N_m, p->radius_m, p->mass_kg, p->inertia_kg_m2, p->id};
    const int na = (int)(sizeof arr / sizeof *arr);
    int aligned = 1;
    for (int a = 0; a < na; ++a)
        aligned &= (uintptr_t)arr[a] % 64 == 0;
    GF_CHECK(aligned);
    for (size_t i = 0; i < n; i += 9973) {
        int l1 = distinct_sets(arr, na, i, 4096), l2 = distinct_sets(arr, na, i, 65536);
        gf_test_check(l1 == na && l2 == na, __FILE__, __LINE__,
                      "grain %zu: its %d arrays fall in %d L1 sets and %d L2 sets", i, na, l1, l2);
    }
    printf("store of %zu grains (capacity %zu): %d arrays, element i of each in its own L1 and L2 set\n", n,
           p->capacity, na);
    gf_particles_destroy(&p);
    return gf_test_finish();
}
