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
