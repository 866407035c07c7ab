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

- ``depth``: Ritter's dam break of tests/depth_averaged/dam_break_ritter.prm (0.25 m cells,
  4 s) with 'Courant number' 0.5 (the default), 0.25, 0.125, with its L1 depth error against
  the exact solution.

Each at the shipped 'FLIP fraction' (0.99 for the material points, 0.8 for the
depth-averaged columns) and at 1 (pure FLIP). Found with it (doc/granular-water.md, Not done
yet): a FLIP blend fixed per step is a damping rate (1 - FLIP)/Δt, so the dry column's
energy fell as the step shrank unless FLIP = 1 (now the blend is a rate, FLIP^(Δt/Δt_ref):
doc/mpm.md, "The FLIP blend as a rate"), and the semi-implicit drag smooths the grains'
velocity once per step, so the underwater column's energy halves with each halving. A
scheme that converges shows here as changes per halving that shrink.
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
# scene: (prm, step entry, its three values, the section of 'FLIP fraction', its shipped
# value, the statistics column of the front)
SCENES = {
    "mpm": (os.path.join(ROOT, "tests", "mpm", "column_collapse_short.prm"),
            "Material points/Fixed time step", ["5e-5", "2.5e-5", "1.25e-5"],
            "Material points", "0.99", "runout"),
    "granular": (os.path.join(ROOT, "tests", "granular", "underwater_collapse_short.prm"),
                 "Material points/Time step multiplier", ["0.5", "0.25", "0.125"],
                 "Material points", "0.99", "skeleton_front"),
    "depth": (os.path.join(ROOT, "tests", "depth_averaged", "dam_break_ritter.prm"),
              "Depth averaged/Courant number", ["0.5", "0.25", "0.125"],
              "Depth averaged", "0.8", "x_max"),
}


def run(exe, scene, step_value, flip):
    prm, step_entry, _, flip_section, _, front_key = SCENES[scene]
    out_dir = tempfile.mkdtemp(prefix="sw-dt-")
    command = [exe, "--set", f"Output directory={out_dir}", "--set", "Test/Enable=false",
               "--set", "Time/Output interval=1000", "--set", f"{step_entry}={step_value}",
               "--set", f"{flip_section}/FLIP fraction={flip}", prm]
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
           "error": float(values["depth_error_l1"]) if "depth_error_l1" in values else "",
           "wall_s": wall}
    print(" ".join(f"{k}={v:.6g}" if isinstance(v, float) else f"{k}={v}"
                   for k, v in row.items()), flush=True)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "slidewave"))
    parser.add_argument("--csv", default=os.path.join(ROOT, "benchmarks", "results",
                                                      "time_step_convergence.csv"))
    parser.add_argument("--scenes", default="mpm,granular,depth")
    parser.add_argument("--flips", default="shipped,1",
                        help="FLIP fractions ('shipped': the scene's default)")
    args = parser.parse_args()
    rows = []
    for scene in args.scenes.split(","):
        for flip in args.flips.split(","):
            flip = SCENES[scene][4] if flip == "shipped" else flip
            rows += [run(args.exe, scene, value, flip) for value in SCENES[scene][2]]
    write_csv(args.csv, rows, list(rows[0].keys()))
    print("\n| scene | FLIP | step setting | steps | kinetic energy | change per halving | "
          "front [m] | L1 error | wall [s] |")
    print("|---|---|---|---|---|---|---|---|---|")
    previous = None
    for r in rows:
        same = previous is not None and previous["scene"] == r["scene"] \
            and previous["flip"] == r["flip"]
        change = f"{r['kinetic_energy'] / previous['kinetic_energy'] - 1:+.1%}" if same else "-"
        print(f"| {r['scene']} | {r['flip']} | {r['step_setting']} | {r['steps']} | "
              f"{r['kinetic_energy']:.4e} | {change} | {r['front']:.5f} | "
              f"{r['error'] if r['error'] == '' else format(r['error'], '.4e')} | "
              f"{r['wall_s']:.3g} |")
        previous = r


if __name__ == "__main__":
    main()
