#!/usr/bin/env bash
# Sets up (Debian packages), builds, and runs the landslide on real terrain of issue 19: the
# SRTM-derived DEM near Jacksboro, Tennessee that Debian's matplotlib ships, written as a
# GeoTIFF in degrees (prm/data/jacksboro_dem.tif, by scripts/make_jacksboro_dem.py) and
# reprojected by SlideWave to UTM 16N; about 1e6 m^3 released on the Cumberland escarpment
# (prm/jacksboro-landslide.prm, 90 s of flow in about 20 s on one core). Then draws the
# hazard maps (peak thickness, velocity, dynamic pressure, arrival time, deposit) over the
# terrain to a PNG whose path it prints. Output in output-jacksboro-landslide in the
# repository's root (GeoTIFFs, GeoJSON outlines and summary.csv in its maps/); a relative
# OUTPUT_DIR is taken from there too. doc/terrain.md explains it all.
#
#   scripts/run-jacksboro.sh
#   OUTPUT_DIR=/tmp/jacksboro BUILD_DIR=/tmp/build scripts/run-jacksboro.sh
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(realpath -m "${BUILD_DIR:-$root/build}")
"$root/scripts/setup.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$root"
/usr/bin/python3 scripts/make_jacksboro_dem.py prm/data/jacksboro_dem.tif
output=${OUTPUT_DIR:-output-jacksboro-landslide}
"$build/slidewave" --set "Output directory=$output" prm/jacksboro-landslide.prm
output=$(cd "$output" && pwd)
/usr/bin/python3 scripts/plot_hazard_maps.py "$output" --dem prm/data/jacksboro_dem.tif \
  --png "$output/hazard-maps.png" \
  --title "Landslide near Jacksboro, Tennessee: hazard maps (prm/jacksboro-landslide.prm)"
