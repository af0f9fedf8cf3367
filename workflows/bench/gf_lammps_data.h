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

/* PATH.params opened for appending a scene's own assignments (geometry,
 * schedule) after gf_bench_write_lammps; NULL when it cannot be opened. */
FILE *gf_bench_append_params(const char *path);

/* Input e of LAMMPS pair granular's `damping tsuji` (29 Sep 2021: damping
 * alpha(e) sqrt(m* k_n), alpha Tsuji's sixth-order polynomial) for which
 * alpha(e) = 2 zeta: grainflow's per-pair damping 2 zeta sqrt(m* k_n). */
double gf_bench_tsuji_input(double zeta);

#endif
