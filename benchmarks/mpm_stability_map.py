#!/usr/bin/python3
"""Stability map of the explicit material point method: which runs complete and which are
stopped by the guards (exit status 2), over the time step multiplier alpha of Eq. 23
(0.1 ... 1; above 1/sqrt(2) = 0.7071 the program refuses the scene before the run,
exit status 1, shown as 'refused') and the number of points per cell direction (1 ... 4), for Q1 and GIMP with the
USL update, on two problems:

  bar     the vibrating bar of tests/mpm/bar_vibration.prm at its standard amplitude
          (0.1 m/s), on 0.5 m cells, with its verification tolerance off: outcome and the
          largest centre-of-mass velocity error over the period (m/s)
  column  the dry sand column collapse of prm/granular-column-collapse.prm on 5 mm cells,
          with Eq. 23 instead of the fixed time step (Fixed time step = 0), to t = 0.3 s:
          outcome, final kinetic energy, front position and lost mass

Every run is one `slidewave` process in test mode (nice -n 19). The outcome is 'completed'
(exit 0) or 'stopped' (exit 2) with the guard that stopped it ('volume': a point's volume
became non-positive, 'non-finite': a non-finite value, 'energy': kinetic energy above the
energy available), the step and the time. Prints the table, writes a CSV (rows already in
the CSV are reused unless --rerun) and draws the figure.

  /usr/bin/python3 benchmarks/mpm_stability_map.py [--build build] [--problems bar column]
      [--csv benchmarks/results/mpm_stability_map.csv]
      [--figure doc/figures/mpm-stability-map.png] [--rerun] [--plot-only]
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MULTIPLIERS = [0.1, 0.25, 0.5, 0.6, 0.7071, 0.75, 1.0]
PARTICLES = [1, 2, 3, 4]
SHAPES = ["q1", "gimp"]
FIELDS = ["problem", "shape", "multiplier", "particles_per_direction", "points", "outcome",
          "guard", "stop_step", "stop_time", "steps", "end_time", "kinetic_energy",
          "max_particle_speed", "runout", "mass", "lost_mass", "error", "wall_seconds",
          "message"]

PROBLEMS = {
    "bar": dict(
        scene=os.path.join("tests", "mpm", "bar_vibration.prm"),
        settings=["Material points/Verification/Tolerance=0",
                  "Material points/Grid/Cell size=0.5",
                  "Time/Statistics interval=1000000"]),
    "column": dict(
        scene=os.path.join("prm", "granular-column-collapse.prm"),
        settings=["Material points/Grid/Cell size=0.005",
                  "Material points/Fixed time step=0",
                  "Time/End time=0.3",
                  "Time/Output interval=0",
                  "Time/Statistics interval=1000000"]),
}


def parse_row(line):
    return {k: v for k, v in re.findall(r"(\w+)=(\S+)", line)}


def run(build, problem, shape, multiplier, ppd):
    spec = PROBLEMS[problem]
    directory = "/tmp/slidewave-bench/stability-map/%s-%s-%g-%d" % (problem, shape, multiplier,
                                                                      ppd)
    command = ["nice", "-n", "19", os.path.join(build, "slidewave"),
               "--set", "Test/Enable=true",
               "--set", "Output directory=" + directory,
               "--set", "Material points/Shape functions=" + shape,
               "--set", "Material points/Update scheme=usl",
               "--set", "Material points/Time step multiplier=%g" % multiplier,
               "--set", "Material points/Particles per direction=%d" % ppd]
    for s in spec["settings"]:
        command += ["--set", s]
    command.append(os.path.join(ROOT, spec["scene"]))
    start = time.time()
    result = subprocess.run(command, capture_output=True, text=True)
    wall = time.time() - start
    rows = [parse_row(l) for l in result.stdout.splitlines() if l.startswith("time=")]
    first, last = (rows[0], rows[-1]) if rows else ({}, {})
    record = dict(problem=problem, shape=shape, multiplier=multiplier,
                  particles_per_direction=ppd, points=first.get("particles"),
                  steps=last.get("step"), end_time=last.get("time"),
                  kinetic_energy=last.get("kinetic_energy"),
                  max_particle_speed=last.get("max_particle_speed"),
                  runout=last.get("runout"), mass=last.get("mass"),
                  lost_mass=last.get("lost_mass"), error="", guard="", stop_step="",
                  stop_time="", message="", wall_seconds="%.1f" % wall)
    error = re.search(r"error against the exact solution = (\S+)", result.stdout)
    if error:
        record["error"] = error.group(1)
    if result.returncode == 0:
        record["outcome"] = "completed"
    elif result.returncode == 2:
        record["outcome"] = "stopped"
        message = result.stderr.strip().splitlines()[-1]
        record["message"] = message
        where = re.search(r"at step (\d+), t = (\S+) s", message)
        if where:
            record["stop_step"], record["stop_time"] = where.group(1), where.group(2)
        if "non-positive volume" in message:
            record["guard"] = "volume"
        elif "non-finite" in message:
            record["guard"] = "non-finite"
        elif "kinetic energy" in message:
            record["guard"] = "energy"
        elif "left the domain" in message:
            record["guard"] = "wall"
        else:
            record["guard"] = "other"
    elif result.returncode == 1:
        record["outcome"] = "refused"
        record["message"] = (result.stderr.strip().splitlines() or [""])[-1]
    else:
        record["outcome"] = "exit %d" % result.returncode
        record["message"] = (result.stderr.strip().splitlines() or [""])[-1]
    return record


def key(r):
    return (r["problem"], r["shape"], float(r["multiplier"]), int(r["particles_per_direction"]))


def describe(r):
    if r["outcome"] == "completed":
        if r["problem"] == "bar":
            return "ok, err %.1e" % float(r["error"])
        return "ok, KE %.2g" % float(r["kinetic_energy"])
    if r["outcome"] == "stopped":
        return "%s @%s" % (r["guard"], r["stop_step"])
    return r["outcome"]


def print_table(records):
    for problem in PROBLEMS:
        for shape in SHAPES:
            print("\n%s, %s (USL): rows = particles per direction, columns = multiplier"
                  % (problem, shape))
            print("%4s " % "ppd" + "".join("%17g" % m for m in MULTIPLIERS))
            for ppd in PARTICLES:
                cells = []
                for m in MULTIPLIERS:
                    r = records.get((problem, shape, m, ppd))
                    cells.append("%17s" % (describe(r) if r else "-"))
                print("%4d " % ppd + "".join(cells))


COLOURS = {"completed": "#4daf4a", "volume": "#e41a1c", "energy": "#ff7f00",
           "non-finite": "#984ea3", "wall": "#377eb8", "refused": "#cccccc",
           "other": "#999999"}


def plot(records, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Patch, Rectangle
    fig, axes = plt.subplots(2, 2, figsize=(12, 7.5), constrained_layout=True)
    titles = {"bar": "vibrating bar, 0.5 m cells, 10 s", "column": "sand column, 5 mm cells, 0.3 s"}
    for row, problem in enumerate(PROBLEMS):
        for col, shape in enumerate(SHAPES):
            ax = axes[row][col]
            for i, m in enumerate(MULTIPLIERS):
                for j, ppd in enumerate(PARTICLES):
                    r = records.get((problem, shape, m, ppd))
                    if r is None:
                        colour, text = "white", "not run"
                    elif r["outcome"] == "completed":
                        colour = COLOURS["completed"]
                        text = ("err\n%.1e" % float(r["error"]) if problem == "bar" else
                                "KE\n%.2g" % float(r["kinetic_energy"]))
                        if r["lost_mass"] not in ("", "0") and float(r["lost_mass"]) > 0:
                            text += "\nlost %.2g" % float(r["lost_mass"])
                    elif r["outcome"] == "refused":
                        colour, text = COLOURS["refused"], "refused\n(alpha > 0.7071)"
                    else:
                        colour = COLOURS.get(r["guard"], COLOURS["other"])
                        text = "step %s\nt=%.3g" % (r["stop_step"], float(r["stop_time"] or "nan"))
                    ax.add_patch(Rectangle((i - 0.45, j - 0.45), 0.9, 0.9, facecolor=colour,
                                           edgecolor="black", linewidth=0.5))
                    ax.text(i, j, text, ha="center", va="center", fontsize=7)
            ax.set_xlim(-0.5, len(MULTIPLIERS) - 0.5)
            ax.set_ylim(-0.5, len(PARTICLES) - 0.5)
            ax.set_xticks(range(len(MULTIPLIERS)))
            ax.set_xticklabels(["%g" % m for m in MULTIPLIERS])
            ax.set_yticks(range(len(PARTICLES)))
            ax.set_yticklabels(["%d" % p for p in PARTICLES])
            ax.set_xlabel("time step multiplier (Eq. 23)")
            ax.set_ylabel("particles per direction")
            ax.set_title("%s, %s (USL)" % (titles[problem], shape.upper()), fontsize=10)
    handles = [Patch(facecolor=COLOURS["completed"], edgecolor="black", label="completed"),
               Patch(facecolor=COLOURS["volume"], edgecolor="black",
                     label="stopped: non-positive volume"),
               Patch(facecolor=COLOURS["energy"], edgecolor="black",
                     label="stopped: kinetic energy above the energy available"),
               Patch(facecolor=COLOURS["non-finite"], edgecolor="black",
                     label="stopped: non-finite values"),
               Patch(facecolor=COLOURS["wall"], edgecolor="black",
                     label="stopped: point crossed a wall"),
               Patch(facecolor=COLOURS["refused"], edgecolor="black",
                     label="refused before the run")]
    fig.legend(handles=handles, loc="lower center", ncol=3, fontsize=8,
               bbox_to_anchor=(0.5, -0.04))
    os.makedirs(os.path.dirname(out), exist_ok=True)
    fig.savefig(out, dpi=110, bbox_inches="tight")
    print("wrote", out)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--problems", nargs="+", default=list(PROBLEMS), choices=list(PROBLEMS))
    parser.add_argument("--csv", default=os.path.join(ROOT, "benchmarks", "results",
                                                      "mpm_stability_map.csv"))
    parser.add_argument("--figure", default=os.path.join(ROOT, "doc", "figures",
                                                         "mpm-stability-map.png"))
    parser.add_argument("--rerun", action="store_true", help="ignore rows already in the CSV")
    parser.add_argument("--plot-only", action="store_true")
    args = parser.parse_args()

    records = {}
    if os.path.exists(args.csv) and not args.rerun:
        for r in csv.DictReader(open(args.csv)):
            records[key(r)] = r
    if not args.plot_only:
        os.makedirs(os.path.dirname(args.csv), exist_ok=True)
        for problem in args.problems:
            for shape in SHAPES:
                for ppd in PARTICLES:
                    for m in MULTIPLIERS:
                        if (problem, shape, m, ppd) in records:
                            continue
                        r = run(args.build, problem, shape, m, ppd)
                        records[key(r)] = r
                        print("%-6s %-4s alpha=%-4g ppd=%d: %-22s (%s s)"
                              % (problem, shape, m, ppd, describe(r), r["wall_seconds"]),
                              flush=True)
                        with open(args.csv, "w", newline="") as f:
                            writer = csv.DictWriter(f, fieldnames=FIELDS)
                            writer.writeheader()
                            for k in sorted(records):
                                writer.writerow({f_: records[k].get(f_, "") for f_ in FIELDS})
    print_table(records)
    plot(records, args.figure)


if __name__ == "__main__":
    sys.exit(main())
