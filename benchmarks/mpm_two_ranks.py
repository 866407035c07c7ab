#!/usr/bin/env python3
"""Two MPI ranks against one on the column collapse: interleaved pairs.

On a shared machine the same run varies by 10 % or more from one run to the next, and the
machine's speed drifts over minutes. A one-rank run and a two-rank run far apart in time
therefore measure the machine as much as the code. This script runs N pairs back to back
(one rank, then two ranks, N times) of the column collapse of
``prm/granular-column-collapse.prm`` at one size (default 819,200 points, 0.3125 mm cells,
100 steps; Q1, linear elastic; no output but the first and last) and prints, per pair, the
wall time of the time loop ('mpm: advance', rank 0's timer) and the speed-up; then the
median of the pairs' speed-ups, the ratio of the medians and the ratio of the fastest runs.

Usage: benchmarks/mpm_two_ranks.py [--pairs 5] [--cell-size 0.0003125] [--steps 100]
       [--shape q1] [--material "linear elastic"] [--csv FILE]
Results go to ``benchmarks/results/mpm_two_ranks.csv`` (one row per run).
"""
import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import find_executable, fmt, wait_until_idle, write_csv  # noqa: E402
from mpm_throughput import column_collapse_settings, run_slidewave  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
COLUMNS = ["pair", "ranks", "particles", "cells", "steps", "advance_wall_s",
           "setup_wall_s", "background_load", "status"]


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--exe", default=os.path.join(REPO, "build", "slidewave"))
    p.add_argument("--prm", default=os.path.join(REPO, "prm", "granular-column-collapse.prm"))
    p.add_argument("--mpirun", default="mpirun")
    p.add_argument("--pairs", type=int, default=5, help="number of one-/two-rank pairs")
    p.add_argument("--cell-size", type=float, default=0.0003125,
                   help="cell size [m] (0.0003125: 819,200 points)")
    p.add_argument("--steps", type=int, default=100)
    p.add_argument("--shape", default="q1")
    p.add_argument("--material", default="linear elastic")
    p.add_argument("--idle-wait", type=float, default=60.0,
                   help="before each pair, wait up to this many seconds for an idle machine")
    p.add_argument("--csv", default=os.path.join(REPO, "benchmarks", "results",
                                                 "mpm_two_ranks.csv"))
    args = p.parse_args(argv)
    exe = find_executable(args.exe, 0.)
    _, settings = column_collapse_settings(args.cell_size, args.steps, args.shape,
                                           args.material)
    rows, times = [], {1: [], 2: []}
    print(f"{'pair':>4} {'1 rank [s]':>11} {'2 ranks [s]':>12} {'speed-up':>9}")
    for pair in range(1, args.pairs + 1):
        if args.idle_wait > 0:
            wait_until_idle(args.idle_wait)
        for ranks in (1, 2):
            r = run_slidewave(exe, args.prm, settings, ranks, args.mpirun)
            r.update(pair=pair, ranks=ranks)
            rows.append(r)
            if r["status"] != "ok":
                sys.exit(f"pair {pair}, {ranks} rank(s): {r['status']}")
            times[ranks].append(r["advance_wall_s"])
        print(f"{pair:>4} {times[1][-1]:>11.2f} {times[2][-1]:>12.2f} "
              f"{times[1][-1] / times[2][-1]:>8.2f}x", flush=True)
    write_csv(args.csv, rows, COLUMNS)
    ratios = [a / b for a, b in zip(times[1], times[2])]
    print(f"{rows[0]['particles']} points, {rows[0]['cells']} cells, {args.steps} steps, "
          f"{args.shape}, {args.material}")
    print(f"median of the pairs' speed-ups: {statistics.median(ratios):.2f}x "
          f"(from {min(ratios):.2f}x to {max(ratios):.2f}x)")
    print(f"ratio of the medians: {statistics.median(times[1]) / statistics.median(times[2]):.2f}x"
          f" ({fmt(statistics.median(times[1]), '.2f')} s / "
          f"{fmt(statistics.median(times[2]), '.2f')} s)")
    print(f"ratio of the fastest runs: {min(times[1]) / min(times[2]):.2f}x")
    print(f"results: {args.csv}")


if __name__ == "__main__":
    main()
