/* SoA particle store; see gf_particles.h. */
#include "particles/gf_particles.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/gf_soa.h"

#define GF_DOUBLE_FIELDS(X)                                                                     \
    X(x_m) X(y_m) X(z_m) X(vx_m_s) X(vy_m_s) X(vz_m_s) X(wx_rad_s) X(wy_rad_s) X(wz_rad_s)     \
    X(fx_N) X(fy_N) X(fz_N) X(tx_N_m) X(ty_N_m) X(tz_N_m) X(radius_m) X(mass_kg) X(inertia_kg_m2)

gf_status gf_particles_create(gf_ctx *ctx, size_t capacity, gf_particles **out)
{
    gf_particles *p = calloc(1, sizeof *p);
    if (!p)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "particles: cannot allocate store");
    *out = p;
    return gf_particles_reserve(ctx, p, capacity > 0 ? capacity : 64);
}

void gf_particles_destroy(gf_particles **pp)
{
    if (!pp || !*pp)
        return;
    gf_particles *p = *pp;
    gf_soa_free(p->soa_block);
    free(p->flags);
    free(p);
    *pp = NULL;
}

static int grow(void **ptr, size_t elem, size_t n)
{
    void *q = realloc(*ptr, elem * n);
    if (!q)
        return 0;
    *ptr = q;
    return 1;
}

gf_status gf_particles_reserve(gf_ctx *ctx, gf_particles *p, size_t n)
{
    if (n <= p->capacity)
        return GF_OK;
    size_t cap = p->capacity ? p->capacity : 64;
    while (cap < n)
        cap *= 2;
    /* the double arrays and id (8 bytes each) in one staggered block */
#define GF_FIELD_PTR(f) (void **)&p->f,
    void **field[] = {GF_DOUBLE_FIELDS(GF_FIELD_PTR)(void **)&p->id};
#undef GF_FIELD_PTR
    enum { N_FIELDS = sizeof field / sizeof *field };
    void *old[N_FIELDS], *fresh[N_FIELDS];
    for (int a = 0; a < N_FIELDS; ++a)
        old[a] = *field[a];
    void *block =
        gf_soa_alloc(N_FIELDS, sizeof(double), cap, GF_SOA_LINE_PARTICLES, fresh, old, p->n_local + p->n_ghost);
    int ok = block != NULL && grow((void **)&p->flags, sizeof(uint8_t), cap);
    if (block) {
        for (int a = 0; a < N_FIELDS; ++a)
            *field[a] = fresh[a];
        gf_soa_free(p->soa_block);
        p->soa_block = block;
    }
    if (!ok)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "particles: cannot grow store to %zu grains", cap);
    p->capacity = cap;
    return GF_OK;
}

gf_status gf_particles_add(gf_ctx *ctx, gf_particles *p, double x, double y, double z, double radius,
                           double density, uint8_t flags, size_t *index)
{
    if (!(radius > 0.0) || !isfinite(radius))
        return GF_FAIL(ctx, GF_ERR_PHYSICS, "particles: radius must be > 0 (got %g m)", radius);
    if (!(density > 0.0) || !isfinite(density))
        return GF_FAIL(ctx, GF_ERR_PHYSICS, "particles: density must be > 0 (got %g kg/m3)", density);
    if (!isfinite(x) || !isfinite(y) || !isfinite(z))
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "particles: non-finite position");
    p->n_ghost = 0;
    GF_TRY(gf_particles_reserve(ctx, p, p->n_local + 1));
    size_t i = p->n_local++;
    p->order_epoch++;
    p->id[i] = p->next_id++;
    p->x_m[i] = x, p->y_m[i] = y, p->z_m[i] = z;
    p->vx_m_s[i] = p->vy_m_s[i] = p->vz_m_s[i] = 0.0;
    p->wx_rad_s[i] = p->wy_rad_s[i] = p->wz_rad_s[i] = 0.0;
    p->fx_N[i] = p->fy_N[i] = p->fz_N[i] = 0.0;
    p->tx_N_m[i] = p->ty_N_m[i] = p->tz_N_m[i] = 0.0;
    p->radius_m[i] = radius;
    p->mass_kg[i] = density * 4.0 / 3.0 * M_PI * radius * radius * radius;
    p->inertia_kg_m2[i] = 0.4 * p->mass_kg[i] * radius * radius;
    p->flags[i] = flags;
    if (index)
        *index = i;
    return GF_OK;
}

void gf_particles_remove(gf_particles *p, size_t i)
{
    if (i >= p->n_local)
        return;
    size_t last = p->n_local - 1;
    if (i != last) {
#define GF_MOVE_FIELD(f) p->f[i] = p->f[last];
        GF_DOUBLE_FIELDS(GF_MOVE_FIELD)
#undef GF_MOVE_FIELD
        p->id[i] = p->id[last];
        p->flags[i] = p->flags[last];
    }
    p->n_local = last;
    p->n_ghost = 0;
    p->order_epoch++;
}

void gf_particles_permute(gf_particles *p, const size_t *perm, double *tmp)
{
    const size_t n = p->n_local;
#define GF_PERMUTE_FIELD(f)                                                                                  \
    for (size_t q = 0; q < n; ++q)                                                                           \
        tmp[q] = p->f[perm[q]];                                                                              \
    memcpy(p->f, tmp, n * sizeof(double));
    GF_DOUBLE_FIELDS(GF_PERMUTE_FIELD)
#undef GF_PERMUTE_FIELD
    int64_t *ti = (int64_t *)tmp; /* same size as a double */
    for (size_t q = 0; q < n; ++q)
        ti[q] = p->id[perm[q]];
    memcpy(p->id, ti, n * sizeof(int64_t));
    uint8_t *tf = (uint8_t *)tmp;
    for (size_t q = 0; q < n; ++q)
        tf[q] = p->flags[perm[q]];
    memcpy(p->flags, tf, n);
    p->n_ghost = 0;
    p->order_epoch++;
}

void gf_particles_clear_forces(gf_particles *p)
{
    gf_particles_clear_forces_from(p, 0);
}

void gf_particles_clear_forces_from(gf_particles *p, size_t first)
{
    size_t n = p->n_local + p->n_ghost;
    if (first >= n)
        return;
    double *a[6] = {p->fx_N, p->fy_N, p->fz_N, p->tx_N_m, p->ty_N_m, p->tz_N_m};
    for (int c = 0; c < 6; ++c)
        memset(a[c] + first, 0, (n - first) * sizeof(double));
}

double gf_particles_kinetic_energy(const gf_particles *p)
{
    double e = 0.0;
    for (size_t i = 0; i < p->n_local; ++i) {
        if (p->flags[i] & GF_P_GLUED)
            continue;
        double v2 = p->vx_m_s[i] * p->vx_m_s[i] + p->vy_m_s[i] * p->vy_m_s[i] + p->vz_m_s[i] * p->vz_m_s[i];
        double w2 = p->wx_rad_s[i] * p->wx_rad_s[i] + p->wy_rad_s[i] * p->wy_rad_s[i] +
                    p->wz_rad_s[i] * p->wz_rad_s[i];
        e += 0.5 * p->mass_kg[i] * v2 + 0.5 * p->inertia_kg_m2[i] * w2;
    }
    return e;
}

double gf_particles_ecx_per_grain(const gf_particles *p)
{
    double e = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < p->n_local; ++i) {
        if (p->flags[i] & GF_P_GLUED)
            continue;
        e += 0.5 * p->mass_kg[i] * p->vx_m_s[i] * p->vx_m_s[i];
        ++n;
    }
    return n ? e / (double)n : 0.0;
}

double gf_particles_mobile_volume(const gf_particles *p, double density_kg_m3)
{
    double m = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        if (!(p->flags[i] & GF_P_GLUED))
            m += p->mass_kg[i];
    return m / density_kg_m3;
}

void gf_particles_momentum(const gf_particles *p, double out[3])
{
    out[0] = out[1] = out[2] = 0.0;
    for (size_t i = 0; i < p->n_local; ++i) {
        if (p->flags[i] & GF_P_GLUED)
            continue;
        out[0] += p->mass_kg[i] * p->vx_m_s[i];
        out[1] += p->mass_kg[i] * p->vy_m_s[i];
        out[2] += p->mass_kg[i] * p->vz_m_s[i];
    }
}

gf_status gf_particles_check_finite(gf_ctx *ctx, const gf_particles *p)
{
    for (size_t i = 0; i < p->n_local; ++i) {
        double s = p->x_m[i] + p->y_m[i] + p->z_m[i] + p->vx_m_s[i] + p->vy_m_s[i] + p->vz_m_s[i] +
                   p->wx_rad_s[i] + p->wy_rad_s[i] + p->wz_rad_s[i];
        if (!isfinite(s))
            return GF_FAIL(ctx, GF_ERR_NUMERIC, "non-finite state of grain %lld (index %zu)",
                           (long long)p->id[i], i);
    }
    return GF_OK;
}
