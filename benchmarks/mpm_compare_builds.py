#!/usr/bin/python3
"""Speed of two builds of SlideWave side by side: the MPM throughput runs of
``mpm_throughput.py --quick`` (dry sand column collapse, 12,800 and 51,200 points), each
model (shape functions x material) run by the two executables as interleaved pairs.

A refactoring must not cost speed; on a shared VM whose speed drifts by tens of percent, only
runs made next to each other compare. Each pair runs the two builds back to back, the order
alternating from pair to pair (A B, B A, A B, ...) so that a drift within a pair favours
neither. Per model and size it prints the median 'mpm: advance' wall time of each build,
the median of the per-pair ratios new/base and the ratio of the medians (> 1: the new build
is slower).

Usage::

    benchmarks/mpm_compare_builds.py --base OLD/slidewave --new build/slidewave [--pairs 3]
        [--sizes 12800,51200] [--shapes q1,gimp] [--materials "linear elastic,drucker prager"]
        [--ranks 1] [--csv benchmarks/results/mpm_compare_builds.csv]

Only the Python standard library is used.
"""

import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import (check_distinct_builds, interleaved_pairs,  # noqa: E402
                              write_csv)
from mpm_throughput import (MATERIALS, REPO, SHAPES, SIZES,  # noqa: E402
                            column_collapse_settings, run_slidewave)

COLUMNS = ["shape", "material", "ranks", "particles", "steps", "pair", "order",
           "base_advance_s", "new_advance_s", "ratio"]


def parse_list(text, convert=str):
    return [convert(item.strip()) for item in text.split(",") if item.strip()]


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--base", required=True, help="the reference executable")
    p.add_argument("--new", default=os.path.join(REPO, "build", "slidewave"),
                   help="the executable to compare")
    p.add_argument("--prm", default=os.path.join(REPO, "prm", "granular-column-collapse.prm"))
    p.add_argument("--mpirun", default="mpirun --oversubscribe")
    p.add_argument("--pairs", type=int, default=3, help="interleaved pairs per case")
    p.add_argument("--sizes", default="12800,51200",
                   help="particle counts (rows of mpm_throughput.py's quick run)")
    p.add_argument("--shapes", default=",".join(SHAPES))
    p.add_argument("--materials", default=",".join(MATERIALS))
    p.add_argument("--ranks", default="1", help="MPI rank counts")
    p.add_argument("--csv", default=os.path.join(REPO, "benchmarks", "results",
                                                 "mpm_compare_builds.csv"))
    args = p.parse_args(argv)

    # Quick-run rows: 2.5 mm (12,800 points, 2000 steps) and 1.25 mm (51,200, 500 steps).
    by_count = {12800 * round((0.0025 / cell) ** 2): (cell, quick)
                for cell, _, quick in SIZES if quick}
    sizes = [by_count[n] for n in parse_list(args.sizes, int)]
    executables = {"base": os.path.abspath(args.base), "new": os.path.abspath(args.new)}
    check_distinct_builds(executables)

    rows, failed = [], False
    print(f"{'shape':5} {'material':15} {'ranks':>5} {'points':>7} {'steps':>5} "
          f"{'base [s]':>9} {'new [s]':>9} {'median ratio':>12} {'ratio of medians':>16}")
    for cell, steps in sizes:
        for shape in parse_list(args.shapes):
            for material in parse_list(args.materials):
                for ranks in parse_list(args.ranks, int):
                    _, settings = column_collapse_settings(cell, steps, shape, material)
                    def run(which):
                        r = run_slidewave(executables[which], args.prm, settings, ranks,
                                          args.mpirun)
                        if r["status"] != "ok":
                            print(f"{which} {shape} {material}: {r['status']}")
                            return None
                        return r
                    done, any_failed = interleaved_pairs(run, args.pairs)
                    failed = failed or any_failed
                    times = {which: [results[which]["advance_wall_s"] for _, _, results in done]
                             for which in ("base", "new")}
                    ratios = [n / b for b, n in zip(times["base"], times["new"])]
                    particles = done[-1][2]["new"]["particles"] if done else None
                    for (pair, order, results), ratio in zip(done, ratios):
                        rows.append({"shape": shape, "material": material, "ranks": ranks,
                                     "particles": particles, "steps": steps, "pair": pair,
                                     "order": order,
                                     "base_advance_s": f"{results['base']['advance_wall_s']:.4f}",
                                     "new_advance_s": f"{results['new']['advance_wall_s']:.4f}",
                                     "ratio": f"{ratio:.4f}"})
                    if not ratios:
                        continue
                    base_median = statistics.median(times["base"])
                    new_median = statistics.median(times["new"])
                    print(f"{shape:5} {material:15} {ranks:5d} {particles:7d} {steps:5d} "
                          f"{base_median:9.3f} {new_median:9.3f} "
                          f"{statistics.median(ratios):12.3f} "
                          f"{new_median / base_median:16.3f}", flush=True)
    write_csv(args.csv, rows, COLUMNS)
    print(f"pairs in {args.csv}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
