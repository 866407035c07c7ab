#!/usr/bin/env bash
# Sets up (Debian packages), builds and runs SlideWave's whole test suite with ctest.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "${BUILD_DIR:-$root/build}"
ctest -j "$(nproc 2>/dev/null || echo 2)" --output-on-failure "$@"
