#!/usr/bin/python3
"""The elastic vortex in a closed box: an exact standing wave of the grains in water.

An elastic saturated skeleton (linear elastic, E = 1 MPa, nu = 0.3, dry density 1375 kg/m^3,
grains 2500 kg/m^3, porosity 0.45) fills a closed square box L = 0.1 m (rollers for the grains,
free slip for the water, water everywhere, no gravity). Grains and water start with the
divergence-free velocity u = A (sin(pi x/L) cos(pi y/L), -cos(pi x/L) sin(pi y/L)),
A = 0.01 m/s: an eigenmode of an incompressible linear elastic medium with slip walls. It
oscillates without pore pressure at omega = sqrt(2) (pi/L) sqrt(G/rho), G = E/(2(1+nu)):

* locked (k = 1e-10 m^2, the default; drag relaxation time rho_s (1-n) k / mu = 1.1e-5 s, far
  below the period): grains and water move together, rho = rho_dry + n rho_w = 1829.5 kg/m^3,
  T = 9.754 ms;
* drained (k = 1e-6 m^2: 0.11 s, far above it): the skeleton oscillates alone, rho = rho_dry,
  T = 8.456 ms. The dry reference (``Physics = material points``, the same skeleton, no
  water) has this period too and gives the MPM's own loss on the grid.

The grains' kinetic energy (statistics.csv, written every step) oscillates with period T/2
between 0 and KE0 = 3.4375e-4 J/m and decays only through the drag on the relative motion
the water's inertia needs: energy rate (n rho_w)^2 omega^2 / (C rho) = 1.93 1/s locked
(C = n^2 mu / k), 0.908 of KE0 left at 50 ms (the water's viscous decay, ~0.013 1/s, is
negligible). Measured per run:

* period: 2 x the mean spacing of the KE minima, each refined by the parabola through its
  three samples; its relative error against the exact period of the regime (the dry reference
  and drained runs against 8.456 ms, locked runs against 9.754 ms);
* energy retained: the KE's peak (parabola-refined) in the last half-period window over KE0;
* steps and the wall time of the process.

Cases: couplings ``--couplings`` ('semi-implicit projected', 'semi-implicit', 'dry') x time
step multipliers ``--multipliers`` (0.5, 0.25, 0.125) x cells ``--sizes`` (0.01, 0.005; on
the cells after the first only the first multiplier unless ``--all-multipliers``) x
permeabilities ``--permeabilities`` (1e-10; the dry reference runs once per size and step).
Prints a table (coupling, k, h, multiplier, period error, energy retained, steps, wall s),
writes ``--csv`` (benchmarks/results/granular_vortex.csv) and ``--png``
(doc/figures/granular-vortex.png: KE/KE0 over time, one panel per coupling, the dry MPM in
grey, ticks at the exact locked KE minima (j + 1/2) T/2). About a minute on 2 vCPUs.
"""
import argparse
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark_common import fmt, write_csv  # noqa: E402

L, A, E, NU, N, RHO_DRY, RHO_S, RHO_W, MU = 0.1, 0.01, 1e6, 0.3, 0.45, 1375.0, 2500.0, 1010.0, 0.012
G = E / (2 * (1 + NU))
KE0 = 0.5 * RHO_DRY * A ** 2 * L ** 2 / 2  # J/m: <|u|^2> = A^2/2 over the box


# T = 2 pi / omega, omega = sqrt(2) (pi/L) sqrt(G/rho): locked (mixture density) and drained (dry).
T_LOCKED, T_DRAINED = (math.sqrt(2) * L / math.sqrt(G / rho) for rho in (RHO_DRY + N * RHO_W, RHO_DRY))
VELOCITY = "{A}*sin({w}*x)*cos({w}*y); -{A}*cos({w}*x)*sin({w}*y)".format(A=A, w=repr(math.pi / L))

SKELETON = """subsection Material points
  set Shape functions         = gimp
  set Particles per direction = 2
  set Gravity                 = 0, 0
  subsection Grid
    set Lower left  = 0, 0
    set Upper right = 0.1, 0.1
    set Cell size   = 0.01
  end
  subsection Boundary conditions
    set Left   = roller
    set Right  = roller
    set Bottom = roller
    set Top    = roller
  end
  subsection Material 1
    set Name            = skeleton
    set Model           = linear elastic
    set Density         = 1375
    set Young's modulus = 1e6
    set Poisson ratio   = 0.3
  end
  subsection Region 1
    set Shape     = rectangle
    set Rectangle = 0, 0, 0.1, 0.1
    set Material  = skeleton
    set Initial velocity = {velocity}
  end
end
"""
TIME = """subsection Time
  set End time            = {end}
  set Statistics interval = 1
end
"""
DRY_SCENE = "set Physics = material points\n" + TIME + SKELETON
WATER_SCENE = "set Physics = granular water\n" + TIME + """subsection Granular water
  set Grain density    = 2500
  set Permeability law = constant
  set Permeability     = 1e-10
  set Drag law         = Darcy
end
""" + SKELETON + """subsection Free surface flow
  subsection Grid
    set Lower left  = 0, 0
    set Upper right = 0.1, 0.1
    set Cell size   = 0.01
  end
  subsection Fluids
    set Water density   = 1010
    set Water viscosity = 0.012
    set Gravity = 0, 0
  end
  subsection Boundary conditions
    set Left   = free slip
    set Right  = free slip
    set Bottom = free slip
    set Top    = free slip
  end
  subsection Initial water
    set Surface elevation = 1
    set Velocity = {velocity}
  end
end
"""


def vertex(t, k, i):
    """Time and value of the parabola's vertex through samples i-1, i, i+1 (sample i if flat)."""
    (t0, t1, t2), (k0, k1, k2) = t[i - 1:i + 2], k[i - 1:i + 2]
    c = np.polyfit([t0 - t1, 0.0, t2 - t1], [k0, k1, k2], 2)
    if c[0] == 0 or not t0 < t1 - c[1] / (2 * c[0]) < t2:
        return t1, k1
    s = -c[1] / (2 * c[0])
    return t1 + s, np.polyval(c, s)


def measure(t, k, period):
    """Half period from the KE minima and the peak of the last half-period window over KE0."""
    minima = []
    for i in range(1, len(k) - 1):
        near = k[np.abs(t - t[i]) <= period / 8]  # a true minimum lies far below its surroundings
        if k[i] < k[i - 1] and k[i] <= k[i + 1] and k[i] < 0.2 * near.max():
            minima.append(vertex(t, k, i)[0])
    measured = 2 * (minima[-1] - minima[0]) / (len(minima) - 1) if len(minima) > 1 else None
    window = np.nonzero(t >= t[-1] - period / 2)[0]
    i = window[np.argmax(k[window])]
    peak = vertex(t, k, i)[1] if 0 < i < len(k) - 1 else k[i]
    return measured, len(minima), peak / KE0


def run(exe, coupling, h, multiplier, permeability, end):
    work = tempfile.mkdtemp(prefix="sw-vortex-")
    dry = coupling == "dry"
    prm = os.path.join(work, "scene.prm")
    with open(prm, "w") as f:
        f.write((DRY_SCENE if dry else WATER_SCENE).format(end=end, velocity=VELOCITY))
    sets = [f"Output directory={work}/out", f"Material points/Time step multiplier={multiplier}",
            f"Material points/Grid/Cell size={h}"]
    if not dry:
        sets += [f"Granular water/Drag coupling={coupling}", f"Granular water/Permeability={permeability}",
                 f"Free surface flow/Grid/Cell size={h}"]
    command = [exe] + [a for s in sets for a in ("--set", s)] + [prm]
    row = {"coupling": coupling, "permeability_m2": None if dry else permeability, "cell_size_m": h,
           "multiplier": multiplier, "status": "ok"}
    tau = RHO_S * (1 - N) * permeability / MU
    row["regime"] = "dry" if dry else "locked" if tau < 0.01 * T_LOCKED else "drained" if tau > 10 * T_DRAINED \
        else "intermediate"
    row["exact_period_ms"] = 1e3 * (T_LOCKED if row["regime"] in ("locked", "intermediate") else T_DRAINED)
    for attempt in range(4):  # the executable may be being relinked: wait and retry
        start = time.perf_counter()
        try:
            done = subprocess.run(command, cwd=work, capture_output=True, text=True)
        except OSError as e:
            done = subprocess.CompletedProcess(command, 127, "", str(e))
        row["wall_s"] = time.perf_counter() - start
        loader = done.returncode in (126, 127) or "error while loading shared" in done.stderr
        if not loader or attempt == 3:
            break
        time.sleep(30)
    stats = os.path.join(work, "out", "statistics.csv")
    if done.returncode != 0 or not os.path.isfile(stats):
        row["status"] = "FAILED: " + (done.stderr.strip().splitlines() or ["?"])[-1][:200]
    else:
        with open(stats) as f:
            records = list(csv.DictReader(f))
        t = np.array([float(r["time"]) for r in records])
        k = np.array([float(r["kinetic_energy" if dry else "skeleton_kinetic_energy"]) for r in records])
        measured, row["minima"], row["energy_retained"] = measure(t, k, row["exact_period_ms"] * 1e-3)
        row["period_ms"] = None if measured is None else 1e3 * measured
        row["period_error"] = None if measured is None else measured / (row["exact_period_ms"] * 1e-3) - 1
        row["steps"], row["end_time_s"], row["_curve"] = int(records[-1]["step"]), t[-1], (t, k / KE0)
    shutil.rmtree(work, ignore_errors=True)
    return row


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    done = [r for r in rows if r["status"] == "ok"]
    h0 = max(r["cell_size_m"] for r in done)
    couplings = [c for c in dict.fromkeys(r["coupling"] for r in done) if c != "dry"]
    if not couplings:
        return
    multipliers = sorted({r["multiplier"] for r in done}, reverse=True)
    colours = dict(zip(multipliers, ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple"]))
    fig, axes = plt.subplots(len(couplings), 1, figsize=(12, 3.3 * len(couplings)), sharex=True, squeeze=False)
    for ax, coupling in zip(axes[:, 0], couplings):
        for r in done:
            t, e = r["_curve"]
            if r["coupling"] == "dry" and r["cell_size_m"] == h0 and r["multiplier"] == multipliers[-1]:
                ax.plot(1e3 * t, e, color="0.6", lw=1.2, label=f"dry MPM, multiplier {r['multiplier']:g}")
            elif r["coupling"] == coupling and r["cell_size_m"] == h0:
                ax.plot(1e3 * t, e, color=colours[r["multiplier"]], lw=1.2, label=f"multiplier {r['multiplier']:g}")
            elif r["coupling"] == coupling:
                ax.plot(1e3 * t, e, color=colours[r["multiplier"]], lw=0.9, ls=":",
                        label=f"multiplier {r['multiplier']:g}, h = {1e3 * r['cell_size_m']:g} mm")
        tmax = max(r["end_time_s"] for r in done)
        for j in range(int(tmax / (T_LOCKED / 2) + 0.5)):
            ax.axvline(1e3 * (j + 0.5) * T_LOCKED / 2, ymin=0, ymax=0.05, color="k", lw=1.2)
        ax.plot([], [], "|k", label=f"exact locked KE minima:\n(j + 1/2) T/2, T = {1e3 * T_LOCKED:.3f} ms")
        ax.set_title(f"'{coupling}' coupling, h = {1e3 * h0:g} mm, k = "
                     + ", ".join(sorted({f"{r['permeability_m2']:g}" for r in done if r["coupling"] == coupling}))
                     + " m$^2$",
                     fontsize=10)
        ax.set_ylabel("grains' KE / KE$_0$ [-]")
        ax.set_ylim(0, 1.12)
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    axes[-1, 0].set_xlabel("time [ms]")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=130)
    print(f"written: {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "slidewave"))
    parser.add_argument("--csv", default=os.path.join(ROOT, "benchmarks", "results", "granular_vortex.csv"))
    parser.add_argument("--png", default=os.path.join(ROOT, "doc", "figures", "granular-vortex.png"),
                        help="KE over time per coupling ('' for none)")
    parser.add_argument("--sizes", default="0.01,0.005")
    parser.add_argument("--multipliers", default="0.5,0.25,0.125")
    parser.add_argument("--all-multipliers", action="store_true", help="every multiplier on every size")
    parser.add_argument("--couplings", default="semi-implicit projected,semi-implicit,dry")
    parser.add_argument("--permeabilities", default="1e-10")
    parser.add_argument("--end", type=float, default=0.05, help="end time [s]")
    args = parser.parse_args()
    os.environ.setdefault("OPENBLAS_CORETYPE", "Haswell")
    sizes = [float(s) for s in args.sizes.split(",")]
    multipliers = [float(m) for m in args.multipliers.split(",")]
    print(f"exact periods: locked {1e3 * T_LOCKED:.4g} ms, drained/dry {1e3 * T_DRAINED:.4g} ms; "
          f"KE0 = {KE0:.5g} J/m\n")
    print("| coupling | k [m^2] | h [mm] | multiplier | period [ms] | period error | energy retained | "
          "steps | wall [s] |")
    print("|---|---|---|---|---|---|---|---|---|")
    rows = []
    for h in sizes:
        for m in (multipliers if h == sizes[0] or args.all_multipliers else multipliers[:1]):
            for coupling in args.couplings.split(","):
                for k in ([None] if coupling == "dry" else [float(p) for p in args.permeabilities.split(",")]):
                    r = run(os.path.abspath(args.exe), coupling, h, m, k or 0.0, args.end)
                    rows.append(r)
                    print(f"| {coupling} | {fmt(r['permeability_m2'], 'g')} | {1e3 * h:g} | {m:g} | "
                          + (f"{r['status']} |" if r["status"] != "ok" else
                             f"{fmt(r['period_ms'], '.3f')} ({r['regime']}) | {fmt(r['period_error'], '+.2%')} | "
                             f"{r['energy_retained']:.3g} | {r['steps']} | {r['wall_s']:.1f} |"), flush=True)
    if args.png:
        plot(rows, args.png)
    write_csv(args.csv, rows, ["coupling", "permeability_m2", "regime", "cell_size_m", "multiplier", "status",
                               "end_time_s", "steps", "wall_s", "minima", "period_ms", "exact_period_ms",
                               "period_error", "energy_retained"])
    print(f"\nwritten: {args.csv}")


if __name__ == "__main__":
    main()
