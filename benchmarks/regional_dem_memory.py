#!/usr/bin/python3
"""Memory and set-up time of a landslide on a regional DEM, uniform against adaptive grid
(issue 28, doc/terrain.md "A grid that follows the flow").

The scene ``prm/regional-landslide.prm``: 10^6 m^3 released on a synthetic mountain of a
10 km x 10 km DEM of 5 m pixels (4 million pixels; ``scripts/make_regional_dem.py`` writes
``prm/data/regional_dem.tif``). Cases:

* ``adaptive``: the scene as shipped (40 m cells refined to 5 m where the flow is and 8
  cells ahead of it), the whole flow (``--end`` s);
* ``cropped``: the uniform 5 m grid of a window cropped by hand around the area the
  adaptive run's flow covered (its affected area's bounding box and 200 m more on each
  side, on multiples of 40 m), the same flow;
* ``uniform``: the uniform 5 m grid of a quarter of the DEM (5 km x 5 km around the
  release: 1 million cells; ``--full-uniform``: the whole DEM, 4 million cells, about 9 GB),
  set-up and ``--uniform-end`` s only (its memory is the set-up's; its steps cost what the
  cropped grid's do plus the work over every cell of the grid). The whole DEM's figures
  are extrapolated from the quarter's (memory and set-up grow with the cells: the
  Jacksboro grid of 10^6 cells took 2.1-2.4 GB, doc/terrain.md).

Per run: the peak resident memory (``/usr/bin/time -f %M``), the timer table's set-up
('depth averaged: setup': the DEM read, the grid, the release), its steps ('advance') and
the hazard maps' updates, and the cells of the grid at the start. Prints a table and the
ratio adaptive / cropped memory (target: below 2).

    /usr/bin/python3 benchmarks/regional_dem_memory.py              # ~3 min, 2.5 GB
    /usr/bin/python3 benchmarks/regional_dem_memory.py --full-uniform   # ~9 GB
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, "prm", "regional-landslide.prm")
DEM = os.path.join(ROOT, "prm", "data", "regional_dem.tif")
PARTS = {"setup": "depth averaged: setup", "advance": "depth averaged: advance",
         "maps": "depth averaged: hazard maps"}


def run(exe, output, overrides):
    """One run: its timer rows, peak memory [MB] and cells."""
    args = ["/usr/bin/time", "-f", "%M", exe, "--set", f"Output directory={output}"]
    for o in overrides:
        args += ["--set", o]
    process = subprocess.run(args + [SCENE], capture_output=True, text=True, cwd=ROOT)
    if process.returncode != 0:
        sys.exit(f"a run failed ({overrides}):\n{process.stdout[-2000:]}\n{process.stderr[-2000:]}")
    row = {}
    for key, name in PARTS.items():
        m = re.search(r"\|\s*" + re.escape(name) + r"\s*\|\s*\d+\s*\|\s*([0-9.e+-]+)s", process.stdout)
        row[key] = float(m.group(1)) if m else 0.0
    memory = [int(v) for v in process.stderr.split() if v.isdigit()]
    row["rss_mb"] = memory[-1] / 1024 if memory else float("nan")
    cells = re.search(r"(\d+) columns on (\d+) cells", process.stdout)
    row["columns"], row["cells"] = (int(cells.group(1)), int(cells.group(2))) if cells else (0, 0)
    return row


def affected_window(maps, margin, base):
    """The bounding box of the affected pixels of peak_flow_thickness.tif, grown by
    ``margin`` metres and rounded outwards to multiples of ``base`` metres."""
    from osgeo import gdal
    import numpy as np
    data = gdal.Open(os.path.join(maps, "peak_flow_thickness.tif"))
    values = data.GetRasterBand(1).ReadAsArray()
    x0, dx, _, y0, _, dy = data.GetGeoTransform()
    rows, cols = np.nonzero(values > 0.1)
    west = x0 + (cols.min()) * dx - margin
    east = x0 + (cols.max() + 1) * dx + margin
    north = y0 + rows.min() * dy + margin
    south = y0 + (rows.max() + 1) * dy - margin
    return (math.floor(west / base) * base, math.floor(south / base) * base,
            math.ceil(east / base) * base, math.ceil(north / base) * base)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "slidewave"))
    parser.add_argument("--end", type=float, default=80.0, help="end time of the flow [s]")
    parser.add_argument("--uniform-end", type=float, default=0.5,
                        help="end time of the uniform whole-DEM run [s]")
    parser.add_argument("--skip-uniform", action="store_true")
    parser.add_argument("--full-uniform", action="store_true",
                        help="the uniform grid of the whole DEM (about 9 GB) instead of a quarter")
    parser.add_argument("--csv", default=os.path.join(ROOT, "benchmarks", "results",
                                                      "regional_dem_memory.csv"))
    args = parser.parse_args()
    if not os.path.exists(DEM):
        sys.exit("prm/data/regional_dem.tif is missing: /usr/bin/python3 scripts/make_regional_dem.py")
    common = [f"Time/End time={args.end}", "Depth averaged/Output grid=false",
              "Time/Output interval=1000"]
    rows = {}
    with tempfile.TemporaryDirectory() as directory:
        adaptive = os.path.join(directory, "adaptive")
        rows["adaptive"] = run(args.exe, adaptive, common)
        west, south, east, north = affected_window(os.path.join(adaptive, "maps"), 200.0, 40.0)
        print(f"affected area's window: [{west:.0f}, {east:.0f}] x [{south:.0f}, {north:.0f}]")
        rows["cropped"] = run(args.exe, os.path.join(directory, "cropped"), common + [
            "Depth averaged/Adaptive grid/Enable=false",
            "Depth averaged/Grid/Extent=corners",
            f"Depth averaged/Grid/Lower left={west}, {south}",
            f"Depth averaged/Grid/Upper right={east}, {north}"])
        if not args.skip_uniform:
            window = [] if args.full_uniform else [
                "Depth averaged/Grid/Extent=corners",
                "Depth averaged/Grid/Lower left=501500, 5002500",
                "Depth averaged/Grid/Upper right=506500, 5007500"]
            rows["uniform"] = run(args.exe, os.path.join(directory, "uniform"), [
                f"Time/End time={args.uniform_end}", "Depth averaged/Output grid=false",
                "Depth averaged/Adaptive grid/Enable=false"] + window)
    print(f"\n{'grid':10s} {'cells':>9s} {'columns':>8s} {'peak RSS':>9s} {'set-up':>7s} "
          f"{'steps':>7s} {'maps':>6s}")
    for case, row in rows.items():
        print(f"{case:10s} {row['cells']:9d} {row['columns']:8d} {row['rss_mb']:7.0f} MB "
              f"{row['setup']:5.1f} s {row['advance']:5.1f} s {row['maps']:4.1f} s")
    if "uniform" in rows and not args.full_uniform:
        u = rows["uniform"]
        print(f"uniform, whole DEM (4 x the quarter): {4 * u['cells']} cells, "
              f"about {4 * u['rss_mb'] / 1024:.1f} GB, set-up about {4 * u['setup']:.0f} s")
    print(f"\nadaptive / cropped memory: {rows['adaptive']['rss_mb'] / rows['cropped']['rss_mb']:.2f}")
    os.makedirs(os.path.dirname(args.csv), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["case", "cells", "columns", "rss_mb", "setup", "advance", "maps"])
        for case, row in rows.items():
            writer.writerow([case, row["cells"], row["columns"], f"{row['rss_mb']:.0f}",
                             row["setup"], row["advance"], row["maps"]])


if __name__ == "__main__":
    main()
