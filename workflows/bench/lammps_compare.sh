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
# Observables (second part): both codes settle the SAME unsettled stack (the
# settled_bed scene's jittered body-centred stack before any step, no
# quench) for SETTLE_STEPS steps; the script then prints, for each code, the
# bed height h = 2 <y> (centre of mass) and the packing fraction of the bulk
# (grains centred in 3 D <= y <= h - 3 D over that slab), and their difference.
#
# Dry collapse (third part): workflows/bench/lammps_collapse.sh runs the
# column collapse from the same prepared t = 0 state in both codes and
# compares run-out, deposit height and throughput over COLLAPSE_SEEDS seeds.
#
# usage: lammps_compare.sh [N] [STEPS] [BUILD_DIR] [N_SETTLE] [SETTLE_STEPS]
#        (defaults 10000 3000 build-dem 2000 20000; N_SETTLE = 0 skips the observables)
# COLLAPSE_SEEDS=K (default 3) seeds for the dry collapse, 0 skips it (a few CPU minutes per seed).
# LMP_SKIN=M (metres) gives LAMMPS another neighbour skin than grainflow's (the
# thin skin of grainflow's near list, say: LAMMPS has no inner skin, so a
# settled bed is its best case with a thin one).
# GF_BED=PREFIX reuses (or keeps) the settled bed PREFIX_<N>.h5 (gf-bench-dem --bed).
# NICE=, PIN=CPU: how both codes run (workflows/bench/lammps_common.sh; default
# nice, both pinned to cpu0).
# needs: apt-get install -y lammps  (binary `lmp`)
set -eu
SCRIPT=lammps_compare
. "$(dirname "$0")/lammps_common.sh" # ROOT, NICE, PINNED, LMP
N=${1:-10000}
STEPS=${2:-3000}
BUILD=${3:-$ROOT/build-dem}
N_SETTLE=${4:-2000}
SETTLE_STEPS=${5:-20000}
lammps_bench "$BUILD" gf-bench-dem # BENCH, WORK

echo "== grainflow: settled bed, N = $N, $STEPS steps, 1 thread"
OMP_NUM_THREADS=1 $PINNED $NICE "$BENCH" --n "$N" --steps "$STEPS" --threads 1 --lammps-data "$WORK/bed.data" \
    ${GF_BED:+--bed "$GF_BED"} | tee "$WORK/gf.out"
GF_RATE=$(sed -n 's/.*s wall (speed-up [0-9.]*), \([0-9.e+]*\) per CPU-second.*/\1/p' "$WORK/gf.out" | tail -1)
. "$WORK/bed.data.params"

# LAMMPS input: data file $1, $2 steps, final positions to $3 (x y z radius)
lammps_input() {
    lammps_head "p f p" "$1"
    cat <<EOS
neighbor        ${LMP_SKIN:-$SKIN} bin
neigh_modify    delay 0 every 1 check yes
pair_style      gran/hooke/history $KN $KT $GAMMAN $GAMMAT $MU 0
pair_coeff      * *
fix             floor all wall/gran hooke/history $KN $KT $GAMMAN $GAMMAT $MU 0 yplane 0.0 NULL
fix             grav all gravity $G vector 0 -1 0
fix             int all nve/sphere
timestep        $DT
thermo          1000
run             $2
write_dump      all custom $3 x y z radius modify sort id
EOS
}
lammps_input "$WORK/bed.data" "$STEPS" "$WORK/lmp_bed.dump" > "$WORK/in.bed"
lammps_input "$WORK/bed.data" 0 "$WORK/lmp_setup.dump" > "$WORK/in.setup"
echo "== LAMMPS ($LMP): same bed, same law, 1 core"
CPU_SETUP=$(lammps_cpu "$WORK/in.setup" "$WORK/log.setup")
CPU_ALL=$(lammps_cpu "$WORK/in.bed" "$WORK/log.lammps")
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

# bed height h = 2 <y> and bulk packing fraction (centres in [3 D, h - 3 D]) of
# a file of "x y z radius" lines (LAMMPS dump headers skipped)
observe() {
    awk -v lx="$LX" -v lz="$LZ" -v d="$D" '
        NF == 4 && $1 + 0 == $1 { n++; y[n] = $2; r[n] = $4; sy += $2 }
        END {
            h = 2 * sy / n; lo = 3 * d; hi = h - 3 * d; v = 0
            for (i = 1; i <= n; i++) if (y[i] >= lo && y[i] <= hi) v += 4.18879020478639 * r[i] ^ 3
            printf "%.6f %.6f\n", h / d, v / (lx * lz * (hi - lo))
        }' "$1"
}
settle_observables() {
    echo "== observables: N = $N_SETTLE grains settle from the same unsettled stack for $SETTLE_STEPS steps in both codes"
    OMP_NUM_THREADS=1 $PINNED $NICE "$BENCH" --n "$N_SETTLE" --steps "$SETTLE_STEPS" --settle 0 --threads 1 \
        --lammps-data "$WORK/stack.data" --dump "$WORK/gf_settled.txt" | grep "thread(s)" | tee "$WORK/gf_settle.out"
    GF_SETTLE_RATE=$(sed -n 's/.*s wall (speed-up [0-9.]*), \([0-9.e+]*\) per CPU-second.*/\1/p' "$WORK/gf_settle.out")
    . "$WORK/stack.data.params"
    lammps_input "$WORK/stack.data" "$SETTLE_STEPS" "$WORK/lmp_settled.dump" > "$WORK/in.settle"
    lammps_input "$WORK/stack.data" 0 "$WORK/lmp_stack0.dump" > "$WORK/in.settle0"
    CPU_SETUP=$(lammps_cpu "$WORK/in.settle0" "$WORK/log.settle0")
    CPU_ALL=$(lammps_cpu "$WORK/in.settle" "$WORK/log.settle")
    grep -E "Loop time|CPU use" "$WORK/log.settle" || true
    LMP_SETTLE_RATE=$(awk -v n="$N_SETTLE" -v s="$SETTLE_STEPS" -v a="$CPU_ALL" -v b="$CPU_SETUP" 'BEGIN { printf "%.4e", n * s / (a - b) }')
    awk -v a="$GF_SETTLE_RATE" -v b="$LMP_SETTLE_RATE" 'BEGIN {
        printf "== settling, per CPU-second: grainflow %.4e, LAMMPS %.4e, ratio %.2f\n", a, b, a / b }'
    set -- $(observe "$WORK/gf_settled.txt") $(observe "$WORK/lmp_settled.dump")
    echo "== bed height h/D: grainflow $1, LAMMPS $3; bulk packing fraction: grainflow $2, LAMMPS $4"
    awk -v h1="$1" -v p1="$2" -v h2="$3" -v p2="$4" 'BEGIN {
        printf "== difference grainflow - LAMMPS: h %+.4f D (%+.2f %%), packing fraction %+.4f (%+.2f %%)\n",
               h1 - h2, 100 * (h1 - h2) / h2, p1 - p2, 100 * (p1 - p2) / p2 }'
}
[ "$N_SETTLE" -gt 0 ] && settle_observables

COLLAPSE_SEEDS=${COLLAPSE_SEEDS-3}
[ "$COLLAPSE_SEEDS" -gt 0 ] || exit 0
if [ -x "$BUILD/workflows/bench/gf-bench-collapse" ]; then
    NICE="$NICE" PIN="$PIN" "$ROOT/workflows/bench/lammps_collapse.sh" "$COLLAPSE_SEEDS" "$BUILD"
else
    echo "== dry collapse skipped: no $BUILD/workflows/bench/gf-bench-collapse (build it, or COLLAPSE_SEEDS=0)"
fi
