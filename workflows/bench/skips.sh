#!/bin/sh
# Side-by-side measurement of the skips of issue #6 (engine/sim/gf_skips.c)
# and of the pressure-based contact stiffness (engine/gf_stiffness_rule.h):
# speed-up (process CPU time, best of the repeats, off/on pairs run back to
# back) and the change in each scene's observable. Results: docs/notes/benchmarks.md.
#
# usage: workflows/bench/skips.sh [BUILD_DIR] [REPEAT] [CASE...]
# docs/notes/benchmarks.md: `skips.sh build 3 tangential_gas tangential_bed output`
# and `skips.sh build 1 lubrication stiffness` (4 seeds each, ~4 CPU min).
#        (defaults: build, 2, every case: tangential_gas tangential_bed
#         lubrication output stiffness)
set -eu
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
REPEAT=${2:-2}
[ $# -gt 2 ] && shift 2 || set --
cmake --build "$BUILD" --target gf-bench-skips >/dev/null
ARGS="--repeat $REPEAT"
for c in "$@"; do ARGS="$ARGS --case $c"; done
echo "== $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg)"
# shellcheck disable=SC2086
OMP_NUM_THREADS=1 "$BUILD/workflows/bench/gf-bench-skips" $ARGS
echo "== load after: $(cut -d' ' -f1-3 /proc/loadavg)"
