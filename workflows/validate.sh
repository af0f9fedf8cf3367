#!/usr/bin/env bash
# Long validations (ctest label `slow`): full dry-collapse sweep, avalanche, settling.
set -euo pipefail
exec bash "$(dirname "$0")/ctest.sh" -L slow "$@"
