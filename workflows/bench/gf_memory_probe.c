/*
 * What the machine's memory system alone does to a pair loop as the store
 * grows from 1e4 to 1e5 grains (docs/notes/benchmarks.md, "Single core at 1e5:
 * the memory system").
 *
 * The engine runs ~2x slower per particle-step on the 1e5 bed than on the
 * 1e4 bed, while LAMMPS slows by ~1.3x. This probe separates the engine's
 * choices from the machine: a synthetic soft-sphere step with the engine's
 * access pattern (a half list j > i over a jittered cubic lattice of touching
 * grains in Morton order, 9 candidates per row; per pair: positions and radii
 * of both grains, predicted velocities, velocities and spins, a 3-vector
 * history, forces and torques added to both; then a kick-drift over every
 * grain), timed at both sizes in alternating rounds, in the engine's layout
 * (19 per-grain arrays) and in three 64-byte records per grain (position,
 * radius and predicted velocity | velocity and spin | force and torque, the
 * layout LAMMPS's per-atom vectors come closest to), with and without
 * software prefetch of partner j's lines some pairs ahead. The arithmetic is
 * a simplified linear law: what is compared is time per pair.
 *
 * usage: gf-memory-probe [ROUNDS] [PREFETCH_DISTANCE]   (defaults 3, 32)
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { N_ARRAYS = 19, N_OFFSETS = 9 };

typedef struct { double x, y, z, r, vpx, vpy, vpz, pad; } kin_record;
typedef struct { double vx, vy, vz, wx, wy, wz, pad0, pad1; } vel_record;
typedef struct { double fx, fy, fz, tx, ty, tz, pad0, pad1; } force_record;

typedef struct lattice {
    size_t n, m;          /* grains, candidate pairs */
    int32_t *pi, *pj;     /* pairs, rows ascending */
    double *hist;         /* 3 per pair */
    double *arr[N_ARRAYS]; /* x y z r vpx vpy vpz vx vy vz wx wy wz fx fy fz tx ty tz */
    kin_record *kin;
    vel_record *vel;
    force_record *frc;
} lattice;

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static uint64_t spread3(uint64_t v)
{
    uint64_t r = 0;
    for (int b = 0; b < 21; ++b)
        r |= ((v >> b) & 1u) << (3 * b);
    return r;
}

static uint64_t *sort_keys;
static int by_key(const void *a, const void *b)
{
    uint64_t x = sort_keys[*(const size_t *)a], y = sort_keys[*(const size_t *)b];
    return x < y ? -1 : x > y;
}

/* nx * ny * nz grains of diameter ~1 at spacing 0.99 (face neighbours touch),
 * stored in Morton order of their lattice site. */
static int lattice_build(lattice *L, int nx, int ny, int nz)
{
    static const int off[N_OFFSETS][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, -1, 0},
                                          {1, 0, 1}, {1, 0, -1}, {0, 1, 1}, {0, 1, -1}};
    size_t n = (size_t)nx * ny * nz;
    memset(L, 0, sizeof *L);
    L->n = n;
    size_t *order = malloc(n * sizeof *order), *slot = malloc(n * sizeof *slot);
    sort_keys = malloc(n * sizeof *sort_keys);
    L->pi = malloc(2 * N_OFFSETS * n * sizeof *L->pi);
    L->pj = malloc(2 * N_OFFSETS * n * sizeof *L->pj);
    L->kin = aligned_alloc(64, n * sizeof *L->kin);
    L->vel = aligned_alloc(64, n * sizeof *L->vel);
    L->frc = aligned_alloc(64, n * sizeof *L->frc);
    if (!order || !slot || !sort_keys || !L->pi || !L->pj || !L->kin || !L->vel || !L->frc)
        return -1;
    for (int a = 0; a < N_ARRAYS; ++a) { /* staggered by a line, as the engine's store (core/gf_soa.h) */
        char *block = aligned_alloc(4096, (n * sizeof(double) + 8192) / 4096 * 4096);
        if (!block)
            return -1;
        L->arr[a] = (double *)(block + 64 * a);
        memset(L->arr[a], 0, n * sizeof(double));
    }
    memset(L->kin, 0, n * sizeof *L->kin), memset(L->vel, 0, n * sizeof *L->vel), memset(L->frc, 0, n * sizeof *L->frc);
    for (size_t c = 0; c < n; ++c) {
        int ix = (int)(c % nx), iy = (int)(c / nx % ny), iz = (int)(c / ((size_t)nx * ny));
        sort_keys[c] = spread3(ix) | spread3(iy) << 1 | spread3(iz) << 2;
        order[c] = c;
    }
    qsort(order, n, sizeof *order, by_key);
    for (size_t i = 0; i < n; ++i)
        slot[order[i]] = i;
    srand(1);
    for (size_t c = 0; c < n; ++c) {
        size_t i = slot[c];
        int ix = (int)(c % nx), iy = (int)(c / nx % ny), iz = (int)(c / ((size_t)nx * ny));
        double jitter = 0.01 * (rand() / (double)RAND_MAX - 0.5), r = 0.5 * (1.0 + 0.1 * (rand() / (double)RAND_MAX - 0.5));
        double p[4] = {0.99 * ix + jitter, 0.99 * iy, 0.99 * iz, r};
        for (int a = 0; a < 4; ++a)
            L->arr[a][i] = p[a];
        L->kin[i].x = p[0], L->kin[i].y = p[1], L->kin[i].z = p[2], L->kin[i].r = p[3];
    }
    for (size_t i = 0; i < n; ++i) {
        size_t c = order[i];
        int ix = (int)(c % nx), iy = (int)(c / nx % ny), iz = (int)(c / ((size_t)nx * ny));
        for (int sgn = -1; sgn <= 1; sgn += 2)
            for (int o = 0; o < N_OFFSETS; ++o) {
                int jx = ix + sgn * off[o][0], jy = iy + sgn * off[o][1], jz = iz + sgn * off[o][2];
                if (jx < 0 || jy < 0 || jz < 0 || jx >= nx || jy >= ny || jz >= nz)
                    continue;
                size_t j = slot[(size_t)jz * nx * ny + (size_t)jy * nx + (size_t)jx];
                if (j > i)
                    L->pi[L->m] = (int32_t)i, L->pj[L->m] = (int32_t)j, L->m++;
            }
    }
    L->hist = calloc(3 * L->m + 1, sizeof *L->hist);
    free(order), free(slot), free(sort_keys);
    return L->hist ? 0 : -1;
}

/* The pair's force and torque terms from its geometry and relative velocities
 * (linear normal law with damping, tangential spring without cap). */
#define PAIR_FORCE(DX, DY, DZ, RS, VN_REL, U0, U1, U2, H)                                                        \
    double r2 = DX * DX + DY * DY + DZ * DZ;                                                                     \
    if (r2 >= RS * RS)                                                                                           \
        continue;                                                                                                \
    double r = sqrt(r2), n0 = DX / r, n1 = DY / r, n2 = DZ / r, f_n = 1e3 * (RS - r) - 0.1 * (VN_REL);           \
    H[0] += (U0) * dt, H[1] += (U1) * dt, H[2] += (U2) * dt;                                                    \
    double F0 = f_n * n0 - H[0], F1 = f_n * n1 - H[1], F2 = f_n * n2 - H[2];                                     \
    double T0 = -(n1 * H[2] - n2 * H[1]), T1 = -(n2 * H[0] - n0 * H[2]), T2 = -(n0 * H[1] - n1 * H[0]);

static void step_arrays(lattice *L, double dt, int pf)
{
    double *const *a = L->arr;
    double *x = a[0], *y = a[1], *z = a[2], *R = a[3], *vpx = a[4], *vpy = a[5], *vpz = a[6];
    double *vx = a[7], *vy = a[8], *vz = a[9], *wx = a[10], *wy = a[11], *wz = a[12];
    double *fx = a[13], *fy = a[14], *fz = a[15], *tx = a[16], *ty = a[17], *tz = a[18];
    for (size_t k = 0; k < L->m; ++k) {
        if (pf) {
            size_t ahead = (size_t)L->pj[k + (size_t)pf < L->m ? k + (size_t)pf : k];
            for (int q = 0; q < N_ARRAYS; ++q)
                __builtin_prefetch(a[q] + ahead, 1, 3);
        }
        size_t i = (size_t)L->pi[k], j = (size_t)L->pj[k];
        double dx = x[i] - x[j], dy = y[i] - y[j], dz = z[i] - z[j], rs = R[i] + R[j], *h = L->hist + 3 * k;
        PAIR_FORCE(dx, dy, dz, rs, (vpx[i] - vpx[j]) * dx + (vpy[i] - vpy[j]) * dy + (vpz[i] - vpz[j]) * dz,
                   vx[i] - vx[j] + R[i] * wx[i] + R[j] * wx[j], vy[i] - vy[j] + R[i] * wy[i] + R[j] * wy[j],
                   vz[i] - vz[j] + R[i] * wz[i] + R[j] * wz[j], h)
        fx[i] += F0, fy[i] += F1, fz[i] += F2, fx[j] -= F0, fy[j] -= F1, fz[j] -= F2;
        tx[i] += T0, ty[i] += T1, tz[i] += T2, tx[j] += T0, ty[j] += T1, tz[j] += T2;
    }
    for (size_t i = 0; i < L->n; ++i) {
        vx[i] += 1e-9 * fx[i], vy[i] += 1e-9 * fy[i], vz[i] += 1e-9 * fz[i];
        wx[i] += 1e-9 * tx[i], wy[i] += 1e-9 * ty[i], wz[i] += 1e-9 * tz[i];
        x[i] += vx[i] * dt, y[i] += vy[i] * dt, z[i] += vz[i] * dt;
        vpx[i] = vx[i], vpy[i] = vy[i], vpz[i] = vz[i];
        fx[i] = fy[i] = fz[i] = tx[i] = ty[i] = tz[i] = 0.0;
    }
}

static void step_records(lattice *L, double dt, int pf)
{
    kin_record *kin = L->kin;
    vel_record *vel = L->vel;
    force_record *frc = L->frc;
    for (size_t k = 0; k < L->m; ++k) {
        if (pf) {
            size_t ahead = (size_t)L->pj[k + (size_t)pf < L->m ? k + (size_t)pf : k];
            __builtin_prefetch(kin + ahead, 1, 3), __builtin_prefetch(vel + ahead, 1, 3);
            __builtin_prefetch(frc + ahead, 1, 3);
        }
        size_t i = (size_t)L->pi[k], j = (size_t)L->pj[k];
        const kin_record *a = kin + i, *b = kin + j;
        const vel_record *va = vel + i, *vb = vel + j;
        double dx = a->x - b->x, dy = a->y - b->y, dz = a->z - b->z, rs = a->r + b->r, *h = L->hist + 3 * k;
        PAIR_FORCE(dx, dy, dz, rs, (a->vpx - b->vpx) * dx + (a->vpy - b->vpy) * dy + (a->vpz - b->vpz) * dz,
                   va->vx - vb->vx + a->r * va->wx + b->r * vb->wx, va->vy - vb->vy + a->r * va->wy + b->r * vb->wy,
                   va->vz - vb->vz + a->r * va->wz + b->r * vb->wz, h)
        force_record *fa = frc + i, *fb = frc + j;
        fa->fx += F0, fa->fy += F1, fa->fz += F2, fb->fx -= F0, fb->fy -= F1, fb->fz -= F2;
        fa->tx += T0, fa->ty += T1, fa->tz += T2, fb->tx += T0, fb->ty += T1, fb->tz += T2;
    }
    for (size_t i = 0; i < L->n; ++i) {
        kin_record *a = kin + i;
        vel_record *v = vel + i;
        force_record *f = frc + i;
        v->vx += 1e-9 * f->fx, v->vy += 1e-9 * f->fy, v->vz += 1e-9 * f->fz;
        v->wx += 1e-9 * f->tx, v->wy += 1e-9 * f->ty, v->wz += 1e-9 * f->tz;
        a->x += v->vx * dt, a->y += v->vy * dt, a->z += v->vz * dt;
        a->vpx = v->vx, a->vpy = v->vy, a->vpz = v->vz;
        f->fx = f->fy = f->fz = f->tx = f->ty = f->tz = 0.0;
    }
}

/* ns per candidate pair of `steps` steps. */
static double time_per_pair(lattice *L, int records, int pf, int steps)
{
    double t = now_s();
    for (int s = 0; s < steps; ++s) {
        if (records)
            step_records(L, 1e-6, pf);
        else
            step_arrays(L, 1e-6, pf);
    }
    return (now_s() - t) / steps / (double)L->m * 1e9;
}

int main(int argc, char **argv)
{
    int rounds = argc > 1 ? atoi(argv[1]) : 3, pf = argc > 2 ? atoi(argv[2]) : 32;
    lattice small, large;
    if (lattice_build(&small, 25, 16, 25) || lattice_build(&large, 54, 34, 54)) {
        fprintf(stderr, "gf-memory-probe: out of memory\n");
        return 1;
    }
    const char *names[4] = {"19 arrays", "19 arrays, prefetch", "3 records", "3 records, prefetch"};
    printf("grains %zu and %zu, %.2f and %.2f candidate pairs per grain, prefetch distance %d pairs\n", small.n,
           large.n, (double)small.m / small.n, (double)large.m / large.n, pf);
    printf("%-6s %-22s %12s %12s %8s\n", "round", "layout", "1e4 ns/pair", "1e5 ns/pair", "ratio");
    for (int r = 1; r <= rounds; ++r)
        for (int v = 0; v < 4; ++v) {
            int records = v >= 2, p = v % 2 ? pf : 0;
            double a = time_per_pair(&small, records, p, 1000), b = time_per_pair(&large, records, p, 100);
            printf("%-6d %-22s %12.2f %12.2f %8.2f\n", r, names[v], a, b, b / a);
        }
    return 0;
}
