#!/usr/bin/python3
"""Work-precision of the depth-averaged material points on every exact solution they have.

Error against wall time, for each numerical option varied one at a time from the defaults
(issue 28: GIMP, 'Depth update = projection', 4 x 4 columns per cell, FLIP fraction 0.8,
'Split stretch = 1.5'; until the columns were split, PIC without splitting), on five exact
problems:

* ``rigid``: the rigid translation of ``tests/depth_averaged/rigid_translation_q1_strain.prm``
  (a weightless uniform layer 0.5 m deep over [1, 3] x [1, 2] moving at (1, 0.5) m/s for
  2 s; exact: every column keeps its depth), cell sizes 0.25, 0.125, 0.0625 m; error: the
  relative L1 error of the columns' depth;
* ``Stoker`` and ``Ritter``: the dam break of ``prm/dam-break-channel.prm`` (mu = tau_Y = 0,
  no friction: shallow water) on the channel [0, 100] x [0, 4 C], 1 m of water left of
  x = 50 m, 0.5 m (Stoker) or a dry bed (Ritter) right of it, t = 4 s, cell sizes C = 1 to
  0.0625 m; error: the relative L1 error of the nodal depth and, beside it, that of the
  columns' own depths (``column_error``: sum_p |h_p - h(x_p)| A_p / integral of h); for
  Ritter also the front;
* ``slope``: the dry-bed dam break on a 40 deg plane with Coulomb friction phi = 20 deg of
  ``prm/dam-break-on-slope.prm`` (Mangeney et al. 2000; reservoir 1 m deep over [8, 28]),
  on [0, 64] x [0, 4 C], t = 2 s, C = 0.5 to 0.0625 m; error: the relative L1 error of the
  nodal depth and that of the columns' own depths, as for Stoker and Ritter; the front;
* ``block``: the slab sliding on 40 deg with phi = 15 deg of
  ``tests/depth_averaged/sliding_block_40.prm``, C = 0.5 m, 1 s; error: the relative error
  of the horizontal acceleration momentum_x / (M t) (round-off for every option).

Both depth errors are reported because the nodal depth, the deposit sum_p V_p N_i(x_p) / a_i,
carries a quadrature error set by the columns' spacing relative to the cell, which does not
shrink at a fixed number of columns per cell; the columns' own error has no such floor.
(Runs of a program that does not print the columns' error, and the CSV's older rows, have
none.)

The front is where the nodal depth first exceeds 1 % of the release depth, against the
same point of the exact solution, in per cent of the exact distance travelled (the line
"Front (the last node deeper than 1 % ...)" of the program).

Lines (``--lines``), named shape-transfer-update-N[-sX]:

==========================  ===============  =============  ============  ==========  =============
line                        Shape functions  FLIP fraction  Depth update  points/dir  Split stretch
==========================  ===============  =============  ============  ==========  =============
gimp-flip80-proj-4-s1.5     gimp             0.8            projection    4           1.5 (the defaults)
gimp-flip80-proj-4-s0       gimp             0.8            projection    4           0 (no splitting)
gimp-pic-proj-4-s1.5        gimp             0 (PIC)        projection    4           1.5
gimp-flip80-proj-4-s2       gimp             0.8            projection    4           2
q1-flip80-proj-4-s1.5       q1               0.8            projection    4           1.5
gimp-flip80-strain-4-s1.5   gimp             0.8            strain        4           1.5
gimp-flip80-proj-2-s1.5     gimp             0.8            projection    2           1.5
gimp-pic-proj-4-s0          gimp             0              projection    4           0 (the defaults before splitting)
q1-pic-strain-2-s0          q1               0              strain        2           0 (paper 001)
==========================  ===============  =============  ============  ==========  =============

(``flipNN`` is a FLIP fraction 0.NN, ``pic`` 0, ``flip`` 1; without ``-sX`` the program's
default split stretch.)

Measurements: the error lines the program prints at the end; ``advance[s]``: the
'depth averaged: advance' row of the timer table (the time loop's steps; start-up, the
stable-step reduction, checks and output are outside it); ``total[s]``: the process;
``order``: log(e_coarse / e_fine) / log(C_coarse / C_fine) against the next coarser C;
``column_order``: the same of ``column_error``.
Every run has its own temporary output directory (particles only at the start and the end,
no statistics rows between, no grid output), removed afterwards. Every run is started
with ``nice`` (``--nice``, default 10; the machine is shared). The study is repeated
``--repeat`` times (default 3) in rounds (every run once, then every run again), so that a
drift of the machine's speed touches all runs alike; the times reported are the medians
over the rounds, and each row records the median background load (cores busy with other
work during the run). The errors do not change between rounds (the script says so if they
do). A run that fails is recorded with the reason; the study goes on.

Output: a line per run while it goes, markdown tables per problem, the CSV ``--csv``
(default benchmarks/results/depth_averaged_work_precision.csv) and the figure ``--png``
(default doc/figures/depth-averaged-work-precision.png): error against advance wall time,
log-log, one panel per problem (for the defaults also the columns' own error, dashed with
hollow markers), and the front error of Ritter and of the slope. With ``--merge`` the rows
of the existing CSV whose (problem, line, cell size) are not run this time are kept and the
others replaced (the orders recomputed over the merged rows); without it the CSV holds only
this study. ``--plot-only`` redraws the figure and the tables from the CSV.

Usage:
    /usr/bin/python3 benchmarks/depth_averaged_work_precision.py               # ~40 minutes
    /usr/bin/python3 benchmarks/depth_averaged_work_precision.py --quick       # ~4 minutes
    /usr/bin/python3 benchmarks/depth_averaged_work_precision.py --problems Ritter,slope \\
        --lines gimp-flip80-proj-4-s1.5,gimp-pic-proj-4-s0 --repeat 1
    /usr/bin/python3 benchmarks/depth_averaged_work_precision.py --merge --problems Stoker \\
        --lines gimp-flip80-proj-4-s1.5 --repeat 1    # only these rows of the CSV replaced
    /usr/bin/python3 benchmarks/depth_averaged_work_precision.py --plot-only
"""

import argparse
import csv
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
from depth_averaged_lines import (  # noqa: E402
    CELL_SIZES, DEFAULT_LINES, DEFAULTS, FRONT_PROBLEMS, PAPER_001, PROBLEMS, QUICK_CELL_SIZES,
    QUICK_LINES, REPO, SCENES, SHAPES, TITLES, UPDATES, parse_line, settings_for, split_of)

_RIGID_RE = re.compile(r"Rigid translation at t = [0-9.eE+-]+ s: relative L1 error of the "
                       r"columns' depth = ([0-9.eE+-]+|nan|inf)")
# The dam breaks: the nodal depth's error, then (newer programs) the columns' own.
_COLUMNS = r"(?: \(the columns' own depths: (-?nan|-?inf|[0-9.eE+-]+)\))?"
_DAM_RE = re.compile(r"Dam break \((?:Ritter|Stoker)\) at t = [0-9.eE+-]+ s: relative L1 "
                     r"error of the depth = (-?nan|-?inf|[0-9.eE+-]+)" + _COLUMNS)
_SLOPE_RE = re.compile(r"Dam break on a [0-9.]+ deg slope \(Mangeney et al. 2000\) at t = "
                       r"[0-9.eE+-]+ s: relative L1 error of the depth = "
                       r"(-?nan|-?inf|[0-9.eE+-]+)" + _COLUMNS)
_BLOCK_RE = re.compile(r"Sliding block on a [0-9.]+ deg slope at t = [0-9.eE+-]+ s: .* "
                       r"relative error ([0-9.eE+-]+|nan|inf)")
ERROR_RE = {"rigid": _RIGID_RE, "Stoker": _DAM_RE, "Ritter": _DAM_RE, "slope": _SLOPE_RE,
            "block": _BLOCK_RE}
_FRONT_RE = re.compile(r"Front \(the last node deeper than 1 % of the left depth\) x = "
                       r"([0-9.eE+-]+) m, exact ([0-9.eE+-]+) m: error [0-9.eE+-]+ m, "
                       r"([0-9.eE+-]+) % of")
_HEADER_RE = re.compile(r"Depth-averaged flow: (\d+) columns on (\d+) cells")
# Rows of the timer table of rank 0, e.g. "| depth averaged: advance  |  69 |  0.00929s |  18% |"
_TIMER_RE = re.compile(
    r"^\|\s*(depth averaged: [a-z ]+?)\s*\|\s*(\d+)\s*\|\s*([0-9.]+(?:[eE][-+]?\d+)?)s\s*\|"
    r"\s*[0-9.]+%", re.MULTILINE)

CSV_COLUMNS = ["problem", "line", "shape", "flip_fraction", "depth_update",
               "particles_per_direction", "cell_size", "columns", "cells", "steps", "error",
               "order", "column_error", "column_order", "front", "front_exact",
               "front_error_percent", "advance_wall_s", "advance_min_s", "advance_max_s",
               "total_wall_s", "repeats", "background_load", "status"]


def children_cpu_seconds():
    """User + system CPU seconds of this script's finished child processes."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_slidewave(exe, problem, line, cell_size, niceness):
    """One run in a fresh temporary directory; returns a dict (status 'ok' or a reason)."""
    workdir = tempfile.mkdtemp(prefix="slidewave-da-wp-", dir="/tmp")
    cmd = (["nice", "-n", str(niceness)] if niceness else []) + [exe]
    settings = settings_for(problem, line, cell_size)
    for key, value in list(settings.items()) + [("Output directory",
                                                 os.path.join(workdir, "out"))]:
        cmd += ["--set", f"{key}={value}"]
    cmd.append(os.path.join(REPO, SCENES[problem]))
    r = {"status": "ok", "columns": None, "cells": None, "steps": None, "error": None,
         "column_error": None, "front": None, "front_exact": None, "front_error_percent": None,
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
        m = ERROR_RE[problem].search(out)
        if m:
            r["error"] = float(m.group(1))
            if len(m.groups()) >= 2 and m.group(2) is not None:
                r["column_error"] = float(m.group(2))
        m = _FRONT_RE.search(out)
        if m:
            r["front"], r["front_exact"] = float(m.group(1)), float(m.group(2))
            r["front_error_percent"] = float(m.group(3))
        if proc.returncode != 0:
            reason = [l for l in out.strip().splitlines() if l.startswith("slidewave:")]
            text = reason[-1] if reason else " | ".join(out.strip().splitlines()[-2:])
            r["status"] = f"failed (exit {proc.returncode}): {text[:200]}"
        elif r["error"] is None:
            r["status"] = "failed: no error line in the output"
        elif r["advance_wall_s"] is None:
            r["status"] = "failed: no 'depth averaged: advance' row in the timer table"
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    return r


# --------------------------------------------------------------------------------------
# Tables and figure
# --------------------------------------------------------------------------------------

HEADER = (f"{'problem':<7} {'line':<18} {'C[m]':>6} {'columns':>7} {'cells':>6} "
          f"{'steps':>5} {'advance[s]':>10} {'total[s]':>8} {'error':>10} {'order':>6} "
          f"{'col.error':>10} {'c.ord':>6} {'front%':>7} {'bg':>4}")


def row_line(row):
    line = (f"{row['problem']:<7} {row['line']:<18} {row['cell_size']:>6g} "
            f"{fmt(row['columns'], 'd'):>7} {fmt(row['cells'], 'd'):>6} "
            f"{fmt(row['steps'], 'd'):>5} {fmt(row['advance_wall_s'], '.4g'):>10} "
            f"{fmt(row['total_wall_s'], '.2f'):>8} {fmt(row['error'], '.4e'):>10} "
            f"{fmt(row['order'], '.2f'):>6} {fmt(row.get('column_error'), '.4e'):>10} "
            f"{fmt(row.get('column_order'), '.2f'):>6} "
            f"{fmt(row['front_error_percent'], '.1f'):>7} "
            f"{fmt(row['background_load'], '.1f'):>4}")
    if row["status"] != "ok":
        line += f"  {row['status']}"
    return line


def ordered_lines(rows):
    lines = []
    for r in rows:
        if r["line"] not in lines:
            lines.append(r["line"])
    return lines


def add_column_orders(rows):
    """``add_orders`` of the columns' own error: row["column_order"] against the next
    coarser cell size of the same problem and line (None where either has none)."""
    add_orders(rows, error="column_error", order="column_order")


def markdown(rows):
    """Markdown tables: per problem, one row per line (error per cell size, the observed
    order between the two finest, the median advance time at the finest), below it, where
    the runs have it, a row of the columns' own error and its order; the front error per
    cell size for the dry-bed problems."""
    out = []
    for problem in [p for p in PROBLEMS if any(r["problem"] == p for r in rows)]:
        sizes = sorted({r["cell_size"] for r in rows if r["problem"] == problem},
                       reverse=True)
        columns = any(r.get("column_error") is not None for r in rows
                      if r["problem"] == problem)
        out.append(f"\n**{problem}**: {TITLES[problem]}; order between the two finest; "
                   "advance = median time-loop wall time at the finest"
                   + ("; the rows '..., columns' own depths': the error of the columns' own "
                      "depths in the same runs" if columns else "") + "\n")
        out.append("| line | " + " | ".join(f"C = {c:g}" for c in sizes)
                   + " | order | advance [s] |")
        out.append("|---|" + "---:|" * (len(sizes) + 2))
        for line in ordered_lines(rows):
            group = {r["cell_size"]: r for r in rows
                     if r["problem"] == problem and r["line"] == line}
            if not group:
                continue
            cells = ["-" if c not in group else
                     (fmt(group[c]["error"], ".3g") if group[c]["status"] == "ok"
                      else "failed") for c in sizes]
            finest = group[min(group)]
            out.append(f"| {line} | " + " | ".join(cells) +
                       f" | {fmt(finest['order'], '.2f')} | "
                       f"{fmt(finest['advance_wall_s'], '.3g')} |")
            if any(r.get("column_error") is not None for r in group.values()):
                cells = ["-" if c not in group else
                         (fmt(group[c].get("column_error"), ".3g")
                          if group[c]["status"] == "ok" else "failed") for c in sizes]
                out.append(f"| {line}, columns' own depths | " + " | ".join(cells) +
                           f" | {fmt(finest.get('column_order'), '.2f')} | (same runs) |")
        if problem in FRONT_PROBLEMS:
            out.append(f"\n**{problem}, front** (per cent of the distance travelled)\n")
            out.append("| line | " + " | ".join(f"C = {c:g}" for c in sizes) + " |")
            out.append("|---|" + "---:|" * len(sizes))
            for line in ordered_lines(rows):
                group = {r["cell_size"]: r for r in rows
                         if r["problem"] == problem and r["line"] == line}
                if group:
                    out.append(f"| {line} | " + " | ".join(
                        "-" if c not in group else
                        fmt(group[c]["front_error_percent"], "+.1f") for c in sizes) + " |")
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
            for k in ("flip_fraction", "cell_size", "error", "order", "column_error",
                      "column_order", "front", "front_exact", "front_error_percent",
                      "advance_wall_s", "advance_min_s", "advance_max_s", "total_wall_s",
                      "background_load"):
                row[k] = to_number(r.get(k), float)  # older CSVs: no column_error, ..._order
            for k in ("particles_per_direction", "columns", "cells", "steps", "repeats"):
                row[k] = to_number(r[k], int)
            rows.append(row)
    return rows


def line_style(line):
    """Colour by the option that differs from the defaults, dashes for FLIP, marker by
    columns per cell."""
    shape, flip, update, ppd = parse_line(line)
    split = split_of(line)
    if line == DEFAULTS:
        colour = "black"
    elif line == PAPER_001:
        colour = "tab:red"
    elif line == "gimp-pic-proj-4-s0":
        colour = "tab:gray"
    elif split == 0:
        colour = "tab:brown"
    elif split is not None and split != 1.5:
        colour = "tab:pink"
    elif shape == "q1":
        colour = "tab:orange"
    elif shape == "cpgimp":
        colour = "tab:olive"
    elif update == "strain":
        colour = "tab:green"
    elif ppd == 2:
        colour = "tab:cyan"
    elif ppd >= 8:
        colour = "tab:purple"
    else:
        colour = "tab:blue"
    style = "-" if flip == 0 else "--"
    marker = {2: "v", 4: "o", 8: "s"}.get(ppd, "D")
    return colour, style, marker


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = [(p, "error") for p in PROBLEMS if p != "block"
              and any(r["problem"] == p for r in rows)]
    panels += [(p, "front") for p in FRONT_PROBLEMS if any(r["problem"] == p for r in rows)]
    if not panels:
        print(f"no figure: the sliding block alone has no panel ({path} not written)")
        return
    ncols = 3
    nrows = (len(panels) + ncols - 1) // ncols
    fig, axes = plt.subplots(nrows, ncols, figsize=(5.6 * ncols, 4.6 * nrows + 1.2),
                             squeeze=False)
    fig.subplots_adjust(left=0.06, right=0.985, top=0.93, bottom=0.14, wspace=0.24,
                        hspace=0.32)
    lines = ordered_lines(rows)
    handles = {}
    columns_label = "defaults, columns' own depths"
    for ax, (problem, what) in zip(axes.flat, panels):
        for line in lines:
            group = sorted((r for r in rows if r["problem"] == problem and r["line"] == line
                            and r["status"] == "ok" and r["error"] is not None
                            and r["advance_wall_s"]),
                           key=lambda r: -r["cell_size"])
            if not group:
                continue
            colour, style, marker = line_style(line)
            x = [r["advance_wall_s"] for r in group]
            if what == "error":
                y = [max(r["error"], 1e-16) for r in group]
                handles[line], = ax.loglog(x, y, color=colour, ls=style, marker=marker,
                                           ms=5, lw=1.4, label=line)
                finest = group[-1]
                if finest.get("order") is not None and finest["error"] > 1e-9:
                    ax.annotate(f"{finest['order']:+.2f}", (x[-1], y[-1]),
                                textcoords="offset points", xytext=(5, -3), fontsize=7,
                                color=colour, fontweight="bold")
                own = [r for r in group if r.get("column_error") is not None]
                if line == DEFAULTS and own:
                    # The columns' own error of the same runs: no quadrature floor.
                    xc = [r["advance_wall_s"] for r in own]
                    yc = [max(r["column_error"], 1e-16) for r in own]
                    handles[columns_label], = ax.loglog(
                        xc, yc, color=colour, ls=(0, (2.5, 2)), marker=marker, ms=5,
                        mfc="none", lw=1.2, label=columns_label)
                    if own[-1].get("column_order") is not None:
                        ax.annotate(f"{own[-1]['column_order']:+.2f}", (xc[-1], yc[-1]),
                                    textcoords="offset points", xytext=(5, -3), fontsize=7,
                                    color=colour, fontweight="bold")
            else:
                y = [r["front_error_percent"] for r in group]
                handles[line], = ax.semilogx(x, y, color=colour, ls=style, marker=marker,
                                             ms=5, lw=1.4, label=line)
            if line == DEFAULTS:
                for xi, yi, r in zip(x, y, group):
                    ax.annotate(f"{r['cell_size']:g}", (xi, yi), textcoords="offset points",
                                xytext=(-4, 6), fontsize=7, color=colour)
        if what == "error":
            ax.set_title(TITLES[problem], fontsize=9)
            ax.set_ylabel("relative error")
        else:
            ax.set_title(f"{problem}: front (h > 1 % of the release depth)", fontsize=9)
            ax.set_ylabel("front error [% of the distance travelled]")
            ax.axhspan(-2, 2, color="0.85", zorder=0)
            ax.axhline(0, color="0.4", lw=0.8)
        ax.set_xlabel("wall time of the time loop [s]")
        ax.grid(True, which="both", alpha=0.3)
        ax.margins(x=0.12)
    for ax in list(axes.flat)[len(panels):]:
        ax.axis("off")
    labels = [l for l in lines if l in handles]
    if columns_label in handles:
        labels.insert(labels.index(DEFAULTS) + 1 if DEFAULTS in labels else 0, columns_label)
    fig.legend([handles[l] for l in labels], labels,
               loc="lower center", ncol=min(5, len(handles)), fontsize=8,
               title="shape - PIC / FLIP (fraction 1; flipNN: 0.NN) - depth update strain / "
                     "projection - columns per cell direction; black: the defaults; bold "
                     "numbers: observed order between the two finest cells; small numbers: "
                     "the cell size [m]; grey band: the issue's 2 %", title_fontsize=8)
    fig.suptitle("Depth-averaged MPM: error against the median wall time of the time loop "
                 "(2-core machine shared with builds; nice 10)", fontsize=10)
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)


# --------------------------------------------------------------------------------------
# Main
# --------------------------------------------------------------------------------------

def main(argv=None):
    p = argparse.ArgumentParser(
        description="Work-precision of the depth-averaged material points on their exact "
                    "solutions (see the module docstring).",
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("--exe", default=os.path.join(REPO, "build", "slidewave"),
                   help="SlideWave executable")
    p.add_argument("--wait", type=float, default=60.0,
                   help="seconds to wait for the executable to appear (also before the "
                        "one retry of a run that failed for no reason of its own)")
    p.add_argument("--quick", action="store_true",
                   help="two lines, coarse cells, one round")
    p.add_argument("--lines", help="comma-separated shape-pic|flip|flipNN-strain|proj-N "
                   "(default: the nine of the docstring)")
    p.add_argument("--problems", default=",".join(PROBLEMS),
                   help="rigid, Stoker, Ritter, slope, block")
    p.add_argument("--finest", type=float, default=0.,
                   help="leave out cell sizes below this [m]")
    p.add_argument("--repeat", type=int, help="rounds (default 3; --quick 1); the median "
                   "time is reported")
    p.add_argument("--nice", type=int, default=10, help="niceness of the runs (0: none)")
    p.add_argument("--idle-wait", type=float, default=0.0,
                   help="before each round, wait up to this many seconds for the machine "
                        "to be idle; 0: do not wait")
    p.add_argument("--csv", default=os.path.join(REPO, "benchmarks", "results",
                                                 "depth_averaged_work_precision.csv"))
    p.add_argument("--png", default=os.path.join(REPO, "doc", "figures",
                                                 "depth-averaged-work-precision.png"))
    p.add_argument("--merge", action="store_true",
                   help="keep the rows of the existing --csv whose (problem, line, cell "
                        "size) are not run this time, replace the others")
    p.add_argument("--plot-only", action="store_true",
                   help="only redraw the figure (and the tables) from the CSV")
    args = p.parse_args(argv)

    if args.plot_only:
        rows = read_csv(args.csv)
        add_column_orders(rows)  # older CSVs have no column_order
        print(markdown(rows))
        plot(rows, args.png)
        print(f"wrote {args.png}")
        return 0

    exe = find_executable(os.path.abspath(args.exe), args.wait)
    lines = [l.strip() for l in (args.lines or ",".join(
        QUICK_LINES if args.quick else DEFAULT_LINES)).split(",") if l.strip()]
    for line in lines:
        try:
            parse_line(line)
        except (KeyError, ValueError):
            sys.exit(f"bad line name '{line}' (shape-pic|flip|flipNN-strain|proj-N[-sX], e.g. "
                     "gimp-flip80-proj-4-s1.5)")
    problems = [q.strip() for q in args.problems.split(",") if q.strip()]
    for q in problems:
        if q not in PROBLEMS:
            sys.exit(f"unknown problem '{q}' (one of {', '.join(PROBLEMS)})")
    sizes = QUICK_CELL_SIZES if args.quick else CELL_SIZES
    repeat = args.repeat or (1 if args.quick else 3)
    cases = [(q, l, c) for q in problems for l in lines for c in sizes[q] if c >= args.finest]

    t_start = time.perf_counter()
    exe_mtime = os.path.getmtime(exe)
    print(f"SlideWave depth-averaged work-precision: {exe}; {len(cases)} runs x {repeat} "
          f"round(s), nice {args.nice}")
    results = {case: [] for case in cases}
    for round_ in range(repeat):
        if args.idle_wait > 0:
            load = wait_until_idle(args.idle_wait)
            print(f"round {round_ + 1}/{repeat}: background load {load:.2f} cores",
                  flush=True)
        print(f"round {round_ + 1}/{repeat}")
        print(HEADER)
        print("-" * len(HEADER))
        for case in cases:
            q, l, c = case
            if results[case] and results[case][0]["status"] != "ok":
                continue  # a failed run fails again
            r = retry_once(lambda: run_slidewave(exe, q, l, c, args.nice), exe, args.wait)
            results[case].append(r)
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
               "depth_update": update, "particles_per_direction": ppd, "cell_size": c,
               "advance_wall_s": None, "advance_min_s": None, "advance_max_s": None,
               "total_wall_s": None, "background_load": None, "repeats": 0}
        row.update({k: first[k] for k in ("status", "columns", "cells", "steps", "error",
                                          "column_error", "front", "front_exact",
                                          "front_error_percent")})
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
            if any(r["error"] != first["error"] or r["steps"] != first["steps"]
                   or r["column_error"] != first["column_error"] for r in ok):
                changed.append(case)
        rows.append(row)
    kept = []
    if args.merge and os.path.exists(args.csv):
        done = set(cases)
        kept = [r for r in read_csv(args.csv)
                if (r["problem"], r["line"], r["cell_size"]) not in done]
    add_orders(rows + kept)
    add_column_orders(rows + kept)

    print("-" * len(HEADER))
    print(f"Medians over {repeat} round(s) (advance, total, bg):")
    print(HEADER)
    for row in rows:
        print(row_line(row))
    failed = [r for r in rows if r["status"] != "ok"]
    print(f"{len(rows)} cases ({len(failed)} failed) in {time.perf_counter() - t_start:.0f} s. "
          "advance = median wall time of 'depth averaged: advance'; total = process; "
          "order = against the next coarser C; front% = front error in % of the distance "
          "travelled; bg = median cores busy with other work during the run.")
    if os.path.getmtime(exe) != exe_mtime:
        print(f"WARNING: {exe} was rebuilt during the study; the runs may mix two builds.")
    if changed:
        print("WARNING: the error or the step count changed between repetitions for "
              + ", ".join(f"{q}/{l}/{c:g}" for q, l, c in changed))
    if args.merge:
        # Sorted as a whole study writes them: problem, line (the docstring's order, then
        # others as they come), cell size coarse to fine.
        order = list(DEFAULT_LINES)
        for r in kept + rows:
            if r["line"] not in order:
                order.append(r["line"])
        rows = sorted(kept + rows, key=lambda r: (PROBLEMS.index(r["problem"]),
                                                  order.index(r["line"]), -r["cell_size"]))
        print(f"merged with {len(kept)} rows kept from {args.csv}")
    write_csv(args.csv, rows, CSV_COLUMNS)
    print(f"wrote {args.csv}")
    plot(rows, args.png)
    print(f"wrote {args.png}")
    print(markdown(rows))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
