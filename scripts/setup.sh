#!/usr/bin/env bash
# Installs PeriStep's Debian 12 packages (when missing) and builds it in ./build (Release): the host
# program and PeriStep.fmu, or with --tests everything (tests and benchmarks too).
#
#   bash scripts/setup.sh            # what `peristep run` needs
#   bash scripts/setup.sh --tests    # and what `ctest --test-dir build` runs
set -euo pipefail
cd "$(dirname "$0")/.."

targets=(--target peristep fmu)
case "${1:-}" in
  "") ;;
  --tests) targets=() ;;
  *) echo "usage: bash scripts/setup.sh [--tests]" >&2; exit 2 ;;
esac

packages=(cmake g++ make pkg-config patchelf libeigen3-dev libsundials-dev libhdf5-dev zlib1g-dev libxml2-dev catch2
          libopenblas-dev libsuitesparse-dev libmumps-seq-dev libmetis-dev libzip-dev libtomlplusplus-dev libcli11-dev libpng-dev
          python3 python3-numpy gnuplot-nox libopenmpi-dev openmpi-bin python3-paraview python3-h5py
          liblapacke-dev libboost-dev python3-venv python3-pip python3-setuptools python3-wheel python3-pytest python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" "${targets[@]}"
