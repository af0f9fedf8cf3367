#!/bin/sh
# Cost of the packing preparation (engine/particles/gf_packing.h) at several
# grain counts, one thread, process CPU time: one deposit of a square
# periodic bed at mu_prep 0.2 (the DEM cost alone) per size, for each build
# given, so that two builds (before and after a change) run side by side on
# the same machine at the same load. Results: docs/packing.md.
#
# usage: workflows/bench/packing.sh [BUILD_DIR...] (default: build)
#        SIZES="500 5000 20000" to choose the grain counts
set -eu
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
[ $# -gt 0 ] || set -- "$ROOT/build"
SIZES=${SIZES:-"500 5000 20000"}
for b in "$@"; do cmake --build "$b" --target gf-bench-packing >/dev/null; done
echo "== $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg)"
for n in $SIZES; do
  for b in "$@"; do
    printf '%s, %s grains: ' "$b" "$n"
    OMP_NUM_THREADS=1 "$b/workflows/bench/gf-bench-packing" --grains "$n" | head -1
  done
done
