#!/usr/bin/env python3
"""Two MPI ranks against one on the column collapse: interleaved pairs.

On a shared machine the same run varies by 10 % or more from one run to the next, and the
machine's speed drifts over minutes. A one-rank run and a two-rank run far apart in time
therefore measure the machine as much as the code. This script runs N pairs back to back
(one rank, then two ranks, N times) of the column collapse of
``prm/granular-column-collapse.prm`` at one size (default 819,200 points, 0.3125 mm cells,
100 steps; Q1, linear elastic; no output but the first and last) and prints, per pair, the
wall time of the time loop ('mpm: advance', rank 0's timer), the speed-up and the CPU
seconds the hypervisor took from the machine's cores during each run ('stolen', /proc/stat's
steal time: a core was ready to run and the host ran something else); then the
median of the pairs' speed-ups, the ratio of the medians and the ratio of the fastest runs.

With ``--timeline`` the runs write 'Material points/Step timeline' (per step and rank the
time of each part of the step, the exchanges between ranks apart), and each pair also gets
  work       the one-rank run's own work (every part but the exchanges) over the larger of
             the two ranks' own work: the speed-up if no rank ever waited for the other;
  step-max   the one-rank work over the sum over the steps of the larger rank's work of
             that step: the speed-up if the exchanges cost nothing but every step waits for
             the rank that was slower in it (what the ranks' speeds from step to step allow).
With ``--control`` each pair also runs two one-rank runs side by side, each bound to one of
the two cores (``taskset``), and prints
  side by side  their loop times;
  ceiling       2 x the pair's one-rank time over the slower of the two: what the two cores
                deliver on two independent copies of the one-rank run, no communication and
                no decomposition involved. The two-rank speed-up over this ceiling is what
                the code itself (decomposition, ghosts, exchanges) costs; the ceiling below
                2 is the machine (cores that slow down when both are busy).
The per-step rows of every run go to ``--timeline-csv``; ``--plot`` draws the pair with the
median speed-up (``--png``); ``--plot-only`` redraws it from the CSV.

Usage: benchmarks/mpm_two_ranks.py [--pairs 5] [--cell-size 0.0003125] [--steps 100]
       [--shape q1] [--material "linear elastic"] [--csv FILE] [--control]
       [--timeline] [--plot] [--plot-only PAIR]
Results go to ``benchmarks/results/mpm_two_ranks.csv`` (one row per run; the side-by-side
copies of --control have their core in ``side_by_side_core``). With --plot-only, --shape and
--material only name the run in the figures' titles.
"""
import argparse
import csv
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import (cpu_steal_seconds, find_executable, fmt,  # noqa: E402
                              on_both_cores, wait_until_idle, write_csv)
from mpm_throughput import column_collapse_settings, run_slidewave  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
COLUMNS = ["pair", "ranks", "side_by_side_core", "particles", "cells", "steps",
           "advance_wall_s", "setup_wall_s", "background_load", "steal_s", "own_work_s", "exchange_s",
           "step_max_work_s", "status"]
# The parts of step_timeline.csv: a rank's own work, and the exchanges where it may wait.
EXCHANGE_PARTS = ["exchange_sums", "exchange_velocities", "relocation_reduction"]
WORK_PARTS = ["grid_changes", "scatter", "grid_update", "gather", "musl_remap", "relocation",
              "full_sort"]


def summarize_timeline(rows):
    """Own work and exchange time [s] of the busiest rank, and the sum over the steps of
    the larger rank's work in that step."""
    work, exchange, per_step = {}, {}, {}
    for r in rows:
        rank, step = int(r["rank"]), int(r["step"])
        w = sum(r[p] for p in WORK_PARTS)
        work[rank] = work.get(rank, 0.) + w
        exchange[rank] = exchange.get(rank, 0.) + sum(r[p] for p in EXCHANGE_PARTS)
        per_step[step] = max(per_step.get(step, 0.), w)
    busiest = max(work, key=work.get)
    return {"own_work_s": work[busiest], "exchange_s": exchange[busiest],
            "step_max_work_s": sum(per_step.values()), "work_by_rank": work}


def side_by_side(exe, prm, settings, mpirun):
    """Two one-rank runs started together, on cores 0 and 1. Returns the two results."""
    return on_both_cores(lambda core: run_slidewave(exe, prm, settings, 1, mpirun,
                                                    prefix=("taskset", "-c", str(core))))


def pair_figures(rows):
    """Per pair, from the result rows: the two-rank speed-up, the ceiling (with --control),
    and the work and step-max speed-ups (with --timeline). Returns {pair: {name: value}}."""
    runs = {}
    for r in rows:
        core = r.get("side_by_side_core")
        if core not in (None, ""):
            kind = f"side by side {int(core)}"
        else:
            kind = "alone" if int(r["ranks"]) == 1 else "two ranks"
        runs.setdefault(int(r["pair"]), {})[kind] = r
    figures = {}
    for pair, k in sorted(runs.items()):
        alone, two = k["alone"], k["two ranks"]
        one = float(alone["advance_wall_s"])
        f = {"speed-up": one / float(two["advance_wall_s"])}
        if "side by side 0" in k and "side by side 1" in k:
            f["ceiling"] = 2 * one / max(float(k[f"side by side {c}"]["advance_wall_s"])
                                         for c in (0, 1))
        if alone.get("own_work_s") not in (None, ""):
            own = float(alone["own_work_s"])
            f["work"] = own / float(two["own_work_s"])
            f["step-max"] = own / float(two["step_max_work_s"])
        figures[pair] = f
    return figures


def plot_ceiling(rows, png, scene="Column collapse"):
    """Per pair, the two-rank speed-up against the ceiling of two one-rank runs side by side."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figures = pair_figures(rows)
    pairs = list(figures)
    fig, ax = plt.subplots(figsize=(8, 5))
    ax.axhline(2.0, color="0.7", lw=1, ls=":")
    ax.axhline(1.8, color="tab:red", lw=1, ls="--", label="target 1.8x")
    styles = (("ceiling", "tab:green", "s",
               "ceiling: two one-rank runs side by side (2 x alone / slower)"),
              ("work", "tab:blue", "^", "work speed-up (the ranks' own work, no waiting)"),
              ("speed-up", "black", "o", "two ranks: speed-up of the time loop"))
    for name, color, marker, label in styles:
        xs = [p for p in pairs if name in figures[p]]
        if xs:
            ax.plot(xs, [figures[p][name] for p in xs], color=color, marker=marker, lw=0.8,
                    label=label)
    ax.set_xlabel("pair (one rank, two ranks, two one-rank runs side by side; in that order)")
    ax.set_ylabel("speed-up over the pair's one-rank run")
    ax.set_xticks(pairs)
    ax.set_title(f"{scene}: what two cores of this machine deliver, and what two ranks get",
                 fontsize=9)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.15), ncol=2)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(png)), exist_ok=True)
    fig.savefig(png, dpi=110)


def read_result_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_timeline_csv(path):
    with open(path, newline="") as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def plot(rows, pair, png, scene="Column collapse"):
    """Per step, the own work of the two ranks of ``pair`` against half the one-rank run
    (``scene``: what was run, for the title)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def series(ranks, rank):
        picked = sorted((int(r["step"]), sum(r[p] for p in WORK_PARTS))
                        for r in rows if int(r["pair"]) == pair and int(r["ranks"]) == ranks
                        and int(r["rank"]) == rank)
        return [s for s, _ in picked], [1e3 * w for _, w in picked]

    fig, ax = plt.subplots(figsize=(8, 4))
    steps, serial = series(1, 0)
    ax.plot(steps, [w / 2 for w in serial], color="0.5", lw=1.5,
            label="one rank, half its work per step")
    for rank, color in ((0, "tab:blue"), (1, "tab:orange")):
        s, w = series(2, rank)
        ax.plot(s, w, color=color, lw=1, label=f"two ranks: rank {rank}'s own work")
    ax.set_xlabel("step")
    ax.set_ylabel("wall time of the step's own work [ms]")
    ax.set_title(f"{scene}: pair {pair} (every step waits for the slower rank)", fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(png)), exist_ok=True)
    fig.savefig(png, dpi=110)


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
    p.add_argument("--timeline", action="store_true",
                   help="write and analyse the step timeline of every run")
    p.add_argument("--timeline-csv", default=os.path.join(REPO, "benchmarks", "results",
                                                          "mpm_two_ranks_timeline.csv"))
    p.add_argument("--control", action="store_true",
                   help="per pair also two one-rank runs side by side (the machine's ceiling)")
    p.add_argument("--plot", action="store_true",
                   help="with --timeline: draw the pair with the median speed-up (--png); "
                        "with --control: the speed-ups against the ceiling (--ceiling-png)")
    p.add_argument("--plot-only", type=int, metavar="PAIR",
                   help="only redraw the figures: the timeline of pair PAIR from "
                        "--timeline-csv, the ceiling from --csv if it has --control runs")
    p.add_argument("--png", default=os.path.join(REPO, "doc", "figures",
                                                 "mpm-two-ranks-timeline.png"))
    p.add_argument("--ceiling-png", default=os.path.join(REPO, "doc", "figures",
                                                         "mpm-two-ranks-ceiling.png"))
    args = p.parse_args(argv)
    if args.plot_only is not None:
        # The titles name the run: its size from --csv, shape and material from the options.
        results = read_result_csv(args.csv)
        scene = (f"Column collapse, {int(results[0]['particles']):,} points, {args.shape}, "
                 f"{args.material}")
        if os.path.isfile(args.timeline_csv):
            plot(read_timeline_csv(args.timeline_csv), args.plot_only, args.png, scene)
            print(f"wrote {args.png}")
        if any(r.get("side_by_side_core") not in (None, "") for r in results):
            plot_ceiling(results, args.ceiling_png, scene)
            print(f"wrote {args.ceiling_png}")
        return
    exe = find_executable(args.exe, 0.)
    _, settings = column_collapse_settings(args.cell_size, args.steps, args.shape,
                                           args.material)
    if args.timeline:
        settings["Material points/Step timeline"] = "true"
    rows, times, steals, timeline_rows = [], {1: [], 2: []}, {1: [], 2: []}, []
    header = (f"{'pair':>4} {'1 rank [s]':>11} {'2 ranks [s]':>12} {'speed-up':>9} "
              f"{'stolen [s]':>11}")
    if args.control:
        header += f" {'side by side [s]':>17} {'ceiling':>8}"
    if args.timeline:
        header += f" {'work':>7} {'step-max':>9} {'rank work [s]':>14} {'exchanges [s]':>14}"
    print(header)
    for pair in range(1, args.pairs + 1):
        if args.idle_wait > 0:
            wait_until_idle(args.idle_wait)
        summaries = {}
        for ranks in (1, 2):
            steal = cpu_steal_seconds()
            r = run_slidewave(exe, args.prm, settings, ranks, args.mpirun)
            r.update(pair=pair, ranks=ranks, steal_s=cpu_steal_seconds() - steal)
            steals[ranks].append(r["steal_s"])
            if r["status"] != "ok":
                sys.exit(f"pair {pair}, {ranks} rank(s): {r['status']}")
            if args.timeline:
                if not r["timeline"]:
                    sys.exit(f"pair {pair}, {ranks} rank(s): no step_timeline.csv")
                summaries[ranks] = summarize_timeline(r["timeline"])
                r.update({k: summaries[ranks][k] for k in
                          ("own_work_s", "exchange_s", "step_max_work_s")})
                timeline_rows += [dict(t, pair=pair, ranks=ranks, step=int(t["step"]),
                                      rank=int(t["rank"])) for t in r["timeline"]]
            rows.append(r)
            times[ranks].append(r["advance_wall_s"])
        if args.control:
            both = side_by_side(exe, args.prm, settings, args.mpirun)
            for core, r in enumerate(both):
                if r["status"] != "ok":
                    sys.exit(f"pair {pair}, side by side on core {core}: {r['status']}")
                r.update(pair=pair, ranks=1, side_by_side_core=core)
                r.pop("timeline", None)
                rows.append(r)
        f = pair_figures([r for r in rows if r["pair"] == pair])[pair]
        line = (f"{pair:>4} {times[1][-1]:>11.2f} {times[2][-1]:>12.2f} "
                f"{f['speed-up']:>8.2f}x {steals[1][-1]:>5.2f}/{steals[2][-1]:<5.2f}")
        if args.control:
            line += (f" {both[0]['advance_wall_s']:>8.2f}/{both[1]['advance_wall_s']:<8.2f}"
                     f" {f['ceiling']:>7.2f}x")
        if args.timeline:
            two = summaries[2]
            by_rank = "/".join(f"{two['work_by_rank'][k]:.2f}" for k in sorted(two["work_by_rank"]))
            line += (f" {f['work']:>6.2f}x {f['step-max']:>8.2f}x {by_rank:>14} "
                     f"{two['exchange_s']:>14.2f}")
        print(line, flush=True)
    write_csv(args.csv, rows, COLUMNS)
    figures = list(pair_figures(rows).values())
    ratios = [f["speed-up"] for f in figures]
    scene = (f"Column collapse, {rows[0]['particles']:,} points, {args.shape}, "
             f"{args.material}")
    print(f"{rows[0]['particles']} points, {rows[0]['cells']} cells, {args.steps} steps, "
          f"{args.shape}, {args.material}")
    print(f"median of the pairs' speed-ups: {statistics.median(ratios):.2f}x "
          f"(from {min(ratios):.2f}x to {max(ratios):.2f}x)")
    print(f"ratio of the medians: {statistics.median(times[1]) / statistics.median(times[2]):.2f}x"
          f" ({fmt(statistics.median(times[1]), '.2f')} s / "
          f"{fmt(statistics.median(times[2]), '.2f')} s)")
    print(f"ratio of the fastest runs: {min(times[1]) / min(times[2]):.2f}x")
    if args.control:
        ceilings = [f["ceiling"] for f in figures]
        efficiency = [r / c for r, c in zip(ratios, ceilings)]
        print(f"median ceiling (two one-rank runs side by side): "
              f"{statistics.median(ceilings):.2f}x (from {min(ceilings):.2f}x to "
              f"{max(ceilings):.2f}x); median two-rank speed-up over the pair's ceiling: "
              f"{statistics.median(efficiency):.2f}")
        if args.plot:
            plot_ceiling(rows, args.ceiling_png, scene)
            print(f"figure of the speed-ups against the ceiling: {args.ceiling_png}")
    print(f"results: {args.csv}")
    if args.timeline:
        work = statistics.median(f["work"] for f in figures)
        step_max = statistics.median(f["step-max"] for f in figures)
        print(f"median work speed-up (no rank waits): {work:.2f}x; "
              f"median step-max speed-up (each step waits for its slower rank, free "
              f"exchanges): {step_max:.2f}x")
        columns = ["pair", "ranks", "step", "rank"] + WORK_PARTS + EXCHANGE_PARTS
        write_csv(args.timeline_csv, timeline_rows, columns)
        print(f"step timelines: {args.timeline_csv}")
        if args.plot:
            median_pair = sorted(range(len(ratios)), key=lambda i: ratios[i])[len(ratios) // 2] + 1
            plot(timeline_rows, median_pair, args.png, scene)
            print(f"figure of pair {median_pair} (median speed-up): {args.png}")


if __name__ == "__main__":
    main()
