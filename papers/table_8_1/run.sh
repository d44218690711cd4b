#!/usr/bin/env bash
# Book Table 8.1, reproduced: builds and runs papers/table_8_1 (after the README's set-up).
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target table_8_1 >/dev/null
build/papers/table_8_1
