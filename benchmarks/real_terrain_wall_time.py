#!/usr/bin/python3
"""Wall time of the real-terrain landslide at the size of issue 19: 10^5 columns, 20 s of flow.

The Jacksboro scene (``prm/jacksboro-landslide.prm``: the SRTM DEM that Debian's matplotlib
ships, reprojected to UTM 16N; 10^6 m^3 released from a GeoJSON polygon, the
Bindo-Cortenova parameters of paper 001, section 4.3; hazard maps on) on a 2.5 km x 2.5 km
window of 2.5 m cells (10^6 cells) with 4 x 4 columns per cell: 129,024 columns, 20 s of
flow (about 250 steps), no grid output. Needs ``prm/data/jacksboro_dem.tif``
(``scripts/make_jacksboro_dem.py``; ``scripts/run-jacksboro.sh`` makes it).

Cases, in rounds (every case once, then again, in an order that turns from round to round,
with a pause before each: the machine's speed drifts by tens of per cent over minutes, so
only interleaved runs compare):

* ``1 rank``: the executable alone;
* ``ceiling``: two one-rank copies started side by side; each copy's time against ``1
  rank`` of the same round is what sharing the machine costs, so 2 x t(1 rank) / t(copies)
  is the most two ranks can gain here (no decomposition, no communication);
* ``2 ranks``: ``mpirun -np 2``.

Per run: the wall time of the process, the timer table's 'setup' (grid of 10^6 cells, the
DEM read and warped, the release read and filled), 'advance' (the steps) and 'hazard maps'
(the nodal state every 5 steps) rows (on 2 ranks the slowest rank's), and the peak
resident memory of the largest process (``/usr/bin/time -f %M``). Prints the medians and the
speed-ups, and writes every run to ``results/real_terrain_wall_time.csv``.

    /usr/bin/python3 benchmarks/real_terrain_wall_time.py              # 3 rounds, ~9 min
    /usr/bin/python3 benchmarks/real_terrain_wall_time.py --rounds 1
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import find_executable, wait_until_idle, write_csv  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, "prm", "jacksboro-landslide.prm")
OVERRIDES = ["Depth averaged/Grid/Lower left=747000, 4041500",
             "Depth averaged/Grid/Upper right=749500, 4044000",
             "Depth averaged/Grid/Cell size=2.5",
             "Depth averaged/Release/Particles per direction=4",
             "Time/End time=20",
             "Depth averaged/Output grid=false"]
PARTS = {"setup": "depth averaged: setup", "advance": "depth averaged: advance",
         "maps": "depth averaged: hazard maps"}


def command(exe, output, ranks):
    """The command line of one run into ``output`` on ``ranks`` ranks."""
    args = [exe, "--set", f"Output directory={output}"]
    for o in OVERRIDES:
        args += ["--set", o]
    args.append(SCENE)
    launcher = ["mpirun", "-np", str(ranks)] if ranks > 1 else []
    return ["/usr/bin/time", "-f", "%M"] + launcher + args


def parse(log, time_err, ranks):
    """The timer rows (the slowest rank's on several ranks) and the peak memory."""
    row = {}
    for key, name in PARTS.items():
        m = re.search(r"\|\s*" + re.escape(name) + r"\s*\|\s*\d+\s*\|([^|]*)\|([^|]*)\|([^|]*)\|",
                      log)
        if m:
            cells = [c.split() for c in m.groups()]
            # One rank: "time | %"; several: "min rank | avg | max rank".
            row[key] = float(cells[2][0].rstrip("s")) if ranks > 1 \
                else float(cells[0][0].rstrip("s"))
    memory = [int(v) for v in time_err.split() if v.isdigit()]
    row["rss_mb"] = memory[-1] / 1024 if memory else None
    columns = re.search(r"(\d+) columns", log)
    row["columns"] = int(columns.group(1)) if columns else None
    return row


def start(exe, ranks, tag, directory):
    out = os.path.join(directory, tag)
    return subprocess.Popen(command(exe, out, ranks), stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, cwd=ROOT)


def finish(process, ranks, case, round_, t0):
    log, err = process.communicate()
    if process.returncode != 0:
        sys.exit(f"a run failed ({case}, round {round_}):\n{err[-2000:]}")
    row = parse(log, err, ranks)
    row.update(case=case, round=round_, ranks=ranks, wall=time.perf_counter() - t0)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "slidewave"))
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--pause", type=float, default=10.,
                        help="seconds of rest before each case (default 10)")
    parser.add_argument("--csv", default=os.path.join(ROOT, "benchmarks", "results",
                                                      "real_terrain_wall_time.csv"))
    args = parser.parse_args()
    exe = find_executable(args.exe, 0)
    if not os.path.exists(os.path.join(ROOT, "prm", "data", "jacksboro_dem.tif")):
        sys.exit("prm/data/jacksboro_dem.tif is missing: /usr/bin/python3 "
                 "scripts/make_jacksboro_dem.py")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    rows = []
    with tempfile.TemporaryDirectory() as directory:
        for r in range(1, args.rounds + 1):
            # The order turns from round to round: a run right after the two copies
            # freed 5 GB was measured 40 % slower (the VM's memory returning).
            cases = ["1 rank", "ceiling", "2 ranks"]
            for case in cases[r % 3:] + cases[:r % 3]:
                print(f"round {r}, {case}: background load {wait_until_idle(60):.2f} cores",
                      flush=True)
                time.sleep(args.pause)
                t0 = time.perf_counter()
                if case == "ceiling":
                    pair = [start(exe, 1, f"copy{k}-{r}", directory) for k in (0, 1)]
                    rows += [finish(p, 1, case, r, t0) for p in pair]
                else:
                    ranks = 1 if case == "1 rank" else 2
                    rows.append(finish(start(exe, ranks, f"{ranks}-{r}", directory), ranks,
                                       case, r, t0))
            for row in rows[-4:]:
                print(f"  {row['case']:8s} wall {row['wall']:6.1f} s  setup {row['setup']:5.1f}"
                      f"  advance {row['advance']:5.1f}  maps {row['maps']:4.1f} s"
                      f"  RSS {row['rss_mb']:6.0f} MB", flush=True)
    write_csv(args.csv, rows, ["case", "round", "ranks", "columns", "wall", "setup",
                               "advance", "maps", "rss_mb"])

    def median(case, key):
        return statistics.median(row[key] for row in rows if row["case"] == case)

    print(f"\n{rows[0]['columns']} columns, 20 s of flow; medians over {args.rounds} rounds:")
    for case in ("1 rank", "ceiling", "2 ranks"):
        print(f"  {case:8s} wall {median(case, 'wall'):6.1f} s  setup {median(case, 'setup'):5.1f}"
              f"  advance {median(case, 'advance'):5.1f}  maps {median(case, 'maps'):4.1f} s")
    one, copies, two = (median(c, "wall") for c in ("1 rank", "ceiling", "2 ranks"))
    print(f"  2 ranks / 1 rank: {one / two:.2f}x faster (wall); the machine's ceiling "
          f"2 x t(1) / t(copies) = {2 * one / copies:.2f}x; steps alone: "
          f"{median('1 rank', 'advance') / median('2 ranks', 'advance'):.2f}x")
    print(f"rows in {args.csv}")


if __name__ == "__main__":
    main()
