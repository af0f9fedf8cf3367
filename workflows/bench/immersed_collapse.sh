#!/bin/sh
# Cost of a full viscous immersed collapse in the unresolved tier (issue #4,
# "Speed"): configs/column_collapse_immersed.yaml (case A of Izard 2014 Table
# 5.1: a = 0.5, R0 = 16 D, Phi_i = 0.60, rho_p/rho_f = 8, eta_f = 1 Pa s)
# widened to WIDTH D along the periodic axis so that the column holds a few
# thousand grains, run to its end time (60 sqrt(D/g) ~ 7000 T_visq) on
# THREADS OpenMP threads with all output off (`grainflow bench`).
#
# Prints the bench line (grains, steps, wall time and its split between
# neighbour search, force, integration, fluid and coupling), the wall and CPU
# time of the whole process (preparation included, from /usr/bin/time), and
# the cost ratio against the seed's resolved run of case C (798 grains, D/10
# immersed boundary: 20 000 CPU hours on 40 cores, Izard 2014 §5.5).
#
# OpenMP threads wait passively (OMP_WAIT_POLICY=passive unless set): with
# the default active wait, a machine shared with one other busy process made
# this run 13x slower (474 s against 36 s for the preparation and 2500
# steps), the spinning thread holding the core the working one needed.
#
# usage: workflows/bench/immersed_collapse.sh [BUILD_DIR] [WIDTH_OVER_D] [THREADS]
#        (defaults: build, 24, 2)
set -eu
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
WIDTH=${2:-24}
THREADS=${3:-2}
GF=$BUILD/grainflow
[ -x "$GF" ] || { echo "immersed_collapse: build grainflow first ($GF)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "immersed_collapse: needs /usr/bin/time (apt-get install -y time)" >&2; exit 1; }
WORK=$(mktemp -d /tmp/gf_immersed_XXXXXX)
trap 'rm -rf "$WORK"' EXIT

echo "== $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "== immersed collapse, a = 0.5, W = $WIDTH D, $THREADS threads"
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
OMP_NUM_THREADS=$THREADS /usr/bin/time -f '%e %U %S' -o "$WORK/time" \
    "$GF" bench "$ROOT/configs/column_collapse_immersed.yaml" -o "$WORK" \
    --set scene.width_over_D="$WIDTH" | tee "$WORK/bench.out"
read -r WALL USR SYS < "$WORK/time"
echo "== load after: $(cut -d' ' -f1-3 /proc/loadavg)"
awk -v wall="$WALL" -v usr="$USR" -v sys="$SYS" 'BEGIN {
    cpu = usr + sys
    printf "whole run (preparation included): %.1f s wall, %.1f s CPU (%.2f CPU-hours)\n", wall, cpu, cpu / 3600
    printf "cost ratio against the seed resolved case C (20 000 CPU h): %.3g\n", 20000 * 3600 / cpu
}'
