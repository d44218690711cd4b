#!/usr/bin/env bash
# The main job, from a fresh clone: installs the dependencies, builds the `dtlab` command, then
# runs the kernel's self-check and triangulates the bundled input with its exact verification
# report and statistics.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
export CCACHE_DIR=${CCACHE_DIR:-$HOME/.cache/dtlab-ccache}
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target dtlab_cli
build/dtlab selfcheck
