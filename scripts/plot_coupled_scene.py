#!/usr/bin/python3
"""Draw one finished coupled run (Physics = coupled) as a PNG, in the manner of paper 000's
Figs. 8-10 and 13-15: one panel per time, the material points coloured by their vertical
stress sigma_yy [kPa], the water (surface and filled depth) and the bed the water sees.

  /usr/bin/python3 scripts/plot_coupled_scene.py OUTPUT_DIR [--png PATH] [--times T ...]
                                                 [--title TEXT] [--stress-range MIN MAX]

OUTPUT_DIR holds particles/particles_NNNNN.pvtu and water/profile-NNNNN.csv (written at
the same output times; the time of each is the profile's first line). --times defaults
to 0 0.5 1 5 s, keeping those that were written (all written times if none of them was);
a requested time that was not written is drawn at the nearest written one. The colour
range defaults to [the 0.5th percentile of the sigma_yy drawn, 0], rounded to 5 kPa
(single points at the wall or front can be far more compressed than the rest). --png defaults
to OUTPUT_DIR/coupled-snapshots.png. Takes a second or two. Needs numpy and matplotlib
(Debian: python3-numpy, python3-matplotlib); uses the Agg backend."""
import argparse
import glob
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_water import read_profile  # noqa: E402  (checks numpy/matplotlib, selects Agg)
from plot_particles import read_particles  # noqa: E402

import numpy as np  # noqa: E402

DEFAULT_TIMES = [0.0, 0.5, 1.0, 5.0]


def output_times(directory):
    """{time: index} of the profiles written in OUTPUT_DIR/water."""
    times = {}
    for path in glob.glob(os.path.join(directory, "water", "profile-*.csv")):
        index = int(re.search(r"profile-(\d+)\.csv$", path).group(1))
        with open(path) as f:
            times[float(f.readline().split("=")[1])] = index
    if not times:
        sys.exit("%s: no water/profile-*.csv" % directory)
    return times


def pick_times(available, requested=None):
    """The (time, index) pairs to draw: the requested times (default DEFAULT_TIMES), each at
    the nearest written time."""
    if requested is None:
        requested = [t for t in DEFAULT_TIMES if any(abs(a - t) < 1e-6 for a in available)]
        requested = requested or sorted(available)
    written = sorted(available)
    nearest = [min(written, key=lambda a: abs(a - t)) for t in requested]
    return [(t, available[t]) for t in dict.fromkeys(nearest)]


def draw(directory, png, times=None, title=None, stress_range=None):
    """Draw the snapshots of one run into png; returns png."""
    import matplotlib.pyplot as plt
    frames = []
    for t, index in pick_times(output_times(directory), times):
        points, data = read_particles(os.path.join(directory, "particles",
                                                   "particles_%05d.pvtu" % index))
        _, water = read_profile(os.path.join(directory, "water", "profile-%05d.csv" % index))
        frames.append((t, points, data["stress_yy"] / 1e3, water))
    if stress_range is None:
        low = np.percentile(np.concatenate([s for _, _, s, _ in frames]), 0.5)
        stress_range = (5 * math.floor(low / 5), 0)
    # The height drawn: the highest surface or soil point, with a margin.
    top = max(max(np.max(w["eta"]), np.max(p[:, 1])) for _, p, _, w in frames)
    top = 0.1 * math.ceil(10 * top + 1.5)
    width = math.ceil(max(np.max(w["x"]) for _, _, _, w in frames))
    panel = 9 * top / width
    fig, axes = plt.subplots(len(frames), 1, squeeze=False, sharex=True,
                             figsize=(9.6, (panel + 0.45) * len(frames) + 0.7),
                             constrained_layout=True)
    axes = axes[:, 0]
    for ax, (t, points, stress, water) in zip(axes, frames):
        wet = water["h"] > 1e-6
        eta = np.where(wet, water["eta"], np.nan)
        ax.fill_between(water["x"], water["bed"], eta, where=wet, color="tab:blue",
                        alpha=0.2, lw=0)
        sc = ax.scatter(points[:, 0], points[:, 1], c=stress, s=2, lw=0, cmap="viridis_r",
                        vmin=stress_range[0], vmax=stress_range[1])
        ax.plot(water["x"], eta, color="tab:blue", lw=1.2)
        ax.plot(water["x"], water["bed"], color="0.2", lw=0.7, ls="--")
        ax.set_title("t = %.2f s" % t, fontsize=9, loc="left")
        ax.set_aspect("equal")
        ax.set_xlim(0, width)
        ax.set_ylim(0, top)
        ax.set_ylabel("y [m]")
    axes[-1].set_xlabel("x [m]")
    fig.colorbar(sc, ax=list(axes), label="vertical stress $\\sigma_{yy}$ [kPa]",
                 location="bottom", shrink=0.5, aspect=40)
    fig.suptitle((title or os.path.basename(os.path.normpath(directory)))
                 + "\nsoil coloured by $\\sigma_{yy}$; water surface (blue), bed (dashed)",
                 fontsize=10)
    fig.savefig(png, dpi=90)
    plt.close(fig)
    return png


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory")
    parser.add_argument("--png")
    parser.add_argument("--times", type=float, nargs="+")
    parser.add_argument("--title")
    parser.add_argument("--stress-range", type=float, nargs=2, metavar=("MIN", "MAX"))
    args = parser.parse_args()
    png = args.png or os.path.join(args.directory, "coupled-snapshots.png")
    print("wrote", draw(args.directory, png, args.times, args.title, args.stress_range))


if __name__ == "__main__":
    main()
