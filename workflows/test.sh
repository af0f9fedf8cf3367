#!/usr/bin/env bash
# Second command of the README: dependencies, build, and the default test suite
# (every ctest test not labelled `slow`). Long validations: workflows/validate.sh.
set -euo pipefail
exec bash "$(dirname "$0")/ctest.sh" -LE slow -j2 "$@"
