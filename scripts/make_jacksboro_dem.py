#!/usr/bin/env python3
"""Writes the SRTM-derived DEM that Debian's matplotlib ships (python-matplotlib-data,
sample_data/jacksboro_fault_dem.npz: 344 x 403 int16 elevations in metres, 1/1200 degree
pixels, near Jacksboro, Tennessee) as a GeoTIFF in geographic coordinates (EPSG:4326), for
the depth-averaged scene prm/jacksboro-landslide.prm, which SlideWave reprojects to UTM.

    /usr/bin/python3 scripts/make_jacksboro_dem.py [OUTPUT.tif]

Default output: prm/data/jacksboro_dem.tif (generated, not kept in git). The file's bounds
keys are xmin/xmax (longitudes) and ymin/ymax (latitudes, the two values stored the other
way round); row 0 of the array is the northern edge.
"""
import os
import sys

import matplotlib
import numpy as np
from osgeo import gdal, osr


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    output = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "prm", "data",
                                                                  "jacksboro_dem.tif")
    source = os.path.join(matplotlib.get_data_path(), "sample_data", "jacksboro_fault_dem.npz")
    dem = np.load(source)
    z = dem["elevation"].astype(np.float64)
    west, east = float(dem["xmin"]), float(dem["xmax"])
    south, north = sorted((float(dem["ymin"]), float(dem["ymax"])))
    rows, cols = z.shape
    dx, dy = (east - west) / cols, (north - south) / rows
    os.makedirs(os.path.dirname(os.path.abspath(output)), exist_ok=True)
    gdal.UseExceptions()
    data = gdal.GetDriverByName("GTiff").Create(output, cols, rows, 1, gdal.GDT_Float32)
    data.SetGeoTransform((west, dx, 0.0, north, 0.0, -dy))
    crs = osr.SpatialReference()
    crs.ImportFromEPSG(4326)
    data.SetProjection(crs.ExportToWkt())
    data.GetRasterBand(1).WriteArray(z)
    data.FlushCache()
    print("%s: %d x %d pixels, lon [%.5f, %.5f], lat [%.5f, %.5f], elevation %g to %g m"
          % (output, cols, rows, west, east, south, north, z.min(), z.max()))


if __name__ == "__main__":
    main()
