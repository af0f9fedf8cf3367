#!/usr/bin/env bash
# Long validations (ctest label `slow`): full dry-collapse sweep, avalanche, settling.
set -euo pipefail
cd "$(dirname "$0")/.."
bash workflows/deps.sh
bash workflows/build.sh
cd build
# Tests run two at a time on two cores: threads must not spin while waiting.
export OMP_WAIT_POLICY=passive
ctest --output-on-failure -L slow "$@"
