#!/usr/bin/python3
"""Draws a free-surface-flow run (Physics = free surface flow): the water surface (the
phi = 0.5 contour of free_surface/surface_NNNNN.csv) at every output time, and the surge
front of statistics.csv against time, with Martin and Moyce's measurements when the scene
is their column (Verification/Exact solution = martin moyce; a is read from the first
surface file: the column's width at t = 0).

    python3 scripts/plot_free_surface.py OUTPUT [--png FILE]

Writes OUTPUT/free-surface.png unless --png says otherwise, and prints its path.
"""
import argparse
import csv
import glob
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MEASURED = [(0, 1), (0.41, 1.11), (0.84, 1.23), (1.19, 1.44), (1.43, 1.67), (1.63, 1.89),
            (1.82, 2.11), (1.97, 2.33), (2.2, 2.56), (2.32, 2.78), (2.5, 3), (2.64, 3.22),
            (2.82, 3.44), (2.96, 3.67)]


def read_surface(path):
    with open(path) as f:
        time = float(f.readline().split("=")[1])
        rows = list(csv.DictReader(f))
    return time, [tuple(float(r[k]) for k in ("x0", "y0", "x1", "y1")) for r in rows]


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("output")
    parser.add_argument("--png")
    parser.add_argument("--g", type=float, default=9.81)
    args = parser.parse_args()
    png = args.png or os.path.join(args.output, "free-surface.png")

    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
    files = sorted(glob.glob(os.path.join(args.output, "free_surface", "surface_*.csv")))
    colours = plt.cm.viridis([i / max(1, len(files) - 1) for i in range(len(files))])
    a = None
    for path, colour in zip(files, colours):
        time, segments = read_surface(path)
        if a is None and segments:
            a = max(max(s[0], s[2]) for s in segments)
        for k, s in enumerate(segments):
            left.plot([s[0], s[2]], [s[1], s[3]], color=colour, lw=1.2,
                      label=f"t = {time:.3f} s" if k == 0 else None)
    left.set_aspect("equal")
    left.set_xlabel("x [m]")
    left.set_ylabel("y [m]")
    left.set_title("water surface (phi = 0.5)")
    left.legend(fontsize=7, loc="upper right")

    with open(os.path.join(args.output, "statistics.csv")) as f:
        stats = list(csv.DictReader(f))
    t = [float(r["time"]) for r in stats]
    front = [float(r["front"]) for r in stats]
    if a:
        scale = math.sqrt(2 * args.g / a)
        right.plot([x * scale for x in t], [x / a for x in front], label="SlideWave")
        right.plot([p[0] for p in MEASURED], [p[1] for p in MEASURED], "ko",
                   label="Martin and Moyce (1952), n^2 = 2")
        right.set_xlabel("T = t sqrt(2 g / a)")
        right.set_ylabel("front x / a")
        right.set_title(f"surge front (a = {a:.4g} m)")
    else:
        right.plot(t, front)
        right.set_xlabel("t [s]")
        right.set_ylabel("front [m]")
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print(png)


if __name__ == "__main__":
    main()
