#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build (DTLAB_BUILD_FUZZ=ON): bash scripts/run-fuzz.sh BUILD_DIR.
# scripts/run-tests.sh calls it on its clang ASan + UBSan build. Each target starts from its
# corpus (fuzz/corpus/NAME, copied: the corpus in the tree is not changed); one target per core
# at a time (each is single-threaded); a target's output is printed when it ends, and a failing
# one prints its log's tail and fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?usage: run-fuzz.sh BUILD_DIR}
jobs=$(nproc)
fuzz_seconds=${DTLAB_FUZZ_SECONDS:-60}
# Like RapidCheck's, the fuzz runs are reproducible by default: a fixed seed, a fixed number of
# runs per target (about a minute each here, under ASan), no corpus reload, and no comparison
# tracing (its table holds compared values, heap addresses among them, so with address space
# randomisation the mutations, and with them the inputs tried, differed between two runs of the
# same build). A slower machine stops at the time cap, on a prefix of the same sequence.
# DTLAB_FUZZ_SEED=random explores: a fresh seed, every libFuzzer feature, DTLAB_FUZZ_SECONDS each.
fuzz_seed=${DTLAB_FUZZ_SEED:-20261123}
declare -A fuzz_runs=([constrained2d_fuzz]=7000 [delaunay2d_fuzz]=10000 [delaunay3d_fuzz]=4000
                      [mesh_readers_fuzz]=100000 [mesh_formats_fuzz]=50000 [predicates_fuzz]=75000
                      [mesh2d_fuzz]=1500 [mesh3d_fuzz]=2000 [cli_fuzz]=20000)
if [ "$fuzz_seed" = random ]; then
  echo "fuzz: exploring, ${fuzz_seconds} s each, ${jobs} at a time"
else
  echo "fuzz: seed ${fuzz_seed}, fixed run counts, ${jobs} at a time"
fi
fuzz_one() {
  local target=$1 name corpus work rc=0
  name=$(basename "$target")
  corpus="fuzz/corpus/${name%_fuzz}"
  work=$(mktemp -d)
  [ -d "$corpus" ] && cp -r "$corpus"/. "$work"/
  local mode=(-max_total_time="$fuzz_seconds")
  if [ "$fuzz_seed" != random ]; then
    mode=(-seed="$fuzz_seed" -runs="${fuzz_runs[$name]:-10000}" -max_total_time=300 -reload=0 -use_cmp=0)
  fi
  "$target" "${mode[@]}" -timeout=60 -print_final_stats=1 "$work" >"$work.log" 2>&1 || rc=$?
  echo "-- $name"
  grep -E "^(stat::number_of_executed_units|stat::average_exec_per_sec|Done)" "$work.log" || true
  if [ "$rc" -ne 0 ]; then tail -n 60 "$work.log"; echo "fuzz target $name failed"; fi
  rm -rf "$work" "$work.log"
  return "$rc"
}
# A new target starts as soon as any running one ends (wait -n), so a long target does not hold
# a core idle behind it.
running=0
fuzz_failed=0
for target in "$build"/fuzz/*_fuzz; do
  [ -x "$target" ] || continue
  if [ "$running" -ge "$jobs" ]; then
    wait -n || fuzz_failed=1
    running=$((running - 1))
  fi
  fuzz_one "$target" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
  wait -n || fuzz_failed=1
  running=$((running - 1))
done
[ "$fuzz_failed" -eq 0 ] || exit 1
