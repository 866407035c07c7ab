#!/usr/bin/python3
"""Stripes in a hazard map, as a number: the mean absolute second difference of a map's
pixels along x and along y, over the runs of three neighbouring pixels that all exceed the
threshold (doc/terrain.md, "Hazard maps"). A smooth map of the same flow gives a smaller
number; stripes one or two pixels wide raise it.

Usage:
    /usr/bin/python3 scripts/map_roughness.py OUTPUT/maps [OTHER/maps ...] \\
        [--map deposit_thickness] [--threshold 0.1]
"""

import argparse
import os
import sys

import numpy as np
from osgeo import gdal


def roughness(path, threshold):
    """(along x, along y) for the GeoTIFF at path."""
    dataset = gdal.Open(path)
    if dataset is None:
        sys.exit(f"map_roughness.py: cannot read '{path}'")
    a = dataset.ReadAsArray().astype(float)
    a[~np.isfinite(a)] = 0.
    result = []
    for axis in (1, 0):
        second = np.abs(np.diff(a, 2, axis=axis))
        n = a.shape[axis]
        take = lambda k: np.take(a, range(k, n - 2 + k), axis=axis) > threshold
        mask = take(0) & take(1) & take(2)
        result.append(second[mask].mean() if mask.any() else 0.)
    return result


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("folders", nargs="+", help="maps folders (OUTPUT/maps)")
    p.add_argument("--map", default="deposit_thickness", help="map name (default %(default)s)")
    p.add_argument("--threshold", type=float, default=0.1,
                   help="pixels above it count (default %(default)s m)")
    args = p.parse_args(argv)
    for folder in args.folders:
        x, y = roughness(os.path.join(folder, args.map + ".tif"), args.threshold)
        print(f"{folder}: {args.map} mean |second difference| along x {x:.3f}, along y {y:.3f}")


if __name__ == "__main__":
    main()
