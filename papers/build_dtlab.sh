# Sourced by the papers' run.sh scripts (from the repository root): sets $dtlab to the binary
# given with --dtlab, or builds build/ (BUILD_DIR) and takes its dtlab.
if [[ -z ${dtlab:-} ]]; then
  build="${BUILD_DIR:-build}"
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j"$(nproc)" --target dtlab_cli >/dev/null
  dtlab="$build/dtlab"
fi
