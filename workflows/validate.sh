#!/usr/bin/env bash
# Long validations (ctest label `slow`): full dry-collapse sweep, avalanche, settling.
# The multi-hour ones (label `long`, hours of CPU each) are left out: workflows/ctest.sh -L long.
set -euo pipefail
exec bash "$(dirname "$0")/ctest.sh" -L slow -LE long "$@"
