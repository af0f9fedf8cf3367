#!/usr/bin/env bash
# Configures and builds grainflow into build/ (Release, OpenMP, MPI task farm).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
