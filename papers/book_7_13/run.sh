#!/usr/bin/env bash
# Book §7.13 Tables 7.3 and 7.2, §8.7 Tables 8.2-8.3 (George & Borouchaki 1998) on the unit sphere:
# dtlab mesh (a uniform mesh and two size-controlled ones, elements per minute across sizes) and
# TetGen's meshes before and after dtlab optimize, beside the book's figures.
#   papers/book_7_13/run.sh             cases 1-3, examples 1-3, three TetGen meshes (about 2-3 min)
#   papers/book_7_13/run.sh --large     and example 4's size (1.2 M tetrahedra: about 2 min more)
#   papers/book_7_13/run.sh --quick     cases 1-2, example 1, two TetGen meshes, with the checks (CTest)
#   papers/book_7_13/run.sh --dtlab P   use the dtlab binary P instead of building one
# BUILD_DIR picks the build directory (default: build). Prints a Markdown report on stdout;
# exits non-zero if a run fails or a check in the README's list does not hold. Needs python3 and
# tetgen (Debian's package).
set -euo pipefail
cd "$(dirname "$0")/../.."

args=()
dtlab=""
while (($#)); do
  case "$1" in
    --quick | --large) args+=("$1") ;;
    --dtlab) dtlab="$2"; shift ;;
    *) echo "usage: $0 [--quick] [--large] [--dtlab PATH]" >&2; exit 2 ;;
  esac
  shift
done
source papers/build_dtlab.sh
command -v tetgen >/dev/null || { echo "book_7_13: FAILED: no tetgen on PATH (apt-get install tetgen)" >&2; exit 1; }
exec python3 papers/book_7_13/report.py --dtlab "$dtlab" "${args[@]}"
