#!/usr/bin/python3
"""Throughput and memory of SlideWave's material point method (MPM).

Column collapse (default)
-------------------------
Runs the dry sand column collapse of ``prm/granular-column-collapse.prm`` (the
"MPM: dry sand column collapse" problem of the shared BENCHMARKS.md: a 0.2 m x 0.1 m
column in a 0.6 m x 0.12 m box, 2 x 2 material points per cell) at several particle
counts by refining the cells, same geometry:

==========  =========  ===========  ========================
cell size   particles  grid cells   steps (full / --quick)
==========  =========  ===========  ========================
2.5 mm         12,800       11,520  2000 / 2000
1.25 mm        51,200       46,080  2000 /  500
0.625 mm      204,800      184,320   400 /    -
0.3125 mm     819,200      737,280   100 /    -
==========  =========  ===========  ========================

(``--sizes`` picks rows by particle count, ``--steps`` overrides the step counts.) The
time step is fixed and proportional to the cell size, dt = 2.5e-5 s x (h / 2.5 mm), so
that every size runs at the Courant number of the reference set-up (c_p dt / h = 0.21;
2.5e-5 s on the finer grids would be unstable, and the program refuses a 'Fixed time step'
above the stability limit). The reference row, 2.5 mm and 2000 steps, is exactly the set-up of
BENCHMARKS.md (dt = 2.5e-5 s, t = 0.05 s).

Every size runs for each combination of

* 'Shape functions': ``q1``, ``gimp``;
* 'Material 1/Model': ``linear elastic``, ``drucker prager`` (same density, E, nu);
* MPI ranks: 1 (the executable alone) and 2 (``mpirun -np 2``);

with 'Time/Output interval' = end time (particles are written only at the start and the
end, outside the timed loop) and 'Time/Statistics interval' = 10^9 (one statistics row
at the end). Each run has its own temporary output directory under /tmp, removed
afterwards; its particle files give the number of particles on each rank at the start
and at the end (the load balance).

Hydrostatic column (``--hydrostatic``, also part of the default full run)
------------------------------------------------------------------------
The "MPM: elastic hydrostatic column" problem of BENCHMARKS.md, built from the same
scene by overrides: grid 0.2 m x 0.12 m of 0.01 m cells, column 0.2 x 0.1 m with 5 x 5
points per cell (5000 points), linear elastic rho = 1800, E = 1e6, nu = 0, gravity,
rollers on the sides, fixed base, dt = 1e-5 s, 10,000 steps; q1 and gimp, 1 and 2 ranks.

Measurements
------------
* ``advance[s]``: wall time of the time loop's stepping, the 'mpm: advance' row of the
  TimerOutput table printed by rank 0 (it excludes the stable-time-step reduction, which
  is the 'mpm: time step' row, shown as ``dt[s]``, output and statistics);
* ``p-steps/s``: particles x steps / advance[s];
* ``RSS[MB]``: peak resident set size from ``/usr/bin/time -v`` ("Maximum resident set
  size"), summed over the ranks; ``B/particle`` is that sum divided by the number of
  particles, so it includes the fixed overhead of the process (libraries, MPI, about
  150-190 MB per rank) and the background grid; the marginal bytes per particle between
  two sizes is printed below the table;
* ``busiest``: the share of the particles on the busiest rank at the start and at the end
  (1.00 = all on one rank).

Output: the table on stdout, and as CSV (``--csv``, default
benchmarks/results/mpm_throughput.csv). The script exits with status 1 if a run failed.
Only the Python standard library is used.
"""

import argparse
import csv
import glob
import os
import re
import resource
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import fmt, find_executable, write_csv, cpu_busy_seconds, wait_until_idle  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

REFERENCE_CELL = 0.0025  # m, cell size of the BENCHMARKS.md set-up
REFERENCE_DT = 2.5e-5    # s, its fixed time step

# (cell size [m], steps of the full run, steps of the quick run or None if not in it)
SIZES = [(0.0025, 2000, 2000),
         (0.00125, 2000, 500),
         (0.000625, 400, None),
         (0.0003125, 100, None)]

SHAPES = ["q1", "gimp"]
MATERIALS = ["linear elastic", "drucker prager"]
RANKS = [1, 2]

# Rows of deal.II's TimerOutput table, e.g.
# | mpm: advance                    |       200 |     0.763s |        76% |
_TIMER_RE = re.compile(
    r"^\|\s*(mpm: [a-z ]+?)\s*\|\s*(\d+)\s*\|\s*([0-9.]+(?:[eE][-+]?\d+)?)s\s*\|",
    re.MULTILINE)
_HEADER_RE = re.compile(r"Material points: (\d+) particles on (\d+) cells")
_RSS_RE = re.compile(r"Maximum resident set size \(kbytes\):\s*(\d+)")
_POINTS_RE = re.compile(rb'NumberOfPoints="(\d+)"')

PARTICLE_WEIGHT = "Material points/Load balancing/Particle weight"

CSV_COLUMNS = ["case", "shape", "material", "ranks", "particle_weight", "cell_size", "dt", "particles",
               "cells", "steps", "advance_wall_s", "time_step_wall_s", "setup_wall_s",
               "total_wall_s", "particle_steps_per_s", "peak_rss_sum_mb",
               "peak_rss_max_rank_mb", "bytes_per_particle", "busiest_rank_share_start",
               "busiest_rank_share_end", "background_load", "status"]


# --------------------------------------------------------------------------------------
# Running SlideWave
# --------------------------------------------------------------------------------------

def particles_per_rank(particle_dir, index):
    """Number of particles in each rank's piece of particles_<index>.<rank>.vtu."""
    counts = []
    for path in sorted(glob.glob(os.path.join(particle_dir, f"particles_{index:05d}.*.vtu"))):
        with open(path, "rb") as f:
            m = _POINTS_RE.search(f.read(4096))
        if m:
            counts.append(int(m.group(1)))
    return counts


def children_cpu_seconds():
    """User + system CPU seconds of this script's finished child processes."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_slidewave(exe, prm, settings, ranks, mpirun, prefix=()):
    """Run ``exe`` on ``prm`` with ``--set`` overrides on ``ranks`` MPI ranks.

    ``prefix``: a command that the run goes under (``taskset -c 1``, say); with one rank only.

    Every rank runs under ``/usr/bin/time -v``; the output directory is a fresh temporary
    directory (also the working directory), removed before returning. Returns a dict with
    status ('ok' or an error description), particles, cells, steps, the wall times of the
    timer sections, the total process wall time, the peak RSS summed over the ranks and
    of the largest rank, and the busiest rank's share of the particles at the start and
    the end.
    """
    workdir = tempfile.mkdtemp(prefix="slidewave-mpm-bench-", dir="/tmp")
    outdir = os.path.join(workdir, "out")
    cmd = []
    if ranks > 1:
        if prefix:
            raise ValueError("run_slidewave: a prefix is for one-rank runs only")
        cmd += shlex.split(mpirun) + ["-np", str(ranks)]
    cmd += list(prefix) + ["/usr/bin/time", "-v", exe]
    for key, value in list(settings.items()) + [("Output directory", outdir)]:
        cmd += ["--set", f"{key}={value}"]
    cmd.append(os.path.abspath(prm))
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")

    result = {"status": "ok", "particles": None, "cells": None, "steps": None,
              "advance_wall_s": None, "time_step_wall_s": None, "setup_wall_s": None,
              "total_wall_s": None, "peak_rss_sum_mb": None, "peak_rss_max_rank_mb": None,
              "busiest_rank_share_start": None, "busiest_rank_share_end": None,
              "background_load": None, "timeline": None, "stdout": ""}
    try:
        t0, busy0, own0 = time.perf_counter(), cpu_busy_seconds(), children_cpu_seconds()
        proc = subprocess.run(cmd, cwd=workdir, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True, env=env)
        result["total_wall_s"] = time.perf_counter() - t0
        # Cores busy with other work during the run: all busy CPU time of the machine
        # less that of the run's processes, per second of wall time.
        result["background_load"] = max(
            0., (cpu_busy_seconds() - busy0 - (children_cpu_seconds() - own0))
            / result["total_wall_s"])
        out = proc.stdout
        result["stdout"] = out
        # /usr/bin/time reports "Command exited with non-zero status N" but exits 0 itself
        # only when the command did; mpirun passes the failure on.
        bad = re.search(r"Command exited with non-zero status (\d+)", out)
        if proc.returncode != 0 or bad:
            code = proc.returncode if proc.returncode != 0 else int(bad.group(1))
            lines = [l for l in out.strip().splitlines()
                     if l.strip() and not l.startswith("\t")][-3:]
            result["status"] = f"exit {code}: " + " | ".join(lines)

        m = _HEADER_RE.search(out)
        if m:
            result["particles"], result["cells"] = int(m.group(1)), int(m.group(2))
        timers = {name: (int(calls), float(wall)) for name, calls, wall in
                  _TIMER_RE.findall(out)}
        if "mpm: advance" in timers:
            result["steps"], result["advance_wall_s"] = timers["mpm: advance"]
        elif result["status"] == "ok":
            result["status"] = "no 'mpm: advance' row in the timer table"
        if "mpm: time step" in timers:
            result["time_step_wall_s"] = timers["mpm: time step"][1]
        if "mpm: setup" in timers:
            result["setup_wall_s"] = timers["mpm: setup"][1]
        rss = [int(k) for k in _RSS_RE.findall(out)]
        if rss:
            result["peak_rss_sum_mb"] = sum(rss) / 1024.
            result["peak_rss_max_rank_mb"] = max(rss) / 1024.

        # 'Material points/Step timeline': one row per step and rank, the parts in seconds.
        timeline = os.path.join(outdir, "step_timeline.csv")
        if os.path.isfile(timeline):
            with open(timeline, newline="") as f:
                result["timeline"] = [{k: float(v) for k, v in row.items()}
                                      for row in csv.DictReader(f)]

        particle_dir = os.path.join(outdir, "particles")
        for key, index in (("busiest_rank_share_start", 0), ("busiest_rank_share_end", 1)):
            counts = particles_per_rank(particle_dir, index)
            if counts and sum(counts) > 0:
                result[key] = max(counts) / sum(counts)
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    return result


def best_of(exe, prm, settings, ranks, mpirun, repeat, idle_wait_s):
    """Run ``repeat`` times; keep the run with the smallest 'mpm: advance' time.

    Before each run, wait up to ``idle_wait_s`` seconds for the machine to be idle.
    """
    best = None
    for _ in range(max(repeat, 1)):
        if idle_wait_s > 0:
            wait_until_idle(idle_wait_s)
        r = run_slidewave(exe, prm, settings, ranks, mpirun)
        if r["status"] != "ok":
            return r
        if best is None or r["advance_wall_s"] < best["advance_wall_s"]:
            best = r
    return best


# --------------------------------------------------------------------------------------
# Scenes
# --------------------------------------------------------------------------------------

def column_collapse_settings(cell_size, steps, shape, material):
    """Overrides of prm/granular-column-collapse.prm for one throughput run."""
    dt = float(f"{REFERENCE_DT * cell_size / REFERENCE_CELL:.10g}")
    end_time = float(f"{steps * dt:.12g}")
    return dt, {
        "Time/End time": repr(end_time),
        "Time/Output interval": repr(end_time),
        "Time/Statistics interval": 1000000000,
        "Material points/Fixed time step": repr(dt),
        "Material points/Grid/Cell size": repr(cell_size),
        "Material points/Shape functions": shape,
        "Material points/Material 1/Model": material,
    }


HYDROSTATIC_DT = 1e-5
HYDROSTATIC_STEPS = 10000


def hydrostatic_settings(shape, steps):
    """Overrides of prm/granular-column-collapse.prm for the elastic hydrostatic column."""
    end_time = steps * HYDROSTATIC_DT
    return {
        "Time/End time": repr(end_time),
        "Time/Output interval": repr(end_time),
        "Time/Statistics interval": 1000000000,
        "Material points/Fixed time step": repr(HYDROSTATIC_DT),
        "Material points/Particles per direction": 5,
        "Material points/Shape functions": shape,
        "Material points/Grid/Lower left": "0, 0",
        "Material points/Grid/Upper right": "0.2, 0.12",
        "Material points/Grid/Cell size": 0.01,
        "Material points/Boundary conditions/Left": "roller",
        "Material points/Boundary conditions/Right": "roller",
        "Material points/Boundary conditions/Bottom": "fixed",
        "Material points/Boundary conditions/Top": "free",
        "Material points/Material 1/Model": "linear elastic",
        "Material points/Material 1/Density": 1800,
        "Material points/Material 1/Young's modulus": 1e6,
        "Material points/Material 1/Poisson ratio": 0,
        "Material points/Region 1/Rectangle": "0, 0, 0.2, 0.1",
    }


# --------------------------------------------------------------------------------------
# Output
# --------------------------------------------------------------------------------------

TABLE_HEADER = (f"{'case':<11} {'shape':<5} {'material':<14} {'ranks':>8} {'particles':>9} "
                f"{'cells':>7} {'steps':>5} {'advance[s]':>10} {'dt[s]':>6} "
                f"{'total[s]':>8} {'p-steps/s':>9} {'RSS[MB]':>8} {'B/particle':>10} "
                f"{'busiest':>11} {'bg':>4}")


def table_row(row):
    """One fixed-width line of the printed table."""
    busiest = (f"{fmt(row['busiest_rank_share_start'], '.2f')}/"
               f"{fmt(row['busiest_rank_share_end'], '.2f')}")
    ranks = str(row["ranks"]) + ("" if row.get("particle_weight") is None
                                 else f"w{row['particle_weight']}")
    line = (f"{row['case']:<11} {row['shape']:<5} {row['material']:<14} {ranks:>8} "
            f"{fmt(row['particles'], 'd'):>9} {fmt(row['cells'], 'd'):>7} "
            f"{fmt(row['steps'], 'd'):>5} {fmt(row['advance_wall_s'], '.4g'):>10} "
            f"{fmt(row['time_step_wall_s'], '.2g'):>6} {fmt(row['total_wall_s'], '.1f'):>8} "
            f"{fmt(row['particle_steps_per_s'], '.3e'):>9} "
            f"{fmt(row['peak_rss_sum_mb'], '.0f'):>8} "
            f"{fmt(row['bytes_per_particle'], '.0f'):>10} {busiest:>11} "
            f"{fmt(row['background_load'], '.1f'):>4}")
    if row["status"] != "ok":
        line += f"  FAILED: {row['status']}"
    return line


def make_row(case, shape, material, ranks, cell_size, dt, r, weight=None):
    """Table row from the result ``r`` of one run (``weight``: the 'Particle weight' set,
    None for the scene's)."""
    row = {"case": case, "shape": shape, "material": material, "ranks": ranks,
           "particle_weight": weight, "cell_size": cell_size, "dt": dt}
    row.update({k: r[k] for k in CSV_COLUMNS if k in r})
    row["particle_steps_per_s"] = (
        row["particles"] * row["steps"] / row["advance_wall_s"]
        if row["particles"] and row["steps"] and row["advance_wall_s"] else None)
    row["bytes_per_particle"] = (
        row["peak_rss_sum_mb"] * 1024. * 1024. / row["particles"]
        if row["peak_rss_sum_mb"] and row["particles"] else None)
    return row


def summary(rows):
    """Marginal memory per particle, 2-rank speed-ups and the targets of the issue."""
    ok = [r for r in rows if r["status"] == "ok" and r["case"] == "collapse"]
    lines = []

    def find(shape, material, ranks, particles, weight=None):
        for r in ok:
            if (r["shape"], r["material"], r["ranks"], r["particles"],
                    r.get("particle_weight")) == (shape, material, ranks, particles, weight):
                return r
        return None

    weights = sorted({r.get("particle_weight") for r in ok if r["ranks"] > 1},
                     key=lambda w: -1 if w is None else w)

    sizes = sorted({r["particles"] for r in ok})
    if len(sizes) >= 2:
        lines.append("Marginal peak RSS per particle between sizes (1 rank; includes the "
                     "grid, which grows with the particles):")
        for shape in SHAPES:
            for material in MATERIALS:
                parts = []
                for a, b in zip(sizes, sizes[1:]):
                    ra, rb = find(shape, material, 1, a), find(shape, material, 1, b)
                    if ra and rb and ra["peak_rss_sum_mb"] and rb["peak_rss_sum_mb"]:
                        marginal = ((rb["peak_rss_sum_mb"] - ra["peak_rss_sum_mb"])
                                    * 1024. * 1024. / (b - a))
                        parts.append(f"{a}->{b}: {marginal:.0f} B")
                if parts:
                    lines.append(f"  {shape:<5} {material:<14} " + ", ".join(parts))

    lines.append("Speed-up of 2 ranks over 1 rank ('mpm: advance'):")
    for particles in sizes:
        for weight in weights:
            parts = []
            for shape in SHAPES:
                for material in MATERIALS:
                    r1, r2 = (find(shape, material, 1, particles),
                              find(shape, material, 2, particles, weight))
                    if r1 and r2:
                        parts.append(f"{shape}/{material}: "
                                     f"{r1['advance_wall_s'] / r2['advance_wall_s']:.2f}x")
            if parts:
                label = "scene weight" if weight is None else f"weight {weight}"
                lines.append(f"  {particles:>7} particles ({label}): " + ", ".join(parts))

    lines.append("Targets (one core, no output):")
    for shape, material, target in (("q1", "linear elastic", 4e6),
                                    ("gimp", "drucker prager", 1.5e6)):
        rates = [(r["particles"], r["particle_steps_per_s"]) for r in ok
                 if (r["shape"], r["material"], r["ranks"]) == (shape, material, 1)]
        if rates:
            text = ", ".join(f"{p}: {v / 1e6:.2f} M" for p, v in sorted(rates))
            best = max(v for _, v in rates)
            lines.append(f"  {shape} + {material}: >= {target / 1e6:g} M particle-steps/s "
                         f"-> {text} ({'met' if best >= target else 'NOT met'})")
    if sizes and sizes[-1] >= 500000:
        n = sizes[-1]
        for weight in weights:
            parts = []
            for shape in SHAPES:
                for material in MATERIALS:
                    r1, r2 = find(shape, material, 1, n), find(shape, material, 2, n, weight)
                    if r1 and r2:
                        s = r1["advance_wall_s"] / r2["advance_wall_s"]
                        parts.append(f"{shape}/{material} {s:.2f}x "
                                     f"({'met' if s >= 1.8 else 'NOT met'})")
            if parts:
                label = "scene weight" if weight is None else f"weight {weight}"
                lines.append(f"  2 ranks ({label}) >= 1.8x one rank at {n} particles: "
                             + ", ".join(parts))
    return "\n".join(lines)


# --------------------------------------------------------------------------------------
# Main
# --------------------------------------------------------------------------------------

def main(argv=None):
    """Command-line entry point."""
    p = argparse.ArgumentParser(
        description="Throughput (particle-steps per second of the time loop) and peak "
                    "memory of SlideWave's MPM on the dry sand column collapse at several "
                    "particle counts, and on the elastic hydrostatic column.",
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("--exe", default=os.path.join(REPO, "build", "slidewave"),
                   help="SlideWave executable")
    p.add_argument("--prm", default=os.path.join(REPO, "prm", "granular-column-collapse.prm"),
                   help="column-collapse scene file (also the base of the hydrostatic "
                        "column)")
    p.add_argument("--mpirun", default="mpirun",
                   help="MPI launcher (with options, e.g. 'mpirun --bind-to none') for the "
                        "runs on more than one rank")
    p.add_argument("--wait", type=float, default=0.0,
                   help="seconds to wait for the executable to appear")
    p.add_argument("--quick", action="store_true",
                   help="only 12,800 and 51,200 particles (2000 and 500 steps), no "
                        "hydrostatic column")
    p.add_argument("--sizes", type=lambda s: [int(c) for c in s.split(",") if c.strip()],
                   help="comma-separated particle counts to run, from 12800, 51200, "
                        "204800, 819200")
    p.add_argument("--steps", type=int, help="steps of every column-collapse run "
                                             "(default: per size, see --help's text)")
    p.add_argument("--shapes", default=",".join(SHAPES), help="shape functions")
    p.add_argument("--materials", default=",".join(MATERIALS), help="material models")
    p.add_argument("--ranks", default=",".join(map(str, RANKS)), help="MPI rank counts")
    p.add_argument("--particle-weights", default="scene",
                   help="comma-separated values of 'Material points/Load balancing/Particle "
                        "weight' for the runs on more than one rank ('scene': the scene's, "
                        "i.e. the default 100000)")
    p.add_argument("--hydrostatic", action="store_true",
                   help="run only the elastic hydrostatic column")
    p.add_argument("--no-hydrostatic", action="store_true",
                   help="skip the elastic hydrostatic column in a full run")
    p.add_argument("--hydrostatic-steps", type=int, default=HYDROSTATIC_STEPS,
                   help="steps of the hydrostatic column")
    p.add_argument("--repeat", type=int, default=1,
                   help="repetitions of each run; the fastest time loop is reported")
    p.add_argument("--idle-wait", type=float, default=120.0,
                   help="before each run, wait up to this many seconds for the machine to "
                        "be idle (less than 0.25 cores busy); 0: do not wait")
    p.add_argument("--csv", default=os.path.join(REPO, "benchmarks", "results",
                                                 "mpm_throughput.csv"),
                   help="CSV file of the table")
    args = p.parse_args(argv)

    args.exe = find_executable(os.path.abspath(args.exe), args.wait)
    if not os.path.isfile(args.prm):
        sys.exit(f"scene file not found: {args.prm} (option --prm)")
    shapes = [s.strip() for s in args.shapes.split(",") if s.strip()]
    materials = [m.strip() for m in args.materials.split(",") if m.strip()]
    ranks_list = [int(r) for r in args.ranks.split(",") if r.strip()]
    weights = [None if w.strip() == "scene" else int(w)
               for w in args.particle_weights.split(",") if w.strip()]
    rank_variants = [(ranks, weight) for ranks in ranks_list
                     for weight in ([None] if ranks == 1 else weights)]

    sizes = []
    for cell, steps_full, steps_quick in SIZES:
        particles = round(0.2 / cell) * round(0.1 / cell) * 4
        if args.sizes is not None:
            if particles not in args.sizes:
                continue
        elif args.quick and steps_quick is None:
            continue
        if args.hydrostatic:
            continue
        steps = args.steps or (steps_quick if args.quick and steps_quick else steps_full)
        sizes.append((cell, steps))
    run_hydrostatic = args.hydrostatic or not (args.quick or args.no_hydrostatic
                                               or args.sizes is not None)

    rows = []
    t_start = time.perf_counter()
    print(f"SlideWave MPM throughput: {args.exe}, best of {args.repeat} run(s); "
          f"1 rank = the executable alone, N ranks = {args.mpirun} -np N")
    if sizes:
        print("Column collapse (prm/granular-column-collapse.prm): dt = 2.5e-5 s x "
              "(h / 2.5 mm) (same Courant number on every grid), "
              "output only at start and end (outside the timed loop); sizes: "
              + ", ".join(f"h = {c * 1000:g} mm {steps} steps" for c, steps in sizes)
              + ("" if all(s == 2000 for _, s in sizes) else
                 " (fewer steps than the 2000 of BENCHMARKS.md on the larger grids)"))
    print(TABLE_HEADER)
    print("-" * len(TABLE_HEADER))
    for cell, steps in sizes:
        for shape in shapes:
            for material in materials:
                for ranks, weight in rank_variants:
                    dt, settings = column_collapse_settings(cell, steps, shape, material)
                    if weight is not None:
                        settings[PARTICLE_WEIGHT] = weight
                    r = best_of(args.exe, args.prm, settings, ranks, args.mpirun,
                                args.repeat, args.idle_wait)
                    row = make_row("collapse", shape, material, ranks, cell, dt, r, weight)
                    rows.append(row)
                    print(table_row(row), flush=True)
    if run_hydrostatic:
        for shape in shapes:
            for ranks, weight in rank_variants:
                settings = hydrostatic_settings(shape, args.hydrostatic_steps)
                if weight is not None:
                    settings[PARTICLE_WEIGHT] = weight
                r = best_of(args.exe, args.prm, settings, ranks, args.mpirun, args.repeat,
                            args.idle_wait)
                row = make_row("hydrostatic", shape, "linear elastic", ranks, 0.01,
                               HYDROSTATIC_DT, r, weight)
                rows.append(row)
                print(table_row(row), flush=True)
    elapsed = time.perf_counter() - t_start
    print("-" * len(TABLE_HEADER))
    failed = [r for r in rows if r["status"] != "ok"]
    print(f"{len(rows)} runs ({len(failed)} failed) in {elapsed:.0f} s. advance = wall "
          "time of 'mpm: advance' (rank 0's TimerOutput); dt = 'mpm: time step' (the "
          "stable-time-step reduction, outside advance); total = whole process incl. "
          "start-up, set-up and output; p-steps/s = particles x steps / advance; RSS = peak "
          "resident set size summed over ranks; B/particle = RSS / particles (includes "
          "the fixed overhead); busiest = share of the particles on the busiest rank at "
          "start/end; ranks 2wN = 2 ranks with 'Load balancing/Particle weight' = N (--particle-weights); bg = cores busy with other processes during the run (should be ~0).")
    print(summary(rows))
    if run_hydrostatic:
        print("Reference (BENCHMARKS.md, another open-source C++ MPM): column collapse "
              "0.69 M particle-steps/s on one core, 1.15 M on two ranks, 124 MB; "
              "hydrostatic column 1.56 M on one core, 1.94 M on two threads.")
    write_csv(args.csv, rows, CSV_COLUMNS)
    print(f"wrote {args.csv}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
