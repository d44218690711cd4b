#!/usr/bin/env bash
# The closed adaptive loop, reproduced: builds and runs papers/adapt_loop (after the README's
# set-up), writes papers/adapt_loop/loop.tsv and the convergence plot convergence.png.
# Options go to the program (--cycles C; --quick for the small run CTest makes).
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target adapt_loop >/dev/null
build/papers/adapt_loop --tsv papers/adapt_loop/loop.tsv "$@"
py=/usr/bin/python3; [ -x "$py" ] || py=python3  # Debian's, with python3-matplotlib
"$py" papers/adapt_loop/plot.py papers/adapt_loop/loop.tsv papers/adapt_loop/convergence.png
echo "wrote papers/adapt_loop/loop.tsv and papers/adapt_loop/convergence.png"
