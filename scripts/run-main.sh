#!/usr/bin/env bash
# The main job, from a fresh clone: installs the dependencies, builds the `dtlab` command, runs
# the kernel's self-check, then triangulates the bundled input (data/default.node: uniform
# points, a cocircular grid, exactly cocircular sets, a collinear run and duplicates) with every
# registered 2D variant, each with its exact verification report and statistics, and writes
# out/default.mesh.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
export CCACHE_DIR=${CCACHE_DIR:-$HOME/.cache/dtlab-ccache}
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target dtlab_cli
mkdir -p out
build/dtlab selfcheck
for algo in $(build/dtlab delaunay --list-algos | cut -f1); do
  echo
  echo "== dtlab delaunay data/default.node --algo $algo --verify --stats"
  build/dtlab delaunay data/default.node --algo "$algo" -o "out/default-$algo.mesh" --verify --stats
done
