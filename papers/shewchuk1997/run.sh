#!/usr/bin/env bash
# Shewchuk 1997, predicate cost by stage, reproduced: builds and runs papers/shewchuk1997.
#   papers/shewchuk1997/run.sh            full run (about 20 s of CPU)
#   papers/shewchuk1997/run.sh --quick    the consistency checks only
# BUILD_DIR picks the build directory (default: build).
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${BUILD_DIR:-build}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" --target shewchuk1997 >/dev/null
"$build"/papers/shewchuk1997 "$@"
