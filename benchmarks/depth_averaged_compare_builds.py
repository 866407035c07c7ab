#!/usr/bin/python3
"""Speed of two builds of SlideWave side by side for the depth-averaged material points: the
mud collapse of ``prm/inclined-obstacle.prm`` as ``depth_averaged_throughput.py`` runs it
(fixed step dt = 0.048 s/m x cell size, t = 0 to 0.6 s, no output in the loop), per shape
function and cell size, the two executables run as interleaved pairs.

The companion of ``mpm_compare_builds.py`` (the soil): a refactoring of the engine must not
cost the depth-averaged model speed either. Each pair runs the two builds back to back, the
order alternating from pair to pair (A B, B A, ...), so that a drift of the machine within a
pair favours neither (``benchmark_common.interleaved_pairs``). Per case it prints the median
'depth averaged: advance' wall time of each build, the median of the per-pair ratios
new/base and the ratio of the medians (> 1: the new build is slower).

Usage::

    benchmarks/depth_averaged_compare_builds.py --base OLD/slidewave --new build/slidewave
        [--pairs 5] [--sizes 0.25,0.125] [--shapes q1,gimp] [--ranks 1]
        [--csv benchmarks/results/depth_averaged_compare_builds.csv]

Only the Python standard library is used.
"""

import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import (check_distinct_builds, interleaved_pairs,  # noqa: E402
                              write_csv)
from depth_averaged_throughput import (END_TIME, REPO, run_once,  # noqa: E402
                                       settings_for)

COLUMNS = ["shape", "ranks", "cell_size", "columns", "steps", "pair", "order",
           "base_advance_s", "new_advance_s", "ratio"]


def parse_list(text, convert=str):
    return [convert(item.strip()) for item in text.split(",") if item.strip()]


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--base", required=True, help="the reference executable")
    p.add_argument("--new", default=os.path.join(REPO, "build", "slidewave"),
                   help="the executable to compare")
    p.add_argument("--prm", default=os.path.join(REPO, "prm", "inclined-obstacle.prm"))
    p.add_argument("--mpirun", default="mpirun --oversubscribe")
    p.add_argument("--pairs", type=int, default=5, help="interleaved pairs per case")
    p.add_argument("--sizes", default="0.25,0.125", help="cell sizes [m] (4 x 4 points)")
    p.add_argument("--shapes", default="q1,gimp")
    p.add_argument("--ranks", default="1", help="MPI rank counts")
    p.add_argument("--csv", default=os.path.join(REPO, "benchmarks", "results",
                                                 "depth_averaged_compare_builds.csv"))
    args = p.parse_args(argv)
    executables = {"base": os.path.abspath(args.base), "new": os.path.abspath(args.new)}
    check_distinct_builds(executables)

    rows, failed = [], False
    print(f"{'shape':5} {'ranks':>5} {'cell':>6} {'columns':>8} {'steps':>5} "
          f"{'base [s]':>9} {'new [s]':>9} {'median ratio':>12} {'ratio of medians':>16}")
    for cell in parse_list(args.sizes, float):
        for shape in parse_list(args.shapes):
            for ranks in parse_list(args.ranks, int):
                _, settings = settings_for(cell, 4, END_TIME, shape, False)
                def run(which):
                    r = run_once(executables[which], args.prm, settings, ranks, args.mpirun)
                    if r["status"] != "ok":
                        print(f"{which} {shape} {cell}: {r['status']}")
                        return None
                    return r
                done, any_failed = interleaved_pairs(run, args.pairs)
                failed = failed or any_failed
                times = {which: [results[which]["advance_wall_s"] for _, _, results in done]
                         for which in ("base", "new")}
                ratios = [n / b for b, n in zip(times["base"], times["new"])]
                columns = done[-1][2]["new"]["columns"] if done else None
                steps = done[-1][2]["new"]["steps"] if done else None
                for (pair, order, results), ratio in zip(done, ratios):
                    rows.append({"shape": shape, "ranks": ranks, "cell_size": cell,
                                 "columns": columns, "steps": steps, "pair": pair,
                                 "order": order,
                                 "base_advance_s": f"{results['base']['advance_wall_s']:.4f}",
                                 "new_advance_s": f"{results['new']['advance_wall_s']:.4f}",
                                 "ratio": f"{ratio:.4f}"})
                if not ratios:
                    continue
                base_median = statistics.median(times["base"])
                new_median = statistics.median(times["new"])
                print(f"{shape:5} {ranks:5d} {cell:6g} {columns:8d} {steps:5d} "
                      f"{base_median:9.3f} {new_median:9.3f} "
                      f"{statistics.median(ratios):12.3f} {new_median / base_median:16.3f}",
                      flush=True)
    write_csv(args.csv, rows, COLUMNS)
    print(f"pairs in {args.csv}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
