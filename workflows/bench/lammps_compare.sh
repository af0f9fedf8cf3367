#!/bin/sh
# Side-by-side throughput of grainflow's DEM core and Debian LAMMPS on the SAME
# settled bed (workflows/bench/gf_bench_dem.c writes it as a LAMMPS data file):
# same N, positions, radii, density, box (periodic x and z, floor at y = 0),
# gravity, law (linear spring-dashpot + tangential spring with Coulomb cap and
# history: LAMMPS pair gran/hooke/history with the same k_n, gamma_n (per unit
# effective mass, LAMMPS convention), k_t, mu, gamma_t = 0), time step and
# neighbour skin (rebuild when a grain moved more than skin/2: LAMMPS
# `neigh_modify delay 0 every 1 check yes`), one core each.
#
# Throughput is compared per CPU-second of the stepping loop (the machine is
# shared: wall time measures the neighbours' load, CPU time measures us):
# grainflow from CLOCK_PROCESS_CPUTIME_ID around gf_sim_advance, LAMMPS from
# the CPU time of the process (/usr/bin/time, user + system) less that of the
# same input with `run 0` (MPI start, reading the data, first neighbour build).
# Its "Loop time" x reported CPU use is printed too; that CPU use has one
# decimal, too coarse when a loaded machine gives LAMMPS a few per cent.
#
# usage: lammps_compare.sh [N] [STEPS] [BUILD_DIR]    (defaults 10000 3000 build-dem)
# NICE= (empty) runs both at normal priority (default: nice; CPU time is
# measured either way, nice only stretches the wall time on a loaded machine).
# GF_BED=PREFIX reuses (or keeps) the settled bed PREFIX_<N>.h5 (gf-bench-dem --bed).
# needs: apt-get install -y lammps  (binary `lmp`)
set -eu
NICE=${NICE-nice}
N=${1:-10000}
STEPS=${2:-3000}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${3:-$ROOT/build-dem}
LMP=$(command -v lmp || command -v lmp_serial || true)
[ -n "$LMP" ] || { echo "lammps_compare: no LAMMPS binary (apt-get install -y lammps)" >&2; exit 1; }
BENCH=$BUILD/workflows/bench/gf-bench-dem
[ -x "$BENCH" ] || { echo "lammps_compare: build gf-bench-dem first ($BENCH)" >&2; exit 1; }
WORK=$(mktemp -d /tmp/gf_lammps_XXXXXX)
trap 'rm -rf "$WORK"' EXIT

echo "== grainflow: settled bed, N = $N, $STEPS steps, 1 thread"
OMP_NUM_THREADS=1 $NICE "$BENCH" --n "$N" --steps "$STEPS" --threads 1 --lammps-data "$WORK/bed.data" \
    ${GF_BED:+--bed "$GF_BED"} | tee "$WORK/gf.out"
GF_RATE=$(sed -n 's/.*s wall (speed-up [0-9.]*), \([0-9.e+]*\) per CPU-second.*/\1/p' "$WORK/gf.out" | tail -1)
. "$WORK/bed.data.params"

cat > "$WORK/in.bed" <<EOS
units           si
atom_style      sphere
atom_modify     map array
boundary        p f p
comm_modify     vel yes
read_data       $WORK/bed.data
neighbor        $SKIN bin
neigh_modify    delay 0 every 1 check yes
pair_style      gran/hooke/history $KN $KT $GAMMAN $GAMMAT $MU 0
pair_coeff      * *
fix             floor all wall/gran hooke/history $KN $KT $GAMMAN $GAMMAT $MU 0 yplane 0.0 NULL
fix             grav all gravity $G vector 0 -1 0
fix             int all nve/sphere
timestep        $DT
thermo          1000
run             $STEPS
EOS
sed "s/^run .*/run             0/" "$WORK/in.bed" > "$WORK/in.setup"
lmp_cpu() { # CPU seconds (user + system) of one LAMMPS run of input $1
    OMP_NUM_THREADS=1 /usr/bin/time -f "%U %S" -o "$WORK/time.out" $NICE "$LMP" -in "$1" -log "$2" -screen none
    awk '{ printf "%.3f", $1 + $2 }' "$WORK/time.out"
}
echo "== LAMMPS ($LMP): same bed, same law, 1 core"
CPU_SETUP=$(lmp_cpu "$WORK/in.setup" "$WORK/log.setup")
CPU_ALL=$(lmp_cpu "$WORK/in.bed" "$WORK/log.lammps")
grep -E "Loop time|CPU use|Pair  |Neigh |Modify|Comm  " "$WORK/log.lammps" || true
LOOP=$(sed -n 's/^Loop time of \([0-9.e+-]*\) on.*/\1/p' "$WORK/log.lammps")
CPU=$(sed -n 's/^\([0-9.]*\)% CPU use.*/\1/p' "$WORK/log.lammps")
[ -n "$CPU" ] || CPU=100
LMP_RATE=$(awk -v n="$N" -v s="$STEPS" -v a="$CPU_ALL" -v b="$CPU_SETUP" 'BEGIN { printf "%.4e", n * s / (a - b) }')
LMP_LOOP=$(awk -v n="$N" -v s="$STEPS" -v t="$LOOP" -v c="$CPU" 'BEGIN { printf "%.4e", n * s / (t * c / 100) }')
LMP_WALL=$(awk -v n="$N" -v s="$STEPS" -v t="$LOOP" 'BEGIN { printf "%.4e", n * s / t }')
echo "== LAMMPS CPU: $CPU_ALL s in all, $CPU_SETUP s for the set-up (run 0)"
echo "== throughput per CPU-second: grainflow $GF_RATE, LAMMPS $LMP_RATE (LAMMPS loop time x CPU use: $LMP_LOOP; wall: $LMP_WALL, CPU use $CPU %)"
awk -v a="$GF_RATE" -v b="$LMP_RATE" 'BEGIN { printf "== ratio grainflow / LAMMPS = %.2f (target >= 2)\n", a / b }'
