#!/usr/bin/env bash
# First command of the README: dependencies, build, and the embedded default campaign.
# Ends with where the summary and figures are.
set -euo pipefail
cd "$(dirname "$0")/.."
bash workflows/deps.sh
bash workflows/build.sh
out=runs
args=("$@")
for ((i = 0; i < ${#args[@]}; ++i)); do
  case "${args[i]}" in
    -o|--output) out=${args[i+1]:-runs} ;;
    --output=*) out=${args[i]#--output=} ;;
  esac
done
./build/grainflow demo -o "$out" "$@"
dir="$out/demo"
echo
echo "demo: summary table  $dir/summary.csv (and summary.nc)"
if ls "$dir"/figures/*.svg > /dev/null 2>&1; then
  echo "demo: figures        $(cd "$dir/figures" && pwd)/ (open the .svg files in a browser):"
  for f in "$dir"/figures/*.svg; do echo "  $f"; done
fi
echo "demo: grains in ParaView: open $dir/<run>/particles.xmf (XDMF Reader; docs/output.md)"
