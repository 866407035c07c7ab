#!/usr/bin/python3
"""Compares two rasters pixel by pixel (the restart tests' maps written on another number
of ranks, whose sums over the ranks change order).

    compare_rasters.py A.tif B.tif TOLERANCE

Passes (exit 0) when both have the same size and the same no-data pixels, and the largest
difference is at most TOLERANCE times the largest absolute value of A; prints the
difference either way. Exit 1 otherwise, 2 when a file cannot be read.
"""
import sys

import numpy as np
from osgeo import gdal


def read(path):
    data = gdal.Open(path)
    if data is None:
        print(f"compare_rasters.py: cannot read '{path}'")
        sys.exit(2)
    band = data.GetRasterBand(1)
    values = band.ReadAsArray().astype(float)
    nodata = band.GetNoDataValue()
    missing = ~np.isfinite(values)
    if nodata is not None:
        missing |= values == nodata
    return values, missing


def main():
    first, second, tolerance = sys.argv[1], sys.argv[2], float(sys.argv[3])
    a, missing_a = read(first)
    b, missing_b = read(second)
    if a.shape != b.shape:
        print(f"{first}: {a.shape} pixels, {second}: {b.shape}")
        return 1
    if (missing_a != missing_b).any():
        print(f"{first}: {(missing_a != missing_b).sum()} pixels are no-data in one only")
        return 1
    valid = ~missing_a
    scale = np.abs(a[valid]).max() if valid.any() else 0.
    difference = np.abs(a[valid] - b[valid]).max() if valid.any() else 0.
    print(f"{first}: largest difference {difference:.3e} of largest value {scale:.6e} "
          f"(allowed {tolerance:g} of it)")
    return 0 if difference <= tolerance * scale else 1


if __name__ == "__main__":
    sys.exit(main())
