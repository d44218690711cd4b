#!/usr/bin/env bash
# The main job, from a fresh clone: installs the dependencies, builds the `dtlab` command, runs
# the kernel's self-check, then triangulates the bundled input (data/default.node: uniform
# points, a cocircular grid, exactly cocircular sets, a collinear run and duplicates) with every
# registered 2D variant, each with its exact verification report and statistics; then every 3D
# variant on a generated integer grid (cospherical everywhere), every constrained method on the
# bundled planar graph (data/square_with_hole.poly) and on Schönhardt's prism
# (data/schonhardt.off), likewise verified. Meshes go to out/. It ends with one line per run
# (verified or not, elements, time; also in out/summary.txt) and exits 1 if any run failed.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
export CCACHE_DIR=${CCACHE_DIR:-$HOME/.cache/dtlab-ccache}
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target dtlab_cli
mkdir -p out
build/dtlab selfcheck

# run_case LABEL UNIT COMMAND...: runs COMMAND (its output shown as it comes), then keeps one
# summary line: verified (an "ok:" line and exit 0) or not, the elements and the seconds of its
# JSON line. A failed run does not stop the job; the summary says which.
summary=()
failures=0
run_case() {
  local label=$1 unit=$2 rc=0 log status elements seconds
  shift 2
  echo
  echo "== dtlab ${*:2}"
  log=$(mktemp)
  "$@" | tee "$log" || rc=$?
  local json
  json=$(grep '^{' "$log" | tail -n 1 || true)
  # "elements", or (2D constrain) "triangles".
  elements=$(grep -o '"elements":[0-9]*' <<<"$json" | head -n 1 | cut -d: -f2 || true)
  [[ -n "$elements" ]] || elements=$(grep -o '"triangles":[0-9]*' <<<"$json" | head -n 1 | cut -d: -f2 || true)
  # "seconds": a number, or an object of phases with its "total".
  seconds=$(grep -o '"seconds":[0-9.eE+-]*' <<<"$json" | head -n 1 | cut -d: -f2 || true)
  [[ -n "$seconds" ]] || seconds=$(grep -o '"total":[0-9.eE+-]*' <<<"$json" | tail -n 1 | cut -d: -f2 || true)
  if [[ $rc -eq 0 ]] && grep -q '^ok:' "$log"; then
    status=verified
  else
    status="FAILED (exit $rc)"
    failures=$((failures + 1))
  fi
  rm -f "$log"
  local time='? s'
  [[ -z "$seconds" ]] || time=$(LC_ALL=C awk -v s="$seconds" 'BEGIN { if (s < 0.01) printf "%.3f ms", s * 1000; else printf "%.3f s", s }')
  summary+=("$(LC_ALL=C printf '%-18s %-52s %10s %-10s %10s' "$status" "$label" "${elements:-?}" "$unit" "$time")")
}
for algo in $(build/dtlab delaunay --list-algos | cut -f1); do
  run_case "delaunay 2D $algo, data/default.node" triangles \
    build/dtlab delaunay data/default.node --algo "$algo" -o "out/default-$algo.mesh" --verify --stats
done
for algo in $(build/dtlab delaunay --list-algos --dim 3 | cut -f1); do
  run_case "delaunay 3D $algo, 20000-point grid" tetrahedra \
    build/dtlab delaunay --dim 3 --random 20000 --distribution grid --algo "$algo" --threads 2 \
    -o "out/grid3d-$algo.mesh" --verify --stats
done
for method in $(build/dtlab constrain --list-methods | sed -n '/^2D/,/^3D/p' | grep -P '\t' | cut -f1); do
  run_case "constrain 2D $method, data/square_with_hole.poly" triangles \
    build/dtlab constrain data/square_with_hole.poly --method "$method" -o "out/square-$method.mesh" --verify --stats
done
for method in $(build/dtlab constrain --list-methods | sed -n '/^3D/,$p' | grep -P '\t' | cut -f1); do
  run_case "constrain 3D $method, data/schonhardt.off" tetrahedra \
    build/dtlab constrain data/schonhardt.off --method "$method" -o "out/schonhardt-$method.mesh" --verify --stats
done

{
  echo
  echo "== Summary: ${#summary[@]} runs, $(( ${#summary[@]} - failures )) verified (meshes in out/)"
  printf '%-18s %-52s %21s %10s\n' status run elements time
  printf '%s\n' "${summary[@]}"
} | tee out/summary.txt
[[ $failures -eq 0 ]]
