#!/usr/bin/python3
"""Work-precision and throughput benchmarks of SlideWave's 1D shallow-water solver.

Default mode (work-precision)
-----------------------------
Runs the Stoker dam break of ``prm/dam-break.prm`` (1 m | 0.5 m, dam at x = 0.5 on [0, 1],
end time 0.1 s) for every combination of

* numerical flux: ``roe``, ``hll``;
* reconstruction: ``first order``; ``second order`` with the ``minmod``, ``van leer`` and
  ``superbee`` limiters;
* time integrator: ``forward euler``, ``ssp rk2``;

on uniform meshes of 100, 200, 400, 800, 1600 cells (``--cells``; ``--quick``: 100, 200,
400), with Courant number 0.9 for first order and 0.45 for second order
(``--courant-first``, ``--courant-second``), output interval 0 and no gauges. Each run
gets its own temporary output directory, deleted afterwards.

For each run a table row is printed with the steps taken (last row of statistics.csv),
the wall time of the time loop (the ``water: advance`` row of the timer table printed by
the program; the smallest over ``--repeat`` repetitions), the wall time of the whole
process, the throughput in cell-steps per second (cells * steps / advance wall time), the
L1 errors of depth and velocity (water/errors.csv), the observed order of the depth error
against the previous, coarser mesh, the smallest depth of the final profile and the
largest relative water-volume imbalance in statistics.csv.

The table is written as CSV (``--csv``, default benchmarks/results/water_work_precision.csv)
and two figures are drawn: L1 depth error against the time-loop wall time, log-log, one
line per scheme (``--png``, default doc/figures/water-work-precision.png), and L1 depth
error against the number of cells (``--convergence-png``, default
doc/figures/water-convergence.png).

Throughput mode (``--throughput``)
----------------------------------
Runs the second-order Roe/minmod scheme with both time integrators on 10,000 cells
(``--throughput-cells``) for a fixed number of steps (``--throughput-steps``, 2000): the
dam break is moved to [0, 100] m with the dam at 50 m, the time step is pinned by
'Time/Maximum time step' below the stability limit, and the end time is steps * dt, so
that the waves stay far from the walls. Only the start and end profiles are written
and statistics only at the end. It prints cell-steps per second (and, for ssp rk2,
cell-stages per second).

Only the Python standard library, numpy and matplotlib are used; the figures use
matplotlib's Agg backend.
"""

import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

try:
    import numpy as np  # noqa: F401  (matplotlib needs it; imported to fail early)
    import matplotlib
except ImportError as exc:  # e.g. a pyenv python3 first in PATH without Debian's packages
    sys.exit(f"{exc}; run this script with a python3 that has numpy and matplotlib "
             f"(Debian's: /usr/bin/python3 {' '.join(sys.argv)})")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after selecting the backend)
import matplotlib.ticker  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import fmt, find_executable, write_csv  # noqa: E402


REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

FLUXES = ["roe", "hll"]
# (reconstruction, limiter); first order has no limiter.
RECONSTRUCTIONS = [("first order", None),
                   ("second order", "minmod"),
                   ("second order", "van leer"),
                   ("second order", "superbee")]
INTEGRATORS = ["forward euler", "ssp rk2"]

# 'water: advance' row of deal.II's TimerOutput table:
# | water: advance                  |        75 |  0.000785s |        16% |
_ADVANCE_RE = re.compile(
    r"^\|\s*water: advance\s*\|\s*(\d+)\s*\|\s*([0-9.]+(?:[eE][-+]?\d+)?)s\s*\|",
    re.MULTILINE)

CSV_COLUMNS = ["flux", "reconstruction", "limiter", "integrator", "courant", "cells",
               "steps", "advance_wall_s", "total_wall_s", "cell_steps_per_s",
               "l1_depth", "l1_velocity", "order_l1_depth", "min_depth",
               "max_volume_balance", "status"]


# --------------------------------------------------------------------------------------
# Running SlideWave
# --------------------------------------------------------------------------------------

def scheme_label(flux, reconstruction, limiter, integrator):
    """Short label of a scheme, e.g. 'roe / 2nd minmod / ssp rk2'."""
    order = "1st order" if reconstruction == "first order" else f"2nd {limiter}"
    return f"{flux} / {order} / {integrator}"


def read_csv_rows(path):
    """Return the rows of a CSV file with a header line as a list of dicts."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_final_min_depth(water_dir):
    """Smallest depth h in the last water/profile-*.csv (None if there is none)."""
    profiles = sorted(p for p in os.listdir(water_dir)
                      if p.startswith("profile-") and p.endswith(".csv"))
    if not profiles:
        return None
    with open(os.path.join(water_dir, profiles[-1])) as f:
        f.readline()                                   # '# time = T'
        rows = list(csv.DictReader(f))
    return min(float(r["h"]) for r in rows) if rows else None


def run_slidewave(exe, prm, settings):
    """Run ``exe`` on ``prm`` with ``--set`` overrides in a fresh temporary directory.

    ``settings`` maps parameter paths ('Shallow water/Numerical flux') to values. The
    output directory is a temporary directory, which is also the working directory.

    Returns a dict with: status ('ok' or an error description), steps, advance_wall_s,
    advance_calls, total_wall_s, l1_depth, l1_velocity, min_depth, max_volume_balance,
    stdout. The temporary directory is removed before returning.
    """
    workdir = tempfile.mkdtemp(prefix="slidewave-bench-")
    outdir = os.path.join(workdir, "out")
    cmd = [exe]
    for key, value in list(settings.items()) + [("Output directory", outdir)]:
        cmd += ["--set", f"{key}={value}"]
    cmd.append(os.path.abspath(prm))

    result = {"status": "ok", "steps": None, "advance_wall_s": None,
              "advance_calls": None, "total_wall_s": None, "l1_depth": None,
              "l1_velocity": None, "min_depth": None, "max_volume_balance": None,
              "stdout": ""}
    try:
        t0 = time.perf_counter()
        proc = subprocess.run(cmd, cwd=workdir, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True)
        result["total_wall_s"] = time.perf_counter() - t0
        result["stdout"] = proc.stdout
        if proc.returncode != 0:
            tail = proc.stdout.strip().splitlines()[-3:]
            result["status"] = f"exit {proc.returncode}: " + " | ".join(tail)

        m = _ADVANCE_RE.search(proc.stdout)
        if m:
            result["advance_calls"] = int(m.group(1))
            result["advance_wall_s"] = float(m.group(2))
        elif result["status"] == "ok":
            result["status"] = "no 'water: advance' row in the timer table"

        stats_path = os.path.join(outdir, "statistics.csv")
        if os.path.isfile(stats_path):
            rows = read_csv_rows(stats_path)
            if rows:
                result["steps"] = int(float(rows[-1]["step"]))
                if "water_volume_balance" in rows[0] and "water_volume" in rows[0]:
                    v0 = float(rows[0]["water_volume"]) or 1.0
                    result["max_volume_balance"] = max(
                        abs(float(r["water_volume_balance"])) for r in rows) / abs(v0)

        errors_path = os.path.join(outdir, "water", "errors.csv")
        if os.path.isfile(errors_path):
            rows = read_csv_rows(errors_path)
            if rows:
                result["l1_depth"] = float(rows[-1]["l1_depth"])
                result["l1_velocity"] = float(rows[-1]["l1_velocity"])

        water_dir = os.path.join(outdir, "water")
        if os.path.isdir(water_dir):
            result["min_depth"] = read_final_min_depth(water_dir)
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    return result


def best_of(exe, prm, settings, repeat):
    """Run ``repeat`` times; keep the run with the smallest time-loop wall time.

    The total process wall time reported is also the smallest of the repetitions. Errors
    and step counts are deterministic, so any successful run gives them.
    """
    best = None
    total_min = None
    for _ in range(max(repeat, 1)):
        r = run_slidewave(exe, prm, settings)
        if r["status"] != "ok":
            return r
        if r["total_wall_s"] is not None:
            total_min = r["total_wall_s"] if total_min is None else min(total_min,
                                                                        r["total_wall_s"])
        if best is None or r["advance_wall_s"] < best["advance_wall_s"]:
            best = r
    best["total_wall_s"] = total_min
    return best


# --------------------------------------------------------------------------------------
# Output
# --------------------------------------------------------------------------------------

TABLE_HEADER = (f"{'flux':<4} {'order/limiter':<14} {'integrator':<13} {'cells':>6} "
                f"{'steps':>6} {'advance[s]':>10} {'total[s]':>9} {'cell-steps/s':>12} "
                f"{'L1 depth':>10} {'order':>6} {'L1 veloc.':>10} {'min h':>8} "
                f"{'vol.bal.':>8}")


def table_row(row):
    """One fixed-width line of the printed table."""
    order = ("1st order" if row["reconstruction"] == "first order"
             else f"2nd {row['limiter']}")
    line = (f"{row['flux']:<4} {order:<14} {row['integrator']:<13} {row['cells']:>6} "
            f"{fmt(row['steps'], 'd'):>6} {fmt(row['advance_wall_s'], '.4g'):>10} "
            f"{fmt(row['total_wall_s'], '.3g'):>9} "
            f"{fmt(row['cell_steps_per_s'], '.3e'):>12} "
            f"{fmt(row['l1_depth'], '.4e'):>10} {fmt(row['order_l1_depth'], '.2f'):>6} "
            f"{fmt(row['l1_velocity'], '.3e'):>10} {fmt(row['min_depth'], '.4f'):>8} "
            f"{fmt(row['max_volume_balance'], '.1e'):>8}")
    if row["status"] != "ok":
        line += f"  FAILED: {row['status']}"
    return line


_COLOURS = {("first order", ""): "black", ("second order", "minmod"): "tab:blue",
            ("second order", "van leer"): "tab:green",
            ("second order", "superbee"): "tab:red"}
_LINESTYLES = {"roe": "-", "hll": "--"}
_MARKERS = {"forward euler": "o", "ssp rk2": "s"}


def group_by_scheme(rows):
    """Map (flux, reconstruction, limiter, integrator) -> rows sorted by cells."""
    groups = {}
    for row in rows:
        key = (row["flux"], row["reconstruction"], row["limiter"], row["integrator"])
        groups.setdefault(key, []).append(row)
    for key in groups:
        groups[key].sort(key=lambda r: r["cells"])
    return groups


def _plot_schemes(ax, rows, xkey):
    """Draw one line per scheme of l1_depth against ``xkey`` on ``ax``."""
    for (flux, rec, lim, integ), group in group_by_scheme(rows).items():
        pts = [(r[xkey], r["l1_depth"]) for r in group
               if r["status"] == "ok" and r[xkey] and r["l1_depth"]]
        if not pts:
            continue
        xs, ys = zip(*pts)
        ax.loglog(xs, ys, linestyle=_LINESTYLES.get(flux, "-"),
                  marker=_MARKERS.get(integ, "o"), markersize=4.5,
                  markerfacecolor="none" if integ == "forward euler" else None,
                  color=_COLOURS.get((rec, lim), "k"), lw=1.3,
                  label=scheme_label(flux, rec, lim, integ))


def plot_work_precision(rows, path, title):
    """L1 depth error against time-loop wall time, log-log, one line per scheme."""
    fig, ax = plt.subplots(figsize=(10.5, 6.2), constrained_layout=True)
    _plot_schemes(ax, rows, "advance_wall_s")
    ax.set_xlabel("wall time of the time loop ('water: advance') [s]")
    ax.set_ylabel("L1 error of the depth at t = end [m²]")
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper left", bbox_to_anchor=(1.01, 1.0),
              title="flux / reconstruction / integrator", title_fontsize=8)
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=130)
    plt.close(fig)


def plot_convergence(rows, path, title):
    """L1 depth error against the number of cells, log-log, with slope guides."""
    fig, ax = plt.subplots(figsize=(10.5, 6.2), constrained_layout=True)
    _plot_schemes(ax, rows, "cells")
    ok = [r for r in rows if r["status"] == "ok" and r["l1_depth"]]
    if ok:
        n0 = min(r["cells"] for r in ok)
        n1 = max(r["cells"] for r in ok)
        e_hi = max(r["l1_depth"] for r in ok if r["cells"] == n0)
        e_lo = min(r["l1_depth"] for r in ok if r["cells"] == n0)
        ns = np.array([n0, n1], dtype=float)
        # Guides: slope -1/2 above all the data, slope -1 below it.
        for slope, e0, style in ((1.0, 0.6 * e_lo, ":"), (0.5, 1.3 * e_hi, "-.")):
            ax.loglog(ns, e0 * (ns / n0) ** (-slope), color="k", ls=style, lw=1,
                      label=f"slope -{slope:g}")
        ax.set_xticks(sorted({r["cells"] for r in ok}))
        ax.xaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_xlabel("number of cells")
    ax.set_ylabel("L1 error of the depth at t = end [m²]")
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper left", bbox_to_anchor=(1.01, 1.0),
              title="flux / reconstruction / integrator", title_fontsize=8)
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=130)
    plt.close(fig)


# --------------------------------------------------------------------------------------
# Modes
# --------------------------------------------------------------------------------------

def work_precision(args):
    """Run the work-precision study; print the table, write the CSV and the figures."""
    cells_list = args.cells or ([100, 200, 400] if args.quick
                                else [100, 200, 400, 800, 1600])
    rows = []
    t_start = time.perf_counter()
    print(f"SlideWave work-precision: {args.prm}, end time {args.end_time} s, "
          f"cells {cells_list}, Courant {args.courant_first} (1st order) / "
          f"{args.courant_second} (2nd order), best of {args.repeat} run(s)")
    print(TABLE_HEADER)
    print("-" * len(TABLE_HEADER))
    for flux in FLUXES:
        for rec, lim in RECONSTRUCTIONS:
            for integ in INTEGRATORS:
                courant = args.courant_first if rec == "first order" else args.courant_second
                previous = None
                for cells in cells_list:
                    settings = {
                        "Time/End time": args.end_time,
                        "Time/Output interval": 0,
                        "Shallow water/Gauges/Positions": "",
                        "Shallow water/Numerical flux": flux,
                        "Shallow water/Reconstruction": rec,
                        "Shallow water/Time integrator": integ,
                        "Shallow water/Courant number": courant,
                        "Shallow water/Mesh/Type": "uniform",
                        "Shallow water/Mesh/Number of cells": cells,
                    }
                    if lim is not None:
                        settings["Shallow water/Limiter"] = lim
                    r = best_of(args.exe, args.prm, settings, args.repeat)
                    row = {"flux": flux, "reconstruction": rec, "limiter": lim or "",
                           "integrator": integ, "courant": courant, "cells": cells}
                    row.update({k: r[k] for k in (
                        "status", "steps", "advance_wall_s", "total_wall_s", "l1_depth",
                        "l1_velocity", "min_depth", "max_volume_balance")})
                    row["cell_steps_per_s"] = (
                        cells * row["steps"] / row["advance_wall_s"]
                        if row["steps"] and row["advance_wall_s"] else None)
                    row["order_l1_depth"] = None
                    if (previous and previous["l1_depth"] and row["l1_depth"]
                            and previous["cells"] != cells):
                        row["order_l1_depth"] = (
                            math.log(previous["l1_depth"] / row["l1_depth"])
                            / math.log(cells / previous["cells"]))
                    previous = row
                    rows.append(row)
                    print(table_row(row), flush=True)
    elapsed = time.perf_counter() - t_start
    print("-" * len(TABLE_HEADER))
    failed = [r for r in rows if r["status"] != "ok"]
    print(f"{len(rows)} runs ({len(failed)} failed) in {elapsed:.1f} s. "
          "advance = wall time of the time loop (TimerOutput 'water: advance'); "
          "total = whole process; order = observed order of the L1 depth error against "
          "the previous mesh; min h = smallest depth at the end; vol.bal. = largest "
          "|volume balance| / initial volume.")

    write_csv(args.csv, rows, CSV_COLUMNS)
    print(f"wrote {args.csv}")
    title = (f"Stoker dam break (h_l = 1 m, h_r = 0.5 m), t = {args.end_time} s\n"
             f"cells {', '.join(map(str, cells_list))}; "
             f"C = {args.courant_first} (1st) / {args.courant_second} (2nd order)")
    plot_work_precision(rows, args.png, "Work-precision, " + title)
    print(f"wrote {args.png}")
    plot_convergence(rows, args.convergence_png, "Convergence, " + title)
    print(f"wrote {args.convergence_png}")
    return 1 if failed else 0


def throughput(args):
    """Time a fixed number of steps of the 2nd-order Roe/minmod scheme on many cells."""
    cells, steps = args.throughput_cells, args.throughput_steps
    length, dam = 100.0, 50.0
    dx = length / cells
    # Largest signal speed of this dam break (1 m | 0.5 m): |u| + sqrt(g h) <= 3.6 m/s
    # (left state 3.13, plateau 0.92 + 2.67). Pin dt at 60 % of the stability limit of
    # the Courant number 0.45, so that every step has the same dt.
    dt = 0.6 * args.courant_second * dx / 3.6
    end_time = steps * dt
    print(f"SlideWave throughput: 2nd-order Roe/minmod, {cells} cells on [0, {length:g}] m "
          f"(dam at {dam:g} m), dt = {dt:.4e} s fixed, {steps} steps "
          f"(t = {end_time:.4g} s), no intermediate output, best of {args.repeat} run(s)")
    header = (f"{'integrator':<14} {'cells':>7} {'steps':>6} {'advance[s]':>10} "
              f"{'total[s]':>9} {'cell-steps/s':>13} {'cell-stages/s':>14}")
    print(header)
    print("-" * len(header))
    status = 0
    for integ in INTEGRATORS:
        settings = {
            "Time/End time": repr(end_time),
            "Time/Maximum time step": repr(dt),
            "Time/Output interval": 0,
            "Time/Statistics interval": 1000000000,
            "Shallow water/Gauges/Positions": "",
            "Shallow water/Numerical flux": "roe",
            "Shallow water/Reconstruction": "second order",
            "Shallow water/Limiter": "minmod",
            "Shallow water/Time integrator": integ,
            "Shallow water/Courant number": args.courant_second,
            "Shallow water/Mesh/Type": "uniform",
            "Shallow water/Mesh/Left end": 0,
            "Shallow water/Mesh/Right end": length,
            "Shallow water/Mesh/Number of cells": cells,
            "Shallow water/Initial condition/Variable": "water depth",
            "Shallow water/Initial condition/Function expression":
                f"x < {dam:g} ? 1.0 : 0.5",
            "Shallow water/Verification/Exact solution": "none",
        }
        r = best_of(args.exe, args.prm, settings, args.repeat)
        if r["status"] != "ok":
            print(f"{integ:<14} FAILED: {r['status']}")
            status = 1
            continue
        n_steps = r["steps"]
        rate = cells * n_steps / r["advance_wall_s"]
        stages = 2 if integ == "ssp rk2" else 1
        print(f"{integ:<14} {cells:>7} {n_steps:>6} {r['advance_wall_s']:>10.4g} "
              f"{r['total_wall_s']:>9.3g} {rate:>13.3e} {rate * stages:>14.3e}", flush=True)
    return status


def main(argv=None):
    """Command-line entry point."""
    p = argparse.ArgumentParser(
        description="Work-precision (default) and throughput (--throughput) benchmarks "
                    "of SlideWave's 1D shallow-water solver on the Stoker dam break.",
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("--exe", default=os.path.join(REPO, "build", "slidewave"),
                   help="SlideWave executable")
    p.add_argument("--prm", default=os.path.join(REPO, "prm", "dam-break.prm"),
                   help="dam-break scene file")
    p.add_argument("--wait", type=float, default=0.0,
                   help="seconds to wait for the executable to appear (e.g. during a "
                        "rebuild)")
    p.add_argument("--cells", type=lambda s: [int(c) for c in s.split(",") if c.strip()],
                   help="comma-separated mesh sizes (default 100,200,400,800,1600)")
    p.add_argument("--quick", action="store_true",
                   help="cells 100,200,400 only (unless --cells is given)")
    p.add_argument("--end-time", type=float, default=0.1, help="end time [s]")
    p.add_argument("--courant-first", type=float, default=0.9,
                   help="Courant number of the first-order schemes")
    p.add_argument("--courant-second", type=float, default=0.45,
                   help="Courant number of the second-order schemes")
    p.add_argument("--repeat", type=int, default=3,
                   help="repetitions of each run; the fastest time loop is reported")
    p.add_argument("--csv", default=os.path.join(REPO, "benchmarks", "results",
                                                 "water_work_precision.csv"),
                   help="CSV file of the work-precision table")
    p.add_argument("--png", default=os.path.join(REPO, "doc", "figures",
                                                 "water-work-precision.png"),
                   help="work-precision diagram")
    p.add_argument("--convergence-png", default=os.path.join(REPO, "doc", "figures",
                                                             "water-convergence.png"),
                   help="convergence diagram (L1 error against cells)")
    p.add_argument("--throughput", action="store_true",
                   help="run the throughput benchmark instead of the work-precision one")
    p.add_argument("--throughput-cells", type=int, default=10000,
                   help="cells of the throughput benchmark")
    p.add_argument("--throughput-steps", type=int, default=2000,
                   help="time steps of the throughput benchmark")
    args = p.parse_args(argv)

    args.exe = find_executable(os.path.abspath(args.exe), args.wait)
    if not os.path.isfile(args.prm):
        sys.exit(f"scene file not found: {args.prm} (option --prm)")
    return throughput(args) if args.throughput else work_precision(args)


if __name__ == "__main__":
    sys.exit(main())
