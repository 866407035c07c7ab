#!/usr/bin/python3
"""Make the figures of doc/mpm.md: runs the scenes with build/slidewave (into /tmp) and
draws them with matplotlib.

  /usr/bin/python3 scripts/mpm_figures.py [--build build] [--out doc/figures] [--only NAME]

NAME: tunnel, column, compaction."""
import argparse
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_particles import read_particles  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(build, scene, directory, *settings):
    command = [os.path.join(build, "slidewave"), "--set", "Output directory=" + directory]
    for s in settings:
        command += ["--set", s]
    command.append(os.path.join(ROOT, scene))
    print(" ".join(command), flush=True)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)


def snapshot(directory, index):
    return read_particles(os.path.join(directory, "particles", "particles_%05d.pvtu" % index))


def tunnel(build, out, plt):
    directory = "/tmp/slidewave-figures/tunnel"
    run(build, "prm/tunnel-face-collapse.prm", directory)
    # Output every 0.05 s: indices 0, 2, 4, 20 are t = 0, 0.1, 0.2, 1.0 s.
    fig, axes = plt.subplots(2, 2, figsize=(10, 4.6), sharex=True, sharey=True,
                             constrained_layout=True)
    for ax, (index, t) in zip(axes.flat, [(0, 0.0), (2, 0.1), (4, 0.2), (20, 1.0)]):
        points, data = snapshot(directory, index)
        speed = np.linalg.norm(data["velocity"], axis=1)
        sc = ax.scatter(points[:, 0], points[:, 1], c=speed, s=2.5, lw=0, cmap="viridis",
                        vmin=0, vmax=0.8)
        ax.plot([0, 0.12], [0.08, 0.08], "k-", lw=2)
        ax.set_title("t = %.1f s" % t)
        ax.set_aspect("equal")
        ax.set_xlim(0, 0.42)
        ax.set_ylim(0, 0.17)
    for ax in axes[1]:
        ax.set_xlabel("x [m]")
    for ax in axes[:, 0]:
        ax.set_ylabel("y [m]")
    fig.colorbar(sc, ax=axes, label="speed [m/s]", shrink=0.8)
    fig.savefig(os.path.join(out, "tunnel-face-collapse.png"), dpi=120)
    print("wrote tunnel-face-collapse.png")


def column(build, out, plt):
    directory = "/tmp/slidewave-figures/column"
    run(build, "prm/granular-column-collapse.prm", directory, "Time/Output interval=0.05")
    fig, axes = plt.subplots(4, 1, figsize=(8, 6.5), sharex=True, constrained_layout=True)
    points0, _ = snapshot(directory, 0)
    for ax, (index, t) in zip(axes, [(1, 0.05), (2, 0.1), (4, 0.2), (8, 0.4)]):
        ax.scatter(points0[:, 0], points0[:, 1], c="0.85", s=1, lw=0)
        points, data = snapshot(directory, index)
        sc = ax.scatter(points[:, 0], points[:, 1], c=data["equivalent_plastic_strain"], s=1,
                        lw=0, cmap="magma_r", vmin=0, vmax=1)
        ax.set_title("t = %.2f s, front at x = %.3f m" % (t, points[:, 0].max()), fontsize=10)
        ax.set_aspect("equal")
        ax.set_ylim(0, 0.11)
        ax.set_xlim(0, 0.4)
        ax.set_ylabel("y [m]")
    axes[-1].set_xlabel("x [m]")
    fig.colorbar(sc, ax=axes, label="equivalent plastic strain", shrink=0.8)
    fig.savefig(os.path.join(out, "granular-column-collapse.png"), dpi=120)
    print("wrote granular-column-collapse.png")


def compaction(build, out, plt):
    scene = "tests/mpm/self_weight_compaction_gimp.prm"
    fig, ax = plt.subplots(figsize=(6, 5))
    y = np.linspace(0, 50, 2)
    ax.plot(-80 * 10 * (50 - y) / 1e3, y, "k-", lw=1.5, label="exact: -rho0 g (H0 - Y)")
    for label, settings, style in [
            ("Q1, MUSL", ["Material points/Shape functions=q1", "Material points/Update scheme=musl"], "o"),
            ("GIMP, USL", [], "s")]:
        directory = "/tmp/slidewave-figures/compaction-" + label.split(",")[0].lower()
        run(build, scene, directory, "Test/Enable=false", "Time/Output interval=300",
            "Material points/Verification/Tolerance=0", *settings)
        points, data = snapshot(directory, 1)
        ax.plot(data["stress_yy"] / 1e3, data["initial_y"], style, ms=4, mfc="none", label=label)
    ax.set_xlabel("sigma_yy [kPa]")
    ax.set_ylabel("initial height Y [m]")
    ax.set_title("Self-weight compaction, E = 2e5 Pa, 2 m cells")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "mpm-compaction-stress.png"), dpi=120)
    print("wrote mpm-compaction-stress.png")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", default=os.path.join(ROOT, "doc", "figures"))
    parser.add_argument("--only")
    args = parser.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    for name, function in [("tunnel", tunnel), ("column", column), ("compaction", compaction)]:
        if args.only in (None, name):
            function(args.build, args.out, plt)


if __name__ == "__main__":
    main()
