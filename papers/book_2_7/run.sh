#!/usr/bin/env bash
# Book §2.7 / §7.13 Table 7.2 (George & Borouchaki 1998), construction rate against n: our 3D
# Delaunay rate beside the book's, whose triangulation share is derived from its "Del" column.
#   papers/book_2_7/run.sh             the six sizes of Table 7.2, median of 5 runs each (about 2 min)
#   papers/book_2_7/run.sh --quick     examples 1-3 only, with the checks (CTest runs this)
#   papers/book_2_7/run.sh --runs 5    more runs per size
#   papers/book_2_7/run.sh --dtlab P   use the dtlab binary P instead of building one
# BUILD_DIR picks the build directory (default: build). Prints a Markdown report on stdout;
# exits non-zero if a run fails or a check in the README's list does not hold.
set -euo pipefail
cd "$(dirname "$0")/../.."
book_table=papers/book_2_7/table_7_2.tsv

quick=0
runs=5
dtlab=""
while (($#)); do
  case "$1" in
    --quick) quick=1 ;;
    --runs) runs="$2"; shift ;;
    --dtlab) dtlab="$2"; shift ;;
    *) echo "usage: $0 [--quick] [--runs K] [--dtlab PATH]" >&2; exit 2 ;;
  esac
  shift
done
source papers/build_dtlab.sh

fail() { echo "book_2_7: FAILED: $*" >&2; exit 1; }
field() { sed -n "s/.*\"$1\":\([^,}]*\).*/\1/p" <<<"$2"; }

# Our point count per book example. Examples 1-4: the book's np. Examples 5-6: the book's np
# would give about 6.75 tetrahedra per point here against its 5.9 (uniform points in a cube
# against a mesh; see the README), so n is chosen to give the book's element count instead.
examples=(1 2 3 4 5 6)
our_n=(1014 36252 62495 214184 455000 1289000)
((quick)) && examples=(1 2 3)

# The book's figures: the transcription must agree with itself (v = ne * 60 / t up to the
# book's rounding of v to thousands).
awk -F'\t' '!/^#/ && $1 != "example" {
  rate = $4 * 60 / $5
  if (rate < $6 * 0.99 || rate > $6 * 1.01) { print "example " $1 ": ne*60/t = " rate " but v = " $6 >"/dev/stderr"; bad = 1 }
} END { exit bad }' "$book_table" || fail "$book_table is not consistent with itself"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
threads_for() { [[ $1 == parallel ]] && nproc || echo 1; }

median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int(NR / 2) + 1] }'; }

# One run; leaves its stdout and stderr in $work/out and $work/err, returns dtlab's exit status.
run_once() {
  local algo="$1" n="$2" extra=()
  ((quick)) && extra=(--verify)
  "$dtlab" delaunay --dim 3 --random "$n" --seed 1 --algo "$algo" --threads "$(threads_for "$algo")" \
    --stats "${extra[@]}" >"$work/out" 2>"$work/err"
}

# $runs runs of one variant at one size, checked; appends "algo example n elements seconds rss"
# (seconds and rss: the median over the runs, the upper one of an even count) to $work/ours.
measure() {
  local algo="$1" example="$2" n="$3" times=() sizes=() elements=""
  for ((r = 0; r < runs; ++r)); do
    run_once "$algo" "$n" || fail "$algo, n=$n: dtlab exited with an error: $(cat "$work/err")"
    local json e s pm rss
    json="$(tail -n 1 "$work/out")"
    e="$(field elements "$json")"; s="$(field seconds "$json")"
    pm="$(field elements_per_minute "$json")"; rss="$(field peak_rss_mb "$json")"
    [[ -n $e && -n $s && -n $pm && -n $rss ]] || fail "$algo, n=$n: no statistics line: $json"
    ((quick)) && { grep -q '^ok' "$work/out" || fail "$algo, n=$n: $(head -n 1 "$work/out")"; }
    # Uniform points: about 24*pi^2/35 = 6.77 tetrahedra per point in the limit, fewer near the
    # hull of a small sample; outside [5n, 7n] the triangulation is not the one of these points.
    ((e >= 5 * n && e <= 7 * n)) || fail "$algo, n=$n: $e tetrahedra, outside [5n, 7n]"
    [[ -z $elements || $e == "$elements" ]] || fail "$algo, n=$n: $e tetrahedra, $elements in an earlier run"
    awk -v e="$e" -v s="$s" -v pm="$pm" 'BEGIN { exit !(s > 0 && (pm - e * 60 / s) ^ 2 <= (1e-4 * pm) ^ 2) }' ||
      fail "$algo, n=$n: elements_per_minute $pm is not elements*60/seconds ($e, $s)"
    elements="$e"
    times+=("$s") sizes+=("$rss")
  done
  echo "$algo $example $n $elements $(median "${times[@]}") $(median "${sizes[@]}")" >>"$work/ours"
}

# The variants: incremental first, then every other registered one that runs. Those still
# being written refuse with "not built yet" and are listed as skipped.
variants=(incremental)
skipped=()
while IFS=$'\t' read -r name _; do
  [[ -z $name || $name == incremental ]] && continue
  if run_once "$name" "${our_n[0]}"; then
    variants+=("$name")
  elif grep -q "not built yet" "$work/err"; then
    skipped+=("$name")
  else
    fail "$name, n=${our_n[0]}: $(cat "$work/err")"
  fi
done < <("$dtlab" delaunay --dim 3 --list-algos)

: >"$work/ours"
for algo in "${variants[@]}"; do
  for i in "${!examples[@]}"; do
    echo "book_2_7: $algo, n=${our_n[i]} ($runs runs)" >&2
    measure "$algo" "${examples[i]}" "${our_n[i]}"
  done
done

# Every variant computes the same (unique, perturbed) Delaunay tetrahedralization.
awk '$1 == "incremental" { ref[$2] = $4 } $1 != "incremental" && $4 != ref[$2] {
  print $1 " gives " $4 " tetrahedra at n=" $3 ", incremental " ref[$2]; bad = 1 } END { exit bad }' \
  "$work/ours" || fail "the variants disagree on the number of tetrahedra"

# The report.
cpu="$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -n 1)"
echo "# Book Table 7.2 (George & Borouchaki 1998, §7.13, p. 211) beside dtlab's 3D Delaunay"
echo
echo "- machine: ${cpu:-unknown CPU}, $(nproc) logical CPUs"
echo "- dtlab: $("$dtlab" --version)"
echo "- ours: \`dtlab delaunay --dim 3 --random N --seed 1 --stats\`, uniform points in the unit cube;"
echo "  seconds = median of $runs runs of the triangulation call (no i/o); peak RSS of the process (median)"
echo "- book: mesh boundaries plus the interior points its mesher created, whole mesh generation"
echo "  timed (CPU, i/o included); \"Del\" = share of that time spent inserting points"
((${#skipped[@]})) && echo "- variants not built yet, skipped: ${skipped[*]}"
((${#variants[@]} > 1)) && echo "- parallel runs with $(nproc) threads; the others with one"
echo
awk -F'\t' -v variants="${variants[*]}" '
function commas(x,   s, out) {
  s = sprintf("%.0f", x); out = ""
  while (length(s) > 3) { out = "," substr(s, length(s) - 2) out; s = substr(s, 1, length(s) - 3) }
  return s out
}
function thousands(x) { return commas(int(x / 1000 + 0.5) * 1000) }
FNR == 1 { file++ }
file == 1 && !/^#/ && $1 != "example" {
  ex = $1; book[++books] = ex; mach[ex] = $2; np[ex] = $3; ne[ex] = $4; t[ex] = $5; v[ex] = $6; del[ex] = $7
  delrate[ex] = $4 * 60 / ($5 * $7 / 100)
}
file == 2 {
  split($0, f, " ")
  key = f[1] SUBSEP f[2]; n[f[2]] = f[3]; el[key] = f[4]; sec[key] = f[5]; rss[key] = f[6]
  if (!(f[2] in seen)) { seen[f[2]] = 1; order[++rows] = f[2] }
}
END {
  print "## The book (Table 7.2 as printed; last column derived)"
  print ""
  print "| example | machine | np | ne | t (s) | v (elements/min) | Del % | Delaunay-only rate = ne / (t x Del) (elements/min) |"
  print "|---:|---|---:|---:|---:|---:|---:|---:|"
  for (i = 1; i <= books; i++) {
    ex = book[i]
    printf "| %s | %s | %s | %s | %s | %s | %s | %s |\n", ex, mach[ex], commas(np[ex]), commas(ne[ex]), t[ex], commas(v[ex]), del[ex], thousands(delrate[ex])
  }
  nv = split(variants, vs, " ")
  print ""
  print "## Ours beside the book'"'"'s Delaunay-only rate"
  print ""
  head = "| example | book: Delaunay-only (elements/min) | n | tetrahedra | tetrahedra / book ne | seconds | incremental (elements/min) | ratio to book | peak RSS (MB) | bytes/tetrahedron |"
  rule = "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  for (j = 2; j <= nv; j++) { head = head " " vs[j] " (elements/min) | ratio to book |"; rule = rule "---:|---:|" }
  print head; print rule
  for (i = 1; i <= rows; i++) {
    ex = order[i]; key = "incremental" SUBSEP ex
    rate = el[key] * 60 / sec[key]
    line = sprintf("| %s | %s | %s | %s | %.3f | %.3g | %s | %.0f | %.0f | %.0f |", ex, thousands(delrate[ex]), commas(n[ex]), commas(el[key]),
                   el[key] / ne[ex], sec[key], thousands(rate), rate / delrate[ex], rss[key], rss[key] * 1048576 / el[key])
    for (j = 2; j <= nv; j++) {
      k = vs[j] SUBSEP ex; r = el[k] * 60 / sec[k]
      line = line sprintf(" %s | %.0f |", thousands(r), r / delrate[ex])
    }
    print line
  }
}' "$book_table" "$work/ours"
