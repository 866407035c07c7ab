#!/usr/bin/python3
"""Paper 000's Tables 3 and 5 for SlideWave: runs the clay column in still water
(R_ws = h_w/h_0 = 1, 1.5, 2) and in a dam break (R = h_l/h_r = 0.5, 1, 2), each with both
'Coupling/Water pressure on soil' forms (the paper's 'excess over initial level' and
'hydrostatic'), 12 runs of 6-20 s each, one at a time (about 2 minutes), into
/tmp/slidewave-figures like scripts/coupled_figures.py (--keep reuses its runs there), and
prints markdown tables in the paper's layout: one row per ratio, and for t = 0.5, 1 and 5 s
  Δs/h_s            statistics.csv column runout
  η_max/h_s         max_free_surface (the highest wet surface above the tank floor)
  |v_s|max/√(g h_s) max_soil_speed (the fastest material point)
  |u_0|max/√(g h_s) max_water_speed (the fastest water cell)
with h_s = 1 m and g = 9.81 m/s². The values are those of the statistics.csv row whose
time is that instant: the run control shortens the step to land on every output time
(every 0.25 s) and writes a statistics row there. If such a row is missing (another
output interval), the same quantities are taken from the particle and profile files
written at that instant (Δs from the points' largest x against that at t = 0, so the
same definition); the CSV's column 'source' says which.

  /usr/bin/python3 scripts/coupled_paper_tables.py [--build build] [--keep]
      [--csv benchmarks/results/coupled_paper_tables.csv]"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from coupled_figures import PRESSURES, ROOT, SCENES, run  # noqa: E402
import numpy as np  # noqa: E402
from plot_coupled_scene import output_times  # noqa: E402
from plot_particles import read_particles  # noqa: E402
from plot_water import read_profile  # noqa: E402

H_S, G = 1.0, 9.81
TIMES = [0.5, 1.0, 5.0]
# statistics.csv column, table heading, scale, CSV column (dimensionless).
QUANTITIES = [("runout", "Δs/h_s", H_S, "runout_over_hs"),
              ("max_free_surface", "η_max/h_s", H_S, "eta_max_over_hs"),
              ("max_soil_speed", "\\|v_s\\|max/√(gh_s)", math.sqrt(G * H_S),
               "soil_speed_over_sqrt_ghs"),
              ("max_water_speed", "\\|u_0\\|max/√(gh_s)", math.sqrt(G * H_S),
               "water_speed_over_sqrt_ghs")]
RATIOS = {"in-water": ("R_ws", "Table 3: clay column in still water"),
          "dam-break": ("R", "Table 5: clay column in a dam break")}


def from_files(directory, t):
    """The four quantities at time t from the output files written then."""
    written = output_times(directory)
    index = {when: written[min(written, key=lambda a: abs(a - when))] for when in (0.0, t)}
    toe = read_particles(os.path.join(directory, "particles", "particles_%05d.pvtu"
                                      % index[0.0]))[0][:, 0].max()
    points, data = read_particles(os.path.join(directory, "particles",
                                               "particles_%05d.pvtu" % index[t]))
    _, water = read_profile(os.path.join(directory, "water", "profile-%05d.csv" % index[t]))
    wet = water["h"] > 1e-6
    return {"runout": points[:, 0].max() - toe,
            "max_free_surface": water["eta"][wet].max(),
            "max_soil_speed": np.linalg.norm(data["velocity"][:, :2], axis=1).max(),
            "max_water_speed": np.abs(water["u"]).max()}


def values_at(directory, t):
    with open(os.path.join(directory, "statistics.csv")) as f:
        for row in csv.DictReader(f):
            if abs(float(row["time"]) - t) < 1e-9:
                return {q[0]: float(row[q[0]]) for q in QUANTITIES}, "statistics.csv"
    return from_files(directory, t), "output files"


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--keep", action="store_true")
    parser.add_argument("--csv", default=os.path.join(ROOT, "benchmarks", "results",
                                                      "coupled_paper_tables.csv"))
    args = parser.parse_args()
    rows = []
    for name, (_, _, values, _, _) in SCENES.items():
        ratio, caption = RATIOS[name]
        for pressure in sorted(PRESSURES):
            head = "| %s |" % ratio + "".join(" %s, t = %g s |" % (label, t) for t in TIMES
                                              for _, label, _, _ in QUANTITIES)
            lines = ["", "%s; water pressure on soil: %s" % (caption, pressure), "",
                     head, "|" + "---:|" * (1 + len(TIMES) * len(QUANTITIES))]
            for value in values:
                directory = run(args.build, name, value, pressure, args.keep)
                cells = []
                for t in TIMES:
                    found, source = values_at(directory, t)
                    scaled = {column: found[q] / scale for q, _, scale, column in QUANTITIES}
                    cells += ["%.3f" % v for v in scaled.values()]
                    rows.append(dict(scene=name, pressure=pressure, ratio_name=ratio,
                                     ratio=value, time=t, source=source,
                                     **{c: "%.5f" % v for c, v in scaled.items()}))
                lines.append("| %g | %s |" % (value, " | ".join(cells)))
            print("\n".join(lines), flush=True)
    os.makedirs(os.path.dirname(args.csv), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print("\nwrote", args.csv)


if __name__ == "__main__":
    main()
