#!/bin/sh
# Throughput of two builds of grainflow on the same settled bed, timed in
# alternation (A, B, A, B, ...) so that a host whose load drifts over minutes
# weighs on both alike: for a change that must not cost speed (a
# restructuring, a new layer around the step). Each run is gf-bench-dem,
# one thread, in particle-steps per CPU-second of the stepping loop (the
# machine may be shared: CPU time measures the code, wall time the
# neighbours' load); the two builds must also print the same state hash
# (the same bits). Prints each round, then the median of each build and the
# ratio B/A of the medians.
#
# usage: before_after.sh BUILD_A BUILD_B [N] [STEPS] [ROUNDS] [THREADS]
#        (defaults 10000 3000 5 1)
# GF_BED=PREFIX reuses (or keeps) the settled bed PREFIX_<N>.h5 (default /tmp/gfbed).
set -eu
A=${1:?usage: before_after.sh BUILD_A BUILD_B [N] [STEPS] [ROUNDS] [THREADS]}
B=${2:?usage: before_after.sh BUILD_A BUILD_B [N] [STEPS] [ROUNDS] [THREADS]}
N=${3:-10000}
STEPS=${4:-3000}
ROUNDS=${5:-5}
THREADS=${6:-1}
BED=${GF_BED:-/tmp/gfbed}
WORK=$(mktemp -d /tmp/gf_before_after_XXXXXX)
trap 'rm -rf "$WORK"' EXIT
for build in "$A" "$B"; do
    [ -x "$build/workflows/bench/gf-bench-dem" ] || { echo "before_after: no $build/workflows/bench/gf-bench-dem" >&2; exit 1; }
done
run() { # build, label: one timing, appended to $WORK/label
    OMP_NUM_THREADS=$THREADS "$1/workflows/bench/gf-bench-dem" --n "$N" --steps "$STEPS" --threads "$THREADS" \
        --bed "$BED" > "$WORK/out" 2>&1 || { cat "$WORK/out" >&2; exit 1; }
    rate=$(sed -n 's/.*, \([0-9.e+]*\) per CPU-second.*/\1/p' "$WORK/out" | tail -1)
    hash=$(sed -n 's/.*state hash \([0-9a-f]*\).*/\1/p' "$WORK/out" | tail -1)
    echo "$rate" >> "$WORK/$2"
    echo "$hash" >> "$WORK/hash_$2"
    printf '%s %s per CPU-second, state hash %s\n' "$2" "$rate" "$hash"
}
r=1
while [ "$r" -le "$ROUNDS" ]; do
    echo "== round $r: N = $N, $STEPS steps, $THREADS thread(s)"
    run "$A" A
    run "$B" B
    r=$((r + 1))
done
median() { sort -g "$1" | awk '{v[NR] = $1} END {printf "%.4g\n", (NR % 2) ? v[(NR + 1) / 2] : 0.5 * (v[NR / 2] + v[NR / 2 + 1])}'; }
MA=$(median "$WORK/A")
MB=$(median "$WORK/B")
echo "A = $A: median $MA per CPU-second (range $(sort -g "$WORK/A" | head -1)-$(sort -g "$WORK/A" | tail -1))"
echo "B = $B: median $MB per CPU-second (range $(sort -g "$WORK/B" | head -1)-$(sort -g "$WORK/B" | tail -1))"
awk -v a="$MA" -v b="$MB" 'BEGIN {printf "ratio B/A of the medians: %.3f\n", b / a}'
if [ "$(sort -u "$WORK/hash_A" "$WORK/hash_B" | wc -l)" -ne 1 ]; then
    echo "state hashes differ: the two builds do not compute the same bits" >&2
    exit 2
fi
echo "same state hash in every run"
