#!/usr/bin/python3
"""Work-precision of SlideWave's free surface flow (doc/free-surface-flow.md).

Runs, with the shipped defaults unless a row says otherwise:

* the hydrostatic tank (``tests/fluid/hydrostatic_tank.prm``) at 0.04, 0.02, 0.01 and
  0.005 m cells: the largest pressure error and the spurious currents;
* the Poiseuille channel (``tests/fluid/poiseuille.prm``) at 0.02, 0.01, 0.005 m;
* the Martin-Moyce dam break (``tests/fluid/dam_break_martin_moyce.prm``) on uniform grids of
  a/4, a/8, a/16 and on adaptive grids reaching a/16 (3 levels) and a/32 (4 levels), the
  front against the experiment (largest and RMS difference of x/a without a time shift,
  RMS with the best shift);
* the dam break at a/8 and a/16 with the AMG preconditioner instead of ILU.

Each row: cells at the end, steps, wall time of the time loop (the ``fluid: advance`` row
of the program's timer table), cell-steps per second, mean flow and phase-field GMRES
iterations per step, error(s). Written to ``--csv`` (default
benchmarks/results/free_surface_work_precision.csv); figures: error against wall time
(``--png``, doc/figures/free-surface-work-precision.png) and the front against the
experiment (``--front-png``, doc/figures/free-surface-martin-moyce.png).

These are single runs on a shared 2-vCPU machine whose speed drifts by +-30 %: read the
times as orders of magnitude, the errors and iteration counts exactly.
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import write_csv  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
A = 0.05715
G = 9.81
MEASURED = [(0, 1), (0.41, 1.11), (0.84, 1.23), (1.19, 1.44), (1.43, 1.67), (1.63, 1.89),
            (1.82, 2.11), (1.97, 2.33), (2.2, 2.56), (2.32, 2.78), (2.5, 3), (2.64, 3.22),
            (2.82, 3.44), (2.96, 3.67)]


def run(exe, scene, settings, label, case):
    out_dir = tempfile.mkdtemp(prefix="sw-fluid-")
    command = [exe, "--set", f"Output directory={out_dir}", "--set", "Test/Enable=false",
               "--set", "Time/Output interval=1000", "--set", "Time/Statistics interval=1"]
    for s in settings:
        command += ["--set", s]
    command.append(os.path.join(ROOT, scene))
    text = subprocess.run(command, capture_output=True, text=True).stdout
    row = {"case": case, "label": label}
    m = re.search(r"fluid: advance\s*\|\s*(\d+)\s*\|\s*([0-9.]+)s", text)
    row["advance_s"] = float(m.group(2)) if m else None
    with open(os.path.join(out_dir, "statistics.csv")) as f:
        stats = list(csv.DictReader(f))
    row["steps"] = int(float(stats[-1]["step"]))
    row["cells"] = int(float(stats[-1]["cells"]))
    steps = [r for r in stats if float(r["step"]) > 0]
    row["flow_iterations"] = sum(float(r["flow_iterations"]) for r in steps) / len(steps)
    row["phase_iterations"] = sum(float(r["phase_iterations"]) for r in steps) / len(steps)
    cell_steps = sum(float(r["cells"]) for r in steps)
    row["cell_steps_per_s"] = cell_steps / row["advance_s"] if row["advance_s"] else None
    row["volume_drift"] = max(abs(float(r["volume_drift"])) for r in stats)
    if case == "hydrostatic":
        m = re.search(r"largest relative error = ([0-9.e+-]+); largest speed \(spurious currents\) = ([0-9.e+-]+)", text)
        row["error"], row["spurious_speed"] = float(m.group(1)), float(m.group(2))
    elif case == "poiseuille":
        row["error"] = float(re.search(r"relative to the peak = ([0-9.e+-]+)", text).group(1))
    else:
        m = re.search(r"largest difference ([0-9.]+), RMS ([0-9.]+); with the time shifted by ([0-9.]+), RMS ([0-9.]+)", text)
        row["error"], row["rms"] = float(m.group(1)), float(m.group(2))
        row["shift"], row["rms_shifted"] = float(m.group(3)), float(m.group(4))
        row["front"] = [(float(r["time"]) * math.sqrt(2 * G / A), float(r["front"]) / A) for r in stats]
    subprocess.run(["rm", "-rf", out_dir])
    print(" ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}"
                   for k, v in row.items() if k != "front"), flush=True)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "slidewave"))
    parser.add_argument("--csv", default=os.path.join(ROOT, "benchmarks", "results", "free_surface_work_precision.csv"))
    parser.add_argument("--png", default=os.path.join(ROOT, "doc", "figures", "free-surface-work-precision.png"))
    parser.add_argument("--front-png", default=os.path.join(ROOT, "doc", "figures", "free-surface-martin-moyce.png"))
    args = parser.parse_args()

    rows = []
    tank = "tests/fluid/hydrostatic_tank.prm"
    for h in [0.04, 0.02, 0.01, 0.005]:
        rows.append(run(args.exe, tank, [f"Free surface flow/Grid/Cell size={h}"], f"h={h}", "hydrostatic"))
    channel = "tests/fluid/poiseuille.prm"
    for h in [0.02, 0.01, 0.005]:
        rows.append(run(args.exe, channel, [f"Free surface flow/Grid/Cell size={h}"], f"h={h}", "poiseuille"))
    dam = "tests/fluid/dam_break_martin_moyce.prm"
    for n in [4, 8, 16]:
        rows.append(run(args.exe, dam, [f"Free surface flow/Grid/Cell size={A / n}"], f"uniform a/{n}", "martin moyce"))
    # The adaptive grids: the tank 8a long (base cells divide it), refined along the surface.
    for n, levels in [(16, 3), (32, 4)]:
        rows.append(run(args.exe, dam, [f"Free surface flow/Grid/Cell size={A / n}",
                                        "Free surface flow/Grid/Upper right=0.4572, 0.2286",
                                        "Free surface flow/Adaptive grid/Enable=true",
                                        f"Free surface flow/Adaptive grid/Levels={levels}",
                                        "Free surface flow/Adaptive grid/Interval=5"],
                        f"adaptive a/{n}", "martin moyce"))
    for n in [8, 16]:
        rows.append(run(args.exe, dam, [f"Free surface flow/Grid/Cell size={A / n}",
                                        "Free surface flow/Linear solver/Preconditioner=amg"],
                        f"uniform a/{n} amg", "martin moyce amg"))

    columns = ["case", "label", "cells", "steps", "advance_s", "cell_steps_per_s", "flow_iterations",
               "phase_iterations", "error", "rms", "shift", "rms_shifted", "spurious_speed", "volume_drift"]
    write_csv(args.csv, rows, columns)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(13, 4))
    for ax, case, ylabel in zip(axes, ["hydrostatic", "poiseuille", "martin moyce"],
                                ["largest pressure error / (rho g depth)", "largest u_x error / peak",
                                 "front: largest |x/a - measured|"]):
        for style, select in [("o-", lambda r: "adaptive" not in r["label"]), ("s--", lambda r: "adaptive" in r["label"])]:
            sel = [r for r in rows if r["case"] == case and select(r)]
            if sel:
                ax.loglog([r["advance_s"] for r in sel], [r["error"] for r in sel], style,
                          label="adaptive" if "adaptive" in sel[0]["label"] else "uniform")
                for r in sel:
                    ax.annotate(r["label"].replace("uniform ", "").replace("adaptive ", ""),
                                (r["advance_s"], r["error"]), fontsize=7)
        if case == "martin moyce":
            sel = [r for r in rows if r["case"] == case]
            ax.loglog([r["advance_s"] for r in sel], [r["rms_shifted"] for r in sel], "^:", label="RMS, best time shift")
        ax.set_xlabel("wall time of the time loop [s]")
        ax.set_ylabel(ylabel)
        ax.set_title(case)
        ax.legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(os.path.dirname(args.png), exist_ok=True)
    fig.savefig(args.png, dpi=120)

    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot([p[0] for p in MEASURED], [p[1] for p in MEASURED], "ko", label="Martin and Moyce (1952)")
    for r in rows:
        if r["case"] == "martin moyce":
            ax.plot([p[0] for p in r["front"]], [p[1] for p in r["front"]], label=r["label"])
    ax.set_xlabel("T = t sqrt(2 g / a)")
    ax.set_ylabel("front x / a")
    ax.set_xlim(0, 3.2)
    ax.set_ylim(1, 4.5)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.front_png, dpi=120)


if __name__ == "__main__":
    main()
