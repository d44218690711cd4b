#!/usr/bin/env bash
# Book Tables 6.2-6.4 (§6.4): the surface sigma(x, y) = (x, y, 3 sin 2x cos 2y) over the disc of
# radius 3 under six metric maps; our np, ne beside the book's. Usage (from the repository root):
#   papers/table_6_2/run.sh [--gap EPS] [--cells N]
set -euo pipefail
build="${BUILD_DIR:-build}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" --target table_6_2 >/dev/null
"$build/papers/table_6_2" "$@"
