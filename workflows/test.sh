#!/usr/bin/env bash
# Second command of the README: dependencies, build, and the default test suite
# (every ctest test not labelled `slow`). Long validations: workflows/validate.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
bash workflows/deps.sh
bash workflows/build.sh
cd build
# Tests run two at a time on two cores: threads must not spin while waiting.
export OMP_WAIT_POLICY=passive
ctest --output-on-failure -LE slow -j2 "$@"
