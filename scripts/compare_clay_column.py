#!/usr/bin/python3
"""Compare runs of the clay column in water at two fidelities (issue 27).

The 1D coupled scene (prm/clay-column-in-water.prm: MPM soil + depth-averaged shallow
water) and the 2D granular-water scene (prm/clay-column-in-water-2d.prm: MPM skeleton +
Navier-Stokes with a phase-field surface on the same grid) of one event. Each run is an
output directory, given as LABEL=DIR; its kind is read from what it holds:

  coupled         statistics.csv (time, runout) and water/gauges.csv
  granular water  statistics.csv (time, skeleton_front) and free_surface/gauges.csv

The runout is the advance of the soil's rightmost point since t = 0 (the coupled scene's
'runout'; skeleton_front minus its first value for granular water). At the gauge x = 4 m:
the arrival of the first wave, the first time the surface stands 'threshold' (1 cm) above
its initial level; the first crest, the highest surface between the arrival and the first
time the surface falls back to the initial level (or the end of the record), its height
above that level and its time; the half-crest time, when the surface first stands half the
crest's height above the level (an arrival time that does not depend on the wave's size:
a low wave crosses a fixed threshold late on its front, and a slow rise of the whole pool
crosses it early). The wall time of a run is read from DIR/wall_time.txt (one
number, seconds, written by benchmarks/clay_column_fidelities.py) when it is there.

Writes the figure (runout over time; surface elevation at x = 4 m over time) and prints a
Markdown table. Only the standard library and matplotlib.

  scripts/compare_clay_column.py '1D coupled=/tmp/clay/oned' '2D granular water=/tmp/clay/twod'
"""
import argparse
import csv
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GAUGE_X = 4.0


def read_columns(path):
    """The CSV file at ``path`` as a dict of column name -> list of floats."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        names = [n.strip() for n in next(reader)]
        columns = {n: [] for n in names}
        for row in reader:
            if len(row) != len(names):
                continue
            try:
                values = [float(v) for v in row]
            except ValueError:
                continue
            for n, v in zip(names, values):
                columns[n].append(v)
    return columns


def gauge_column(columns, x):
    """The name of the gauges.csv column of the gauge at ``x``."""
    for name in columns:
        if name.startswith("eta(x=") and abs(float(name[6:-1]) - x) < 1e-9:
            return name
    raise KeyError(f"no gauge at x = {x} (columns: {', '.join(columns)})")


def load_run(directory):
    """Runout and gauge series of one output directory, with its kind and wall time."""
    stats = read_columns(os.path.join(directory, "statistics.csv"))
    if os.path.isfile(os.path.join(directory, "water", "gauges.csv")):
        kind = "coupled"
        gauges = read_columns(os.path.join(directory, "water", "gauges.csv"))
        runout = stats["runout"]
    elif os.path.isfile(os.path.join(directory, "free_surface", "gauges.csv")):
        kind = "granular water"
        gauges = read_columns(os.path.join(directory, "free_surface", "gauges.csv"))
        front = stats["skeleton_front"]
        runout = [f - front[0] for f in front]
    else:
        raise FileNotFoundError(f"{directory}: neither water/gauges.csv nor "
                                "free_surface/gauges.csv")
    wall = None
    wall_file = os.path.join(directory, "wall_time.txt")
    if os.path.isfile(wall_file):
        with open(wall_file) as f:
            wall = float(f.read().split()[0])
    eta = gauges[gauge_column(gauges, GAUGE_X)]
    return {"kind": kind, "time": stats["time"], "runout": runout,
            "gauge_time": gauges["time"], "eta": eta, "wall_s": wall}


def first_wave(time, eta, still, threshold):
    """Arrival time, crest time, crest height above ``still`` and half-crest time of the
    first wave."""
    arrival = None
    for i, (t, e) in enumerate(zip(time, eta)):
        if e - still >= threshold:
            arrival = i
            break
    if arrival is None:
        return None, None, None, None
    crest = arrival
    for i in range(arrival, len(eta)):
        if eta[i] < still:
            break
        if eta[i] > eta[crest]:
            crest = i
    height = eta[crest] - still
    half = next(t for t, e in zip(time, eta) if e - still >= 0.5 * height)
    return time[arrival], time[crest], height, half


def summarize(label, directory, threshold=0.01, still=None):
    """The numbers of the table for one run."""
    run = load_run(directory)
    level = run["eta"][0] if still is None else still
    arrival, crest_time, crest, half = first_wave(run["gauge_time"], run["eta"], level, threshold)
    run.update({"label": label, "directory": directory, "end_time": run["time"][-1],
                "runout_end": run["runout"][-1], "still_level": level,
                "arrival_s": arrival, "crest_time_s": crest_time, "crest_m": crest,
                "half_crest_s": half,
                "runout_1s": interpolate(run["time"], run["runout"], 1.0)})
    return run


def interpolate(xs, ys, x):
    """Linear interpolation of the series at x (None outside it)."""
    if not xs or x < xs[0] or x > xs[-1]:
        return None
    for i in range(1, len(xs)):
        if xs[i] >= x:
            w = (x - xs[i - 1]) / (xs[i] - xs[i - 1]) if xs[i] > xs[i - 1] else 1.
            return ys[i - 1] + w * (ys[i] - ys[i - 1])
    return ys[-1]


def fmt(value, spec):
    return "-" if value is None else format(value, spec)


def print_table(runs):
    print("| run | model | end [s] | runout at 1 s [m] | runout at the end [m] | "
          "first crest at x = 4 m [m] | arrival (1 cm) [s] | half-crest [s] | crest time [s] | "
          "wall time [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in runs:
        print(f"| {r['label']} | {r['kind']} | {r['end_time']:.3g} | {fmt(r['runout_1s'], '.3f')} | "
              f"{r['runout_end']:.3f} | {fmt(r['crest_m'], '.3f')} | {fmt(r['arrival_s'], '.2f')} | "
              f"{fmt(r['half_crest_s'], '.2f')} | {fmt(r['crest_time_s'], '.2f')} | "
              f"{fmt(r['wall_s'], '.3g')} |")


def plot(runs, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax_runout, ax_gauge) = plt.subplots(1, 2, figsize=(11, 4))
    styles = ["-", "--", "-.", ":"]
    for i, r in enumerate(runs):
        style = styles[i % len(styles)]
        ax_runout.plot(r["time"], r["runout"], style, label=r["label"])
        ax_gauge.plot(r["gauge_time"], [e - r["still_level"] for e in r["eta"]], style,
                      label=r["label"])
        if r["crest_m"] is not None:
            ax_gauge.plot([r["crest_time_s"]], [r["crest_m"]], "o",
                          color=ax_gauge.lines[-1].get_color(), markersize=4)
    ax_runout.set_xlabel("t [s]")
    ax_runout.set_ylabel("runout: advance of the soil's front [m]")
    ax_runout.set_title("Clay column in water: runout")
    ax_gauge.set_xlabel("t [s]")
    ax_gauge.set_ylabel("surface elevation above the still level at x = 4 m [m]")
    ax_gauge.set_title("Gauge x = 4 m (dots: first crest)")
    for ax in (ax_runout, ax_gauge):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(png)), exist_ok=True)
    fig.savefig(png, dpi=120)
    print("figure:", png)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("runs", nargs="+", metavar="LABEL=DIR",
                        help="a run's label and its output directory")
    parser.add_argument("--png", default=os.path.join(ROOT, "doc", "figures",
                                                      "clay-column-fidelities.png"))
    parser.add_argument("--threshold", type=float, default=0.01,
                        help="rise above the initial level that marks the arrival [m]")
    args = parser.parse_args()
    runs = []
    for spec in args.runs:
        label, _, directory = spec.rpartition("=")
        runs.append(summarize(label or directory, directory, args.threshold))
    print_table(runs)
    plot(runs, args.png)
    return runs


if __name__ == "__main__":
    main()
