#!/usr/bin/env bash
# Cost of the run manifests (postproc/rundir/gf_manifest.h): the time to
# verify a done run (reopen every netCDF file, read every byte for its CRC-32)
# against the time of the run itself, on a 4-run dry collapse campaign
# (R0 = 8 D, end_time 8 sqrt(D/g)) at two output intervals (1 and 0.1
# sqrt(D/g): 10x the bytes per run). `campaign --dry-run` verifies every done
# run and runs nothing, so its time over 4 is the verification of one run (a
# run pays the same once more when it writes its manifest). Files are in the
# page cache (just written): a cold read adds the disk's time.
# Results: docs/integrity.md.
#
# usage: workflows/bench/integrity_cost.sh [BUILD_DIR]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
G=$BUILD/grainflow
WORK=$(mktemp -d /tmp/gf_integrity_cost_XXXXXX)
trap 'rm -rf "$WORK"' EXIT
echo "== $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-9s %12s %12s %12s %14s %12s\n' interval bytes/run run_wall_s run_cpu_s verify_s/run verify/run
for interval in 1.0 0.1; do
  cat > "$WORK/c.yaml" <<YAML
name: cost
seed: 1
end_time: 8
scene: {name: column_collapse, column_length_over_D: 8, width_over_D: 3}
grains: {diameter_m: 7.6e-3, polydispersity: 0.05, density_kg_m3: 2500}
output: {interval_nd: $interval}
grid: {a: [1.0, 2.0], Phi_i: [0.58, 0.60], combine: product}
YAML
  rm -rf "$WORK/runs"
  run=$( { /usr/bin/time -f '%e %U %S' "$G" campaign "$WORK/c.yaml" -o "$WORK/runs" -j 1 -q --no-post >/dev/null; } 2>&1 | tail -1)
  ver=$( { /usr/bin/time -f '%e' "$G" campaign "$WORK/c.yaml" -o "$WORK/runs" --dry-run >/dev/null; } 2>&1 | tail -1)
  bytes=$(cat "$WORK"/runs/cost/*/manifest | awk '$1 == "file" {s += $3} END {print s / 4}')
  read -r wall user sys <<<"$run"
  awk -v i="$interval" -v b="$bytes" -v w="$wall" -v u="$user" -v s="$sys" -v v="$ver" 'BEGIN {
    printf "%-9s %12.0f %12.2f %12.2f %14.4f %11.2g%%\n", i, b, w / 4, (u + s) / 4, v / 4, 100 * (v / 4) / (w / 4) }'
done
echo "== load after: $(cut -d' ' -f1-3 /proc/loadavg)"
