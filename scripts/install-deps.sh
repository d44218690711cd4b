#!/usr/bin/env bash
# Installs dtlab's build and test dependencies from Debian's packages (run as root on a fresh
# Debian 12 machine). Does nothing when every package is already there.
set -euo pipefail
packages=(
  build-essential cmake git ccache python3 python3-matplotlib time
  clang-14 libclang-rt-14-dev          # libFuzzer targets and their sanitizer runtimes
  libgmp-dev libmpfr-dev               # exact fallback and correctly rounded constructions
  libcgal-dev                          # reference implementation, verify/ and bench/ only
  libbenchmark-dev libgtest-dev libgmock-dev librapidcheck-dev
  libtbb-dev libeigen3-dev libcli11-dev
  libopenmpi-dev openmpi-bin           # dtlab-mpi (mpi/) and its mpirun tests
  tetgen                               # peer in bench/ (Debian binary)
  libcgal-demo                         # real scanned point clouds and surfaces for tests
  python3-meshio                       # reads what `dtlab convert` writes (cli_convert_read_by_meshio)
  # the Python module (python/) and its tests; they use Debian's /usr/bin/python3, not a pyenv one
  python3-dev pybind11-dev python3-numpy python3-pytest python3-hypothesis python3-scipy python3-meshio
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
