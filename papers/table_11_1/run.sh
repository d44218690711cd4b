#!/usr/bin/env bash
# Book Tables 11.1 and 11.2, reproduced: builds and runs papers/table_11_1 (after the README's set-up).
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target table_11_1 >/dev/null
build/papers/table_11_1
