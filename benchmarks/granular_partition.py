#!/usr/bin/env python3
"""How the grid's partition among two ranks sets the speed of a granular-water scene.

The grid shared by the skeleton and the water is split among the ranks by one weight per
cell: 1000 for the cell, 'Material points/Load balancing/Particle weight' per point
(default 1,000,000) and, in this physics, 1,000,000 per degree of freedom of the water (12
per cell) and of the phase field (4): a cell of water weighs as much as 16 points. (Before
2026-12-08 the water's degrees of freedom weighed 100 each, as in the free-surface flow
alone, and the points' default handed one rank nearly all of the water.) This script runs
a scene at several point weights on two ranks, and on one rank, in interleaved rounds
(the order rotates from round to round), and prints per run the wall time, each rank's
cells at the last output and the timer summary's water and exchange times (rank 0); then
per setting the median wall time and its speed-up over the one-rank median. Each row
records the repository's commit (``build``: the executable is taken to be its build).

Usage: benchmarks/granular_partition.py [--scene prm/underwater-collapse-loose.prm]
       [--end-time 0.1] [--weights 0 250000 1000000 4000000 16000000] [--rounds 3]
       [--set 'A/B=v' ...]
       [--exe build/slidewave] [--csv FILE]
Results go to ``benchmarks/results/granular_partition.csv`` (one row per run).
"""
import argparse
import glob
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import find_executable, fmt, wait_until_idle, write_csv  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
COLUMNS = ["round", "ranks", "particle_weight", "wall_s", "water_s", "exchange_s",
           "cells_per_rank", "background_load", "build", "status"]


def timer_row(log, name):
    """The wall time of the timer summary's row ``name`` (rank 0's table), or None."""
    found = re.findall(r"^\| " + re.escape(name) + r"\s+\|\s+\d+\s+\|\s+([0-9.e+-]+)s",
                       log, re.MULTILINE)
    return float(found[-1]) if found else None


def cells_per_rank(output_dir):
    """Each rank's cells in the last output of the water's fields (its .vtu pieces)."""
    pieces = sorted(glob.glob(os.path.join(output_dir, "free_surface", "fields_*.vtu")))
    if not pieces:
        return None
    last = pieces[-1].rsplit("_", 1)[1].split(".")[0]
    counts = []
    for piece in sorted(glob.glob(os.path.join(output_dir, "free_surface",
                                               f"fields_{last}.*.vtu"))):
        with open(piece, errors="replace") as f:
            match = re.search(r'NumberOfCells="(\d+)"', f.read(4096))
        counts.append(int(match.group(1)) if match else -1)
    return "/".join(str(c) for c in counts)


def commit_of(repo):
    """The repository's commit (short), with '+changes' when its tracked files differ."""
    def git(*args):
        return subprocess.run(["git", "-C", repo] + list(args), capture_output=True,
                              text=True).stdout.strip()
    head = git("rev-parse", "--short", "HEAD") or "unknown"
    return head + ("+changes" if git("status", "--porcelain", "--untracked-files=no") else "")


def run(exe, scene, ranks, weight, end_time, settings, work, r):
    # A directory of its own per run: a failed run reports no cells, not an earlier run's.
    out = os.path.join(work, f"round{r}_np{ranks}_w{weight}")
    command = [exe, scene, "--set", f"Output directory={out}", "--set",
               f"Time/End time={end_time}", "--set",
               f"Material points/Load balancing/Particle weight={weight}"]
    for s in settings:
        command += ["--set", s]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks), "-x", "OPENBLAS_CORETYPE"] + command
    env = dict(os.environ, OPENBLAS_CORETYPE="Haswell", OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    load = wait_until_idle(60)
    start = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True, env=env)
    wall = time.perf_counter() - start
    log = done.stdout + done.stderr
    status = "ok" if done.returncode == 0 else (log.strip().splitlines() or ["failed"])[-1]
    return {"ranks": ranks, "particle_weight": weight, "wall_s": wall,
            "water_s": timer_row(log, "granular: water"),
            "exchange_s": timer_row(log, "granular: exchange"),
            "cells_per_rank": cells_per_rank(out), "background_load": load,
            "status": status}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scene", default=os.path.join(REPO, "prm",
                                                        "underwater-collapse-loose.prm"))
    parser.add_argument("--end-time", type=float, default=0.1)
    parser.add_argument("--weights", type=int, nargs="+",
                        default=[0, 250000, 1000000, 4000000, 16000000])
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--set", dest="settings", action="append", default=[],
                        help="a further --set of slidewave (repeatable)")
    parser.add_argument("--exe", default=os.path.join(REPO, "build", "slidewave"))
    parser.add_argument("--csv", default=os.path.join(REPO, "benchmarks", "results",
                                                      "granular_partition.csv"))
    args = parser.parse_args()
    exe = find_executable(args.exe, 0)
    # One rank (its weight plays no part) and two ranks at each weight.
    settings = [(1, args.weights[-1])] + [(2, w) for w in args.weights]
    rows = []
    build = commit_of(REPO)
    with tempfile.TemporaryDirectory() as work:
        for r in range(args.rounds):
            shift = r % len(settings)
            for ranks, weight in settings[shift:] + settings[:shift]:
                row = run(exe, args.scene, ranks, weight, args.end_time, args.settings, work, r)
                row["round"] = r
                row["build"] = build
                rows.append(row)
                print(f"round {r}  ranks {ranks}  weight {weight:>8}  wall {row['wall_s']:7.2f} s"
                      f"  water {fmt(row['water_s'], '7.2f')} s  exchange "
                      f"{fmt(row['exchange_s'], '6.2f')} s  cells {row['cells_per_rank']}"
                      f"  load {row['background_load']:.2f}  {row['status']}", flush=True)
    write_csv(args.csv, rows, COLUMNS)

    def median(ranks, weight):
        walls = [row["wall_s"] for row in rows if row["ranks"] == ranks and row["status"] == "ok"
                 and (ranks == 1 or row["particle_weight"] == weight)]
        return statistics.median(walls) if walls else None

    one = median(1, None)
    print(f"\none rank: median {fmt(one, '.2f')} s")
    for weight in args.weights:
        two = median(2, weight)
        speedup = one / two if one and two else None
        print(f"two ranks, particle weight {weight:>8}: median {fmt(two, '.2f')} s, "
              f"speed-up over one rank {fmt(speedup, '.2f')}")
    print(f"rows: {args.csv}")


if __name__ == "__main__":
    main()
