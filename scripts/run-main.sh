#!/usr/bin/env bash
# The main job, from a fresh clone: installs the dependencies, builds the `dtlab` command, runs
# the kernel's self-check, then triangulates the bundled input (data/default.node: uniform
# points, a cocircular grid, exactly cocircular sets, a collinear run and duplicates) with every
# registered 2D variant, each with its exact verification report and statistics; then every 3D
# variant on a generated integer grid (cospherical everywhere), every constrained method on the
# bundled planar graph (data/square_with_hole.poly) and on Schönhardt's prism
# (data/schonhardt.off), likewise verified. Meshes go to out/.
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
for algo in $(build/dtlab delaunay --list-algos --dim 3 | cut -f1); do
  echo
  echo "== dtlab delaunay --dim 3 --random 20000 --distribution grid --algo $algo --verify --stats"
  build/dtlab delaunay --dim 3 --random 20000 --distribution grid --algo "$algo" --threads 2 \
    -o "out/grid3d-$algo.mesh" --verify --stats
done
for method in $(build/dtlab constrain --list-methods | sed -n '/^2D/,/^3D/p' | grep -P '\t' | cut -f1); do
  echo
  echo "== dtlab constrain data/square_with_hole.poly --method $method --verify --stats"
  build/dtlab constrain data/square_with_hole.poly --method "$method" -o "out/square-$method.mesh" --verify --stats
done
for method in $(build/dtlab constrain --list-methods | sed -n '/^3D/,$p' | grep -P '\t' | cut -f1); do
  echo
  echo "== dtlab constrain data/schonhardt.off --method $method --verify --stats"
  build/dtlab constrain data/schonhardt.off --method "$method" -o "out/schonhardt-$method.mesh" --verify --stats
done
