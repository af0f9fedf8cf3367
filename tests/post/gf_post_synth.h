/*
 * Synthetic run files for the post-processing tests, written with netCDF-C
 * directly from docs/output.md (not with the engine's writer, so that the
 * tests check the reading side against the contract itself).
 */
#ifndef GF_POST_SYNTH_H
#define GF_POST_SYNTH_H

#include <stddef.h>

typedef struct synth_meta {
    const char *run_id, *scene, *fluid_model;
    double St, r, a, phi;                 /* asked-for groups (NaN if none) */
    double D, rho_p, rho_f, eta, g;       /* grains and fluid */
    double incline_deg, R0, H0;           /* geometry (0 if none) */
} synth_meta;

/* Fills m with a dry-less default: D = 5 mm, rho_p = 2500, rho_f = 1000, eta = 0.01, g = 9.81. */
void synth_meta_default(synth_meta *m, const char *run_id, const char *scene);

/* dir/diagnostics.nc with time[nt] and n_vars series values[v][nt]. */
int synth_diagnostics(const char *dir, const synth_meta *m, size_t nt, const double *t, int n_vars,
                      const char *const *names, const char *const *units, const double *const *values);
/* dir/particles.nc: n grains, nt frames; x, y, z, u as [grain][frame] (u may be NULL: zero). */
int synth_particles(const char *dir, const synth_meta *m, size_t n, size_t nt, const double *t, const double *radius,
                    const unsigned char *glued, const double *x, const double *y, const double *z, const double *u);
/* dir/probes.nc: ns stations (names, x), P[station][time]. */
int synth_probes(const char *dir, const synth_meta *m, size_t ns, const char *const *names, const double *xs,
                 size_t nt, const double *t, const double *P);
/* dir/fields.nc: uniform grid nx, ny, nz of cell size dx from the origin, nt records;
 * eps and u as [time][z][y][x] (x fastest). */
int synth_fields(const char *dir, const synth_meta *m, size_t nx, size_t ny, size_t nz, double dx, size_t nt,
                 const double *t, const double *eps, const double *u);
/* dir/status with the given line. */
int synth_status(const char *dir, const char *line);
/* mkdir -p for one or two levels. */
int synth_mkdir(const char *dir);
/* Fresh scratch directory under GF_BINARY_DIR (or /tmp): base/name, emptied. */
void synth_scratch(char *buf, size_t size, const char *name);

#endif
