#!/usr/bin/python3
"""Speed against accuracy of the coupled soil-water scene (paper 000, section 4.3).

Runs prm/clay-column-in-water.prm (h_w = 1 m, to t = 5 s unless ``--end-time``) with

* the material points' cell size (``--cell-sizes``, default 0.1, 0.05, 0.025 m; 0.05 m is
  the paper's), GIMP, 200 water cells;
* the water resolution at 0.05 m cells: 100, 200 and 400 cells of an independent water
  mesh ('Water cells = water mesh', the bed interpolated onto it), and the 160 grid
  columns themselves ('Water cells = grid columns');
* Q1 against GIMP at 0.05 m;
* sub-cycling: 'Maximum substeps' 1, 4 and 16 at 0.05 m (the soil's stable step is about
  a tenth of the water's, so the soil sub-cycles inside the water's step and bed and loads
  are exchanged less often).

``--pressure`` sets 'Coupling/Water pressure on soil' (default hydrostatic, the form of the
recorded study in doc/coupled.md; the shipped scene uses the paper's 'excess over initial
level').

The reference is the finest run (0.025 m cells, GIMP, 400 water cells, no sub-cycling).
For every run it prints the particles, water cells, coupled steps, the wall time of the
process and of the time loop (the timer table's total minus 'coupled: setup'), the
particle-steps per second of the soil, and what the users of this scene look at, with
its difference from the reference:

* runout Delta s at the end (displacement of the column's toe) [m];
* eta_max, the highest water surface over the run [m];
* the RMS over time of the difference of the free surface at the gauges x = 4 m and
  x = 8 m from the reference's [m].

A run that stops is recorded as failed, with the reason; the study goes on. Writes the
table as CSV (``--csv``, default benchmarks/results/coupled_work_precision.csv) and, with
``--plot``, the figure doc/figures/coupled-work-precision.png (difference from the
reference against wall time; ``--plot-only`` redraws it from the CSV).
"""

import argparse
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import fmt, find_executable, write_csv, wait_until_idle  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(REPO, "prm", "clay-column-in-water.prm")
COLUMNS = ["case", "cell_size", "shape", "water_cells", "substeps", "particles", "steps",
           "wall_s", "loop_s", "particle_steps_per_s", "runout", "eta_max", "gauge4_rms",
           "gauge8_rms", "d_runout", "d_eta_max", "status"]


def cases(cell_sizes):
    out = [("reference", 0.025, "gimp", 400, 1)]
    out += [("cell size", h, "gimp", 200, 1) for h in cell_sizes if h != 0.025]
    out += [("water cells", 0.05, "gimp", n, 1) for n in (100, 400)]
    out += [("water cells", 0.05, "gimp", "grid columns", 1)]
    out += [("shape functions", 0.05, "q1", 200, 1)]
    out += [("sub-cycling", 0.05, "gimp", 200, n) for n in (4, 16)]
    return out


def run_case(exe, case, end_time, pressure):
    _, h, shape, water, substeps = case
    directory = tempfile.mkdtemp(prefix="slidewave-coupled-")
    settings = {
        "Output directory": directory,
        "Time/End time": str(end_time),
        "Time/Output interval": "0",
        "Time/Statistics interval": "1",
        "Material points/Grid/Cell size": str(h),
        "Material points/Shape functions": shape,
        "Coupling/Maximum substeps": str(substeps),
        "Coupling/Water pressure on soil": pressure,
    }
    if water == "grid columns":
        settings["Coupling/Water cells"] = "grid columns"
    else:
        settings["Coupling/Water cells"] = "water mesh"
        settings["Shallow water/Mesh/Number of cells"] = str(water)
    command = [exe]
    for k, v in settings.items():
        command += ["--set", "%s=%s" % (k, v)]
    command.append(SCENE)
    start = time.perf_counter()
    result = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    row = {"case": case[0], "cell_size": h, "shape": shape, "water_cells": water,
           "substeps": substeps, "wall_s": wall}
    try:
        if result.returncode != 0:
            reason = (result.stderr.strip().splitlines() or ["exit %d" % result.returncode])
            row["status"] = "failed: " + reason[-1][:120]
            return row, None
        total = float(re.search(r"Total wallclock time elapsed since start\s*\|\s*([\d.e+-]+)s",
                                result.stdout).group(1))
        setup = float(re.search(r"coupled: setup\s*\|\s*\d+\s*\|\s*([\d.e+-]+)s",
                                result.stdout).group(1))
        soil = float(re.search(r"coupled: soil\s*\|\s*\d+\s*\|\s*([\d.e+-]+)s",
                               result.stdout).group(1))
        with open(os.path.join(directory, "statistics.csv")) as f:
            stats = list(csv.DictReader(f))
        gauges = np.loadtxt(os.path.join(directory, "water", "gauges.csv"), delimiter=",",
                            skiprows=1, ndmin=2)
        particles = int(re.search(r"Coupled: (\d+) material points", result.stdout).group(1))
        steps = int(stats[-1]["step"])
        soil_steps = sum(int(r["soil_steps"]) for r in stats[1:])
        row.update({
            "particles": particles, "steps": steps, "loop_s": total - setup,
            "particle_steps_per_s": particles * soil_steps / soil,
            "runout": float(stats[-1]["runout"]),
            "eta_max": max(float(r["max_free_surface"]) for r in stats),
            "status": "ok"})
        return row, gauges
    finally:
        shutil.rmtree(directory, ignore_errors=True)


def plot(rows, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker  # noqa: F401
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8), constrained_layout=True)
    markers = {"cell size": "o", "water cells": "s", "shape functions": "^",
               "sub-cycling": "D"}
    for quantity, ax, label in (("d_runout", axes[0], "|runout - ref| [m]"),
                                ("d_eta_max", axes[1], "|eta_max - ref| [m]"),
                                ("gauge4_rms", axes[2], "RMS gauge x = 4 m - ref [m]")):
        for row in rows:
            if row["case"] == "reference" or row.get("status") != "ok":
                continue
            value = max(float(row[quantity]), 1e-6)
            ax.loglog(float(row["loop_s"]), value, markers[row["case"]], color="C%d" %
                      list(markers).index(row["case"]))
            ax.annotate("%s %s %s N=%s" % (row["cell_size"], row["shape"], row["water_cells"],
                                          row["substeps"]),
                        (float(row["loop_s"]), value), fontsize=6, xytext=(3, 3),
                        textcoords="offset points")
        ax.set_xlabel("wall time of the time loop [s]")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3, which="both")
        # Plain numbers on the time axis, which spans about a decade (no crowded minor labels).
        ax.xaxis.set_major_locator(matplotlib.ticker.LogLocator(subs=(1., 2., 5.)))
        ax.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    for case, m in markers.items():
        axes[0].plot([], [], m, color="C%d" % list(markers).index(case), label=case)
    axes[0].legend(fontsize=7)
    fig.suptitle("Clay column in water (h_w = 1 m, 5 s): difference from the reference "
                 "(0.025 m cells, GIMP, 400 water cells) against cost")
    fig.savefig(png, dpi=110)
    print("wrote", png)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--exe", default=os.path.join(REPO, "build", "slidewave"))
    parser.add_argument("--end-time", type=float, default=5.0)
    parser.add_argument("--cell-sizes", default="0.1,0.05,0.025")
    parser.add_argument("--csv", default=os.path.join(REPO, "benchmarks", "results",
                                                      "coupled_work_precision.csv"))
    parser.add_argument("--png", default=os.path.join(REPO, "doc", "figures",
                                                      "coupled-work-precision.png"))
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--pressure", default="hydrostatic",
                        choices=["hydrostatic", "excess over initial level"])
    parser.add_argument("--plot-only", action="store_true")
    args = parser.parse_args()
    if args.plot_only:
        with open(args.csv) as f:
            plot(list(csv.DictReader(f)), args.png)
        return
    exe = find_executable(args.exe, 0)
    load = wait_until_idle(60)
    print("background load before the study: %.2f cores" % load, flush=True)

    rows, reference_gauges = [], None
    header = ("%-15s %6s %5s %12s %3s %7s %6s %8s %8s %10s %8s %8s %9s %9s %9s %9s  %s" %
              ("case", "h[m]", "shape", "water", "N", "points", "steps", "wall[s]", "loop[s]",
               "p-steps/s", "runout", "eta_max", "d_runout", "d_eta", "rms x=4", "rms x=8",
               "status"))
    print(header)
    for case in cases([float(v) for v in args.cell_sizes.split(",")]):
        row, gauges = run_case(exe, case, args.end_time, args.pressure)
        if case[0] == "reference":
            reference_gauges, reference = gauges, row
        if gauges is not None and reference_gauges is not None:
            for k, name in ((1, "gauge4_rms"), (2, "gauge8_rms")):
                own = np.interp(reference_gauges[:, 0], gauges[:, 0], gauges[:, k])
                row[name] = float(np.sqrt(np.mean((own - reference_gauges[:, k]) ** 2)))
            row["d_runout"] = abs(row["runout"] - reference["runout"])
            row["d_eta_max"] = abs(row["eta_max"] - reference["eta_max"])
        rows.append(row)
        print("%-15s %6s %5s %12s %3s %7s %6s %8s %8s %10s %8s %8s %9s %9s %9s %9s  %s" % (
            row["case"], row["cell_size"], row["shape"], row["water_cells"], row["substeps"],
            fmt(row.get("particles"), "d"), fmt(row.get("steps"), "d"),
            fmt(row["wall_s"], ".2f"), fmt(row.get("loop_s"), ".2f"),
            fmt(row.get("particle_steps_per_s"), ".3g"), fmt(row.get("runout"), ".4f"),
            fmt(row.get("eta_max"), ".4f"), fmt(row.get("d_runout"), ".2e"),
            fmt(row.get("d_eta_max"), ".2e"), fmt(row.get("gauge4_rms"), ".2e"),
            fmt(row.get("gauge8_rms"), ".2e"), row["status"]), flush=True)
    write_csv(args.csv, rows, COLUMNS)
    print("wrote", args.csv)
    if args.plot:
        plot(rows, args.png)


if __name__ == "__main__":
    main()
