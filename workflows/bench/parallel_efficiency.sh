#!/bin/sh
# Two-core scaling of the DEM core on the settled bed, measured so that an
# unequal pair of cores does not pass for poor scaling (or for good).
#
# On a virtual machine the two cores need not run at the same speed: one may
# share its physical core with another tenant. Measured here with `taskset`,
# single-thread runs of the same build on cpu0 and cpu1 differed by up to a
# third, in phases of minutes (docs/notes/benchmarks.md). The speed-up of two
# threads over "one thread" then depends on which core the one thread got.
# This script times, in each round and back to back:
#   R0: one thread pinned to cpu0, R1: one thread pinned to cpu1,
#   R2: two threads on cpu0 and cpu1,
# all in particle-steps per second of wall time, and prints
#   speed-up over the faster core  R2 / max(R0, R1),
#   parallel efficiency            R2 / (R0 + R1)
# (efficiency 0.9 is the 1.8x of two equal cores; with unequal cores the
# speed-up over the faster one cannot exceed 1 + min/max), and, measured
# just before R2, the time a cache line takes from one core to the other
# (gf-core-latency, one-way, ns): the grains at the boundary between the two
# threads' chunks are exchanged through the caches at every step, so a large
# latency lowers the efficiency of a small bed whatever the code does.
#
# usage: parallel_efficiency.sh [N] [STEPS] [ROUNDS] [BUILD_DIR]
#        (defaults 10000 3000 3 build)
# GF_BED=PREFIX reuses (or keeps) the settled bed PREFIX_<N>.h5 (default /tmp/gfbed).
# GF_CPUS=A,B pins to cpus A and B instead of 0 and 1 (where cpu0 and cpu1 are
# two hardware threads of one core, pick two cores: lscpu -e).
# OMP_WAIT_POLICY is left to the caller (unset: libgomp spins, then sleeps).
set -eu
N=${1:-10000}
STEPS=${2:-3000}
ROUNDS=${3:-3}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${4:-build}
case $BUILD in /*) ;; *) BUILD=$ROOT/$BUILD ;; esac
BENCH=$BUILD/workflows/bench/gf-bench-dem
LATENCY=$BUILD/workflows/bench/gf-core-latency
BED=${GF_BED:-/tmp/gfbed}
CPUS=${GF_CPUS:-0,1}
CPU_A=${CPUS%,*}
CPU_B=${CPUS#*,}
[ "$CPU_A" != "$CPU_B" ] || { echo "parallel_efficiency.sh: GF_CPUS=$CPUS: name two different cpus, as A,B" >&2; exit 2; }
for exe in "$BENCH" "$LATENCY"; do
    [ -x "$exe" ] || { echo "parallel_efficiency.sh: $exe not built (cmake --build $BUILD --target gf-bench-dem gf-core-latency)" >&2; exit 1; }
done
[ "$(nproc)" -ge 2 ] || { echo "parallel_efficiency.sh: needs 2 cores, this machine has $(nproc)" >&2; exit 1; }

rate() { # cpus threads -> particle-steps per wall second
    taskset -c "$1" "$BENCH" --n "$N" --steps "$STEPS" --threads "$2" --bed "$BED" 2>&1 |
        sed -n 's/.* \([0-9.e+]*\) particle-steps\/s wall.*/\1/p' | tail -1
}

rate "$CPU_A" 1 >/dev/null # settles and keeps the bed on the first call
echo "N = $N, $STEPS steps, $ROUNDS rounds, cpus $CPU_A and $CPU_B, OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-(unset)}"
printf '%-6s %-11s %-11s %-11s %-9s %-9s %-10s %s\n' round "R0_cpu$CPU_A" "R1_cpu$CPU_B" R2_both max/min speed-up efficiency line_ns
r=1
while [ "$r" -le "$ROUNDS" ]; do
    R0=$(rate "$CPU_A" 1)
    R1=$(rate "$CPU_B" 1)
    LAT=$("$LATENCY" "$CPU_A" "$CPU_B" | sed -n 's/.*one-way \([0-9.]*\) ns.*/\1/p')
    R2=$(rate "$CPU_A,$CPU_B" 2)
    awk -v r="$r" -v a="$R0" -v b="$R1" -v c="$R2" -v l="$LAT" 'BEGIN {
        hi = a > b ? a : b; lo = a > b ? b : a;
        printf "%-6d %-11.4g %-11.4g %-11.4g %-9.3f %-9.3f %-10.3f %s\n", r, a, b, c, hi / lo, c / hi, c / (a + b), l }'
    r=$((r + 1))
done
