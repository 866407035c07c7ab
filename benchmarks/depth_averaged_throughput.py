#!/usr/bin/python3
"""Throughput and memory of the depth-averaged material points (paper 001, section 4.2).

Runs the mud collapse on an inclined bed with a Gaussian obstacle of
``prm/inclined-obstacle.prm`` (``Physics = depth averaged``: domain [0, 150] x [0, 20] m,
release [0, 20]^2 up to the level 60 m, Bingham mud with Voellmy friction) scaled up by
refining the cells, same geometry:

=========  ===========  =========  =========  ======================  ===========
cell [m]   points/cell  columns    cells      steps to t = 0.6 s      in --quick
=========  ===========  =========  =========  ======================  ===========
0.5        4 x 4           25,600     12,000   25                     yes
0.25       4 x 4          102,400     48,000   50                     yes
0.125      4 x 4          409,600    192,000  100                     yes
0.0625     4 x 4        1,638,400    768,000  200                     no
=========  ===========  =========  =========  ======================  ===========

(``--sizes CELL:N,...`` picks others, e.g. ``0.0625:2``: 409,600 columns on 768,000 cells.)
The time step is fixed, dt = 0.048 s/m x cell size ('Depth averaged/Fixed time step';
Courant number about 0.39 against sqrt(g h) of the deepest point, 6.7 m, at the start,
close to the scene's 'Courant number' of 0.4), and every size runs the same stretch of
the flow, t = 0 to ``--end-time`` (0.6 s), so that all make the same number of steps per
cell crossed: the cost
of a step grows as the flow speeds up and the columns cross cells (the points are re-sorted
into cells every step), so runs over different stretches would not compare.

How the cost grows as the flow develops: at cell 0.125 m (``--late-size``) the script also
runs to ``--late-end-time`` (1.8 s), on 1 and 2 ranks; the *later window* throughput is
columns x (steps(1.8 s) - steps(0.6 s)) / (advance(1.8 s) - advance(0.6 s)) from the
medians, the rate of the steps between 0.6 s and 1.8 s alone.

Cases, each repeated ``--repeat`` times (default 3; ``--quick`` 2) in rounds (every case
once, then every case again; the machine's speed drifts by tens of per cent over minutes,
so only interleaved runs compare):

* Q1 on 1 rank (the executable alone) and on 2 ranks (``mpirun -np 2``) at every size;
* the *ceiling*: two 1-rank copies of the same run started side by side, bound to cores 0
  and 1 (``taskset``), at the largest size and at 0.125 m, 4 x 4 (``--ceiling-sizes``);
  their combined point-steps per second is the most two ranks of this machine can reach
  (two busy cores with no decomposition and no communication at all);
* GIMP ('Depth averaged/Shape functions' = gimp) on 1 and 2 ranks at cell 0.125 m, 4 x 4
  (``--gimp-size``);
* the defaults since issue 28 (shape ``defaults``: GIMP with 'Depth update = projection'
  instead of the scene's Q1 and 'strain') on 1 and 2 ranks at every size
  (``--defaults-sizes``);
* the later window above.

``--skip ceiling,gimp,late`` leaves those cases out (e.g. for a quick comparison of the
defaults with Q1).

Overrides for every run: 'Depth averaged/Verification/Conservation check' = false,
'Depth averaged/Output grid' = false, 'Time/Output interval' = 100 (points written at the
start and the end only, outside the time loop), 'Time/Statistics interval' = 100000.
``--detailed`` also sets 'Depth averaged/Detailed timing' and records the parts of the step
(sort, particles to grid, grid update, grid to particles; the slowest rank's).

Measurements
------------
* ``advance[s]``: wall time of the time loop's steps, the 'depth averaged: advance' row of
  the timer table (on 2 ranks the largest over the ranks, from the min/avg/max table);
  ``dt[s]``: the 'depth averaged: time step' row (the stable-step reduction, outside
  advance, small with a fixed step); ``total[s]``: the whole process (set-up and the
  output of the points at the start and the end included);
* ``pt-steps/s`` = columns x steps / advance[s] (the figure of ../shared/BENCHMARKS.md:
  point-steps per second of the time loop); ``/core`` divides it by the ranks (or copies);
* ``RSS/rank[MB]``: peak resident set size of each rank (``/usr/bin/time -f %M``), the
  largest over the ranks; ``B/point`` = the sum over the ranks / columns, so it includes
  the fixed overhead of a process (libraries, MPI: about 150-190 MB per rank) and the
  background grid; the marginal bytes per point between sizes (1 rank) is printed below;
* ``bg``: cores busy with other work during the run (0 on an idle machine): the machine's
  busy CPU time (/proc/stat) less the run's own, per second. A third process hurts the
  two-rank runs most (both ranks are bound to a core and wait for each other every step),
  so the summary also gives the medians over the *quiet* runs alone (bg at most
  ``--quiet-load``, 0.25 cores).

Output: a line per run while it goes; then the medians per case, the summary (ceiling,
two ranks against it, the later window, the issue's target of 5 M point-steps/s per core
with Q1, memory per point) and markdown tables. CSV (``--csv``, default
benchmarks/results/depth_averaged_throughput.csv): one row per run (``round`` = 1, 2, ...),
one row per case with the medians (``round`` = median) and one with the medians of the
quiet runs (``round`` = quiet median). ``--summary-only`` recomputes the medians and the
summary from the per-run rows of the CSV (rows of further rounds may be appended to it).
Exits with status 1 if a run failed.

Usage:
    /usr/bin/python3 benchmarks/depth_averaged_throughput.py            # about 20 minutes
    /usr/bin/python3 benchmarks/depth_averaged_throughput.py --quick    # about 3 minutes
    /usr/bin/python3 benchmarks/depth_averaged_throughput.py --sizes 0.125:4 --repeat 5
    /usr/bin/python3 benchmarks/depth_averaged_throughput.py --summary-only
"""

import argparse
import os
import re
import resource
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import (cpu_busy_seconds, find_executable, fmt,  # noqa: E402
                              on_both_cores, retry_once, wait_until_idle, write_csv)

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# (cell size [m], points per direction, in the quick run)
SIZES = [(0.5, 4, True),
         (0.25, 4, True),
         (0.125, 4, True),
         (0.0625, 4, False)]
DT_PER_CELL = 0.048  # s per m of cell size
END_TIME = 0.6  # s, the stretch of the flow every size runs
LATE_END_TIME = 1.8  # s, the end of the later window
TARGET_PER_CORE = 5e6  # point-steps per second per core with Q1 (the issue)

_HEADER_RE = re.compile(r"Depth-averaged flow: (\d+) columns on (\d+) cells")
# Rank 0's table: "| depth averaged: advance |  96 |  4.52s |  42% |"
_TIMER_RE = re.compile(
    r"^\|\s*(depth averaged(?: step)?: [a-z ]+?)\s*\|\s*(\d+)\s*\|\s*([0-9.]+(?:[eE][-+]?\d+)?)s"
    r"\s*\|\s*[0-9.]+%", re.MULTILINE)
# The min/avg/max table of a parallel run:
# "| depth averaged: advance | 25 | 0.1778s 0 | 0.1816s | 0.1854s 1 |"
_TIMER_MAX_RE = re.compile(
    r"^\|\s*(depth averaged(?: step)?: [a-z ]+?)\s*\|\s*(\d+)\s*\|\s*([0-9.eE+-]+)s\s+\d+\s*\|"
    r"\s*([0-9.eE+-]+)s\s*\|\s*([0-9.eE+-]+)s\s+\d+\s*\|", re.MULTILINE)
_TOTAL_RE = re.compile(r"Total wallclock time elapsed since start\s*\|\s*([0-9.eE+-]+)s")
_RSS_RE = re.compile(r"SLIDEWAVE_PEAK_RSS_KB (\d+)")

PARTS = {"sort_s": "depth averaged step: sort particles",
         "p2g_s": "depth averaged step: particles to grid",
         "grid_update_s": "depth averaged step: grid update",
         "g2p_s": "depth averaged step: grid to particles"}

CSV_COLUMNS = ["round", "case", "shape", "ranks", "copies", "cell_size",
               "particles_per_direction", "dt", "end_time", "columns", "cells", "steps",
               "advance_wall_s", "sort_s", "p2g_s", "grid_update_s", "g2p_s",
               "time_step_wall_s", "setup_wall_s", "program_total_s",
               "total_wall_s", "point_steps_per_s", "point_steps_per_s_per_core",
               "peak_rss_max_rank_mb", "peak_rss_sum_mb", "bytes_per_point",
               "background_load", "runs", "status"]


def children_cpu_seconds():
    """User + system CPU seconds of this script's finished child processes."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def settings_for(cell, ppd, end_time, shape, detailed):
    """--set overrides of prm/inclined-obstacle.prm for one run; returns (dt, settings)."""
    dt = float(f"{DT_PER_CELL * cell:.10g}")
    s = {
        "Time/End time": repr(end_time),
        "Time/Output interval": 100,
        "Time/Statistics interval": 100000,
        "Depth averaged/Fixed time step": repr(dt),
        "Depth averaged/Grid/Cell size": repr(cell),
        "Depth averaged/Release/Particles per direction": ppd,
        # 'defaults': the defaults since issue 28, GIMP with 'Depth update = projection'
        # (the scene itself sets Q1 and 'strain', the paper's choices).
        "Depth averaged/Shape functions": "gimp" if shape == "defaults" else shape,
        "Depth averaged/Verification/Conservation check": "false",
        "Depth averaged/Output grid": "false",
    }
    if shape == "defaults":
        s["Depth averaged/Depth update"] = "projection"
    if detailed:
        s["Depth averaged/Detailed timing"] = "true"
    return dt, s


def parse_output(out, result):
    """Fill ``result`` from the program's output (header, timer tables, peak RSS)."""
    m = _HEADER_RE.search(out)
    if m:
        result["columns"], result["cells"] = int(m.group(1)), int(m.group(2))
    timers = {n: (int(c), float(w)) for n, c, w in _TIMER_RE.findall(out)}
    largest = {n: (int(c), float(mx)) for n, c, _mn, _avg, mx in _TIMER_MAX_RE.findall(out)}
    timers.update(largest)  # on several ranks: the slowest rank's time
    if "depth averaged: advance" in timers:
        result["steps"], result["advance_wall_s"] = timers["depth averaged: advance"]
    for key, name in [("time_step_wall_s", "depth averaged: time step"),
                      ("setup_wall_s", "depth averaged: setup")] + list(PARTS.items()):
        if name in timers:
            result[key] = timers[name][1]
    m = _TOTAL_RE.search(out)
    if m:
        result["program_total_s"] = float(m.group(1))
    rss = [int(k) / 1024. for k in _RSS_RE.findall(out)]
    if rss:
        result["peak_rss_max_rank_mb"], result["peak_rss_sum_mb"] = max(rss), sum(rss)


def run_once(exe, prm, settings, ranks, mpirun, prefix=()):
    """One run of ``exe`` (under ``prefix``, e.g. taskset, on 1 rank; under ``mpirun -np
    ranks`` otherwise), every rank under /usr/bin/time, in a fresh temporary directory
    (removed afterwards). Returns a dict; status 'ok' or the reason of a failure."""
    workdir = tempfile.mkdtemp(prefix="slidewave-da-tp-", dir="/tmp")
    outdir = os.path.join(workdir, "out")
    cmd = []
    if ranks > 1:
        cmd += shlex.split(mpirun) + ["-np", str(ranks)]
    # Every rank appends its peak RSS to one file (short appends do not interleave, unlike
    # the ranks' merged output streams).
    rss_file = os.path.join(workdir, "peak_rss.txt")
    cmd += list(prefix) + ["/usr/bin/time", "-a", "-o", rss_file,
                           "-f", "SLIDEWAVE_PEAK_RSS_KB %M", exe]
    for key, value in list(settings.items()) + [("Output directory", outdir)]:
        cmd += ["--set", f"{key}={value}"]
    cmd.append(os.path.abspath(prm))
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    r = {"status": "ok", "columns": None, "cells": None, "steps": None,
         "advance_wall_s": None, "time_step_wall_s": None, "setup_wall_s": None,
         "program_total_s": None, "total_wall_s": None, "peak_rss_max_rank_mb": None,
         "peak_rss_sum_mb": None}
    r.update({k: None for k in PARTS})
    try:
        t0 = time.perf_counter()
        proc = subprocess.run(cmd, cwd=workdir, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True, env=env)
        r["total_wall_s"] = time.perf_counter() - t0
        out = proc.stdout
        if os.path.isfile(rss_file):
            with open(rss_file) as f:
                out += "\n" + f.read()
        parse_output(out, r)
        if r["status"] == "ok" and len(_RSS_RE.findall(out)) != ranks:
            r["peak_rss_max_rank_mb"] = r["peak_rss_sum_mb"] = None  # a rank's is missing
        bad = re.search(r"Command exited with non-zero status (\d+)", out)
        if proc.returncode != 0 or bad:
            code = proc.returncode if proc.returncode != 0 else int(bad.group(1))
            reason = [l for l in out.strip().splitlines() if l.startswith("slidewave:")]
            text = reason[-1] if reason else " | ".join(out.strip().splitlines()[-2:])
            r["status"] = f"failed (exit {code}): {text[:200]}"
        elif r["advance_wall_s"] is None or r["columns"] is None:
            r["status"] = "failed: no header line or no 'depth averaged: advance' row"
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    return r


def run_case(exe, prm, case, mpirun):
    """Run one case: 1 or 2 ranks, or two 1-rank copies side by side ('ceiling').

    Returns a result dict; for the ceiling, the two copies are combined: point-steps per
    second summed, advance = the slower copy's, memory summed."""
    busy0, own0, t0 = cpu_busy_seconds(), children_cpu_seconds(), time.perf_counter()
    if case["kind"] == "ceiling":
        parts = on_both_cores(lambda core: run_once(exe, prm, case["settings"], 1, mpirun,
                                                     prefix=("taskset", "-c", str(core))))
        bad = [p for p in parts if p["status"] != "ok"]
        r = dict(bad[0] if bad else parts[0])
        if not bad:
            r["copy_advance_s"] = [p["advance_wall_s"] for p in parts]
            r["advance_wall_s"] = max(r["copy_advance_s"])
            r["point_steps_per_s"] = sum(p["columns"] * p["steps"] / p["advance_wall_s"]
                                         for p in parts)
            r["peak_rss_sum_mb"] = sum(p["peak_rss_sum_mb"] or 0 for p in parts)
            r["peak_rss_max_rank_mb"] = max(p["peak_rss_max_rank_mb"] or 0 for p in parts)
            r["total_wall_s"] = max(p["total_wall_s"] for p in parts)
    else:
        r = run_once(exe, prm, case["settings"], case["ranks"], mpirun)
        if r["status"] == "ok":
            r["point_steps_per_s"] = r["columns"] * r["steps"] / r["advance_wall_s"]
    wall = time.perf_counter() - t0
    r["background_load"] = max(0., (cpu_busy_seconds() - busy0
                                    - (children_cpu_seconds() - own0)) / wall)
    if r["status"] == "ok":
        r["point_steps_per_s_per_core"] = r["point_steps_per_s"] / case["cores"]
        # Memory per point: per rank or copy, over its own share (a copy holds all points).
        r["bytes_per_point"] = (r["peak_rss_sum_mb"] * 1024. * 1024.
                                / (r["columns"] * case["copies"])
                                if r["peak_rss_sum_mb"] else None)
    return r


def run_retrying(exe, prm, case, mpirun, wait_s):
    """run_case, once more after a failure that is not the program's own (the executable
    being rebuilt meanwhile)."""
    return retry_once(lambda: run_case(exe, prm, case, mpirun), exe, wait_s)


# --------------------------------------------------------------------------------------
# Tables
# --------------------------------------------------------------------------------------

HEADER = (f"{'round':>6} {'case':<18} {'shape':<8} {'C[m]':>6} {'n':>2} {'columns':>9} "
          f"{'cells':>7} {'steps':>5} {'advance[s]':>10} {'dt[s]':>6} {'total[s]':>8} "
          f"{'pt-steps/s':>10} {'/core':>9} {'RSS/rank[MB]':>12} {'B/point':>8} {'bg':>4}")


def row_line(row):
    line = (f"{str(row['round']):>6} {row['case']:<18} {row['shape']:<8} "
            f"{row['cell_size']:>6g} {row['particles_per_direction']:>2} "
            f"{fmt(row.get('columns'), 'd'):>9} {fmt(row.get('cells'), 'd'):>7} "
            f"{fmt(row.get('steps'), 'd'):>5} {fmt(row.get('advance_wall_s'), '.4g'):>10} "
            f"{fmt(row.get('time_step_wall_s'), '.2g'):>6} "
            f"{fmt(row.get('total_wall_s'), '.1f'):>8} "
            f"{fmt(row.get('point_steps_per_s'), '.3e'):>10} "
            f"{fmt(row.get('point_steps_per_s_per_core'), '.3e'):>9} "
            f"{fmt(row.get('peak_rss_max_rank_mb'), '.0f'):>12} "
            f"{fmt(row.get('bytes_per_point'), '.0f'):>8} "
            f"{fmt(row.get('background_load'), '.1f'):>4}")
    if row.get("sort_s") is not None:
        line += ("  sort/p2g/grid/g2p " + "/".join(fmt(row.get(k), ".3g") for k in PARTS)
                 + " s")
    if row["status"] != "ok":
        line += f"  {row['status']}"
    return line


def case_name(kind, ranks):
    return {"alone": "1 rank", "mpi": f"{ranks} ranks",
            "ceiling": "2 copies (ceiling)"}[kind]


def median_row(case, runs, max_load=None):
    """The case's row of medians over its runs (with ``max_load``: over the runs during
    which at most that many cores were busy with other work, round = 'quiet median')."""
    row = {k: case[k] for k in ("case", "shape", "ranks", "copies", "cell_size",
                                "particles_per_direction", "dt", "end_time")}
    row["round"] = "median" if max_load is None else "quiet median"
    ok = [r for r in runs if r["status"] == "ok"]
    row["status"] = "ok" if ok and len(ok) == len(runs) else \
        next((r["status"] for r in runs if r["status"] != "ok"), "no runs")
    if max_load is not None:
        ok = [r for r in ok if r.get("background_load") is not None
              and r["background_load"] <= max_load]
        if not ok and row["status"] == "ok":
            row["status"] = "no quiet run"
    row["runs"] = len(ok)
    if not ok:
        return row
    for k in ("columns", "cells", "steps"):
        row[k] = ok[0][k]
    for k in ["advance_wall_s", "time_step_wall_s", "setup_wall_s", "program_total_s",
              "total_wall_s", "point_steps_per_s", "point_steps_per_s_per_core",
              "peak_rss_max_rank_mb", "peak_rss_sum_mb", "bytes_per_point",
              "background_load"] + list(PARTS):
        values = [r[k] for r in ok if r.get(k) is not None]
        row[k] = statistics.median(values) if values else None
    return row


def find_row(medians, case, shape, cell, ppd):
    for r in medians:
        if (r["case"], r["shape"], r["cell_size"], r["particles_per_direction"]) == \
                (case, shape, cell, ppd) and r["status"] == "ok":
            return r
    return None


def throughput_table(medians, title):
    """Markdown table of the throughput: 1 rank, 2 ranks, ceiling."""
    out = []
    sizes = []
    for r in medians:
        key = (r["cell_size"], r["particles_per_direction"])
        if key not in sizes:
            sizes.append(key)

    def find(case, shape, cell, ppd):
        return find_row(medians, case, shape, cell, ppd)

    quiet = medians and medians[0]["round"] == "quiet median"
    out.append(f"\n**Throughput** ({title}; point-steps/s = columns x steps / 'depth "
               "averaged: advance' seconds; 2 ranks: the slower rank's advance)\n")
    out.append("| shape | cell [m] | points/cell | columns | grid cells | steps | 1 rank "
               "[M pt-steps/s] | 2 ranks [M] | 2 copies = ceiling [M] | 2 ranks / 1 rank "
               "| 2 ranks / ceiling | per core on 2 ranks [M] |"
               + (" quiet runs 1 rank / 2 ranks / ceiling |" if quiet else ""))
    out.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
               + ("---:|" if quiet else ""))
    for shape in ("q1", "gimp", "defaults"):
        for cell, ppd in sizes:
            one, two, ceil = (find("1 rank", shape, cell, ppd), find("2 ranks", shape, cell, ppd),
                              find("2 copies (ceiling)", shape, cell, ppd))
            if not (one or two):
                continue
            base = one or two

            def m(r):
                return fmt(r["point_steps_per_s"] / 1e6 if r else None, ".2f")
            out.append(
                f"| {shape} | {cell:g} | {ppd}x{ppd} | {base['columns']:,} | "
                f"{base['cells']:,} | {base['steps']} | {m(one)} | {m(two)} | {m(ceil)} | "
                + fmt(two["point_steps_per_s"] / one["point_steps_per_s"]
                      if one and two else None, ".2f") + " | "
                + fmt(two["point_steps_per_s"] / ceil["point_steps_per_s"]
                      if two and ceil else None, ".2f") + " | "
                + fmt(two["point_steps_per_s"] / 2e6 if two else None, ".2f") + " |"
                + ("" if not quiet else " " + " / ".join(str(r["runs"]) if r else "-"
                                                         for r in (one, two, ceil)) + " |"))

    return out


def summary(medians, quiet=None, quiet_load=None):
    """Ceiling, two ranks against it, target, memory: text lines and markdown tables."""
    out = []

    def find(case, shape, cell, ppd):
        for r in medians:
            if (r["case"], r["shape"], r["cell_size"], r["particles_per_direction"]) == \
                    (case, shape, cell, ppd) and r["status"] == "ok":
                return r
        return None

    sizes = []
    for r in medians:
        key = (r["cell_size"], r["particles_per_direction"])
        if key not in sizes:
            sizes.append(key)

    out += throughput_table(medians, "medians of all runs")
    if quiet:
        out += throughput_table(quiet, f"medians of the quiet runs only, those during which "
                                f"at most {quiet_load:g} cores were busy with other work")
    out.append("\n**Memory** (medians of the peak RSS; B/point = all ranks' RSS / columns, "
               "fixed overhead of the processes included)\n")
    out.append("| shape | cell [m] | points/cell | columns | 1 rank [MB] | B/point (1 rank) "
               "| 2 ranks: largest rank [MB] | B/point (2 ranks) |")
    out.append("|---|---:|---:|---:|---:|---:|---:|---:|")
    for shape in ("q1", "gimp", "defaults"):
        for cell, ppd in sizes:
            one, two = find("1 rank", shape, cell, ppd), find("2 ranks", shape, cell, ppd)
            if not (one or two):
                continue
            base = one or two
            out.append(f"| {shape} | {cell:g} | {ppd}x{ppd} | {base['columns']:,} | "
                       f"{fmt(one and one['peak_rss_sum_mb'], '.0f')} | "
                       f"{fmt(one and one['bytes_per_point'], '.0f')} | "
                       f"{fmt(two and two['peak_rss_max_rank_mb'], '.0f')} | "
                       f"{fmt(two and two['bytes_per_point'], '.0f')} |")

    lines = []
    for shape in ("q1", "gimp", "defaults"):
        for ppd in sorted({p for _, p in sizes}):
            series = sorted((find("1 rank", shape, c, p) for c, p in sizes if p == ppd),
                            key=lambda r: r["columns"] if r else 0)
            series = [r for r in series if r and r["peak_rss_sum_mb"]]
            parts = []
            for a, b in zip(series, series[1:]):
                marginal = ((b["peak_rss_sum_mb"] - a["peak_rss_sum_mb"]) * 1024. * 1024.
                            / (b["columns"] - a["columns"]))
                parts.append(f"{a['columns']:,} -> {b['columns']:,}: {marginal:.0f} B")
            if parts:
                lines.append(f"  {shape} {ppd}x{ppd}: " + ", ".join(parts))
    if lines:
        out.append("\nMarginal peak RSS per point between sizes (1 rank; includes the grid, "
                   "which grows with the points):")
        out += lines

    late_lines, late_rates = [], {}
    for case in ("1 rank", "2 ranks"):
        for r in medians:
            if r["case"] != case + " late" or r["status"] != "ok":
                continue
            early = find(case, r["shape"], r["cell_size"], r["particles_per_direction"])
            if (not early or r["steps"] <= early["steps"]
                    or r["advance_wall_s"] <= early["advance_wall_s"]):
                continue
            rate = (r["columns"] * (r["steps"] - early["steps"])
                    / (r["advance_wall_s"] - early["advance_wall_s"]))
            late_rates[(case, r["shape"], r["columns"])] = rate
            late_lines.append(
                f"| {case} | {r['shape']} | {r['cell_size']:g} | {r['columns']:,} | "
                f"0 - {early['end_time']:g} s: {early['point_steps_per_s'] / 1e6:.2f} | "
                f"{early['end_time']:g} - {r['end_time']:g} s: {rate / 1e6:.2f} | "
                f"0 - {r['end_time']:g} s: {r['point_steps_per_s'] / 1e6:.2f} | "
                f"{rate / r['ranks'] / 1e6:.2f} |")
    if late_lines:
        out.append("\n**As the flow develops** (M point-steps/s; the later window from the "
                   "difference of the medians of the two runs)\n")
        out.append("| ranks | shape | cell [m] | columns | first window | later window | "
                   "whole run | later window per core |")
        out.append("|---|---|---:|---:|---:|---:|---:|---:|")
        out += late_lines

    q1 = [r for r in medians if r["case"] == "1 rank" and r["shape"] == "q1"
          and r["status"] == "ok"]
    if q1:
        met = [r for r in q1 if r["point_steps_per_s"] >= TARGET_PER_CORE]
        verdict = ("met at every size" if len(met) == len(q1) else
                   f"met at {len(met)} of {len(q1)} sizes" if met else "NOT met")
        out.append(f"\nTarget (issue): >= {TARGET_PER_CORE / 1e6:g} M point-steps/s per core "
                   f"with Q1. One rank, t = 0 to {q1[0]['end_time']:g} s: " + ", ".join(
                       f"{r['columns']:,} ({r['particles_per_direction']}x"
                       f"{r['particles_per_direction']}): {r['point_steps_per_s'] / 1e6:.2f} M"
                       for r in q1) + f" -> {verdict}.")
        q2 = [r for r in medians if r["case"] == "2 ranks" and r["shape"] == "q1"
              and r["status"] == "ok"]
        if q2:
            out.append("Per core on 2 ranks: " + ", ".join(
                f"{r['columns']:,} ({r['particles_per_direction']}x"
                f"{r['particles_per_direction']}): {r['point_steps_per_s'] / 2e6:.2f} M"
                for r in q2) + ".")
        for (case, shape, columns), rate in late_rates.items():
            if case == "1 rank" and shape == "q1":
                out.append(f"Later window, one rank, {columns:,} columns: {rate / 1e6:.2f} M "
                           f"-> {'met' if rate >= TARGET_PER_CORE else 'NOT met'}.")
    return "\n".join(out)


# --------------------------------------------------------------------------------------
# Main
# --------------------------------------------------------------------------------------

def summary_from_csv(path, quiet_load):
    """--summary-only: medians, quiet medians and summary from the per-run rows of ``path``
    (which is rewritten with them)."""
    import csv
    floats = ("cell_size", "dt", "end_time", "advance_wall_s", "time_step_wall_s",
              "setup_wall_s", "program_total_s", "total_wall_s", "point_steps_per_s",
              "point_steps_per_s_per_core", "peak_rss_max_rank_mb", "peak_rss_sum_mb",
              "bytes_per_point", "background_load") + tuple(PARTS)
    ints = ("ranks", "copies", "particles_per_direction", "columns", "cells", "steps", "runs")
    rows = []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            if not r["round"].isdigit():
                continue
            row = dict(r)
            for k in floats:
                row[k] = float(r[k]) if r.get(k) not in ("", None) else None
            for k in ints:
                row[k] = int(r[k]) if r.get(k) not in ("", None) else None
            row["round"] = int(r["round"])
            rows.append(row)
    cases, runs = [], []
    for row in rows:
        key = {k: row[k] for k in ("case", "shape", "ranks", "copies", "cell_size",
                                   "particles_per_direction", "dt", "end_time")}
        if key not in cases:
            cases.append(key)
            runs.append([])
        runs[cases.index(key)].append(row)
    medians = [median_row(c, rs) for c, rs in zip(cases, runs)]
    quiet = [median_row(c, rs, quiet_load) for c, rs in zip(cases, runs)]
    print(HEADER)
    for row in medians + quiet:
        print(row_line(row))
    print(summary(medians, quiet, quiet_load))
    write_csv(path, rows + medians + quiet, CSV_COLUMNS)
    print(f"wrote {path}")
    return 0


def parse_sizes(text):
    out = []
    for item in text.split(","):
        if item.strip():
            cell, _, ppd = item.partition(":")
            out.append((float(cell), int(ppd or 4)))
    return out


def main(argv=None):
    p = argparse.ArgumentParser(
        description="Point-steps per second and peak memory of the depth-averaged material "
                    "points on the scaled-up inclined-obstacle scene (see the module "
                    "docstring).",
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("--exe", default=os.path.join(REPO, "build", "slidewave"),
                   help="SlideWave executable")
    p.add_argument("--prm", default=os.path.join(REPO, "prm", "inclined-obstacle.prm"),
                   help="inclined-obstacle scene")
    p.add_argument("--mpirun", default="mpirun", help="MPI launcher for 2 ranks")
    p.add_argument("--wait", type=float, default=60.0,
                   help="seconds to wait for the executable to appear (also before the "
                        "one retry of a run that failed for no reason of its own)")
    p.add_argument("--quick", action="store_true",
                   help="cells 0.5, 0.25, 0.125 m with 4 x 4 points, 2 rounds")
    p.add_argument("--sizes", type=parse_sizes,
                   help="CELL:POINTS_PER_DIRECTION,... (default: the table of the docstring)")
    p.add_argument("--end-time", type=float, default=END_TIME,
                   help="end time of every run [s] (steps = end time / dt)")
    p.add_argument("--ceiling-sizes", type=parse_sizes,
                   help="sizes with the two-copies ceiling (default: the largest and 0.125:4)")
    p.add_argument("--gimp-size", type=parse_sizes, default=[(0.125, 4)],
                   help="sizes also run with GIMP ('' for none)")
    p.add_argument("--defaults-sizes", type=parse_sizes,
                   help="CELL:N,... where the defaults (GIMP, 'Depth update = projection', "
                        "shape 'defaults') run on 1 and 2 ranks (default: every size)")
    p.add_argument("--skip", type=lambda t: [k.strip() for k in t.split(",") if k.strip()],
                   default=[], help="comma-separated cases to leave out: ceiling, gimp, late")
    p.add_argument("--late-size", type=parse_sizes, default=[(0.125, 4)],
                   help="sizes also run to --late-end-time, 1 and 2 ranks ('' for none)")
    p.add_argument("--late-end-time", type=float, default=LATE_END_TIME,
                   help="end of the later window [s]")
    p.add_argument("--detailed", action="store_true",
                   help="'Detailed timing' on: record the parts of the step")
    p.add_argument("--repeat", type=int, help="rounds (default 3; --quick 2); medians")
    p.add_argument("--idle-wait", type=float, default=20.0,
                   help="before each round, wait up to this many seconds for the machine "
                        "to be idle; 0: do not wait")
    p.add_argument("--quiet-load", type=float, default=0.25,
                   help="the quiet runs: at most this many cores busy with other work "
                        "(medians over them are reported too)")
    p.add_argument("--csv", default=os.path.join(REPO, "benchmarks", "results",
                                                 "depth_averaged_throughput.csv"))
    p.add_argument("--summary-only", action="store_true",
                   help="recompute the medians and the summary from the runs in --csv "
                        "(and rewrite it) without running anything")
    args = p.parse_args(argv)

    if args.summary_only:
        return summary_from_csv(args.csv, args.quiet_load)

    exe = find_executable(os.path.abspath(args.exe), args.wait)
    if not os.path.isfile(args.prm):
        sys.exit(f"scene file not found: {args.prm} (option --prm)")
    sizes = args.sizes or [(c, n) for c, n, q in SIZES if q or not args.quick]
    repeat = args.repeat or (2 if args.quick else 3)

    def columns_of(cell, ppd):
        return round(20 / cell) ** 2 * ppd * ppd

    largest = max(sizes, key=lambda s: (columns_of(*s), s[1]))
    ceiling_sizes = args.ceiling_sizes or [largest, (0.125, 4)]
    cases = []

    def add(kind, shape, ranks, cell, ppd, end_time, late=False):
        dt, settings = settings_for(cell, ppd, end_time, shape, args.detailed)
        name = case_name(kind, ranks) + (" late" if late else "")
        cases.append({"case": name, "kind": kind, "shape": shape, "ranks": ranks,
                      "copies": 2 if kind == "ceiling" else 1,
                      "cores": 2 if kind in ("ceiling", "mpi") else 1,
                      "cell_size": cell, "particles_per_direction": ppd, "dt": dt,
                      "end_time": end_time, "settings": settings})

    for cell, ppd in sizes:
        add("alone", "q1", 1, cell, ppd, args.end_time)
        add("mpi", "q1", 2, cell, ppd, args.end_time)
        if (cell, ppd) in ceiling_sizes and "ceiling" not in args.skip:
            add("ceiling", "q1", 1, cell, ppd, args.end_time)
        if (cell, ppd) in args.gimp_size and "gimp" not in args.skip:
            add("alone", "gimp", 1, cell, ppd, args.end_time)
            add("mpi", "gimp", 2, cell, ppd, args.end_time)
        if args.defaults_sizes is None or (cell, ppd) in args.defaults_sizes:
            add("alone", "defaults", 1, cell, ppd, args.end_time)
            add("mpi", "defaults", 2, cell, ppd, args.end_time)
        if (cell, ppd) in args.late_size and "late" not in args.skip:
            add("alone", "q1", 1, cell, ppd, args.late_end_time, late=True)
            add("mpi", "q1", 2, cell, ppd, args.late_end_time, late=True)

    t_start = time.perf_counter()
    exe_mtime = os.path.getmtime(exe)
    print(f"SlideWave depth-averaged throughput: {exe}, {args.prm}; {len(cases)} cases x "
          f"{repeat} round(s); t = 0 to {args.end_time:g} s (later window: to "
          f"{args.late_end_time:g} s) with dt = {DT_PER_CELL:g} x cell size; 2 ranks = "
          f"{args.mpirun} -np 2; ceiling = two 1-rank copies side by side (taskset -c 0 / 1)")
    print(HEADER)
    print("-" * len(HEADER))
    runs = [[] for _ in cases]
    rows = []
    for round_ in range(1, repeat + 1):
        if args.idle_wait > 0:
            load = wait_until_idle(args.idle_wait)
            print(f"round {round_}/{repeat}: background load before it {load:.2f} cores",
                  flush=True)
        for i, case in enumerate(cases):
            if runs[i] and runs[i][0]["status"] != "ok":
                continue
            r = run_retrying(exe, args.prm, case, args.mpirun, args.wait)
            runs[i].append(r)
            row = {k: case[k] for k in ("case", "shape", "ranks", "copies", "cell_size",
                                        "particles_per_direction", "dt", "end_time")}
            row.update({k: v for k, v in r.items() if k in CSV_COLUMNS})
            row["round"], row["runs"] = round_, 1
            rows.append(row)
            print(row_line(row), flush=True)
    medians = [median_row(case, rs) for case, rs in zip(cases, runs)]
    quiet = [median_row(case, rs, args.quiet_load) for case, rs in zip(cases, runs)]
    elapsed = time.perf_counter() - t_start

    print("-" * len(HEADER))
    print(f"Medians over {repeat} round(s):")
    print(HEADER)
    for row in medians:
        print(row_line(row))
    failed = [r for r in medians if r["status"] != "ok"]
    print(f"{len(rows)} runs ({len(failed)} cases failed) in {elapsed:.0f} s. advance = wall "
          "time of 'depth averaged: advance' (2 ranks: the slower rank; ceiling: the slower "
          "copy); dt = 'depth averaged: time step' (outside advance); total = process(es) "
          "wall time; pt-steps/s = columns x steps / advance (ceiling: the two copies' "
          "sum); /core = over the ranks or copies; RSS/rank = largest peak RSS of a rank; "
          "B/point = all ranks' peak RSS / columns (per copy for the ceiling); bg = cores "
          "busy with other work during the run.")
    loads = [r["background_load"] for r in rows if r.get("background_load") is not None]
    if loads and max(loads) > 0.25:
        print(f"NOTE: the machine was loaded during some runs (background load up to "
              f"{max(loads):.1f} cores, median {statistics.median(loads):.2f}).")
    if os.path.getmtime(exe) != exe_mtime:
        print(f"WARNING: {exe} was rebuilt during the study; the runs may mix two builds.")
    print(summary(medians, quiet, args.quiet_load))
    write_csv(args.csv, rows + medians + quiet, CSV_COLUMNS)
    print(f"wrote {args.csv}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
