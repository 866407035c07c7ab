#!/usr/bin/python3
"""Work-precision of the depth-averaged material points in their shallow-water limit.

Runs the dam break along a straight channel of ``prm/dam-break-channel.prm``
(``Physics = depth averaged``, paper 001; mu = tau_Y = 0 and no basal friction, so the
exact solution is a shallow-water dam break) in two variants:

* Ritter: 1 m of water left of x = 50 m, a dry bed right of it (the scene as shipped);
* Stoker: 0.5 m of water right of the dam ('Depth averaged/Release/Depth' =
  ``x < 50 ? 1 : 0.5`` and 'Depth averaged/Verification/Right depth' = 0.5);

on the channel [0, 100] x [0, W] with W = 4 cells ('Grid/Upper right' = 100, W and
'Release/Rectangle' = 0, 0, 100, W), cell sizes C = 1, 0.5, 0.25, 0.125, 0.0625 m
(``--quick``: down to 0.125 m; ``--cell-sizes``), to t = 4 s (no wave reaches a wall).

Lines (``--lines``; the default set varies one option at a time from the paper's choice,
plus two combinations; ``--lines all`` runs the full product of the 16):

==================  ===============  =============  ============  ==========
line                Shape functions  FLIP fraction  Depth update  points/dir
==================  ===============  =============  ============  ==========
q1-pic-strain-2     q1               0 (PIC)        strain        2  (paper 001)
gimp-pic-strain-2   gimp             0              strain        2
q1-flip-strain-2    q1               0.99 (FLIP)    strain        2
q1-pic-proj-2       q1               0              projection    2
q1-pic-strain-4     q1               0              strain        4
q1-pic-proj-4       q1               0              projection    4
gimp-pic-proj-4     gimp             0              projection    4
==================  ===============  =============  ============  ==========

(the names: shape, pic/flip, strain/proj, 'Release/Particles per direction').

Measurements
------------
* error: the line "Dam break (Ritter|Stoker) at t = 4 s: relative L1 error of the depth =
  X" printed at the end, sum_i |h_i - h(x_i, t)| a_i / sum_i h(x_i, t) a_i over the grid
  nodes;
* ``advance[s]``: wall time of the time loop's steps, the 'depth averaged: advance' row of
  the timer table (the stable-time-step reduction 'depth averaged: time step', the checks,
  statistics and output are outside it); ``total[s]``: the process's wall time, start-up
  included;
* steps: the 'step' column of the last row of OUTPUT/statistics.csv (the same as the calls
  of 'depth averaged: advance');
* order: the observed order of the error against the next coarser cell size,
  log(e_coarse / e_fine) / log(C_coarse / C_fine); the summary gives it between the two
  finest resolutions of each line.

Particles are written only at the start and the end ('Time/Output interval' = 100),
statistics only there too ('Time/Statistics interval' = 100000), no grid output ('Depth
averaged/Output grid' = false). Every run has its own temporary output directory, removed
afterwards. The study is repeated ``--repeat`` times (default 3, ``--quick`` 1) in rounds
(every run once, then every run again), so that a drift of the machine's speed touches all
runs alike; the times reported are the medians over the rounds. The errors do not change
between repetitions (the script says so if they do). A run that fails is recorded with the
reason; the study goes on.

Output: a line per run while it goes, then markdown tables (error per cell size, observed
order between the two finest resolutions, advance time at the finest) per problem; CSV
(``--csv``, default benchmarks/results/depth_averaged_work_precision.csv) and the figure
(``--png``, default doc/figures/depth-averaged-work-precision.png): error against advance
wall time, log-log, one panel Ritter, one Stoker. ``--plot-only`` redraws the figure from
the CSV.

Usage:
    /usr/bin/python3 benchmarks/depth_averaged_work_precision.py            # about 7 minutes
    /usr/bin/python3 benchmarks/depth_averaged_work_precision.py --quick    # about 1 minute
    /usr/bin/python3 benchmarks/depth_averaged_work_precision.py --lines all --repeat 1
    /usr/bin/python3 benchmarks/depth_averaged_work_precision.py --plot-only
"""

import argparse
import csv
import itertools
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import (add_orders, cpu_busy_seconds, find_executable, fmt,  # noqa: E402
                              retry_once, wait_until_idle, write_csv)

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

CELL_SIZES = [1.0, 0.5, 0.25, 0.125, 0.0625]
QUICK_CELL_SIZES = [1.0, 0.5, 0.25, 0.125]
WIDTH_CELLS = 4
END_TIME = 4.0
PROBLEMS = ["Ritter", "Stoker"]

SHAPES = ["q1", "gimp"]
FLIP = {"pic": 0.0, "flip": 0.99}
UPDATES = {"strain": "strain", "proj": "projection"}
PPD = [2, 4]

DEFAULT_LINES = ["q1-pic-strain-2", "gimp-pic-strain-2", "q1-flip-strain-2",
                 "q1-pic-proj-2", "q1-pic-strain-4", "q1-pic-proj-4", "gimp-pic-proj-4"]
ALL_LINES = [f"{s}-{f}-{u}-{n}" for s, f, u, n in
             itertools.product(SHAPES, FLIP, UPDATES, PPD)]

_ERROR_RE = re.compile(r"Dam break \((Ritter|Stoker)\) at t = [0-9.eE+-]+ s: relative L1 "
                       r"error of the depth = ([0-9.eE+-]+|nan|inf|-?nan)")
_HEADER_RE = re.compile(r"Depth-averaged flow: (\d+) columns on (\d+) cells")
# Rows of the timer table of rank 0, e.g. "| depth averaged: advance  |  69 |  0.00929s |  18% |"
_TIMER_RE = re.compile(
    r"^\|\s*(depth averaged: [a-z ]+?)\s*\|\s*(\d+)\s*\|\s*([0-9.]+(?:[eE][-+]?\d+)?)s\s*\|"
    r"\s*[0-9.]+%", re.MULTILINE)

CSV_COLUMNS = ["problem", "line", "shape", "flip_fraction", "depth_update",
               "particles_per_direction", "cell_size", "columns", "cells", "steps", "error",
               "order", "advance_wall_s", "advance_min_s", "advance_max_s", "total_wall_s",
               "repeats", "background_load", "status"]


def parse_line(name):
    """(shape, FLIP fraction, depth update, points per direction) of a line name."""
    shape, flip, update, ppd = name.split("-")
    return shape, FLIP[flip], UPDATES[update], int(ppd)


def settings_for(problem, line, cell_size):
    """--set overrides of prm/dam-break-channel.prm for one run."""
    shape, flip, update, ppd = parse_line(line)
    width = float(f"{WIDTH_CELLS * cell_size:.12g}")
    s = {
        "Time/End time": repr(END_TIME),
        "Time/Output interval": 100,
        "Time/Statistics interval": 100000,
        "Depth averaged/Output grid": "false",
        "Depth averaged/Grid/Cell size": repr(cell_size),
        "Depth averaged/Grid/Upper right": f"100, {width!r}",
        "Depth averaged/Release/Rectangle": f"0, 0, 100, {width!r}",
        "Depth averaged/Shape functions": shape,
        "Depth averaged/FLIP fraction": repr(flip),
        "Depth averaged/Depth update": update,
        "Depth averaged/Release/Particles per direction": ppd,
    }
    if problem == "Stoker":
        s["Depth averaged/Release/Depth"] = "x < 50 ? 1 : 0.5"
        s["Depth averaged/Verification/Right depth"] = 0.5
    return s


def children_cpu_seconds():
    """User + system CPU seconds of this script's finished child processes."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_slidewave(exe, prm, settings, problem):
    """One run in a fresh temporary directory; returns a dict (status 'ok' or a reason)."""
    workdir = tempfile.mkdtemp(prefix="slidewave-da-wp-", dir="/tmp")
    outdir = os.path.join(workdir, "out")
    cmd = [exe]
    for key, value in list(settings.items()) + [("Output directory", outdir)]:
        cmd += ["--set", f"{key}={value}"]
    cmd.append(os.path.abspath(prm))
    r = {"status": "ok", "columns": None, "cells": None, "steps": None, "error": None,
         "advance_wall_s": None, "total_wall_s": None, "background_load": None}
    try:
        t0, busy0, own0 = time.perf_counter(), cpu_busy_seconds(), children_cpu_seconds()
        proc = subprocess.run(cmd, cwd=workdir, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True)
        r["total_wall_s"] = time.perf_counter() - t0
        # Cores busy with other work during the run: the machine's busy CPU time less the
        # run's own, per second of wall time.
        r["background_load"] = max(0., (cpu_busy_seconds() - busy0
                                        - (children_cpu_seconds() - own0)) / r["total_wall_s"])
        out = proc.stdout
        m = _HEADER_RE.search(out)
        if m:
            r["columns"], r["cells"] = int(m.group(1)), int(m.group(2))
        timers = {n: (int(c), float(w)) for n, c, w in _TIMER_RE.findall(out)}
        if "depth averaged: advance" in timers:
            r["steps"], r["advance_wall_s"] = timers["depth averaged: advance"]
        m = _ERROR_RE.search(out)
        if m:
            r["error"] = float(m.group(2))
            if m.group(1) != problem:
                r["status"] = f"failed: the program solved {m.group(1)}, not {problem}"
        stats = os.path.join(outdir, "statistics.csv")
        if os.path.isfile(stats):
            with open(stats, newline="") as f:
                rows = list(csv.DictReader(f))
            if rows and rows[-1].get("step"):
                r["steps"] = int(rows[-1]["step"])
        if proc.returncode != 0:
            reason = [l for l in out.strip().splitlines() if l.startswith("slidewave:")]
            text = reason[-1] if reason else " | ".join(out.strip().splitlines()[-2:])
            r["status"] = f"failed (exit {proc.returncode}): {text[:200]}"
        elif r["error"] is None:
            r["status"] = "failed: no dam-break error line in the output"
        elif r["advance_wall_s"] is None:
            r["status"] = "failed: no 'depth averaged: advance' row in the timer table"
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    return r


def run_retrying(exe, prm, settings, problem, wait_s):
    """run_slidewave, run again once after a failure that is not the program's own
    (the executable being rebuilt meanwhile: missing, busy, or no timer table)."""
    return retry_once(lambda: run_slidewave(exe, prm, settings, problem), exe, wait_s)


# --------------------------------------------------------------------------------------
# Tables and figure
# --------------------------------------------------------------------------------------

HEADER = (f"{'problem':<7} {'line':<18} {'C[m]':>6} {'columns':>7} {'cells':>6} "
          f"{'steps':>5} {'advance[s]':>10} {'total[s]':>8} {'L1 error':>10} {'order':>6} "
          f"{'bg':>4}")


def row_line(row):
    line = (f"{row['problem']:<7} {row['line']:<18} {row['cell_size']:>6g} "
            f"{fmt(row['columns'], 'd'):>7} {fmt(row['cells'], 'd'):>6} "
            f"{fmt(row['steps'], 'd'):>5} {fmt(row['advance_wall_s'], '.4g'):>10} "
            f"{fmt(row['total_wall_s'], '.2f'):>8} {fmt(row['error'], '.4e'):>10} "
            f"{fmt(row['order'], '.2f'):>6} {fmt(row['background_load'], '.1f'):>4}")
    if row["status"] != "ok":
        line += f"  {row['status']}"
    return line


def markdown(rows):
    """Markdown tables: per problem, one row per line."""
    out = []
    sizes = sorted({r["cell_size"] for r in rows}, reverse=True)
    lines_order = []
    for r in rows:
        if r["line"] not in lines_order:
            lines_order.append(r["line"])
    for problem in [p for p in PROBLEMS if any(r["problem"] == p for r in rows)]:
        out.append(f"\n**{problem}** (relative L1 error of the depth at t = 4 s; order = "
                   f"observed order between the two finest cell sizes; advance = median "
                   f"time-loop wall time at the finest)\n")
        out.append("| line | " + " | ".join(f"C = {c:g}" for c in sizes)
                   + " | order (finest) | advance [s] (finest) |")
        out.append("|---|" + "---:|" * (len(sizes) + 2))
        for line in lines_order:
            group = {r["cell_size"]: r for r in rows
                     if r["problem"] == problem and r["line"] == line}
            if not group:
                continue
            cells = []
            for c in sizes:
                r = group.get(c)
                cells.append("-" if r is None else
                             (fmt(r["error"], ".3e") if r["status"] == "ok" else "failed"))
            finest = group.get(min(group))
            out.append(f"| {line} | " + " | ".join(cells) +
                       f" | {fmt(finest['order'], '.2f')} | "
                       f"{fmt(finest['advance_wall_s'], '.3g')} |")
    return "\n".join(out)


def to_number(value, kind):
    if value in ("", None):
        return None
    return kind(value)


def read_csv(path):
    rows = []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            row = dict(r)
            for k in ("flip_fraction", "cell_size", "error", "order", "advance_wall_s",
                      "advance_min_s", "advance_max_s", "total_wall_s", "background_load"):
                row[k] = to_number(r[k], float)
            for k in ("particles_per_direction", "columns", "cells", "steps", "repeats"):
                row[k] = to_number(r[k], int)
            rows.append(row)
    return rows


def line_style(line):
    """Colour by shape/points, line style by depth update, marker by PIC/FLIP."""
    shape, flip, update, ppd = parse_line(line)
    colour = {("q1", 2): "tab:red", ("q1", 4): "tab:orange",
              ("gimp", 2): "tab:blue", ("gimp", 4): "tab:purple"}[(shape, ppd)]
    style = "-" if update == "strain" else "--"
    marker = "o" if flip == 0 else "^"
    return colour, style, marker


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    problems = [p for p in PROBLEMS if any(r["problem"] == p for r in rows)]
    fig, axes = plt.subplots(1, len(problems), figsize=(6.4 * len(problems), 6.0),
                             squeeze=False)
    fig.subplots_adjust(left=0.07, right=0.98, top=0.89, bottom=0.22, wspace=0.22)
    lines_order = []
    for r in rows:
        if r["line"] not in lines_order:
            lines_order.append(r["line"])
    handles = {}
    for ax, problem in zip(axes[0], problems):
        for line in lines_order:
            group = sorted((r for r in rows if r["problem"] == problem and r["line"] == line
                            and r["status"] == "ok" and r["error"] and r["advance_wall_s"]),
                           key=lambda r: -r["cell_size"])
            if not group:
                continue
            colour, style, marker = line_style(line)
            handles[line], = ax.loglog([r["advance_wall_s"] for r in group],
                                       [r["error"] for r in group], color=colour, ls=style,
                                       marker=marker, ms=5, lw=1.4, label=line)
            finest = group[-1]
            if finest.get("order") is not None:
                ax.annotate(f"{finest['order']:+.2f}", (finest["advance_wall_s"],
                                                       finest["error"]),
                            textcoords="offset points", xytext=(5, -3), fontsize=7,
                            color=colour, fontweight="bold")
            if line == lines_order[0]:
                for r in group[:-1]:
                    ax.annotate(f"C = {r['cell_size']:g}", (r["advance_wall_s"], r["error"]),
                                textcoords="offset points", xytext=(-6, 6), fontsize=7,
                                color=colour)
        ax.set_title(f"{problem}: h_l = 1 m, h_r = "
                     f"{'0 (dry bed)' if problem == 'Ritter' else '0.5 m'}, t = 4 s",
                     fontsize=10)
        ax.set_xlabel("wall time of the time loop ('depth averaged: advance') [s]")
        ax.set_ylabel("relative L1 error of the nodal depth")
        ax.grid(True, which="both", alpha=0.3)
        ax.margins(x=0.12)
    fig.legend([handles[l] for l in lines_order if l in handles],
               [l for l in lines_order if l in handles], loc="lower center",
               ncol=min(4, len(handles)), fontsize=8,
               title="shape - PIC (FLIP fraction 0) / FLIP (0.99) - depth update strain / "
                     "projection - points per cell direction; bold numbers: observed order "
                     "between the two finest cell sizes", title_fontsize=8)
    fig.suptitle("Depth-averaged MPM, shallow-water limit: dam break on [0, 100] x "
                 "[0, 4 C] m, cell sizes C (labels on the first line),\n"
                 "error against the median wall time of the repetitions", fontsize=10)
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=120)
    plt.close(fig)


# --------------------------------------------------------------------------------------
# Main
# --------------------------------------------------------------------------------------

def main(argv=None):
    p = argparse.ArgumentParser(
        description="Work-precision of the depth-averaged material points on the Ritter "
                    "and Stoker dam breaks (see the module docstring).",
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("--exe", default=os.path.join(REPO, "build", "slidewave"),
                   help="SlideWave executable")
    p.add_argument("--prm", default=os.path.join(REPO, "prm", "dam-break-channel.prm"),
                   help="dam-break channel scene")
    p.add_argument("--wait", type=float, default=60.0,
                   help="seconds to wait for the executable to appear (also before the "
                        "one retry of a run that failed for no reason of its own)")
    p.add_argument("--quick", action="store_true",
                   help="cell sizes 1 to 0.125 m, one repetition")
    p.add_argument("--cell-sizes",
                   type=lambda s: [float(c) for c in s.split(",") if c.strip()],
                   help="comma-separated cell sizes [m] (default 1,0.5,0.25,0.125,0.0625)")
    p.add_argument("--lines", default=",".join(DEFAULT_LINES),
                   help="comma-separated lines shape-pic|flip-strain|proj-N, or 'all'")
    p.add_argument("--problems", default=",".join(PROBLEMS), help="Ritter, Stoker")
    p.add_argument("--repeat", type=int, help="rounds of the study (default 3; --quick 1); "
                   "the median time is reported")
    p.add_argument("--idle-wait", type=float, default=20.0,
                   help="before each round, wait up to this many seconds for the machine "
                        "to be idle; 0: do not wait")
    p.add_argument("--csv", default=os.path.join(REPO, "benchmarks", "results",
                                                 "depth_averaged_work_precision.csv"))
    p.add_argument("--png", default=os.path.join(REPO, "doc", "figures",
                                                 "depth-averaged-work-precision.png"))
    p.add_argument("--plot-only", action="store_true",
                   help="only redraw the figure (and the tables) from the CSV")
    args = p.parse_args(argv)

    if args.plot_only:
        rows = read_csv(args.csv)
        print(markdown(rows))
        plot(rows, args.png)
        print(f"wrote {args.png}")
        return 0

    exe = find_executable(os.path.abspath(args.exe), args.wait)
    if not os.path.isfile(args.prm):
        sys.exit(f"scene file not found: {args.prm} (option --prm)")
    sizes = args.cell_sizes or (QUICK_CELL_SIZES if args.quick else CELL_SIZES)
    lines = ALL_LINES if args.lines.strip() == "all" else \
        [l.strip() for l in args.lines.split(",") if l.strip()]
    for line in lines:
        try:
            parse_line(line)
        except (KeyError, ValueError):
            sys.exit(f"bad line name '{line}' (shape-pic|flip-strain|proj-N, e.g. "
                     "q1-pic-strain-2)")
    problems = [q.strip() for q in args.problems.split(",") if q.strip()]
    repeat = args.repeat or (1 if args.quick else 3)
    cases = [(q, l, c) for q in problems for l in lines for c in sizes]

    t_start = time.perf_counter()
    exe_mtime = os.path.getmtime(exe)
    print(f"SlideWave depth-averaged work-precision: {exe}, {args.prm}; {len(cases)} runs x "
          f"{repeat} round(s); cell sizes {sizes} m, channel width {WIDTH_CELLS} cells, "
          f"t = {END_TIME:g} s")
    results = {case: [] for case in cases}
    for round_ in range(repeat):
        if args.idle_wait > 0:
            load = wait_until_idle(args.idle_wait)
            print(f"round {round_ + 1}/{repeat}: background load {load:.2f} cores",
                  flush=True)
        if round_ == 0:
            print(HEADER)
            print("-" * len(HEADER))
        for case in cases:
            q, l, c = case
            if results[case] and results[case][0]["status"] != "ok":
                continue  # a failed run fails again
            r = run_retrying(exe, args.prm, settings_for(q, l, c), q, args.wait)
            results[case].append(r)
            if round_ == 0:
                row = {"problem": q, "line": l, "cell_size": c, "order": None}
                row.update(r)
                print(row_line(row), flush=True)

    rows = []
    changed = []
    for case in cases:
        q, l, c = case
        shape, flip, update, ppd = parse_line(l)
        runs = results[case]
        first = runs[0]
        row = {"problem": q, "line": l, "shape": shape, "flip_fraction": flip,
               "depth_update": update, "particles_per_direction": ppd, "cell_size": c}
        row.update({k: first[k] for k in ("status", "columns", "cells", "steps", "error")})
        ok = [r for r in runs if r["status"] == "ok"]
        if len(ok) != len(runs):
            row["status"] = next(r["status"] for r in runs if r["status"] != "ok")
        if ok:
            adv = [r["advance_wall_s"] for r in ok]
            row.update({"advance_wall_s": statistics.median(adv), "advance_min_s": min(adv),
                        "advance_max_s": max(adv),
                        "total_wall_s": statistics.median(r["total_wall_s"] for r in ok),
                        "background_load": statistics.median(r["background_load"]
                                                             for r in ok),
                        "repeats": len(ok)})
            if any(r["error"] != first["error"] or r["steps"] != first["steps"] for r in ok):
                changed.append(case)
        rows.append(row)
    add_orders(rows)

    print("-" * len(HEADER))
    print(f"Medians over {repeat} round(s) (advance, total, bg):")
    print(HEADER)
    for row in rows:
        print(row_line(row))
    failed = [r for r in rows if r["status"] != "ok"]
    print(f"{len(rows)} cases ({len(failed)} failed) in {time.perf_counter() - t_start:.0f} s. "
          "advance = median wall time of 'depth averaged: advance'; total = process; "
          "order = against the next coarser C; bg = median cores busy with other work "
          "during the run (0: an idle machine).")
    if os.path.getmtime(exe) != exe_mtime:
        print(f"WARNING: {exe} was rebuilt during the study; the runs may mix two builds.")
    if changed:
        print("WARNING: the error or the step count changed between repetitions for "
              + ", ".join(f"{q}/{l}/{c:g}" for q, l, c in changed)
              + " (was the executable rebuilt meanwhile?)")
    write_csv(args.csv, rows, CSV_COLUMNS)
    print(f"wrote {args.csv}")
    plot(rows, args.png)
    print(f"wrote {args.png}")
    print(markdown(rows))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
