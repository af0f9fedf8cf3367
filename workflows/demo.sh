#!/usr/bin/env bash
# First command of the README: dependencies, build, and the embedded default campaign.
set -euo pipefail
cd "$(dirname "$0")/.."
bash workflows/deps.sh
bash workflows/build.sh
./build/grainflow demo -o runs "$@"
