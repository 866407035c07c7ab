#!/usr/bin/python3
"""Figures of the underwater granular collapse (paper 002, §4.2; prm/underwater-collapse-*.prm).

  scripts/plot_underwater_collapse.py LOOSE_DIR DENSE_DIR --out doc/figures/granular-underwater-collapse.png
      [--times 0.25 1 2] [--labels loose dense] [--xlim 0 0.2] [--ylim 0 0.1] [--vmax 0.05]

Each DIR is a granular-water scene's output directory (one or more: the half-submerged
column's figure has one). Top rows: the grains (points coloured by their speed) and the
water surface (the phase field's 0.5 contour) of each scene at the given times. Bottom: the front of the granular mass (its rightmost point) and its
height (its highest point) over time, from statistics.csv. Needs numpy and matplotlib."""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_free_surface import read_surface  # noqa: E402
from plot_particles import read_particles  # noqa: E402


def statistics(directory):
    with open(os.path.join(directory, "statistics.csv")) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in ("time", "skeleton_front", "skeleton_top")}


def record_at(directory, time):
    """The index of the output record closest to @p time (from the surface files' headers)."""
    best, best_index = None, None
    folder = os.path.join(directory, "free_surface")
    for name in sorted(os.listdir(folder)):
        if name.startswith("surface_") and name.endswith(".csv"):
            t, _ = read_surface(os.path.join(folder, name))
            if best is None or abs(t - time) < abs(best - time):
                best, best_index = t, int(name[8:13])
    return best, best_index


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dirs", nargs="+")
    parser.add_argument("--out", required=True)
    parser.add_argument("--times", type=float, nargs="+", default=[0.25, 1.0, 2.0])
    parser.add_argument("--labels", nargs="+",
                        default=["loose (n0 = 0.45)", "dense (n0 = 0.40)"])
    parser.add_argument("--xlim", type=float, nargs=2, default=[0, 0.2])
    parser.add_argument("--ylim", type=float, nargs=2, default=[0, 0.1])
    parser.add_argument("--vmax", type=float, default=0.05, help="top of the speed colour scale [m/s]")
    args = parser.parse_args()

    cases = list(zip(args.labels, args.dirs))
    n_times = len(args.times)
    n_rows = len(cases)
    fig = plt.figure(figsize=(4.2 * n_times, 3.2 * n_rows + 3))
    grid = fig.add_gridspec(n_rows + 1, n_times, height_ratios=[1] * n_rows + [1.3])
    speed_max = args.vmax
    for row, (label, directory) in enumerate(cases):
        for col, wanted in enumerate(args.times):
            ax = fig.add_subplot(grid[row, col])
            time, index = record_at(directory, wanted)
            points, data = read_particles(os.path.join(directory, "particles", "particles_%05d.pvtu" % index))
            speed = np.linalg.norm(data["velocity"][:, :2], axis=1)
            scatter = ax.scatter(points[:, 0], points[:, 1], c=speed, s=1.5, cmap="viridis", vmin=0, vmax=speed_max)
            _, segments = read_surface(os.path.join(directory, "free_surface", "surface_%05d.csv" % index))
            for x0, y0, x1, y1 in segments:
                ax.plot([x0, x1], [y0, y1], color="tab:blue", lw=1)
            ax.set_xlim(*args.xlim)
            ax.set_ylim(*args.ylim)
            ax.set_aspect("equal")
            ax.set_title("%s, t = %.2f s" % (label.split(" ")[0], time), fontsize=9)
            if col == 0:
                ax.set_ylabel("y [m]")
    fig.colorbar(scatter, ax=fig.axes, shrink=0.5, label="grain speed [m/s]")
    ax_front = fig.add_subplot(grid[n_rows, : max(1, n_times // 2)])
    ax_top = fig.add_subplot(grid[n_rows, max(1, n_times // 2):])
    for (label, directory), style in zip(cases, ("-", "--", ":", "-.")):
        s = statistics(directory)
        ax_front.plot(s["time"], s["skeleton_front"] * 100, style, label=label)
        ax_top.plot(s["time"], s["skeleton_top"] * 100, style, label=label)
    ax_front.set_xlabel("t [s]")
    ax_front.set_ylabel("front [cm]")
    ax_top.set_xlabel("t [s]")
    ax_top.set_ylabel("height [cm]")
    ax_front.legend(fontsize=8)
    ax_top.legend(fontsize=8)
    fig.savefig(args.out, dpi=120)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
