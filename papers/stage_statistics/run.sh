#!/usr/bin/env bash
# Predicate stages inside the 2D Delaunay variants: builds and runs papers/stage_statistics.
#   papers/stage_statistics/run.sh            n = 10^5 (a few seconds per variant)
#   papers/stage_statistics/run.sh --large    n = 10^5 and 10^6
#   papers/stage_statistics/run.sh --quick    n = 2000, the consistency checks only
# BUILD_DIR picks the build directory (default: build).
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${BUILD_DIR:-build}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" --target stage_statistics >/dev/null
"$build"/papers/stage_statistics "$@"
