#!/usr/bin/env bash
# Installs the Debian 12 packages SlideWave needs (only when one is missing), then configures
# and builds SlideWave in ./build (Release unless BUILD_TYPE says otherwise).
#
#   scripts/setup.sh            install what is missing, configure, build
#   BUILD_TYPE=Debug scripts/setup.sh
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-"$root/build"}
build_type=${BUILD_TYPE:-Release}

# libopenblas0-serial: Debian's optimized BLAS/LAPACK, single-threaded (one thread per MPI
# rank), chosen by the system's libblas.so.3 alternative in place of the reference BLAS; the
# flow's GMRES orthogonalizes with its dgemv (1.2x faster steps, doc/free-surface-flow.md).
packages=(libdeal.ii-dev numdiff cmake g++ make python3-matplotlib python3-numpy openmpi-bin
  clang-format libgdal-dev python3-gdal libopenblas0-serial)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  if [ "$(id -u)" != 0 ]; then sudo_cmd="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc 2>/dev/null || echo 2)
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE="$build_type" >/dev/null
cmake --build "$build_dir" -j "$jobs"
