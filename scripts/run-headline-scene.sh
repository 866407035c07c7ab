#!/usr/bin/env bash
# Sets up (Debian packages), builds, and runs the headline scene: an undrained clay column
# collapsing into a tank of still water and raising a wave (paper 000 §4.3,
# prm/clay-column-in-water.prm, 5 s of flow in under a minute on one core), then draws it:
# the soil coloured by its vertical stress under the water surface at t = 0, 0.5, 1 and 5 s,
# to a PNG whose path it prints. Output in ./output-clay-column-in-water.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
output=${OUTPUT_DIR:-output-clay-column-in-water}
"${BUILD_DIR:-$root/build}/slidewave" --set "Output directory=$output" \
  "$root/prm/clay-column-in-water.prm"
/usr/bin/python3 "$root/scripts/plot_coupled_scene.py" "$output" \
  --png "$output/clay-column-in-water.png" \
  --title "Clay column collapsing into still water (paper 000, section 4.3)"
