#!/usr/bin/env bash
# Runs every command of README.md's ```sh blocks as written, from a scratch
# copy of the repository layout (configs/, workflows/, ... linked, build/ the
# build tree, runs/ fresh), so that a README that drifts from the program
# fails a test. Trimmed to stay short, the same way for every line:
#   grainflow run|campaign|demo|bench   get --set end_time=0.2 (in sqrt(D/g))
#   grainflow campaign (quick mode)     runs only its first run (--index 0), unless
#                                       the line selects runs or only emits a job script
#   mpirun -n N ...                     runs with -n 1 (skipped without mpirun)
#   bash workflows/X.sh                 must exist and parse (bash -n); not run: these
#                                       install packages, build, run the demo or the
#                                       whole suite (CI and a fresh machine run them)
#   any other program                   runs as written; skipped when not installed here
# usage: readme_commands.sh SOURCE_DIR BUILD_DIR [quick|full]
set -uo pipefail
src="$1" bin="$2" mode="${3:-quick}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for entry in "$src"/*; do
  name="$(basename "$entry")"
  [ "$name" = build ] || [ "$name" = runs ] || ln -s "$entry" "$work/$name"
done
ln -s "$bin" "$work/build"
export OMP_WAIT_POLICY=passive OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# The commands: lines inside ```sh ... ``` blocks, comments and blank lines dropped.
commands=()
in_sh=0
while IFS= read -r line; do
  case "$line" in
    '```sh'*|'```bash'*|'```shell'*) in_sh=1; continue ;;
    '```'*) in_sh=0; continue ;;
  esac
  [ "$in_sh" = 1 ] || continue
  line="${line%%#*}"
  line="$(echo "$line" | sed -e 's/[[:space:]]*$//' -e 's/^[[:space:]]*//')"
  [ -n "$line" ] && commands+=("$line")
done <"$src/README.md"

# grainflow's subcommand in a word list ("" when none).
subcommand() {
  local seen=0 w
  for w in "$@"; do
    if [ $seen = 1 ]; then echo "$w"; return; fi
    case "$w" in */grainflow|grainflow) seen=1 ;; esac
  done
}
has_word() { local x="$1" w; shift; for w in "$@"; do [ "$w" = "$x" ] && return 0; done; return 1; }

n_run=0 n_skip=0 n_fail=0
for cmd in "${commands[@]}"; do
  read -r -a words <<<"$cmd"
  prog="${words[0]}"
  if [ "$prog" = bash ] || [ "$prog" = sh ]; then
    script="${words[1]:-}"
    if [ -f "$work/$script" ] && bash -n "$work/$script"; then
      echo "SKIP (exists, parses; installs, builds or runs the suite) $cmd"; n_skip=$((n_skip + 1))
    else
      echo "FAIL (missing or does not parse) $cmd"; n_fail=$((n_fail + 1))
    fi
    continue
  fi
  if [ "$prog" = mpirun ] || [ "$prog" = mpiexec ]; then
    if ! command -v "$prog" >/dev/null; then
      echo "SKIP ($prog not installed here) $cmd"; n_skip=$((n_skip + 1)); continue
    fi
    for i in "${!words[@]}"; do
      case "${words[$i]}" in -n|-np) words[$((i + 1))]=1 ;; esac
    done
  elif [ "${prog#./}" = "$prog" ] && ! command -v "$prog" >/dev/null; then
    echo "SKIP ($prog not installed here) $cmd"; n_skip=$((n_skip + 1)); continue
  fi
  sub="$(subcommand "${words[@]}")"
  case "$sub" in
    run|campaign|demo|bench) words+=(--set end_time=0.2) ;;
  esac
  if [ "$sub" = campaign ] && [ "$mode" = quick ] && ! has_word --emit "${words[@]}" &&
     ! has_word --index "${words[@]}" && ! has_word --only "${words[@]}"; then
    words+=(--index 0)
  fi
  start=$(date +%s)
  (cd "$work" && timeout 600 bash -c "${words[*]}") >"$work/out.txt" 2>&1 # as a shell would: globs expand
  rc=$?
  took=$(($(date +%s) - start))
  if [ $rc = 0 ]; then
    echo "ok   (${took} s) ${words[*]}"; n_run=$((n_run + 1))
  else
    echo "FAIL (exit $rc) ${words[*]}"; sed -e 's/^/     | /' "$work/out.txt" | tail -15; n_fail=$((n_fail + 1))
  fi
done
echo "README.md: ${#commands[@]} commands: $n_run ran, $n_skip skipped (reason given), $n_fail failed"
[ "$n_run" -ge 1 ] || { echo "no command ran: is README.md's \`\`\`sh block still there?"; exit 1; }
[ "$n_fail" = 0 ]
