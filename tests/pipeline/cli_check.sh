#!/usr/bin/env bash
# grainflow check on several files, its cost estimate and warnings, and the
# warning of run and check when the realised Phi_i misses the one asked, and
# `run --resume` after a SIGTERM.
# usage: cli_check.sh GRAINFLOW SOURCE_DIR
set -uo pipefail
g="$1" src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
ok() { echo "ok: $*"; }
cd "$work"

# several files: each checked, all headers printed, exit 0
"$g" check "$src"/configs/*.yaml --brief >out.txt 2>err.txt; rc=$?
n_cfg=$(ls "$src"/configs/*.yaml | wc -l)
n_head=$(grep -c '^# .*: campaign .*, scene ' out.txt)
[ $rc = 0 ] && [ "$n_head" = "$n_cfg" ] && grep -q "^# $n_cfg files checked, 0 invalid" out.txt &&
  ok "check configs/*.yaml: $n_head files" || fail "check configs/*.yaml: exit $rc, $n_head of $n_cfg headers"
# one bad file among good ones: the others still checked, exit 2, the error located
"$g" check "$src/configs/demo.yaml" "$src/tests/pipeline/corpus/unknown_key.yaml" "$src/tests/pipeline/data/bc_ok.yaml" \
  >out.txt 2>err.txt; rc=$?
[ $rc = 2 ] && grep -q 'unknown_key.yaml:3:3: unknown key' err.txt && grep -q 'campaign cli_ok' out.txt &&
  grep -q '^# 3 files checked, 1 invalid' out.txt &&
  ok "check with one invalid file: exit 2, file:line:col, the others checked" ||
  fail "check with one invalid file: exit $rc; $(cat err.txt)"

# method: continuum is priced by its grid: a = 0.5, R0 = 16 D, cell D/2 gives
# (2 + 2.5 a) R0 / (D/2) = 104 by (1.3 H0 + 2 D) / (D/2) = 25 cells, and
# 40 sqrt(D/g) / (0.1 (D/2) / sqrt(g H0)) = 2263 steps (engine/continuum/gf_continuum_collapse.c)
"$g" check "$src/configs/column_collapse_methods.yaml" --brief --set grid.a=0.5 >out.txt 2>err.txt
grep -q '^ *2600 cells, 2.26e+03 steps, CPU [0-9:]* (continuum)' out.txt && grep -q '[0-9]* grains, 2e+05 steps' out.txt &&
  ok "continuum runs priced by cells and steps, DEM runs by grains" || fail "continuum cost: $(grep -E 'cells|grains' out.txt)"

# a scene key the grid overrides is said, at the key
"$g" check "$src/configs/column_collapse_dry.yaml" --brief --set scene.aspect_ratio=2 >out.txt 2>err.txt
grep -q -- '--set scene.aspect_ratio=2: warning: scene.aspect_ratio is overridden by the group a that 4 of the 4 runs set' err.txt &&
  ok "scene.aspect_ratio under a grid over a: warned" || fail "no override warning: $(cat err.txt)"

# the cost: grains, steps, CPU, output per run and campaign; steps = end_time sqrt(D/g) / dt
"$g" check "$src/tests/pipeline/data/phi_loose_column.yaml" >out.txt 2>err.txt
grep -q '^# cost: [0-9]* grains, [0-9.e+]* steps, CPU [0-9:]*, output [0-9.]* [kMG]*B' out.txt &&
  grep -q '^# cost of campaign phi_loose: 1 runs' out.txt && ok "cost lines" || fail "cost lines: $(grep cost out.txt)"
steps=$(sed -n 's/^# cost: [0-9]* grains, \([0-9.e+]*\) steps.*/\1/p' out.txt)
dt=$(sed -n 's/.*dt = \([0-9.e+-]*\) s.*/\1/p' out.txt)
tg=$(sed -n 's/.*sqrt(D\/g) = \([0-9.e+-]*\) s.*/\1/p' out.txt)
awk -v s="$steps" -v dt="$dt" -v tg="$tg" 'BEGIN { e = 0.2 * tg / dt; exit !(s >= 0.99 * e && s <= 1.01 * e + 1) }' &&
  ok "steps $steps = 0.2 sqrt(D/g) / dt" || fail "steps $steps, dt $dt, sqrt(D/g) $tg"

# warnings: a long run, output every step; still valid (exit 0)
"$g" check "$src/tests/pipeline/data/phi_loose_column.yaml" --set end_time=1e7 --set output.interval_nd=0.0002 \
  >out.txt 2>err.txt; rc=$?
[ $rc = 0 ] && grep -q 'warning: run 0 ([0-9a-f]*) needs about [0-9:]* of CPU' err.txt &&
  grep -q 'warning: run 0 ([0-9a-f]*) writes about [0-9.]* [TGP]B' err.txt &&
  grep -q 'warning: run 0 ([0-9a-f]*) writes a record every [0-9.]* steps' err.txt &&
  grep -q 'warning: campaign phi_loose needs about' err.txt && ok "cost warnings" || fail "cost warnings: $(cat err.txt)"
"$g" check "$src/tests/pipeline/data/phi_loose_column.yaml" >out.txt 2>err.txt
[ ! -s err.txt ] && ok "no warning for a short run" || fail "warnings for a short run: $(cat err.txt)"

# the resolved tier priced by its grid: L 50 D x the fluid's 30 D x W 2 D at D/dx 10 is 500 x 300 x 20
# cells; the loose column's settling through the fluid before t = 0 (sediment_T_visq T_visq) is priced too
"$g" check "$src/configs/column_collapse_immersed.yaml" --set fluid.model=resolved --set fluid.d_over_dx=10 \
  --set scene.width_over_D=2 --set scene.domain_length_over_R0=3.125 --set end_time=10 \
  --set scene.sediment_T_visq=8000 >out.txt 2>err.txt
pre=$(sed -n 's/^# cost: .* steps (and \([0-9.e+]*\) before t = 0).*/\1/p' out.txt)
tv=$(sed -n 's/.*T_visq = \([0-9.e+-]*\) s.*/\1/p' out.txt)
dt=$(sed -n 's/.*dt = \([0-9.e+-]*\) s.*/\1/p' out.txt)
grep -q '^# cost: .*, 3e+06 fluid cells x [0-9.e+]* fluid steps, CPU [0-9:]* (DEM + fluid)' out.txt &&
  awk -v p="$pre" -v tv="$tv" -v dt="$dt" 'BEGIN { e = 8000 * tv / dt; exit !(p >= 0.99 * e && p <= 1.01 * e) }' &&
  ok "resolved cost: 3e+06 cells, $pre steps before t = 0 (8000 T_visq / dt)" ||
  fail "resolved cost: $(grep -E '^# (cost|time|contact)' out.txt)"

# Phi_i: run warns exactly when the realised packing (the file's phi_initial_local)
# is further from the asked one than phi_tolerance; check -o says the same afterwards
"$g" run "$src/tests/pipeline/data/phi_loose_column.yaml" -o runs >out.txt 2>err.txt || fail "run failed: $(cat err.txt)"
# the grain estimate against the grains the run held
built=$(sed -n 's/^run [0-9a-f]* done: \([0-9]*\) grains.*/\1/p' out.txt)
"$g" check "$src/tests/pipeline/data/phi_loose_column.yaml" >est.txt 2>/dev/null
est=$(sed -n 's/^# cost: \([0-9]*\) grains.*/\1/p' est.txt)
awk -v b="$built" -v e="$est" 'BEGIN { exit !(b > 0 && e >= 0.9 * b && e <= 1.1 * b) }' &&
  ok "grain estimate $est for $built grains built (10 %)" || fail "grain estimate $est for $built grains built"
nc=$(ls runs/phi_loose/*/diagnostics.nc)
realised=$(ncdump -h "$nc" | sed -n 's/.*:phi_initial_local = \([0-9.e+-]*\) ;.*/\1/p')
beyond=$(awk -v r="$realised" 'BEGIN { d = r - 0.58; if (d < 0) d = -d; print (d > 0.005) }')
if [ "$beyond" = 1 ]; then
  grep -q "warning: run [0-9a-f]* starts at Phi_i = ${realised:0:5}[0-9]* (interior, at t = 0), .* from the 0.58 asked: more than phi_tolerance = 0.005" err.txt &&
    ok "run warns: realised $realised, asked 0.58" || fail "run: realised $realised, no warning: $(cat err.txt)"
  "$g" check "$src/tests/pipeline/data/phi_loose_column.yaml" -o runs --brief >out.txt 2>err.txt
  grep -q "warning: run 0 ([0-9a-f]*) started at Phi_i = ${realised:0:5}" err.txt &&
    ok "check -o warns about the run already done" || fail "check -o: $(cat err.txt)"
else
  ! grep -q "starts at Phi_i" err.txt && ok "run: realised $realised within 0.005, no warning" ||
    fail "run warned although realised $realised is within tolerance"
fi

# run --resume: a run stopped by SIGTERM continues from its checkpoint; a done run is left as it is.
# A frictional gas of 2200 grains, ~4 s of CPU to the end: stopped after 1.5 s.
cat >gas.yaml <<'YAML'
name: cli_resume
scene: {name: elastic_gas, n_grains: 2200, box_over_D: 16}
grains: {diameter_m: 5e-3, density_kg_m3: 2500, polydispersity: 0.05}
contact: {restitution: 0.8, friction: 0.5}
end_time: 120
output: {interval_nd: 0.25, particles: false}
YAML
OMP_NUM_THREADS=1 timeout -s TERM 1.5 "$g" run gas.yaml -o runs -q >out.txt 2>err.txt
rdir=$(ls -d runs/cli_resume/*/)
grep -q '^failed: interrupted: run interrupted at t = .*; checkpoint written' "$rdir/status" && [ -f "$rdir/checkpoint.h5" ] &&
  ok "run stopped by SIGTERM: checkpoint written" || fail "run under SIGTERM: $(cat "$rdir/status" 2>/dev/null)"
OMP_NUM_THREADS=1 "$g" run gas.yaml -o runs --resume >out.txt 2>err.txt; rc=$?
[ $rc = 0 ] && grep -q 'done: 2200 grains, .* (continued from t = [0-9.]* s)' out.txt && [ "$(cat "$rdir/status")" = done ] &&
  ok "run --resume continues from the checkpoint" || fail "run --resume: exit $rc; $(cat out.txt err.txt)"
"$g" run gas.yaml -o runs --resume >out.txt 2>err.txt; rc=$?
[ $rc = 0 ] && grep -q 'already done' out.txt && ok "run --resume on a done run: left as it is" ||
  fail "run --resume on a done run: exit $rc; $(cat out.txt err.txt)"
exit $((fails > 0))
