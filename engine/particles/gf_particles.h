/*
 * The particle store: a plain struct of arrays (SoA), the one deliberate
 * exception to opaque objects, because every kernel reads it.
 *
 * Invariants (only gf_particles_* functions change n_local, n_ghost,
 * capacity or ordering):
 *   - indices [0, n_local) are owned grains, [n_local, n_local + n_ghost)
 *     ghosts (periodic or MPI images), stored after the locals;
 *   - id[] is global and stable across reordering and migration;
 *   - mass_kg and inertia_kg_m2 are consistent with radius_m and the grain
 *     density given at insertion (sphere: I = 2/5 m R^2);
 *   - flags: GF_P_GLUED grains never move (rough beds, walls of glued grains)
 *     and have infinite effective mass in contacts; GF_P_SLEEPING grains are
 *     skipped by the integrator until woken.
 * All quantities SI. Forces/torques are accumulators cleared every step.
 */
#ifndef GF_PARTICLES_H
#define GF_PARTICLES_H

#include <stddef.h>
#include <stdint.h>

#include "core/gf_status.h"

enum { GF_P_GLUED = 1u << 0, GF_P_SLEEPING = 1u << 1 };

typedef struct gf_particles {
    size_t n_local, n_ghost, capacity;
    int64_t *id;
    double *x_m, *y_m, *z_m;
    double *vx_m_s, *vy_m_s, *vz_m_s;
    double *wx_rad_s, *wy_rad_s, *wz_rad_s;
    double *fx_N, *fy_N, *fz_N;
    double *tx_N_m, *ty_N_m, *tz_N_m;
    double *radius_m, *mass_kg, *inertia_kg_m2;
    uint8_t *flags;
    int64_t next_id;
    uint64_t order_epoch; /* changes whenever grains are added, removed or reordered */
    void *soa_block; /* owns id and the double arrays, staggered (core/gf_soa.h) */
} gf_particles;

/* Returns owned store with room for capacity grains (grows on demand). */
gf_status gf_particles_create(gf_ctx *ctx, size_t capacity, gf_particles **out);
/* Accepts NULL; sets *p = NULL. */
void gf_particles_destroy(gf_particles **p);
/* Ensures capacity >= n (keeps contents). */
gf_status gf_particles_reserve(gf_ctx *ctx, gf_particles *p, size_t n);
/* Appends one owned grain at rest; returns its index in *index (may be NULL).
 * Errors: radius or density not > 0, non-finite position. Drops ghosts. */
gf_status gf_particles_add(gf_ctx *ctx, gf_particles *p, double x_m, double y_m, double z_m, double radius_m,
                           double density_kg_m3, uint8_t flags, size_t *index);
/* Removes owned grain i (swap with last local); drops ghosts. */
void gf_particles_remove(gf_particles *p, size_t i);
/* Reorders the locals: index q receives the grain at old index perm[q]
 * (perm: a permutation of [0, n_local)), every field moved together (ids
 * go with their grains); drops ghosts. tmp: scratch of n_local doubles. */
void gf_particles_permute(gf_particles *p, const size_t *perm, double *tmp);
/* Zeroes force and torque accumulators of locals and ghosts. */
void gf_particles_clear_forces(gf_particles *p);
/* The same for grains [first, n_local + n_ghost) only. */
void gf_particles_clear_forces_from(gf_particles *p, size_t first);
/* Total kinetic energy (translation + rotation) of mobile locals, J. */
double gf_particles_kinetic_energy(const gf_particles *p);
/* Horizontal (x) translational kinetic energy per mobile local, J: E_cx of Izard (2014) §5.3. */
double gf_particles_ecx_per_grain(const gf_particles *p);
/* Solid volume of the mobile locals, m^3 (mass over density). */
double gf_particles_mobile_volume(const gf_particles *p, double density_kg_m3);
/* Total momentum of mobile locals, kg m/s. */
void gf_particles_momentum(const gf_particles *p, double out[3]);
/* GF_ERR_NUMERIC with the first bad index if any position/velocity is not finite. */
gf_status gf_particles_check_finite(gf_ctx *ctx, const gf_particles *p);

#endif
