#!/usr/bin/python3
"""Resolution study of the loose bead column of paper 002's underwater collapse (doc/granular-water.md).

The column of tests/granular/underwater_collapse_short.prm (6 cm wide, 5 cm high, glass
beads: Drucker-Prager, phi = 25 deg, no cohesion, E = 1 MPa, dry density 1375 kg/m^3, no-slip
floor, GIMP) on cells of 10, 5, 2.5 and 1.25 mm (``--sizes``), for each dilatancy angle of
``--dilatancy`` (default -5 deg, the scene's loose packing, and 0). The column is 5 cm high,
not the scene's 4.8 cm: the points fill the cells whose points lie in the rectangle, so 4.8 cm
gives columns of 5, 4.75, 4.75 and 4.81 cm on these grids, 5 % apart in mass; 5 cm is the same
column on all of them.

* ``dry``: the column alone (``Physics = material points``, the same material and grid), to
  ``--dry-end`` (default 1 s: at rest with psi = 0);
* ``water`` (with ``--water``): the test's scene itself, grains and water, to 0.25 s, on the
  sizes of ``--water-sizes`` (default 10, 5, 2.5 mm; 2.5 mm takes about 10 minutes).

From the last particle output of each run: the mass centroid x_c, the abscissa holding 99 %
of the mass (x_99), the rightmost point's edge, the highest point's edge, the grains' kinetic
energy (statistics.csv), the steps and the wall time of the process. Each metric's change
against the next coarser cells is printed after it. The rightmost point is the front of the
program's statistics; it follows a layer one point thick and is the least convergent of the
four. Written to ``--csv`` (default benchmarks/results/granular_collapse_resolution.csv).

Single runs on a shared 2-vCPU machine: read the times as orders of magnitude, the metrics
exactly (they do not depend on the machine). ``--set 'PATH=VALUE'`` (repeatable) adds a
parameter to every run, for example ``--set 'Material points/FLIP fraction=1'``.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from benchmark_common import write_csv  # noqa: E402
from plot_particles import read_particles  # noqa: E402

WATER_SCENE = os.path.join(ROOT, "tests", "granular", "underwater_collapse_short.prm")

DRY_SCENE = """# The loose bead column of tests/granular/underwater_collapse_short.prm without water.
set Physics = material points
subsection Time
  set End time            = {end}
  set Output interval     = {end}
  set Statistics interval = 1000000
end
subsection Material points
  set Shape functions         = gimp
  set Particles per direction = 2
  set Gravity                 = 0, -9.81
  subsection Initial stress
    set Type = geostatic
  end
  subsection Grid
    set Lower left  = 0, 0
    set Upper right = 0.3, 0.1
    set Cell size   = {h}
  end
  subsection Boundary conditions
    set Left   = roller
    set Right  = roller
    set Bottom = fixed
    set Top    = free
  end
  subsection Material 1
    set Name            = beads
    set Model           = drucker prager
    set Density         = 1375
    set Young's modulus = 1e6
    set Poisson ratio   = 0.3
    set Friction angle  = 25
    set Dilatancy angle = {psi}
    set Cohesion        = 0
    set Tension cutoff  = 0
  end
  subsection Region 1
    set Shape     = rectangle
    set Rectangle = 0, 0, 0.06, 0.05
    set Material  = beads
  end
end
"""

METRICS = ["centroid_mm", "x99_mm", "front_mm", "top_mm", "kinetic_energy"]


def shape_metrics(directory):
    """Centroid, 99 % mass abscissa, rightmost and highest point edges of the last output."""
    pvtus = []
    for base, _dirs, files in os.walk(directory):
        pvtus += [os.path.join(base, f) for f in files if f.startswith("particles_") and f.endswith(".pvtu")]
    points, data = read_particles(sorted(pvtus)[-1])
    x, y, m = points[:, 0], points[:, 1], data["mass"]
    order = np.argsort(x)
    cumulative = np.cumsum(m[order]) / m.sum()
    return {"_points": (x, y, data["equivalent_plastic_strain"]),
            "centroid_mm": 1e3 * np.sum(m * x) / m.sum(),
            "x99_mm": 1e3 * x[order][np.searchsorted(cumulative, 0.99)],
            "front_mm": 1e3 * (x + data["domain_half_x"]).max(),
            "top_mm": 1e3 * (y + data["domain_half_y"]).max()}


def last_statistics(directory):
    for base, _dirs, files in os.walk(directory):
        if "statistics.csv" in files:
            with open(os.path.join(base, "statistics.csv")) as f:
                return list(csv.DictReader(f))[-1]
    return {}


def run(exe, case, h, psi, dry_end, extra):
    work = tempfile.mkdtemp(prefix="sw-collapse-")
    if case == "dry":
        prm = os.path.join(work, "dry.prm")
        with open(prm, "w") as f:
            f.write(DRY_SCENE.format(end=dry_end, h=h, psi=psi))
        command = [exe]
        for s in extra:
            command += ["--set", s]
        command.append(prm)
    else:
        command = [exe]
        for s in ["Test/Enable=false", f"Output directory={work}/out", "Time/Output interval=0.25",
                  "Time/Statistics interval=1000000", f"Material points/Grid/Cell size={h}",
                  f"Free surface flow/Grid/Cell size={h}", f"Material points/Material 1/Dilatancy angle={psi}",
                  "Material points/Region 1/Rectangle=0, 0, 0.06, 0.05"] + extra:
            command += ["--set", s]
        command.append(WATER_SCENE)
    env = dict(os.environ, OPENBLAS_CORETYPE=os.environ.get("OPENBLAS_CORETYPE", "Haswell"))
    start = time.perf_counter()
    done = subprocess.run(command, cwd=work, capture_output=True, text=True, env=env)
    row = {"case": case, "dilatancy_deg": psi, "cell_size_m": h, "extra": "; ".join(extra),
           "wall_s": time.perf_counter() - start}
    if done.returncode != 0:
        row["status"] = "FAILED: " + (done.stderr.strip().splitlines() or ["?"])[-1][:200]
    else:
        row["status"] = "ok"
        row.update(shape_metrics(work))
        stats = last_statistics(work)
        row["time_s"] = float(stats.get("time", "nan"))
        row["steps"] = int(stats.get("step", "0"))
        row["kinetic_energy"] = float(stats.get("kinetic_energy", stats.get("skeleton_kinetic_energy", "nan")))
    shutil.rmtree(work, ignore_errors=True)
    return row


def plot(rows, path):
    """One panel per run that finished: its last points, coloured by equivalent plastic strain."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    done = [r for r in rows if r["status"] == "ok"]
    if not done:
        return
    series = sorted({(r["case"], r["dilatancy_deg"]) for r in done}, key=lambda k: (k[0], -k[1]))
    sizes = sorted({r["cell_size_m"] for r in done}, reverse=True)
    fig, axes = plt.subplots(len(sizes), len(series), figsize=(5.5 * len(series), 1.6 * len(sizes) + 0.6),
                             squeeze=False, sharex=True, sharey=True)
    for j, key in enumerate(series):
        for i, h in enumerate(sizes):
            ax = axes[i][j]
            match = [r for r in done if (r["case"], r["dilatancy_deg"]) == key and r["cell_size_m"] == h]
            if match:
                x, y, eps = match[0]["_points"]
                # Markers of the points' size: (h / 1.25 mm)^2 times the finest grid's.
                art = ax.scatter(1e3 * x, 1e3 * y, c=eps, s=0.3 * (h / 0.00125) ** 2, vmin=0, vmax=4,
                                 cmap="viridis", rasterized=True)
                ax.text(0.98, 0.85, f"h = {1e3 * h:g} mm, t = {match[0]['time_s']:g} s", transform=ax.transAxes,
                        ha="right", fontsize=8)
            if i == 0:
                ax.set_title(f"{key[0]}, dilatancy {key[1]:g} deg", fontsize=9)
            ax.set_xlim(0, 160)
            ax.set_ylim(0, 50)
            ax.set_aspect("equal")
    for ax in axes[-1]:
        ax.set_xlabel("x [mm]")
    for row in axes:
        row[0].set_ylabel("y [mm]")
    fig.colorbar(art, ax=axes, shrink=0.8, label="equivalent plastic strain")
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=130)
    print(f"written: {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "slidewave"))
    parser.add_argument("--csv", default=os.path.join(ROOT, "benchmarks", "results",
                                                      "granular_collapse_resolution.csv"))
    parser.add_argument("--sizes", default="0.01,0.005,0.0025,0.00125")
    parser.add_argument("--dilatancy", default="-5,0")
    parser.add_argument("--dry-end", type=float, default=1.0)
    parser.add_argument("--water", action="store_true", help="also the grains in water to 0.25 s")
    parser.add_argument("--water-only", action="store_true", help="only the grains in water")
    parser.add_argument("--water-sizes", default="0.01,0.005,0.0025")
    parser.add_argument("--png", default=os.path.join(ROOT, "doc", "figures", "granular-collapse-resolution.png"),
                        help="the final points of every run, coloured by plastic strain ('' for none)")
    parser.add_argument("--set", action="append", default=[], metavar="PATH=VALUE",
                        help="a further parameter for every run, e.g. 'Material points/FLIP fraction=1'")
    args = parser.parse_args()

    cases = ([] if args.water_only else [("dry", args.sizes)]) \
        + ([("water", args.water_sizes)] if args.water or args.water_only else [])
    rows = []
    print("| case | psi [deg] | h [mm] | steps | wall [s] | x_c [mm] | x_99 [mm] | front [mm] | "
          "top [mm] | kinetic energy [J/m] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for case, sizes in cases:
        for psi in [float(p) for p in args.dilatancy.split(",")]:
            previous = None
            for h in [float(s) for s in sizes.split(",")]:
                row = run(os.path.abspath(args.exe), case, h, psi, args.dry_end, args.set)
                rows.append(row)
                if row["status"] != "ok":
                    print(f"| {case} | {psi:g} | {1e3 * h:g} | {row['status']} |", flush=True)
                    previous = None
                    continue
                cells = []
                for k in METRICS:
                    text = f"{row[k]:.3g}" if k == "kinetic_energy" else f"{row[k]:.1f}"
                    if previous is not None and k != "kinetic_energy":
                        text += f" ({row[k] - previous[k]:+.1f})"
                    cells.append(text)
                print(f"| {case} | {psi:g} | {1e3 * h:g} | {row['steps']} | {row['wall_s']:.1f} | "
                      + " | ".join(cells) + " |", flush=True)
                previous = row
    if args.png:
        plot(rows, args.png)
    write_csv(args.csv, rows, ["case", "dilatancy_deg", "cell_size_m", "extra", "status", "time_s",
                               "steps", "wall_s"] + METRICS)
    print(f"\nwritten: {args.csv}")


if __name__ == "__main__":
    main()
