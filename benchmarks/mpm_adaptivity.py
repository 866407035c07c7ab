#!/usr/bin/python3
"""Adaptive against uniform background grid: the dry sand column collapse
(prm/granular-column-collapse.prm, 2.5 mm cells where the sand is, GIMP, run to rest at
t = 0.4 s) on a uniform grid and on adaptive grids with 1 and 2 coarser levels. Prints cells
(at the start and the largest during the run), wall time of the time loop, particle-steps per
second and the final front position; writes a CSV and, with --plot, a figure of the adaptive
grid following the slide (doc/figures/mpm-adaptive-grid.png).

  /usr/bin/python3 benchmarks/mpm_adaptivity.py [--build build] [--csv FILE] [--plot] [--quick]

--quick runs to t = 0.1 s only."""
import argparse
import csv
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))


def run(build, name, end_time, settings):
    directory = "/tmp/slidewave-bench/adaptivity-" + name
    command = [os.path.join(build, "slidewave"), "--set", "Output directory=" + directory,
               "--set", "Time/End time=%g" % end_time, "--set", "Time/Output interval=0.1",
               "--set", "Time/Statistics interval=100"]
    for s in settings:
        command += ["--set", s]
    command.append(os.path.join(ROOT, "prm", "granular-column-collapse.prm"))
    text = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    advance = float(re.search(r"\| mpm: advance\s*\|\s*(\d+)\s*\|\s*([0-9.]+)s", text).group(2))
    steps = int(re.search(r"\| mpm: advance\s*\|\s*(\d+)", text).group(1))
    rows = list(csv.DictReader(open(os.path.join(directory, "statistics.csv"))))
    particles = int(float(rows[0]["particles"]))
    cells = [int(float(r["cells"])) for r in rows]
    return dict(grid=name, particles=particles, cells_start=cells[0], cells_max=max(cells),
                steps=steps, advance_seconds=advance,
                particle_steps_per_second=particles * steps / advance,
                runout=float(rows[-1]["runout"]), directory=directory)


def plot(directory, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    from plot_particles import read_particles, read_vtu
    import glob
    fig, axes = plt.subplots(3, 1, figsize=(8, 5.6), sharex=True, constrained_layout=True)
    for ax, index in zip(axes, [0, 1, 4]):
        quads = []
        for piece in sorted(glob.glob(os.path.join(directory, "grid", "grid_%05d.*.vtu" % index))):
            points, _ = read_vtu(piece)
            for k in range(0, len(points), 4):
                p = points[k:k + 4, :2]
                quads.append([p[0], p[1], p[3], p[2]])
        ax.add_collection(PolyCollection(quads, facecolors="none", edgecolors="0.6", linewidths=0.3))
        particles, data = read_particles(os.path.join(directory, "particles", "particles_%05d.pvtu" % index))
        ax.scatter(particles[:, 0], particles[:, 1], s=0.4, c="tab:orange", lw=0)
        ax.set_xlim(0, 0.6)
        ax.set_ylim(0, 0.12)
        ax.set_aspect("equal")
        ax.set_title("t = %.1f s: %d cells" % (0.1 * index, len(quads)), fontsize=10)
        ax.set_ylabel("y [m]")
    axes[-1].set_xlabel("x [m]")
    fig.savefig(out, dpi=130)
    print("wrote", out)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--csv", default=os.path.join(ROOT, "benchmarks", "results", "mpm_adaptivity.csv"))
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    end_time = 0.1 if args.quick else 0.4
    cases = [("uniform", []),
             ("adaptive-1-level", ["Material points/Adaptive grid/Enable=true",
                                   "Material points/Adaptive grid/Levels=1"]),
             ("adaptive-2-levels", ["Material points/Adaptive grid/Enable=true",
                                    "Material points/Adaptive grid/Levels=2",
                                    "Material points/Output grid=true"])]
    results = []
    print("%-18s %9s %11s %9s %7s %9s %14s %8s" % ("grid", "particles", "cells start", "cells max",
                                                   "steps", "loop [s]", "particle-steps/s", "runout"))
    for name, settings in cases:
        r = run(args.build, name, end_time, settings)
        results.append(r)
        print("%-18s %9d %11d %9d %7d %9.2f %14.3e %8.4f" % (
            r["grid"], r["particles"], r["cells_start"], r["cells_max"], r["steps"],
            r["advance_seconds"], r["particle_steps_per_second"], r["runout"]), flush=True)
    os.makedirs(os.path.dirname(args.csv), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=[k for k in results[0] if k != "directory"])
        writer.writeheader()
        for r in results:
            writer.writerow({k: v for k, v in r.items() if k != "directory"})
    print("wrote", args.csv)
    if args.plot and not args.quick:
        plot(results[-1]["directory"], os.path.join(ROOT, "doc", "figures", "mpm-adaptive-grid.png"))


if __name__ == "__main__":
    main()
