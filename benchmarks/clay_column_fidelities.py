#!/usr/bin/python3
"""Two fidelities, one scene: the clay column collapsing into still water (issue 27).

Runs paper 000's clay column in a tank of still water (1 m deep) with two models of the
water and times each run (wall time of the whole process, output included):

  1D coupled      prm/clay-column-in-water.prm: MPM soil on 0.05 m cells + depth-averaged
                  shallow water on 0.04 m cells; its default 'Water pressure on soil =
                  excess over initial level' (paper 000) and 'hydrostatic' (buoyancy).
  2D granular     prm/clay-column-in-water-2d.prm: MPM skeleton (undrained clay as a skeleton
                  of k = 1e-14 m^2) + 2D Navier-Stokes with a phase-field surface on the
                  same grid, at the cell sizes of --sizes (0.1 m, then the scene's 0.05 m).

One run at a time (the 2D scene takes minutes on one core). The runs' outputs go to
--out-dir (default: a new temporary directory), each with a wall_time.txt that
scripts/compare_clay_column.py reads; the comparison prints its table and writes the figure
doc/figures/clay-column-fidelities.png; the rows (runout, first crest at x = 4 m, its
arrival, wall time, steps) go to benchmarks/results/clay_column_fidelities.csv.

The executable: --exe, else the environment variable SLIDEWAVE, else build/slidewave; its
directory is put in front of LD_LIBRARY_PATH (for a copied binary next to its library).
Single runs on a shared 2-vCPU machine: read the wall times as orders of magnitude.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from benchmark_common import write_csv  # noqa: E402
import compare_clay_column  # noqa: E402

SCENE_1D = os.path.join(ROOT, "prm", "clay-column-in-water.prm")
SCENE_2D = os.path.join(ROOT, "prm", "clay-column-in-water-2d.prm")
COLUMNS = ["label", "model", "cell_size", "end_time", "steps", "wall_s", "runout_1s",
           "runout_end", "arrival_s", "half_crest_s", "crest_time_s", "crest_m",
           "exit_status"]


def run(exe, scene, out_dir, settings, nice):
    """Run ``scene`` with the --set ``settings`` into ``out_dir``; (wall seconds, stdout,
    exit status). The wall time goes to out_dir/wall_time.txt."""
    command = [exe, scene, "--set", f"Output directory={out_dir}"]
    for s in settings:
        command += ["--set", s]
    env = dict(os.environ)
    exe_dir = os.path.dirname(os.path.abspath(exe))
    env["LD_LIBRARY_PATH"] = exe_dir + (":" + env["LD_LIBRARY_PATH"]
                                        if env.get("LD_LIBRARY_PATH") else "")
    start = time.perf_counter()
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, env=env,
                            preexec_fn=(lambda: os.nice(nice)) if nice else None)
    wall = time.perf_counter() - start
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "wall_time.txt"), "w") as f:
        f.write(f"{wall:.3f}\n")
    with open(os.path.join(out_dir, "run.log"), "w") as f:
        f.write(result.stdout)
    if result.returncode != 0:
        print(f"{out_dir}: exit status {result.returncode}; last lines:\n"
              + "\n".join(result.stdout.splitlines()[-8:]), flush=True)
    return wall, result.stdout, result.returncode


def steps_of(text):
    """The number of steps of a run from its last progress line."""
    steps = re.findall(r"^step\s+(\d+)", text, flags=re.M)
    return int(steps[-1]) if steps else None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", default=os.environ.get(
        "SLIDEWAVE", os.path.join(ROOT, "build", "slidewave")))
    parser.add_argument("--out-dir", default=None,
                        help="where the runs write (default: a new temporary directory)")
    parser.add_argument("--sizes", default="0.1,0.05",
                        help="cell sizes of the 2D runs [m], comma-separated")
    parser.add_argument("--end-time-2d", type=float, default=5.0,
                        help="end time of the 2D runs [s] (the 1D runs go to the scene's 5 s)")
    parser.add_argument("--skip-hydrostatic", action="store_true",
                        help="run the 1D scene with its default water pressure only")
    parser.add_argument("--nice", type=int, default=0, help="niceness of the runs")
    parser.add_argument("--csv", default=os.path.join(ROOT, "benchmarks", "results",
                                                      "clay_column_fidelities.csv"))
    parser.add_argument("--png", default=os.path.join(ROOT, "doc", "figures",
                                                      "clay-column-fidelities.png"))
    args = parser.parse_args()
    if not (os.path.isfile(args.exe) and os.access(args.exe, os.X_OK)):
        sys.exit(f"SlideWave executable not found: {args.exe} (--exe or SLIDEWAVE)")
    out_dir = args.out_dir or tempfile.mkdtemp(prefix="sw-clay-column-")

    cases = [("1D coupled, excess (paper 000)", "coupled", 0.05, SCENE_1D, "oned_excess", [])]
    if not args.skip_hydrostatic:
        cases.append(("1D coupled, hydrostatic", "coupled", 0.05, SCENE_1D, "oned_hydrostatic",
                      ["Coupling/Water pressure on soil=hydrostatic"]))
    for h in (float(s) for s in args.sizes.split(",")):
        cases.append((f"2D granular water, {h:g} m", "granular water", h, SCENE_2D,
                      f"twod_{h:g}", [f"Material points/Grid/Cell size={h}",
                                      f"Free surface flow/Grid/Cell size={h}",
                                      f"Time/End time={args.end_time_2d}"]))
    rows, specs = [], []
    for label, model, h, scene, name, settings in cases:
        directory = os.path.join(out_dir, name)
        wall, text, status = run(args.exe, scene, directory, settings, args.nice)
        print(f"{label}: {wall:.1f} s, exit status {status}", flush=True)
        row = {"label": label, "model": model, "cell_size": h, "steps": steps_of(text),
               "wall_s": round(wall, 2), "exit_status": status}
        try:
            summary = compare_clay_column.summarize(label, directory)
        except (OSError, KeyError, IndexError) as error:
            print(f"{label}: no results ({error})", flush=True)
            rows.append(row)
            continue
        specs.append(summary)
        row.update({k: summary[k] for k in ("end_time", "runout_1s", "runout_end",
                                            "arrival_s", "half_crest_s", "crest_time_s",
                                            "crest_m")})
        rows.append(row)
    write_csv(args.csv, rows, COLUMNS)
    print("results:", args.csv)
    print("outputs:", out_dir)
    if specs:
        compare_clay_column.print_table(specs)
        compare_clay_column.plot(specs, args.png)


if __name__ == "__main__":
    main()
