#!/usr/bin/python3
"""Convergence in the time step at a fixed grid: the material points' and the granular water's.

A scheme converges in its time step when, on a fixed grid, halving Δt changes the result
less and less. This script runs two scenes at three steps each, halving, and prints the
last statistics row's kinetic energy and front with the change per halving and the wall
time (the speed-accuracy trade of a shorter step):

- ``mpm``: the dry column collapse of tests/mpm/column_collapse_short.prm (Drucker-Prager,
  5 mm cells, 0.03 s) with 'Fixed time step' 5e-5, 2.5e-5, 1.25e-5 s;
- ``granular``: the loose underwater collapse of tests/granular/underwater_collapse_short.prm
  (10 mm cells, 0.25 s) with 'Time step multiplier' 0.5 (the default), 0.25, 0.125.

Each at the shipped 'FLIP fraction' (0.99) and at 1 (pure FLIP). Found with it (doc/
granular-water.md, Not done yet): the FLIP blend's PIC share per step is a damping rate
(1 - FLIP)/Δt, so the dry column's energy falls as the step shrinks unless FLIP = 1, and the
semi-implicit drag smooths the grains' velocity once per step, so the underwater column's
energy halves with each halving. A fix shows here as changes per halving that shrink.
Written to ``--csv`` (default benchmarks/results/time_step_convergence.csv).

Single runs on a shared 2-vCPU machine whose speed drifts by +-30 %: read the times as
orders of magnitude, the energies exactly (the runs are deterministic).
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import write_csv  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = {
    "mpm": (os.path.join(ROOT, "tests", "mpm", "column_collapse_short.prm"),
            "Material points/Fixed time step", ["5e-5", "2.5e-5", "1.25e-5"], "runout"),
    "granular": (os.path.join(ROOT, "tests", "granular", "underwater_collapse_short.prm"),
                 "Material points/Time step multiplier", ["0.5", "0.25", "0.125"],
                 "skeleton_front"),
}


def run(exe, scene, step_value, flip):
    prm, step_entry, _, front_key = SCENES[scene]
    out_dir = tempfile.mkdtemp(prefix="sw-dt-")
    command = [exe, "--set", f"Output directory={out_dir}", "--set", "Test/Enable=false",
               "--set", "Time/Output interval=1000", "--set", f"{step_entry}={step_value}",
               "--set", f"Material points/FLIP fraction={flip}", prm]
    env = dict(os.environ, OPENBLAS_CORETYPE="Haswell")
    start = time.monotonic()
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    wall = time.monotonic() - start
    if result.returncode != 0:
        sys.exit(f"{scene} {step_entry}={step_value} FLIP {flip} failed:\n{result.stderr}")
    with open(os.path.join(out_dir, "statistics.csv")) as f:
        values = list(csv.DictReader(f))[-1]
    subprocess.run(["rm", "-rf", out_dir])
    energy_key = "kinetic_energy" if "kinetic_energy" in values else "skeleton_kinetic_energy"
    row = {"scene": scene, "step_setting": step_value, "flip": flip,
           "steps": int(values["step"]), "time": float(values["time"]),
           "kinetic_energy": float(values[energy_key]), "front": float(values[front_key]),
           "wall_s": wall}
    print(" ".join(f"{k}={v:.6g}" if isinstance(v, float) else f"{k}={v}"
                   for k, v in row.items()), flush=True)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "slidewave"))
    parser.add_argument("--csv", default=os.path.join(ROOT, "benchmarks", "results",
                                                      "time_step_convergence.csv"))
    parser.add_argument("--scenes", default="mpm,granular")
    parser.add_argument("--flips", default="0.99,1")
    args = parser.parse_args()
    rows = []
    for scene in args.scenes.split(","):
        for flip in args.flips.split(","):
            rows += [run(args.exe, scene, value, flip) for value in SCENES[scene][2]]
    write_csv(args.csv, rows, list(rows[0].keys()))
    print("\n| scene | FLIP | step setting | steps | kinetic energy | change per halving | "
          "front [m] | wall [s] |")
    print("|---|---|---|---|---|---|---|---|")
    previous = None
    for r in rows:
        same = previous is not None and previous["scene"] == r["scene"] \
            and previous["flip"] == r["flip"]
        change = f"{r['kinetic_energy'] / previous['kinetic_energy'] - 1:+.1%}" if same else "-"
        print(f"| {r['scene']} | {r['flip']} | {r['step_setting']} | {r['steps']} | "
              f"{r['kinetic_energy']:.4e} | {change} | {r['front']:.5f} | {r['wall_s']:.3g} |")
        previous = r


if __name__ == "__main__":
    main()
