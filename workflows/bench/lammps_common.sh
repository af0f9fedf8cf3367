# Sourced by the lammps_*.sh scripts (SCRIPT names the caller in messages):
# where the benchmark programs are and how both codes are run side by side.
#   NICE= (empty) runs both at normal priority (default: nice; CPU time is
#     measured either way, nice only stretches the wall time on a loaded machine).
#   PIN=CPU (default 0) runs both codes on that one core (taskset); PIN= (empty)
#     leaves them to the scheduler. The two cores of a virtual machine can differ
#     by a third in speed (workflows/bench/parallel_efficiency.sh), and a ratio
#     of two runs on different cores measures the cores.
# Sets ROOT (the tree, whose build/ is the default build folder), NICE, PINNED
# (the prefix of every timed command) and LMP (the binary).
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
NICE=${NICE-nice}
PIN=${PIN-0}
PINNED=
if [ -n "$PIN" ] && command -v taskset >/dev/null 2>&1; then PINNED="taskset -c $PIN"; fi
LMP=$(command -v lmp || command -v lmp_serial || true)
[ -n "$LMP" ] || { echo "$SCRIPT: no LAMMPS binary (apt-get install -y lammps)" >&2; exit 1; }

# lammps_bench BUILD PROGRAM: sets BENCH, the benchmark PROGRAM of the build
# folder BUILD (it must be built), and WORK, a scratch folder removed on exit.
lammps_bench() {
    BENCH=$1/workflows/bench/$2
    [ -x "$BENCH" ] || { echo "$SCRIPT: build $2 first ($BENCH)" >&2; exit 1; }
    WORK=$(mktemp -d "/tmp/gf_${SCRIPT}_XXXXXX")
    trap 'rm -rf "$WORK"' EXIT
}

# The law in LAMMPS terms, from the data file's .params: PAIR and
# COEFF (pair_style $PAIR, pair_coeff * * $COEFF) and WALL (fix wall/gran $WALL).
# Default: pair granular, hooke with `damping tsuji` at grainflow's
# 2 zeta sqrt(m* k_n) on every pair and wall (TSUJI, gf_lammps_data.h) and
# `limit_damping` (grainflow's clip of F_n at 0), tangential linear_history.
# LMP_LAW=hooke: gran/hooke/history (the bed's law in lammps_compare.sh),
# m* gamma_n damping, right for the mean pair only, and unclipped.
lammps_law() {
    if [ "${LMP_LAW:-granular}" = hooke ]; then
        PAIR="gran/hooke/history $KN $KT $GAMMAN $GAMMAT $MU 0"
        WALL="hooke/history $KN $KT $GAMMAN $GAMMAT $MUW 0"
        COEFF=""
    else
        PAIR=granular
        WALL="granular hooke $KN $TSUJI tangential linear_history $KT 0 $MUW damping tsuji limit_damping"
        COEFF="hooke $KN $TSUJI tangential linear_history $KT 0 $MU damping tsuji limit_damping"
    fi
}

# lammps_params FILE: the assignments of a data file's .params FILE, then the
# law in LAMMPS terms (lammps_law).
lammps_params() {
    . "$1"
    lammps_law
}

# The head of an input: SI units, spheres, boundary $1 (e.g. "p f p"), data file $2.
lammps_head() {
    cat <<EOS
units           si
atom_style      sphere
atom_modify     map array
boundary        $1
comm_modify     vel yes
read_data       $2
EOS
}

# An input with mobile grains (type 1) and glued ones (type 2, no glued-glued
# pairs) under the law of lammps_params: the head (lammps_head: boundary $1,
# data file $2), the pairs, then the scene's own commands read from stdin (the
# glued grains still need `fix freeze` there).
lammps_glued_input() {
    lammps_head "$1" "$2"
    cat <<EOS
group           mobile type 1
group           glued type 2
neighbor        $SKIN bin
neigh_modify    delay 0 every 1 check yes exclude type 2 2
pair_style      $PAIR
pair_coeff      * * $COEFF
EOS
    cat
}

# CPU seconds (user + system) of one LAMMPS run of input $1, log $2, on one
# thread as PINNED and NICE say.
lammps_cpu() {
    OMP_NUM_THREADS=1 /usr/bin/time -f "%U %S" -o "$WORK/time.out" $PINNED $NICE "$LMP" -in "$1" -log "$2" -screen none
    awk '{ printf "%.3f", $1 + $2 }' "$WORK/time.out"
}
