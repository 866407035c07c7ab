#!/usr/bin/python3
"""The spinning block: how much rotation each velocity transfer keeps, against wall time.

The scene of tests/mpm/spinning_block_apic.prm: a free elastic block 0.3 m x 0.3 m (E = 100 kPa,
nu = 0.3, rho = 1000 kg/m^3, no gravity) starts turning rigidly at omega = 1 rad/s about its
centre and turns once (2 pi s); GIMP, 2 x 2 points per cell, USL, B-bar, the default step.
Exact: a rigid rotation for ever, the kinetic energy constant (the centrifugal strain, 2e-4,
stores a negligible energy). The error of a run is the share of the initial kinetic energy
lost after the turn, 1 - KE(2 pi) / KE(0) (statistics.csv).

Cases: transfers ``--transfers`` ('apic'; 'flip', the default FLIP fraction 0.99; 'flip1',
pure FLIP; 'pic') x cells ``--sizes`` (0.05, 0.025, 0.0125 m). Prints a table (transfer, h,
steps, wall s, KE kept, error, observed order against the next coarser cells), writes
``--csv`` (benchmarks/results/mpm_spinning_block.csv) and ``--png``
(doc/figures/mpm-spinning-block.png: KE/KE0 over the turn per transfer on the finest cells,
and the error against wall time). About 40 s on one core.
"""
import argparse
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import fmt, write_csv  # noqa: E402

SCENE = os.path.join(ROOT, "tests", "mpm", "spinning_block_apic.prm")
TRANSFERS = {
    "apic": ["Material points/Velocity transfer=apic"],
    "flip": ["Material points/Velocity transfer=flip"],
    "flip1": ["Material points/Velocity transfer=flip", "Material points/FLIP fraction=1"],
    "pic": ["Material points/Velocity transfer=flip", "Material points/FLIP fraction=0"],
}
LABELS = {"apic": "APIC", "flip": "FLIP 0.99 (default)", "flip1": "pure FLIP", "pic": "PIC"}


def run(exe, transfer, h):
    """One turn; returns (times, KE, steps, wall seconds) or None if the run failed."""
    work = tempfile.mkdtemp(prefix="slidewave_spin_")
    try:
        command = [exe, "--set", "Output directory=" + os.path.join(work, "out"),
                   "--set", f"Material points/Grid/Cell size={h}",
                   "--set", "Time/Statistics interval=25"]
        for setting in TRANSFERS[transfer]:
            command += ["--set", setting]
        start = time.perf_counter()
        result = subprocess.run(command + [SCENE], capture_output=True, text=True)
        wall = time.perf_counter() - start
        if result.returncode != 0:
            print(f"{transfer} h={h}: failed\n{result.stderr}", file=sys.stderr)
            return None
        with open(os.path.join(work, "out", "statistics.csv")) as f:
            records = list(csv.DictReader(f))
        times = [float(r["time"]) for r in records]
        energy = [float(r["kinetic_energy"]) for r in records]
        return times, energy, int(records[-1]["step"]), wall
    finally:
        shutil.rmtree(work, ignore_errors=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "slidewave"))
    parser.add_argument("--transfers", nargs="+", default=["apic", "flip", "flip1", "pic"])
    parser.add_argument("--sizes", nargs="+", type=float, default=[0.05, 0.025, 0.0125])
    parser.add_argument("--csv", default=os.path.join(ROOT, "benchmarks", "results",
                                                      "mpm_spinning_block.csv"))
    parser.add_argument("--png", default=os.path.join(ROOT, "doc", "figures",
                                                      "mpm-spinning-block.png"))
    args = parser.parse_args()

    rows, curves = [], {}
    print(f"{'transfer':>8} {'h':>7} {'steps':>6} {'wall s':>7} {'KE kept':>9} {'error':>9} "
          f"{'order':>6}")
    for transfer in args.transfers:
        previous = None
        for h in sorted(args.sizes, reverse=True):
            result = run(args.exe, transfer, h)
            if result is None:
                continue
            times, energy, steps, wall = result
            kept = energy[-1] / energy[0]
            error = 1. - kept
            order = None
            if previous and previous[1] > 0 and error > 0:
                order = math.log(previous[1] / error) / math.log(previous[0] / h)
            previous = (h, error)
            rows.append({"transfer": transfer, "cell_size": h, "steps": steps,
                         "wall_s": round(wall, 2), "kinetic_energy_kept": kept,
                         "error": error, "order": order})
            curves[(transfer, h)] = (times, [e / energy[0] for e in energy])
            print(f"{transfer:>8} {h:7.4f} {steps:6d} {wall:7.2f} {kept:9.4%} {error:9.2e} "
                  f"{fmt(order, '6.2f')}")
    write_csv(args.csv, rows, ["transfer", "cell_size", "steps", "wall_s",
                               "kinetic_energy_kept", "error", "order"])

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    finest = min(args.sizes)
    for transfer in args.transfers:
        if (transfer, finest) in curves:
            t, ke = curves[(transfer, finest)]
            left.plot(t, ke, label=LABELS[transfer])
        line = [r for r in rows if r["transfer"] == transfer]
        if line:
            right.loglog([r["wall_s"] for r in line], [max(r["error"], 1e-17) for r in line],
                         "o-", label=LABELS[transfer])
    left.set_xlabel("time [s] (one turn: 2 pi s)")
    left.set_ylabel("kinetic energy / initial")
    left.set_title(f"spinning block, {finest} m cells")
    left.legend()
    right.set_xlabel("wall time [s], one core")
    right.set_ylabel("energy lost after one turn")
    right.set_title("error against wall time (cells 0.05, 0.025, 0.0125 m)")
    right.set_ylim(1e-3, 2.)
    right.legend()
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(args.png)), exist_ok=True)
    fig.savefig(args.png, dpi=110)
    print(f"wrote {args.csv} and {args.png}")


if __name__ == "__main__":
    main()
