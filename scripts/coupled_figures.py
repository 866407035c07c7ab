#!/usr/bin/python3
"""Make the figures of doc/coupled.md: runs the coupled scenes with build/slidewave (into
/tmp/slidewave-figures) and draws them with matplotlib, in the manner of paper 000's
Figs. 8-11 and 13-15: the soil coloured by its vertical stress under the water surface at
chosen times, and the free-surface histories at the gauges x = 4 m and x = 8 m for the
three water depths of each scene.

  /usr/bin/python3 scripts/coupled_figures.py [--build build] [--out doc/figures]
                                              [--only NAME] [--keep]

NAME: in-water, dam-break. --keep reuses runs already in /tmp/slidewave-figures."""
import argparse
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_particles import read_particles  # noqa: E402
from plot_water import read_gauges, read_profile  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WORK = "/tmp/slidewave-figures"

# Scene, the constant that sets the water, its values, and the snapshot times [s] (the
# scenes write every 0.25 s).
SCENES = {
    "in-water": ("prm/clay-column-in-water.prm", "hw=%g", [1.0, 1.5, 2.0],
                 "h_w = %g m", [0.0, 0.5, 1.0, 5.0]),
    "dam-break": ("prm/clay-column-dam-break.prm", "hl=%g, hr=1.0, h0=1.0, l0=2",
                  [0.5, 1.0, 2.0], "h_l = %g m", [0.0, 0.5, 1.0, 5.0]),
}


def run(build, scene, directory, keep, *settings):
    if keep and os.path.exists(os.path.join(directory, "statistics.csv")):
        return
    command = [os.path.join(build, "slidewave"), "--set", "Output directory=" + directory]
    for s in settings:
        command += ["--set", s]
    command.append(os.path.join(ROOT, scene))
    print(" ".join(command), flush=True)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)


def snapshots(plt, name, directory, times, label, out):
    top = 1.7  # the highest surface of the first run of each scene is 1.5 m
    fig, axes = plt.subplots(len(times), 1, figsize=(9, (0.8 * 9 * top / 8 + 0.45) * len(times)
                                                     + 0.6),
                             sharex=True, constrained_layout=True)
    for ax, t in zip(axes, times):
        index = int(round(t / 0.25))
        points, data = read_particles(os.path.join(directory, "particles",
                                                   "particles_%05d.pvtu" % index))
        _, water = read_profile(os.path.join(directory, "water", "profile-%05d.csv" % index))
        sc = ax.scatter(points[:, 0], points[:, 1], c=data["stress_yy"] / 1e3, s=1.5, lw=0,
                        cmap="viridis_r", vmin=-30, vmax=0)
        wet = water["h"] > 1e-6
        eta = np.where(wet, water["eta"], np.nan)
        ax.fill_between(water["x"], water["bed"], eta, where=wet, color="tab:blue",
                        alpha=0.25, lw=0)
        ax.plot(water["x"], eta, color="tab:blue", lw=1.2)
        ax.plot(water["x"], water["bed"], color="0.3", lw=0.6, ls="--")
        ax.set_title("t = %.2f s" % t, fontsize=9, loc="left")
        ax.set_aspect("equal")
        ax.set_xlim(0, 8)
        ax.set_ylim(0, top)
        ax.set_ylabel("y [m]")
    axes[-1].set_xlabel("x [m]")
    fig.colorbar(sc, ax=axes, label="vertical stress $\\sigma_{yy}$ [kPa]", shrink=0.7)
    fig.suptitle("%s (%s): soil and water surface" % (os.path.basename(SCENES[name][0]),
                                                       label))
    path = os.path.join(out, "coupled-%s-snapshots.png" % name)
    fig.savefig(path, dpi=110)
    print("wrote", path)


def gauges(plt, name, runs, out):
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.4), sharey=True, constrained_layout=True)
    for label, directory, still in runs:
        header, data = read_gauges(os.path.join(directory, "water", "gauges.csv"))
        for ax, column in zip(axes, (1, 2)):
            # Delta h / h_s with h_s = 1 m: the surface's departure from its still level.
            ax.plot(data[:, 0], data[:, column] - still[column - 1], lw=1, label=label)
            ax.set_title(header[column].replace("eta(", "gauge at ").rstrip(")"), fontsize=10)
            ax.set_xlabel("t [s]")
    axes[0].set_ylabel("$\\eta - \\eta_0$ [m]")
    axes[1].legend(fontsize=8)
    for ax in axes:
        ax.grid(alpha=0.3)
    path = os.path.join(out, "coupled-%s-gauges.png" % name)
    fig.savefig(path, dpi=110)
    print("wrote", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", default=os.path.join(ROOT, "doc", "figures"))
    parser.add_argument("--only", choices=sorted(SCENES))
    parser.add_argument("--keep", action="store_true")
    args = parser.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    os.makedirs(args.out, exist_ok=True)
    for name, (scene, constants, values, label, times) in SCENES.items():
        if args.only and name != args.only:
            continue
        runs = []
        for value in values:
            directory = os.path.join(WORK, "%s-%g" % (name, value))
            run(args.build, scene, directory, args.keep,
                "Shallow water/Initial condition/Function constants=" + constants % value)
            # The still level at the gauges: the first record.
            _, data = read_gauges(os.path.join(directory, "water", "gauges.csv"))
            runs.append((label % value, directory, data[0, 1:]))
        snapshots(plt, name, runs[0][1], times, runs[0][0], args.out)
        gauges(plt, name, runs, args.out)


if __name__ == "__main__":
    main()
