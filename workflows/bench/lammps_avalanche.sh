#!/bin/sh
# usage: lammps_avalanche.sh [ANGLES] [BUILD_DIR] [SEED]
#        (defaults "27.5" build 31; needs `apt-get install -y lammps`, binary `lmp`)
#
# The dry chute flows of test_avalanche (rows 7-8 of the seed, Izard 2014
# §2.1.3.3) side by side in grainflow and Debian LAMMPS, from the SAME t = 0
# state: gf-bench-avalanche prepares the avalanche scene (rough base of glued
# half-grains, bed 12 D on 6 D x 6 D, periodic in x and z, gravity tilted at
# t = 0) and writes it as a LAMMPS data file, mobile grains type 1 and glued
# type 2; grainflow then runs 200 sqrt(D/g) of spin-up and samples 50, one per
# sqrt(D/g), and LAMMPS runs the same steps from the same state, dumping the
# mobile grains at the same times. gf-bench-avalanche --measure-dump reads
# LAMMPS's snapshots with the same slab profiles and the seed's reading (I
# from the Bagnold amplitude with hydrostatic pressure, gf_measure_chute_bagnold),
# so both flows are measured by one definition.
#
# Law in LAMMPS: as lammps_collapse.sh (pair_style granular, hooke with
# `damping tsuji` at grainflow's 2 zeta sqrt(m* k_n), `limit_damping`,
# tangential linear_history, no rolling or twisting resistance; glued grains
# `fix freeze`, glued-glued pairs excluded), the floor y = 0 and the lid as
# `fix wall/gran` planes with the wall friction; gravity (sin theta, -cos theta, 0).
# The flow is chaotic: the two codes' trajectories part within a few
# sqrt(D/g) (their dashpots differ by construction: grainflow damps with the
# predicted end-of-step velocity, LAMMPS with the half-step one), so what is
# compared is the steady state's averages.
# CHUTE_ARGS: more gf-bench-avalanche options for both runs (e.g. "--spin 20 --avg 5 --eps 0.8");
# row 7's transient, test_avalanche's unsteady set-up, window by window:
#   CHUTE_ARGS="--bed 34 --spin 0 --avg 76 --every 0.5 --window 4" lammps_avalanche.sh 40 build 21
# NICE=, PIN=CPU: how both codes run (workflows/bench/lammps_common.sh).
set -eu
SCRIPT=lammps_avalanche
. "$(dirname "$0")/lammps_common.sh" # ROOT, NICE, PINNED, LMP
ANGLES=${1:-27.5}
BUILD=${2:-$ROOT/build}
SEED=${3:-31}
CHUTE_ARGS=${CHUTE_ARGS-}
lammps_bench "$BUILD" gf-bench-avalanche # BENCH, WORK

lammps_input() { # data file $1, snapshots to $2
    lammps_glued_input "p f p" "$1" <<EOS
fix             ywalls mobile wall/gran $WALL yplane 0.0 $TOP
fix             base glued freeze
fix             grav mobile gravity $G vector $GX_UNIT $GY_UNIT 0
fix             int mobile nve/sphere
thermo          1000000
timestep        $DT
run             $SPIN_STEPS
reset_timestep  0
dump            snap mobile custom $SAMPLE_STEPS $2 x y z vx vy vz radius
dump_modify     snap delay 1
run             $((SAMPLES * SAMPLE_STEPS))
EOS
}

for ANGLE in $ANGLES; do
    echo "== chute flow, $ANGLE deg, packing seed $SEED${CHUTE_ARGS:+, $CHUTE_ARGS}"
    OMP_NUM_THREADS=1 $PINNED $NICE "$BENCH" --angle "$ANGLE" --seed "$SEED" $CHUTE_ARGS --lammps-data "$WORK/c.data" |
        tee "$WORK/gf.out"
    lammps_params "$WORK/c.data.params"
    lammps_input "$WORK/c.data" "$WORK/snap.dump" > "$WORK/in.run"
    OMP_NUM_THREADS=1 /usr/bin/time -f "%U %S" -o "$WORK/time.out" $PINNED $NICE "$LMP" -in "$WORK/in.run" \
        -log "$WORK/log.run" -screen none
    "$BENCH" --angle "$ANGLE" --seed "$SEED" $CHUTE_ARGS --measure-dump "$WORK/snap.dump" | sed "s/ 0.0 s CPU/ $(awk '{ printf "%.1f", $1 + $2 }' "$WORK/time.out") s CPU/"
done
