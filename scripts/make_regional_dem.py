#!/usr/bin/env python3
"""Writes the synthetic regional DEM of doc/terrain.md ("A grid that follows the flow",
issue 28): 10 km x 10 km at 5 m pixels, 2000 x 2000 = 4 million pixels, in UTM zone 32N
(EPSG:32632) from (500000, 5000000), as a Float32 GeoTIFF.

The terrain: a valley floor falling gently eastwards (300 m - 1 % of x), a mountain of
1200 m (a Gaussian of 900 m standard deviation centred at x = 3 km, y = 5 km: its flanks
reach 39 degrees 900 m from the summit) and a relief of +-15 m (sine waves of 2.3 and 2.7 km)
that keeps the flow from being symmetric. prm/regional-landslide.prm releases 10^6 m^3 on
the mountain's steep eastern flank; the flow runs out onto the valley floor and covers
about 1 % of the DEM.

    /usr/bin/python3 scripts/make_regional_dem.py [OUTPUT.tif] [--pixel 5]

Default output: prm/data/regional_dem.tif (generated, not kept in git: 16 MB).
"""
import argparse
import os

import numpy as np
from osgeo import gdal, osr

X0, Y0, SIDE = 500000.0, 5000000.0, 10000.0


def elevation(u, v):
    """The terrain [m] at local coordinates u, v [m] from the lower left corner."""
    mountain = 1200.0 * np.exp(-((u - 3000.0) ** 2 + (v - 5000.0) ** 2) / (2 * 900.0 ** 2))
    relief = 15.0 * np.sin(u / 370.0) * np.cos(v / 430.0)
    return 300.0 - 0.01 * u + mountain + relief


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output", nargs="?",
                        default=os.path.join(root, "prm", "data", "regional_dem.tif"))
    parser.add_argument("--pixel", type=float, default=5.0, help="pixel size [m]")
    args = parser.parse_args()
    n = int(round(SIDE / args.pixel))
    centres = (np.arange(n) + 0.5) * args.pixel
    u, v = np.meshgrid(centres, centres[::-1])  # row 0 is the northern edge
    z = elevation(u, v).astype(np.float32)
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    gdal.UseExceptions()
    data = gdal.GetDriverByName("GTiff").Create(args.output, n, n, 1, gdal.GDT_Float32)
    data.SetGeoTransform((X0, args.pixel, 0.0, Y0 + SIDE, 0.0, -args.pixel))
    crs = osr.SpatialReference()
    crs.ImportFromEPSG(32632)
    data.SetProjection(crs.ExportToWkt())
    data.GetRasterBand(1).WriteArray(z)
    data.FlushCache()
    data = None
    print(f"{args.output}: {n} x {n} pixels of {args.pixel} m")


if __name__ == "__main__":
    main()
