/*
 * The grains of a sim as a LAMMPS data file (atom_style sphere, SI units),
 * plus PATH.params, the law's constants in LAMMPS terms as shell
 * assignments, for the side-by-side scripts of workflows/bench/
 * (lammps_compare.sh, lammps_collapse.sh).
 *
 * Atom type 1: mobile grains; type 2: glued grains (the rough base of the
 * collapse), written with zero velocity: the LAMMPS input must neither
 * integrate them nor let them feel forces (fix freeze, which also makes
 * LAMMPS take m* = m_i for a pair with a glued partner, as grainflow does).
 */
#ifndef GF_LAMMPS_DATA_H
#define GF_LAMMPS_DATA_H

#include <stdio.h>

#include "gf_sim.h"

/* Writes path and path.params; 1 on success, 0 when a file cannot be written. */
int gf_bench_write_lammps(gf_sim *sim, const char *path);

/* A scene's own assignments (geometry, schedule) for PATH.params, written
 * to f given the sim's box (gf_sim_box) and the program's arguments. */
typedef void gf_bench_params_fn(FILE *f, gf_sim *sim, const double lo[3], const double hi[3], const void *args);

/* --lammps-data PATH of a program: gf_bench_write_lammps, then append's
 * assignments (none when NULL) at the end of PATH.params. 1 on success, 0
 * with "program: cannot write PATH" on stderr. */
int gf_bench_export_lammps(gf_sim *sim, const char *path, gf_bench_params_fn *append, const void *args,
                           const char *program);

/* The grains as the scripts' LAMMPS dumps list them, one line each: "x y z
 * radius" (SI), then " type" (1 mobile, 2 glued) when with_type is non-zero,
 * so that a script measures both codes' grains with one definition. 1 on
 * success, 0 when the file cannot be written. */
int gf_bench_write_dump(gf_sim *sim, const char *path, int with_type);

/* Input e of LAMMPS pair granular's `damping tsuji` (29 Sep 2021: damping
 * alpha(e) sqrt(m* k_n), alpha Tsuji's sixth-order polynomial) for which
 * alpha(e) = 2 zeta: grainflow's per-pair damping 2 zeta sqrt(m* k_n). */
double gf_bench_tsuji_input(double zeta);

#endif
