#!/usr/bin/python3
"""Runs a depth-averaged scene with hazard maps twice, on its adaptive grid and with
'Adaptive grid/Enable = false' (the uniform grid of 'Cell size'), and compares the maps
pixel by pixel (issue 28: the maps are on the pixels of 'Cell size' whatever the grid).

    compare_maps.py SLIDEWAVE SCENE.prm DIRECTORY TOLERANCE [MPIEXEC RANKS]

Passes (exit 0) when every map's largest difference is at most TOLERANCE times the map's
largest value (arrival times: TOLERANCE times the end time, no-data where the other has
no-data); prints the differences.
"""
import os
import subprocess
import sys

from osgeo import gdal


def run(exe, scene, output, adaptive, launcher):
    args = launcher + [exe, "--set", f"Output directory={output}"]
    if not adaptive:
        args += ["--set", "Depth averaged/Adaptive grid/Enable=false"]
    subprocess.run(args + [scene], check=True, stdout=subprocess.DEVNULL)


def read(path):
    data = gdal.Open(path)
    values = data.GetRasterBand(1).ReadAsArray()
    return values


def main():
    exe, scene, directory, tolerance = sys.argv[1:5]
    launcher = [sys.argv[5], "-np", sys.argv[6]] if len(sys.argv) > 6 else []
    tolerance = float(tolerance)
    os.makedirs(directory, exist_ok=True)
    outputs = {}
    for adaptive in (True, False):
        outputs[adaptive] = os.path.join(directory, "adaptive" if adaptive else "uniform")
        run(exe, scene, outputs[adaptive], adaptive, launcher)
    ok = True
    for name in ["peak_flow_thickness", "peak_flow_velocity", "peak_pressure_dynamic",
                 "peak_pressure_static", "arrival_time", "deposit_thickness"]:
        a = read(os.path.join(outputs[True], "maps", name + ".tif"))
        u = read(os.path.join(outputs[False], "maps", name + ".tif"))
        if a.shape != u.shape:
            print(f"{name}: {a.shape} pixels against {u.shape}")
            ok = False
            continue
        if name == "arrival_time":
            same_reach = ((a == -9999) == (u == -9999)).all()
            reached = (a != -9999) & (u != -9999)
            difference = abs(a[reached] - u[reached]).max() if reached.any() else 0.0
            scale = max(u[reached].max() if reached.any() else 1.0, 1.0)
            good = same_reach and difference <= tolerance * scale
            print(f"{name}: same pixels reached {'yes' if same_reach else 'no'}, "
                  f"largest difference {difference / scale:.1e} of the latest arrival")
        else:
            scale = max(abs(u).max(), 1e-300)
            difference = abs(a - u).max()
            good = difference <= tolerance * scale
            print(f"{name}: largest difference {difference / scale:.1e} of its largest value")
        ok = ok and good
    print("adaptive and uniform maps agree" if ok else "the maps differ")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
