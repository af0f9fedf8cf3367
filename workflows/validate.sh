#!/usr/bin/env bash
# Long validations (ctest label `slow`): full dry-collapse sweep, avalanche, settling.
set -euo pipefail
cd "$(dirname "$0")/.."
bash workflows/deps.sh
bash workflows/build.sh
cd build
ctest --output-on-failure -L slow "$@"
