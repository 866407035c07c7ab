#!/usr/bin/env bash
# Sets up (Debian packages), builds, and runs the 1D dam break of paper 000 §4.2 with its
# error against Stoker's exact solution. Output in ./output-dam-break.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
"${BUILD_DIR:-$root/build}/slidewave" "$root/prm/dam-break.prm"
