# Sourced by lammps_compare.sh and lammps_collapse.sh (SCRIPT names the caller
# in messages): how both codes are run side by side.
#   NICE= (empty) runs both at normal priority (default: nice; CPU time is
#     measured either way, nice only stretches the wall time on a loaded machine).
#   PIN=CPU (default 0) runs both codes on that one core (taskset); PIN= (empty)
#     leaves them to the scheduler. The two cores of a virtual machine can differ
#     by a third in speed (workflows/bench/parallel_efficiency.sh), and a ratio
#     of two runs on different cores measures the cores.
# Sets NICE, PINNED (the prefix of every timed command) and LMP (the binary).
NICE=${NICE-nice}
PIN=${PIN-0}
PINNED=
if [ -n "$PIN" ] && command -v taskset >/dev/null 2>&1; then PINNED="taskset -c $PIN"; fi
LMP=$(command -v lmp || command -v lmp_serial || true)
[ -n "$LMP" ] || { echo "$SCRIPT: no LAMMPS binary (apt-get install -y lammps)" >&2; exit 1; }

# The law in LAMMPS terms, once the data file's .params are sourced: PAIR and
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

# Mobile grains (type 1) and glued ones (type 2, no glued-glued pairs) under
# the law of lammps_law; the glued grains still need `fix freeze`.
lammps_glued_pairs() {
    lammps_law
    cat <<EOS
group           mobile type 1
group           glued type 2
neighbor        $SKIN bin
neigh_modify    delay 0 every 1 check yes exclude type 2 2
pair_style      $PAIR
pair_coeff      * * $COEFF
EOS
}
