#!/bin/sh
# usage: lammps_silo.sh [ORIFICES] [BUILD_DIR] [WIDTH] [FILL] [TRANSIENT] [WINDOW]
#        (defaults "4 6 8" build 25 25.4 5 20; needs `apt-get install -y lammps`, binary `lmp`)
#
# The silo discharge of Djouwe Meffeja (2012) §3.3 side by side in grainflow
# and Debian LAMMPS, from the SAME t = 0 state: gf-bench-silo builds the scene
# silo (free-poured column of WIDTH d x WIDTH d x FILL d, 10 sqrt(d/g) of
# settling on the closed floor, orifice D x D opened) and writes it as a LAMMPS
# data file; then both codes discharge it with the same law, dt, skin and
# gravity for TRANSIENT + WINDOW sqrt(d/g), and Q is the number of grains that
# left (centre below y = -d) during the window over its length.
#
# Floor: grainflow's plane with a hole whose rim the grains roll off
# (gf_sim_set_wall_hole); LAMMPS's `fix wall/gran/region` on each of the four
# blocks of floor around the orifice (`side out`: the grains live outside
# them), whose edges are the same rim (one region made of their union, `side
# out`, lost every grain at the first step in LAMMPS 29 Sep 2021). Side walls and lid: `fix wall/gran`
# planes. Law: lammps_common.sh (pair granular, hooke + damping tsuji at
# grainflow's 2 zeta sqrt(m* k_n), limit_damping, tangential linear_history).
# The grains that leave: grainflow reinjects them on its lattice at 45 d
# (thesis §3.3), LAMMPS deletes them (`fix evaporate`): over a short window the
# column stays above the height where Q saturates (H0 = 2-2.5 d measured in
# both codes at D = 6 d, docs/silo.md; the thesis gives 5.7 d). At large
# orifices keep the window short (18 d: 3 sqrt(d/g) after 2): the comparison is
# then of the settled column, before grainflow's reinjected grains replace it.
# Throughput: grain-steps per CPU-second of the stepping, grainflow's from
# CLOCK_PROCESS_CPUTIME_ID, LAMMPS's from its process CPU time less that of
# the same input with `run 0`.
set -eu
SCRIPT=lammps_silo
. "$(dirname "$0")/lammps_common.sh" # ROOT, NICE, PINNED, LMP
ORIFICES=${1:-4 6 8}
BUILD=${2:-$ROOT/build}
WIDTH=${3:-25}
FILL=${4:-25.4}
TRANSIENT=${5:-5}
WINDOW=${6:-20}
lammps_bench "$BUILD" gf-bench-silo # BENCH, WORK

# LAMMPS input: data $1, $2 transient steps, $3 window steps
lammps_input() {
    lammps_glued_input "f f f" "$1" <<EOS
region          b1 block 0 $OX0 -$D 0 0 $LZB side out units box
region          b2 block $OX1 $LXB -$D 0 0 $LZB side out units box
region          b3 block $OX0 $OX1 -$D 0 0 $OZ0 side out units box
region          b4 block $OX0 $OX1 -$D 0 $OZ1 $LZB side out units box
region          below block INF INF INF $EXIT_Y INF INF units box
fix             floor1 mobile wall/gran/region $WALL region b1
fix             floor2 mobile wall/gran/region $WALL region b2
fix             floor3 mobile wall/gran/region $WALL region b3
fix             floor4 mobile wall/gran/region $WALL region b4
fix             xwalls mobile wall/gran $WALL xplane 0.0 $LXB
fix             zwalls mobile wall/gran $WALL zplane 0.0 $LZB
fix             lid mobile wall/gran $WALL yplane NULL $HB
fix             grav mobile gravity $G vector 0 -1 0
fix             int mobile nve/sphere
fix             out mobile evaporate 100 100000 below 4711
variable        n equal count(mobile)
thermo_style    custom step v_n
thermo          100000
timestep        $DT
run             $2
variable        n0 equal \${n}
print           "N_START \${n0}"
run             $3
print           "N_END \${n}"
EOS
}

echo "== silo ${WIDTH} d x ${WIDTH} d, fill ${FILL} d, orifices $ORIFICES d; window ${WINDOW} sqrt(d/g) after ${TRANSIENT}; LAMMPS law: ${LMP_LAW:-granular}"
for o in $ORIFICES; do
    OMP_NUM_THREADS=1 $PINNED $NICE "$BENCH" --orifice "$o" --width "$WIDTH" --fill "$FILL" --transient "$TRANSIENT" \
        --window "$WINDOW" --lammps-data "$WORK/s.data" | tee "$WORK/gf.out"
    lammps_params "$WORK/s.data.params"
    GF_Q=$(sed -n 's/.*Q = \([0-9.e+]*\) grains\/s.*/\1/p' "$WORK/gf.out")
    GF_CPU=$(sed -n 's/.* steps in \([0-9.]*\) s CPU.*/\1/p' "$WORK/gf.out")
    GF_STEPS=$(sed -n 's/.*; \([0-9]*\) steps in.*/\1/p' "$WORK/gf.out")
    set -- $(awk -v t="$TRANSIENT" -v w="$WINDOW" -v d="$D" -v g="$G" -v dt="$DT" 'BEGIN {
        s = sqrt(d / g) / dt; a = int(t * s / 100 + 0.999999) * 100; b = int(w * s / 100 + 0.999999) * 100; print a, b }')
    TR_STEPS=$1 WIN_STEPS=$2
    lammps_input "$WORK/s.data" "$TR_STEPS" "$WIN_STEPS" > "$WORK/in.run"
    lammps_input "$WORK/s.data" 0 0 > "$WORK/in.setup"
    CPU_SETUP=$(lammps_cpu "$WORK/in.setup" "$WORK/log.setup")
    CPU_ALL=$(lammps_cpu "$WORK/in.run" "$WORK/log.run")
    N0=$(sed -n 's/^N_START \([0-9]*\).*/\1/p' "$WORK/log.run")
    N1=$(sed -n 's/^N_END \([0-9]*\).*/\1/p' "$WORK/log.run")
    awk -v o="$o" -v n0="$N0" -v n1="$N1" -v w="$WIN_STEPS" -v dt="$DT" -v d="$D" -v g="$G" -v gq="$GF_Q" \
        -v gc="$GF_CPU" -v gs="$GF_STEPS" -v ca="$CPU_ALL" -v cs="$CPU_SETUP" -v tr="$TR_STEPS" -v n="$N" 'BEGIN {
        q = (n0 - n1) / (w * dt); tg = sqrt(d / g); lc = ca - cs
        printf "== D = %s d: Q grainflow %.5g grains/s (%.4g sqrt(g/d)), LAMMPS %.5g (%.4g, %d grains left), " \
               "difference %+.1f %% (Poisson 1 sd of the LAMMPS count %.1f %%); CPU %.1f s, %.1f s, " \
               "us per grain-step %.4f, %.4f (LAMMPS/grainflow %.2f)\n", o, gq, gq * tg, q, q * tg, n0 - n1,
               100 * (gq / q - 1), 100 / sqrt(n0 - n1), gc, lc, 1e6 * gc / (n * gs), 1e6 * lc / (n * (tr + w)),
               (lc / (tr + w)) / (gc / gs) }'
done
