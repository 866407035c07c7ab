#!/usr/bin/python3
"""Which numerical options of the depth-averaged material points converge (issue 28, item 1).

Runs, for every combination the program offers of

* 'Depth averaged/Shape functions' q1, gimp, cpgimp,
* 'Depth averaged/Depth update' strain, projection,
* 'Depth averaged/FLIP fraction' 0 (PIC) and 1 (FLIP),
* 'Depth averaged/Release/Particles per direction' 2 and 4,

three exact problems at three resolutions each:

* ``rigid``: the rigid translation of ``tests/depth_averaged/rigid_translation_q1_strain.prm``
  (a weightless uniform layer 0.5 m deep over [1, 3] x [1, 2] moving at (1, 0.5) m/s for
  2 s on a flat bed; exact: every column keeps its depth and its velocity), cell sizes
  0.25, 0.125, 0.0625 m; error: the relative L1 error of the columns' depth (the line
  "Rigid translation ... depth = X (largest Y of the depth)"), and its largest value Y;
* ``Ritter`` and ``Stoker``: the dam breaks of ``prm/dam-break-channel.prm`` on the channel
  [0, 100] x [0, 4 C] (as benchmarks/depth_averaged_work_precision.py), cell sizes C = 0.5,
  0.25, 0.125 m, t = 4 s; error: the relative L1 error of the nodal depth; for Ritter also
  the front (the last node deeper than 1 % of the left depth) against the exact one, as
  a percentage of the exact distance travelled.

Wall time: the 'depth averaged: advance' row of the timer table (the time loop's steps)
and the process's wall time. One round by default (``--repeat`` for more: the median
time is kept; the errors do not change between rounds). Each run has its own temporary
output directory, removed afterwards.

Output: a line per run while it goes, a markdown table per problem at the end, and the
CSV ``--csv`` (default benchmarks/results/depth_averaged_defaults.csv): error against
wall time with the observed order between successive resolutions.

Usage:
    /usr/bin/python3 benchmarks/depth_averaged_defaults.py              # about 10 minutes
    /usr/bin/python3 benchmarks/depth_averaged_defaults.py --problems rigid --lines \\
        q1-pic-strain-2,gimp-pic-proj-4
"""

import argparse
import itertools
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import (add_orders, cpu_busy_seconds, find_executable, fmt,  # noqa: E402
                              wait_until_idle, write_csv)

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

SHAPES = ["q1", "gimp", "cpgimp"]
UPDATES = {"strain": "strain", "proj": "projection"}
FLIP = {"pic": 0.0, "flip": 1.0}
PPD = [2, 4]
ALL_LINES = [f"{s}-{f}-{u}-{n}" for s, u, f, n in
             itertools.product(SHAPES, UPDATES, FLIP, PPD)]

PROBLEMS = ["rigid", "Ritter", "Stoker"]
CELL_SIZES = {"rigid": [0.25, 0.125, 0.0625], "Ritter": [0.5, 0.25, 0.125],
              "Stoker": [0.5, 0.25, 0.125]}
SCENES = {"rigid": os.path.join("tests", "depth_averaged", "rigid_translation_q1_strain.prm"),
          "Ritter": os.path.join("prm", "dam-break-channel.prm"),
          "Stoker": os.path.join("prm", "dam-break-channel.prm")}

_RIGID_RE = re.compile(r"Rigid translation at t = [0-9.eE+-]+ s: relative L1 error of the "
                       r"columns' depth = ([0-9.eE+-]+|nan|inf) \(largest ([0-9.eE+-]+|nan|inf)")
_DAM_RE = re.compile(r"Dam break \((Ritter|Stoker)\) at t = [0-9.eE+-]+ s: relative L1 "
                     r"error of the depth = ([0-9.eE+-]+|nan|inf|-?nan)")
_FRONT_RE = re.compile(r"Front \(the last node deeper than 1 % of the left depth\) x = "
                       r"([0-9.eE+-]+) m, exact ([0-9.eE+-]+) m: error [0-9.eE+-]+ m, "
                       r"([0-9.eE+-]+) % of")
_HEADER_RE = re.compile(r"Depth-averaged flow: (\d+) columns on (\d+) cells")
_TIMER_RE = re.compile(
    r"^\|\s*(depth averaged: [a-z ]+?)\s*\|\s*(\d+)\s*\|\s*([0-9.]+(?:[eE][-+]?\d+)?)s\s*\|"
    r"\s*[0-9.]+%", re.MULTILINE)

CSV_COLUMNS = ["problem", "line", "shape", "depth_update", "flip_fraction",
               "particles_per_direction", "cell_size", "columns", "cells", "steps", "error",
               "error_max", "order", "front", "front_exact", "front_error_percent",
               "advance_wall_s", "total_wall_s", "repeats", "background_load", "status"]


def parse_line(name):
    """(shape, depth update, FLIP fraction, points per direction) of a line name."""
    shape, flip, update, ppd = name.split("-")
    return shape, UPDATES[update], FLIP[flip], int(ppd)


def settings_for(problem, line, cell_size):
    """--set overrides of the problem's scene for one run."""
    shape, update, flip, ppd = parse_line(line)
    s = {
        "Time/Output interval": 100,
        "Time/Statistics interval": 100000,
        "Depth averaged/Output grid": "false",
        "Depth averaged/Grid/Cell size": repr(cell_size),
        "Depth averaged/Shape functions": shape,
        "Depth averaged/FLIP fraction": repr(flip),
        "Depth averaged/Depth update": update,
        "Depth averaged/Release/Particles per direction": ppd,
        "Test/Enable": "false",
        "Depth averaged/Verification/Tolerance": 0,
    }
    if problem in ("Ritter", "Stoker"):
        width = float(f"{4 * cell_size:.12g}")
        s["Time/End time"] = "4.0"
        s["Depth averaged/Grid/Upper right"] = f"100, {width!r}"
        s["Depth averaged/Release/Rectangle"] = f"0, 0, 100, {width!r}"
    if problem == "Stoker":
        s["Depth averaged/Release/Depth"] = "x < 50 ? 1 : 0.5"
        s["Depth averaged/Verification/Right depth"] = 0.5
    return s


def run_slidewave(exe, problem, line, cell_size):
    """One run in a fresh temporary directory; returns a dict (status 'ok' or a reason)."""
    workdir = tempfile.mkdtemp(prefix="slidewave-da-defaults-", dir="/tmp")
    cmd = [exe]
    settings = settings_for(problem, line, cell_size)
    for key, value in list(settings.items()) + [("Output directory",
                                                 os.path.join(workdir, "out"))]:
        cmd += ["--set", f"{key}={value}"]
    cmd.append(os.path.join(REPO, SCENES[problem]))
    r = {"status": "ok"}
    try:
        t0, busy0 = time.perf_counter(), cpu_busy_seconds()
        proc = subprocess.run(cmd, cwd=workdir, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True)
        r["total_wall_s"] = time.perf_counter() - t0
        # Busy cores beyond this run's one, per second of wall time.
        r["background_load"] = max(0., (cpu_busy_seconds() - busy0) / r["total_wall_s"] - 1.)
        out = proc.stdout
        m = _HEADER_RE.search(out)
        if m:
            r["columns"], r["cells"] = int(m.group(1)), int(m.group(2))
        timers = {n: (int(c), float(w)) for n, c, w in _TIMER_RE.findall(out)}
        if "depth averaged: advance" in timers:
            r["steps"], r["advance_wall_s"] = timers["depth averaged: advance"]
        m = _RIGID_RE.search(out) if problem == "rigid" else _DAM_RE.search(out)
        if m:
            r["error"] = float(m.group(1) if problem == "rigid" else m.group(2))
            if problem == "rigid":
                r["error_max"] = float(m.group(2))
        m = _FRONT_RE.search(out)
        if m:
            r["front"], r["front_exact"] = float(m.group(1)), float(m.group(2))
            r["front_error_percent"] = float(m.group(3))
        if proc.returncode != 0:
            reason = [l for l in out.strip().splitlines() if l.startswith("slidewave:")]
            text = reason[-1] if reason else " | ".join(out.strip().splitlines()[-2:])
            r["status"] = f"failed (exit {proc.returncode}): {text[:160]}"
        elif r.get("error") is None:
            r["status"] = "failed: no error line in the output"
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    return r


def markdown(rows):
    out = []
    for problem in [p for p in PROBLEMS if any(r["problem"] == p for r in rows)]:
        sizes = sorted({r["cell_size"] for r in rows if r["problem"] == problem},
                       reverse=True)
        front = problem == "Ritter"
        out.append(f"\n**{problem}** (relative L1 error of the depth; order between the two "
                   f"finest; advance = time-loop wall time at the finest"
                   + ("; front error in % of the distance travelled, finest" if front else "")
                   + ")\n")
        out.append("| line | " + " | ".join(f"C = {c:g}" for c in sizes)
                   + " | order | advance [s] |" + (" front [%] |" if front else ""))
        out.append("|---|" + "---:|" * (len(sizes) + 2 + front))
        for line in ALL_LINES:
            group = {r["cell_size"]: r for r in rows
                     if r["problem"] == problem and r["line"] == line}
            if not group:
                continue
            cells = ["-" if c not in group else
                     (fmt(group[c].get("error"), ".3e") if group[c]["status"] == "ok"
                      else "failed") for c in sizes]
            finest = group[min(group)]
            text = (f"| {line} | " + " | ".join(cells) + f" | {fmt(finest.get('order'), '.2f')}"
                    f" | {fmt(finest.get('advance_wall_s'), '.3g')} |")
            if front:
                text += f" {fmt(finest.get('front_error_percent'), '.1f')} |"
            out.append(text)
    return "\n".join(out)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("--exe", default=os.path.join(REPO, "build", "slidewave"))
    p.add_argument("--problems", default=",".join(PROBLEMS))
    p.add_argument("--lines", default="all",
                   help="comma-separated shape-pic|flip-strain|proj-N, or 'all'")
    p.add_argument("--repeat", type=int, default=1)
    p.add_argument("--idle-wait", type=float, default=0.0,
                   help="before each round, wait up to this many seconds for an idle machine")
    p.add_argument("--csv", default=os.path.join(REPO, "benchmarks", "results",
                                                 "depth_averaged_defaults.csv"))
    args = p.parse_args(argv)
    exe = find_executable(args.exe, 60)
    lines = ALL_LINES if args.lines == "all" else args.lines.split(",")
    problems = args.problems.split(",")
    runs = [(pr, l, c) for pr in problems for l in lines for c in CELL_SIZES[pr]]
    results = {run: [] for run in runs}
    print(f"{'problem':<7} {'line':<20} {'C':>7} {'steps':>5} {'advance':>8} {'error':>10} "
          f"{'max/front':>10}  status")
    for _ in range(args.repeat):
        if args.idle_wait > 0:
            wait_until_idle(args.idle_wait)
        for run in runs:
            r = run_slidewave(exe, *run)
            results[run].append(r)
            extra = r.get("error_max", r.get("front_error_percent"))
            print(f"{run[0]:<7} {run[1]:<20} {run[2]:>7g} {fmt(r.get('steps'), 'd'):>5} "
                  f"{fmt(r.get('advance_wall_s'), '.3f'):>8} {fmt(r.get('error'), '.3e'):>10} "
                  f"{fmt(extra, '.3g'):>10}  {r['status']}", flush=True)
    rows = []
    for (problem, line, cell_size), rs in results.items():
        shape, update, flip, ppd = parse_line(line)
        row = dict(rs[-1])
        row.update(problem=problem, line=line, shape=shape, depth_update=update,
                   flip_fraction=flip, particles_per_direction=ppd, cell_size=cell_size,
                   repeats=len(rs))
        times = [r["advance_wall_s"] for r in rs if r.get("advance_wall_s") is not None]
        row["advance_wall_s"] = statistics.median(times) if times else None
        totals = [r["total_wall_s"] for r in rs if r.get("total_wall_s") is not None]
        row["total_wall_s"] = statistics.median(totals) if totals else None
        rows.append(row)
    add_orders(rows)
    write_csv(args.csv, rows, CSV_COLUMNS)
    print(markdown(rows))
    print(f"\nCSV: {args.csv}")


if __name__ == "__main__":
    main()
