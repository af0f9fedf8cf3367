#!/usr/bin/env bash
# Threads of the resolved tier (issue #32, "Speed"): the settling sphere of
# Izard 2014 §2.2.3 (rho_p/rho = 4, Ar = 800) through the grain-resolved
# fluid at D/dx = DX in a BOX x HEIGHT D box to END sqrt(D/g), run on 1 and
# on 2 OpenMP threads back to back (the machine's load drifts between two
# runs far apart), and again in the reverse order. Prints each run's wall
# and CPU seconds (the harness's clocks, terminal phase and early phase
# together) and whether the two printed histories (5 digits) agree; the
# bitwise check of 1 against 2 threads is test_resolved_restart.
#
# OpenMP threads wait passively: an actively spinning thread holds the core
# its partner needs on a shared machine.
#
# usage: workflows/bench/resolved_threads.sh [BUILD_DIR] [DX] [BOX] [HEIGHT] [END]
#        (defaults build 16 4 8 1)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
DX=${2:-16}
BOX=${3:-4}
HEIGHT=${4:-8}
END=${5:-1}
H=$BUILD/tests/resolved/test_resolved_settling_fast
WORK=$(mktemp -d /tmp/gf_resolved_threads_XXXXXX)
trap 'rm -rf "$WORK"' EXIT
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
echo "== $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "== D/dx $DX, box $BOX x $HEIGHT D, to t = $END sqrt(D/g) (early phase at D/dx 8 in 4 x 6 D)"
run() { # $1 threads, $2 tag
    "$H" dx="$DX" box="$BOX" height="$HEIGHT" end="$END" early_dx=8 early_box=4 early_height=6 threads="$1" \
        >"$WORK/$2.txt"
    grep -v '^resolved settling' "$WORK/$2.txt" | grep -v passed >"$WORK/$2.hist"
    sed -n 's/.*wall \([0-9.]*\) s, cpu \([0-9.]*\) s.*/\1 \2/p' "$WORK/$2.txt"
}
for order in "1 2" "2 1"; do
    for t in $order; do
        read -r wall cpu < <(run "$t" "t$t")
        printf 'threads %d: wall %7.1f s  cpu %7.1f s\n' "$t" "$wall" "$cpu"
    done
done
if cmp -s "$WORK/t1.hist" "$WORK/t2.hist"; then
    echo "histories on 1 and 2 threads: identical"
else
    echo "histories on 1 and 2 threads: DIFFER"
    exit 1
fi
