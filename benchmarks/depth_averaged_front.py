#!/usr/bin/python3
"""What limits the dry front of the depth-averaged material points (issue 28, item 1).

The dry-bed dam breaks of benchmarks/depth_averaged_work_precision.py, Ritter's on a flat
bed (t = 4 s) and Mangeney et al.'s on a 40 deg slope with Coulomb friction phi = 20 deg
(t = 2 s), and Stoker's wet one as the check that a change does not spoil a wet flow; the
front is where the nodal depth first exceeds 1 % of the release depth, against the same
point of the exact solution, in per cent of the exact distance travelled. Errors only (they
are deterministic; no repetitions, no timing). The series, GIMP and 'Depth update =
projection' throughout:

* ``defaults``: the defaults since the columns split (FLIP fraction 0.8, 'Split stretch =
  1.5') on 0.5 to 0.0625 m cells (Ritter also 0.03125 m), with Stoker as the wet check;
* ``parts``: each part of the defaults at 0.0625 m: PIC or FLIP 0.5 to 0.95, 'Split
  stretch' 0, 1.5 or 2;
* ``columns`` (this and the series below without splitting, 'Split stretch = 0', as before
  the columns split): 2, 4, 6, 8, 10 columns per cell direction (the program's limit is
  10) on 0.25 m cells, PIC;
* ``together``: the columns per cell refined with the cell, (C, n) = (0.5, 2), (0.25, 4),
  (0.125, 8), so that the columns' initial spacing C / n falls as C^2 (PIC, and FLIP
  fraction 0.95), with Stoker's wet dam break as the check;
* ``others``: FLIP fraction 0.95 with 8 x 8 columns on the rigid translation (0.25 to
  0.0625 m) and the sliding block on 40 deg (0.5 m);
* ``flip``: FLIP fractions 0, 0.5, 0.8, 0.9, 0.95, 1 on 0.25 m cells with 8 x 8 columns.

Output: a line per run, markdown tables, CSV ``--csv`` (default
benchmarks/results/depth_averaged_front.csv). About 5 minutes on this 2-core machine, and 3 more for
``defaults`` and ``parts``.

Usage:
    /usr/bin/python3 benchmarks/depth_averaged_front.py
    /usr/bin/python3 benchmarks/depth_averaged_front.py --series flip
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import add_orders, find_executable, fmt, write_csv  # noqa: E402
from depth_averaged_work_precision import parse_line, run_slidewave  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

SERIES = {
    # The defaults since the columns split (FLIP 0.8, 'Split stretch = 1.5').
    "defaults": [(q, "gimp-flip80-proj-4-s1.5", c) for q in ("Ritter", "slope", "Stoker")
                 for c in (0.5, 0.25, 0.125, 0.0625)] + [("Ritter", "gimp-flip80-proj-4-s1.5",
                                                          0.03125)],
    # Each part of the defaults at 0.0625 m: the transfer and the split stretch.
    "parts": [(q, line, 0.0625) for q in ("Ritter", "slope", "Stoker")
              for line in ("gimp-pic-proj-4-s0", "gimp-pic-proj-4-s1.5", "gimp-flip50-proj-4-s2",
                           "gimp-flip65-proj-4-s2", "gimp-flip80-proj-4-s2",
                           "gimp-flip95-proj-4-s2")],
    "columns": [(q, f"gimp-pic-proj-{n}-s0", 0.25) for q in ("Ritter", "slope")
                for n in (2, 4, 6, 8, 10)],
    "together": [(q, f"gimp-{t}-proj-{n}-s0", c) for q in ("Ritter", "slope", "Stoker")
                 for t in ("pic", "flip95")
                 for c, n in ((0.5, 2), (0.25, 4), (0.125, 8))],
    # The same transfer on the other exact cases: the rigid translation and the block.
    "others": [("rigid", "gimp-flip95-proj-8-s0", c) for c in (0.25, 0.125, 0.0625)]
    + [("block", "gimp-flip95-proj-8-s0", 0.5)],
    "flip": [(q, f"gimp-{t}-proj-8-s0", 0.25) for q in ("Ritter", "slope", "Stoker")
             for t in ("pic", "flip50", "flip80", "flip90", "flip95", "flip")],
}

CSV_COLUMNS = ["series", "problem", "line", "flip_fraction", "particles_per_direction",
               "cell_size", "columns", "steps", "error", "order", "front", "front_exact",
               "front_error_percent", "advance_wall_s", "status"]


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("--exe", default=os.path.join(REPO, "build", "slidewave"))
    p.add_argument("--series", default=",".join(SERIES),
                   help="defaults, parts, columns, together, others, flip")
    p.add_argument("--nice", type=int, default=10, help="niceness of the runs (0: none)")
    p.add_argument("--csv", default=os.path.join(REPO, "benchmarks", "results",
                                                 "depth_averaged_front.csv"))
    args = p.parse_args(argv)
    exe = find_executable(args.exe, 60)
    rows = []
    print(f"{'series':<9} {'problem':<7} {'line':<20} {'C':>7} {'columns':>8} {'steps':>5} "
          f"{'L1 error':>10} {'front%':>7}  status", flush=True)
    for series in [s.strip() for s in args.series.split(",") if s.strip()]:
        for problem, line, cell in SERIES[series]:
            r = run_slidewave(exe, problem, line, cell, args.nice)
            _shape, flip, _update, ppd = parse_line(line)
            row = dict(r, series=series, problem=problem, line=line, flip_fraction=flip,
                       particles_per_direction=ppd, cell_size=cell)
            rows.append(row)
            print(f"{series:<9} {problem:<7} {line:<20} {cell:>7g} {fmt(r['columns'], 'd'):>8} "
                  f"{fmt(r['steps'], 'd'):>5} {fmt(r['error'], '.4e'):>10} "
                  f"{fmt(r['front_error_percent'], '+.1f'):>7}  {r['status']}", flush=True)
    # Observed orders within the 'together' series (one line = one transfer, the cell and
    # the columns refined together): add_orders groups by (problem, line), so give the
    # series' rows a common line name for that.
    for row in rows:
        row["order"] = None
    together = [dict(r, line="-".join(r["line"].split("-")[:3]) + "-n") for r in rows
                if r["series"] == "together"]
    add_orders(together)
    for r, t in zip([r for r in rows if r["series"] == "together"], together):
        r["order"] = t["order"]
    # And within the 'defaults' series (one line, the cells refined).
    add_orders([r for r in rows if r["series"] == "defaults"])
    write_csv(args.csv, rows, CSV_COLUMNS)
    print(f"\nwrote {args.csv}\n")
    for series in sorted({r["series"] for r in rows}, key=list(SERIES).index):
        print(f"**{series}**\n")
        print("| problem | line | C [m] | columns | L1 of h | order | front [%] |")
        print("|---|---|---:|---:|---:|---:|---:|")
        for r in rows:
            if r["series"] == series:
                print(f"| {r['problem']} | {r['line']} | {r['cell_size']:g} | "
                      f"{fmt(r['columns'], ',')} | {fmt(r['error'], '.4f')} | "
                      f"{fmt(r['order'], '.2f')} | {fmt(r['front_error_percent'], '+.1f')} |")
        print()
    return 0


if __name__ == "__main__":
    sys.exit(main())
