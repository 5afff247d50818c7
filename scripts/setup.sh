#!/usr/bin/env bash
# Installs the Debian 12 packages grainlab needs to build, test and plot.
# Idempotent: asks apt only for what is missing. Works as root or with sudo.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev          # vectors, quaternions, matrices
  libqhull-dev           # convex hulls
  libmeshoptimizer-dev   # mesh simplification
  libassimp-dev          # STL / OBJ / PLY reading
  libtomlplusplus-dev    # config files
  libcli11-dev           # command line
  nlohmann-json3-dev     # JSON output
  libfmt-dev             # formatting
  zlib1g-dev             # compressed ParaView files
  libgtest-dev libgmock-dev  # tests
  libbenchmark-dev       # micro benchmarks
  libinsighttoolkit5-dev # ITK 5.2: CT image formats, distance map, h-maxima and watershed (src/ct only)
  libomp-dev             # OpenMP (gcc ships its own libgomp; this is for clang)
  python3 python3-matplotlib  # report plots
  pybind11-dev python3-pybind11 python3-dev  # the Python module (import grainlab; Python.h)
  python3-numpy python3-pandas   # series as arrays and DataFrames
  python3-distributed python3-tqdm  # sweeps on Dask, progress bars
  python3-pytest python3-nbconvert python3-nbformat python3-nbclient python3-ipykernel  # Python tests, the example notebook
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} Debian packages present"
  exit 0
fi

echo "setup: installing missing Debian packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null; then SUDO="sudo"; else
    echo "setup: need root (or sudo) to run apt-get install ${missing[*]}" >&2; exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
