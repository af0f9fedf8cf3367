#!/usr/bin/env bash
# Dependencies, build, then ctest with the arguments given (the label choice of
# workflows/test.sh or workflows/validate.sh, then the caller's own options).
set -euo pipefail
cd "$(dirname "$0")/.."
bash workflows/deps.sh
bash workflows/build.sh
cd build
# Tests run two at a time on two cores: threads must not spin while waiting.
export OMP_WAIT_POLICY=passive
ctest --output-on-failure "$@"
