#!/bin/sh
# usage: lammps_collapse.sh [SEEDS] [BUILD_DIR] [ASPECT] [R0_OVER_D]
#        (defaults 3 build 1 16; W = 3 D; needs `apt-get install -y lammps`, binary `lmp`)
#
# The dry column collapse side by side in grainflow and Debian LAMMPS, from the
# SAME t = 0 state: gf-bench-collapse prepares the column_collapse scene
# (packing, re-equilibration behind the gate, gate removed) and writes it as a
# LAMMPS data file, mobile grains type 1 and the glued grains of the rough base
# type 2; then both codes run the collapse with the same law, dt, skin and
# gravity for the same number of steps, grainflow until its scene's rest test
# (kinetic energy below 1e-4 m g D per grain after 2 T0) and LAMMPS for as
# many steps (the same physical end time; its final kinetic energy is printed
# against the same test). LAMMPS's flow need not have come to rest by then:
# an untimed second LAMMPS run (LMP_REST=0 skips it) repeats the same steps
# (LAMMPS is deterministic: the same trajectory) and goes on, up to as many
# steps again, until the same rest test holds (`fix halt` on the kinetic
# energy every 0.25 sqrt(D/g), grainflow's check interval), and its deposit is
# measured too.
#
# Law in LAMMPS: pair_style granular, hooke normal with `damping tsuji` and
# `limit_damping`, tangential linear_history (x_gamma_t = 0), no rolling or
# twisting resistance. Tsuji damping is alpha(e) sqrt(m* k_n): the data file's
# TSUJI is the e for which alpha(e) = 2 zeta, so every pair, glued partner and
# wall has grainflow's damping 2 zeta sqrt(m* k_n) (gran/hooke/history damps
# with m* gamma_n: right for the mean pair only, sqrt(2)x too much on a wall)
# and limit_damping is grainflow's clip of F_n at 0. Glued grains: `fix freeze`
# (no force, and m* = m_i for their partners, as grainflow) and no integrator,
# glued-glued pairs excluded from the neighbour lists (grainflow skips them
# too). Walls: the floor y = 0, back wall x = 0, end wall x = L and lid y = TOP
# as `fix wall/gran` planes with the same law and the wall friction; the gate
# is absent (the run starts at its removal). LMP_LAW=hooke runs
# gran/hooke/history instead (the law of lammps_compare.sh's bed; faster in
# LAMMPS, not grainflow's damping on glued partners and walls, no clip).
#
# Observables, with ONE definition applied to both codes' final grains (that of
# the scene's front_position / deposit_height, engine/scenes/gf_measure.c):
# bins of D from the back wall, a bin belongs to the deposit when its mobile
# grains' solid height sum V_i/(D W) >= D/4, one empty bin is bridged, the
# front R_inf is the far edge of the last bin of that contiguous deposit and
# H_inf the highest grain top over it; the farthest grain (x + r) is printed
# too. The collapse is chaotic: SEEDS prepared columns, means and sample
# standard deviations, and the difference of the means against twice its
# standard error sqrt((sd_gf^2 + sd_lmp^2)/SEEDS) ("within the scatter" or
# not). Throughput: particle-steps (all grains, glued included: both codes
# carry them) per CPU-second of the stepping loop, grainflow from
# CLOCK_PROCESS_CPUTIME_ID around gf_sim_advance, LAMMPS from its process CPU
# time less that of the same input with `run 0` (as lammps_compare.sh).
# NICE=, PIN=CPU: how both codes run (workflows/bench/lammps_common.sh; default
# nice, both pinned to cpu0).
set -eu
SCRIPT=lammps_collapse
. "$(dirname "$0")/lammps_common.sh" # ROOT, NICE, PINNED, LMP
LMP_REST=${LMP_REST-1}
REST_ENERGY=1e-4 # the scene's rest_energy: kinetic energy per mobile grain / (m g D)
SEEDS=${1:-3}
BUILD=${2:-$ROOT/build}
ASPECT=${3:-1}
LENGTH=${4:-16}
lammps_bench "$BUILD" gf-bench-collapse # BENCH, WORK

# LAMMPS input: data file $1, $2 steps, final grains to $3 ("x y z radius type")
lammps_input() {
    lammps_glued_input "f f p" "$1" <<EOS
fix             xwalls mobile wall/gran $WALL xplane 0.0 $L
fix             ywalls mobile wall/gran $WALL yplane 0.0 $TOP
fix             base glued freeze
fix             grav mobile gravity $G vector 0 -1 0
fix             int mobile nve/sphere
compute         ke mobile ke
compute         rot mobile erotate/sphere
variable        ke_mgd equal (c_ke+c_rot)/(mass(mobile)*$G*$D)
thermo_style    custom step v_ke_mgd
thermo          50000
timestep        $DT
run             $2
print           "KE_PER_GRAIN_MGD \${ke_mgd}"
write_dump      all custom $3 x y z radius type modify sort id
EOS
}
# the same run, then on until the rest test (untimed): $1 data, $2 steps, $3, $4 dumps at the end time and at rest
lammps_rest_input() {
    lammps_input "$1" "$2" "$3"
    cat <<EOS
fix             rest mobile halt $CHECK v_ke_mgd < $REST_ENERGY error continue
run             $2
variable        rest_step equal step
print           "REST_STEP \${rest_step} KE_PER_GRAIN_MGD \${ke_mgd}"
write_dump      all custom $4 x y z radius type modify sort id
EOS
}
# front/R0, height/R0 (the scene's definitions, see above) and farthest grain/R0
# of a file of "x y z radius type" lines (LAMMPS dump headers skipped)
deposit() {
    awk -v d="$D" -v w="$W" -v l="$L" -v r0="$R0" '
        BEGIN { nb = int(l / d); if (nb * d < l) nb++ }
        NF == 5 && $1 + 0 == $1 && $5 == 1 {
            b = $1 < 0 ? -1 : int($1 / d)
            if ($1 + $4 > far) far = $1 + $4
            if (b >= 0 && b < nb) {
                s[b] += 4.18879020478639 * $4 ^ 3 / (d * w)
                if ($2 + $4 > top[b]) top[b] = $2 + $4
            }
        }
        END {
            front = 0; h = 0; gap = 0; started = 0
            for (b = 0; b < nb; b++) {
                if (s[b] >= 0.25 * d) { started = 1; gap = 0; front = (b + 1) * d; if (top[b] > h) h = top[b] }
                else if (started && ++gap > 1) break
            }
            printf "%.6f %.6f %.6f\n", front / r0, h / r0, far / r0
        }' "$1"
}

echo "== dry collapse, a = $ASPECT, R0 = $LENGTH D, W = 3 D, $SEEDS seeds; LAMMPS law: ${LMP_LAW:-granular}"
: > "$WORK/table"
s=1
while [ "$s" -le "$SEEDS" ]; do
    OMP_NUM_THREADS=1 $PINNED $NICE "$BENCH" --seed "$s" --aspect "$ASPECT" --length "$LENGTH" --width 3 \
        --lammps-data "$WORK/c.data" --dump "$WORK/gf.txt" | tee "$WORK/gf.out"
    lammps_params "$WORK/c.data.params"
    STEPS=$(sed -n 's/.* grains (.*), \([0-9]*\) steps to t.*/\1/p' "$WORK/gf.out")
    GF_CPU=$(sed -n 's/.* sqrt(D\/g), \([0-9.]*\) s CPU.*/\1/p' "$WORK/gf.out")
    lammps_input "$WORK/c.data" "$STEPS" "$WORK/lmp.dump" > "$WORK/in.run"
    lammps_input "$WORK/c.data" 0 "$WORK/lmp0.dump" > "$WORK/in.setup"
    CPU_SETUP=$(lammps_cpu "$WORK/in.setup" "$WORK/log.setup")
    CPU_ALL=$(lammps_cpu "$WORK/in.run" "$WORK/log.run")
    LMP_CPU=$(awk -v a="$CPU_ALL" -v b="$CPU_SETUP" 'BEGIN { printf "%.3f", a - b }')
    LMP_KE=$(sed -n 's/^KE_PER_GRAIN_MGD \([0-9.eE+-]*\).*/\1/p' "$WORK/log.run")
    REST="- - - - -"
    if [ "$LMP_REST" != 0 ]; then
        CHECK=$(awk -v d="$D" -v g="$G" -v dt="$DT" 'BEGIN { c = 0.25 * sqrt(d / g) / dt; n = int(c); print (n < c ? n + 1 : n) }')
        lammps_rest_input "$WORK/c.data" "$STEPS" "$WORK/lmp_end.dump" "$WORK/lmp_rest.dump" > "$WORK/in.rest"
        OMP_NUM_THREADS=1 $PINNED $NICE "$LMP" -in "$WORK/in.rest" -log "$WORK/log.rest" -screen none
        REST="$(deposit "$WORK/lmp_rest.dump") $(sed -n 's/^REST_STEP \([0-9]*\) KE_PER_GRAIN_MGD \([0-9.eE+-]*\).*/\1 \2/p' "$WORK/log.rest")"
    fi
    set -- $(deposit "$WORK/gf.txt") $(deposit "$WORK/lmp.dump") $REST
    echo "$s $1 $2 $3 $4 $5 $6 $GF_CPU $LMP_CPU $N $STEPS $LMP_KE $7 $8 $9 ${10} ${11}" >> "$WORK/table"
    printf "== seed %d, %d steps: front R/R0 grainflow %.4f, LAMMPS %.4f; height H/R0 %.4f, %.4f; farthest grain %.3f, %.3f R0; CPU %s s, %s s; LAMMPS final KE %s m g D per grain\n" \
        "$s" "$STEPS" "$1" "$4" "$2" "$5" "$3" "$6" "$GF_CPU" "$LMP_CPU" "$LMP_KE"
    [ "$LMP_REST" = 0 ] || awk -v s="$s" -v f="$7" -v h="$8" -v st="${10}" -v ke="${11}" -v dt="$DT" -v d="$D" -v g="$G" -v r="$REST_ENERGY" 'BEGIN {
        printf "== seed %d, LAMMPS on to its own rest: %s at t = %.2f sqrt(D/g) (KE %.3g m g D per grain): front %.4f R0, height %.4f R0\n",
               s, ke < r ? "at rest" : "NOT at rest", st * dt / sqrt(d / g), ke, f, h }'
    s=$((s + 1))
done
awk '
    function stats(k,   i, m, v) {
        m = 0; for (i = 1; i <= n; i++) m += c[i, k]; m /= n
        v = 0; for (i = 1; i <= n; i++) v += (c[i, k] - m) ^ 2
        mean[k] = m; sd[k] = n > 1 ? sqrt(v / (n - 1)) : 0
    }
    function compare(name, a, b,   d, se) {
        stats(a); stats(b); d = mean[a] - mean[b]; se = sqrt((sd[a] ^ 2 + sd[b] ^ 2) / n)
        printf "== %s: grainflow %.4f +- %.4f, LAMMPS %.4f +- %.4f (mean +- seed sd); difference %+.4f (%+.1f %%), " \
               "2 x its standard error %.4f: %s\n", name, mean[a], sd[a], mean[b], sd[b], d,
               100 * d / mean[b], 2 * se, (d < 0 ? -d : d) <= 2 * se ? "within the scatter" : "BEYOND the scatter"
    }
    { n++; for (k = 1; k <= NF; k++) c[n, k] = $k; ps += $10 * $11; gf += $8; lmp += $9 }
    END {
        compare("run-out R_inf/R0", 2, 5)
        compare("height H_inf/R0", 3, 6)
        compare("farthest grain /R0", 4, 7)
        if (c[1, 13] != "-") {
            compare("run-out R_inf/R0, LAMMPS at its own rest", 2, 13)
            compare("height H_inf/R0, LAMMPS at its own rest", 3, 14)
        }
        printf "== throughput, particle-steps per CPU-second: grainflow %.4e, LAMMPS %.4e, ratio %.2f\n",
               ps / gf, ps / lmp, lmp / gf
    }' "$WORK/table"
