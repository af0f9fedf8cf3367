/* Kick-drift-kick velocity Verlet; see gf_integrate.h. */
#include "integrate/gf_integrate.h"
#include "core/gf_clones.h"

/* The loops are element-wise: `omp simd` lets the compiler use vector
 * instructions (it does not prove the absence of aliasing between the store
 * arrays by itself); the results are bitwise those of the scalar loop (no
 * reassociation; the max reduction is exact). */
#ifdef _OPENMP
#define GF_PRAGMA(x) _Pragma(#x)
#define GF_SIMD GF_PRAGMA(omp simd)
#define GF_SIMD_MAX(...) GF_PRAGMA(omp simd reduction(max : __VA_ARGS__))
#else
#define GF_SIMD
#define GF_SIMD_MAX(...)
#endif

void gf_integrate_factors_fill(const gf_particles *p, size_t n, double *inv_mass, double *inv_inertia, double *mobile)
{
    const uint8_t frozen = GF_P_GLUED | GF_P_SLEEPING;
    for (size_t i = 0; i < n; ++i) {
        int moves = !(p->flags[i] & frozen);
        inv_mass[i] = moves ? 1.0 / p->mass_kg[i] : 0.0;
        inv_inertia[i] = moves ? 1.0 / p->inertia_kg_m2[i] : 0.0;
        mobile[i] = moves ? 1.0 : 0.0;
    }
}

void gf_integrate_kick(gf_particles *p, size_t i0, size_t i1, double h, const double g[3],
                       const gf_integrate_factors *k)
{
    const double *restrict im = k->inv_mass, *restrict iI = k->inv_inertia, *restrict mob = k->mobile;
    double *restrict vx = p->vx_m_s, *restrict vy = p->vy_m_s, *restrict vz = p->vz_m_s;
    double *restrict wx = p->wx_rad_s, *restrict wy = p->wy_rad_s, *restrict wz = p->wz_rad_s;
    const double *restrict fx = p->fx_N, *restrict fy = p->fy_N, *restrict fz = p->fz_N;
    const double *restrict tx = p->tx_N_m, *restrict ty = p->ty_N_m, *restrict tz = p->tz_N_m;
    const double gx = g[0] * h, gy = g[1] * h, gz = g[2] * h;
    if (!iI) { /* translation only: no torque in this run (gf_skips.c) */
        GF_SIMD
        for (size_t i = i0; i < i1; ++i) {
            double a = h * im[i], m = mob[i];
            vx[i] += fx[i] * a + gx * m;
            vy[i] += fy[i] * a + gy * m;
            vz[i] += fz[i] * a + gz * m;
        }
        return;
    }
    GF_SIMD
    for (size_t i = i0; i < i1; ++i) {
        double a = h * im[i], b = h * iI[i], m = mob[i];
        vx[i] += fx[i] * a + gx * m;
        vy[i] += fy[i] * a + gy * m;
        vz[i] += fz[i] * a + gz * m;
        wx[i] += tx[i] * b;
        wy[i] += ty[i] * b;
        wz[i] += tz[i] * b;
    }
}

/* gf_integrate_kick_drift, with the number of kicks and the rotation as constants. */
static inline __attribute__((always_inline)) gf_drift_d2
kick_drift_impl(gf_particles *p, size_t i0, size_t i1, const int twice, const int spin, double dt_s,
                const double g_m_s2[3], const gf_drift_refs *ref, double *const vp[3], const gf_integrate_factors *k)
{
    const double *restrict im = k->inv_mass, *restrict iI = k->inv_inertia, *restrict mob = k->mobile;
    double *restrict x = p->x_m, *restrict y = p->y_m, *restrict z = p->z_m;
    double *restrict vx = p->vx_m_s, *restrict vy = p->vy_m_s, *restrict vz = p->vz_m_s;
    double *restrict wx = p->wx_rad_s, *restrict wy = p->wy_rad_s, *restrict wz = p->wz_rad_s;
    double *restrict fx = p->fx_N, *restrict fy = p->fy_N, *restrict fz = p->fz_N;
    double *restrict tx = p->tx_N_m, *restrict ty = p->ty_N_m, *restrict tz = p->tz_N_m;
    const double *restrict xr = ref->build[0], *restrict yr = ref->build[1], *restrict zr = ref->build[2];
    const double *restrict xn = ref->near[0], *restrict yn = ref->near[1], *restrict zn = ref->near[2];
    double *restrict px = vp[0], *restrict py = vp[1], *restrict pz = vp[2];
    const double h = 0.5 * dt_s, gx = g_m_s2[0] * h, gy = g_m_s2[1] * h, gz = g_m_s2[2] * h;
    double d2_max = 0.0, dn2_max = 0.0;
    GF_SIMD_MAX(d2_max, dn2_max)
    for (size_t i = i0; i < i1; ++i) {
        double m = mob[i], a = h * im[i], s = dt_s * m;
        double u = vx[i], v = vy[i], w = vz[i];
        const double ax = fx[i] * a + gx * m, ay = fy[i] * a + gy * m, az = fz[i] * a + gz * m;
        if (twice)
            u += ax, v += ay, w += az;
        u += ax, v += ay, w += az;
        vx[i] = u, vy[i] = v, vz[i] = w;
        if (spin) {
            double b = h * iI[i], ox = wx[i], oy = wy[i], oz = wz[i];
            const double bx = tx[i] * b, by = ty[i] * b, bz = tz[i] * b;
            if (twice)
                ox += bx, oy += by, oz += bz;
            wx[i] = ox + bx, wy[i] = oy + by, wz[i] = oz + bz;
        }
        x[i] += u * s;
        y[i] += v * s;
        z[i] += w * s;
        px[i] = u + fx[i] * a + gx * m; /* not u + ax: the drift's order of additions */
        py[i] = v + fy[i] * a + gy * m;
        pz[i] = w + fz[i] * a + gz * m;
        fx[i] = fy[i] = fz[i] = 0.0;
        tx[i] = ty[i] = tz[i] = 0.0;
        double dx = x[i] - xr[i], dy = y[i] - yr[i], dz = z[i] - zr[i];
        double d2 = dx * dx + dy * dy + dz * dz;
        d2_max = d2 > d2_max ? d2 : d2_max;
        double ex = x[i] - xn[i], ey = y[i] - yn[i], ez = z[i] - zn[i];
        double dn2 = ex * ex + ey * ey + ez * ez;
        dn2_max = dn2 > dn2_max ? dn2 : dn2_max;
    }
    return (gf_drift_d2){d2_max, dn2_max};
}

/* The four cases compiled apart, so that each loop is straight-line
 * (vectorised), in an AVX-512 clone too (core/gf_clones.h: the same bits). */
GF_AVX512_CLONES gf_drift_d2 gf_integrate_kick_drift(gf_particles *p, size_t i0, size_t i1, int n_kicks, double dt_s,
                                                        const double g_m_s2[3], const gf_drift_refs *ref,
                                                        double *const vp[3], const gf_integrate_factors *k)
{
    if (k->inv_inertia)
        return n_kicks > 1 ? kick_drift_impl(p, i0, i1, 1, 1, dt_s, g_m_s2, ref, vp, k)
                           : kick_drift_impl(p, i0, i1, 0, 1, dt_s, g_m_s2, ref, vp, k);
    return n_kicks > 1 ? kick_drift_impl(p, i0, i1, 1, 0, dt_s, g_m_s2, ref, vp, k)
                       : kick_drift_impl(p, i0, i1, 0, 0, dt_s, g_m_s2, ref, vp, k);
}

double gf_integrate_drift(gf_particles *p, size_t i0, size_t i1, double dt_s, const double g_m_s2[3],
                          const double *const ref[3], double *const vp[3], const gf_integrate_factors *k)
{
    const double *restrict im = k->inv_mass, *restrict mob = k->mobile;
    double *restrict x = p->x_m, *restrict y = p->y_m, *restrict z = p->z_m;
    const double *restrict vx = p->vx_m_s, *restrict vy = p->vy_m_s, *restrict vz = p->vz_m_s;
    const double *restrict fx = p->fx_N, *restrict fy = p->fy_N, *restrict fz = p->fz_N;
    const double *restrict xr = ref[0], *restrict yr = ref[1], *restrict zr = ref[2];
    double *restrict px = vp[0], *restrict py = vp[1], *restrict pz = vp[2];
    const double h = 0.5 * dt_s, gx = g_m_s2[0] * h, gy = g_m_s2[1] * h, gz = g_m_s2[2] * h;
    double d2_max = 0.0;
    GF_SIMD_MAX(d2_max)
    for (size_t i = i0; i < i1; ++i) {
        const double m = mob[i], a = h * im[i], s = dt_s * m;
        x[i] += vx[i] * s;
        y[i] += vy[i] * s;
        z[i] += vz[i] * s;
        px[i] = vx[i] + fx[i] * a + gx * m;
        py[i] = vy[i] + fy[i] * a + gy * m;
        pz[i] = vz[i] + fz[i] * a + gz * m;
        const double dx = x[i] - xr[i], dy = y[i] - yr[i], dz = z[i] - zr[i];
        const double d2 = dx * dx + dy * dy + dz * dz;
        d2_max = d2 > d2_max ? d2 : d2_max;
    }
    return d2_max;
}
