#!/usr/bin/python3
"""Work-precision of the two-phase MPM-FEM on Terzaghi's consolidation (doc/granular-water.md).

Runs prm/terzaghi-consolidation.prm (the shipped defaults of the granular-water physics,
T_v up to 1) on columns of 3 cells of 0.04, 0.02 and 0.01 m (25, 50 and 100 cells high,
2 x 2 points per cell). Each row: cells, points, steps, wall time of the time loop (the
program's timer rows of the step: skeleton to grid, exchange, water, skeleton update),
its split, cell-steps and point-steps per second, the largest error of the nodes' pore
pressure against Terzaghi's series over T_v = 0.05 ... 1 (relative to the load), and the
largest error of the average degree of consolidation U. Written to ``--csv`` (default
benchmarks/results/granular_terzaghi.csv); figure: error against wall time (``--png``,
doc/figures/granular-terzaghi-work-precision.png).

Single runs on a shared 2-vCPU machine whose speed drifts by +-30 %: read the times as
orders of magnitude, the errors exactly.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import write_csv  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, "prm", "terzaghi-consolidation.prm")
PARTS = ["skeleton to grid", "exchange", "water", "skeleton update"]


def run(exe, h):
    out_dir = tempfile.mkdtemp(prefix="sw-terzaghi-")
    width = 3 * h
    settings = [f"Output directory={out_dir}", "Time/Output interval=1000",
                f"Material points/Grid/Cell size={h}", f"Free surface flow/Grid/Cell size={h}",
                f"Material points/Grid/Upper right={width}, 1",
                f"Free surface flow/Grid/Upper right={width}, 1",
                f"Material points/Region 1/Rectangle=0, 0, {width}, 1"]
    command = [exe]
    for s in settings:
        command += ["--set", s]
    command.append(SCENE)
    text = subprocess.run(command, capture_output=True, text=True).stdout
    row = {"cell_size": h, "cells": 3 * round(1 / h), "points": 12 * round(1 / h)}
    times = {}
    for part in PARTS:
        m = re.search(r"granular: " + part + r"\s*\|\s*(\d+)\s*\|\s*([0-9.]+)s", text)
        times[part] = float(m.group(2)) if m else 0.
        if part == "water":
            row["steps"] = int(m.group(1))
    row["loop_s"] = sum(times.values())
    for part in PARTS:
        row[part.replace(" ", "_") + "_share"] = times[part] / row["loop_s"]
    row["cell_steps_per_s"] = row["cells"] * row["steps"] / row["loop_s"]
    row["point_steps_per_s"] = row["points"] * row["steps"] / row["loop_s"]
    row["error"] = float(re.search(r"Terzaghi: largest pore pressure error ([0-9.e+-]+)", text).group(1))
    row["degree_error"] = max(abs(float(x)) for x in re.findall(r"\(error ([0-9.e+-]+)\)", text))
    subprocess.run(["rm", "-rf", out_dir])
    print(" ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}" for k, v in row.items()),
          flush=True)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "slidewave"))
    parser.add_argument("--csv", default=os.path.join(ROOT, "benchmarks", "results",
                                                      "granular_terzaghi.csv"))
    parser.add_argument("--png", default=os.path.join(ROOT, "doc", "figures",
                                                      "granular-terzaghi-work-precision.png"))
    parser.add_argument("--sizes", default="0.04,0.02,0.01")
    args = parser.parse_args()
    rows = [run(args.exe, float(h)) for h in args.sizes.split(",")]
    columns = list(rows[0].keys())
    write_csv(args.csv, rows, columns)
    print("\n| cell size [m] | cells | steps | loop [s] | water / exchange / skeleton | "
          "cell-steps/s | pore pressure error | U error |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        skeleton = r["skeleton_to_grid_share"] + r["skeleton_update_share"]
        print(f"| {r['cell_size']} | {r['cells']} | {r['steps']} | {r['loop_s']:.3g} | "
              f"{100 * r['water_share']:.0f} / {100 * r['exchange_share']:.0f} / "
              f"{100 * skeleton:.0f} % | {r['cell_steps_per_s']:.3g} | {r['error']:.3e} | "
              f"{r['degree_error']:.2e} |")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 4))
    ax.loglog([r["loop_s"] for r in rows], [r["error"] for r in rows], "o-",
              label="pore pressure (largest, / p0)")
    ax.loglog([r["loop_s"] for r in rows], [r["degree_error"] for r in rows], "s--",
              label="degree of consolidation U")
    for r in rows:
        ax.annotate(f"h = {r['cell_size']}", (r["loop_s"], r["error"]), fontsize=8,
                    textcoords="offset points", xytext=(4, 4))
    ax.set_xlabel("wall time of the time loop [s] (one core)")
    ax.set_ylabel("error against Terzaghi, T_v = 0.05 ... 1")
    ax.set_title("Terzaghi consolidation: work-precision")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(os.path.dirname(args.png), exist_ok=True)
    fig.savefig(args.png, dpi=120)
    print("figure:", args.png)


if __name__ == "__main__":
    main()
