#!/usr/bin/python3
"""Make the figures of the depth-averaged material points (paper 001, Fois, de Falco,
Formaggia): runs the scenes with build/slidewave (Physics = depth averaged, with
'Output point table' on, into --work) and draws them with matplotlib.

  /usr/bin/python3 scripts/depth_averaged_figures.py [--slidewave build/slidewave]
      [--work /tmp/slidewave-depth-averaged] [--out doc/figures] [--only NAME] [--keep]

NAME: lake, obstacle, dam-break. --keep reuses the runs already in --work (a run is kept
when its NAME.status file, its exit status, is there). Figures (in --out):
  depth-averaged-lake-at-rest.png        paper Fig. 3: prm/lake-at-rest.prm over Z1 (the
      scene's bump) and Z2 (a 4 m block on [4, 8]^2) after 1 s, the still-level form of the
      pressure (Eq. 41) against the standard one (Eqs. 14-15, without friction): plan view
      of the points coloured by h, the section y = 5 m and the surface's departure from 10 m
  depth-averaged-inclined-obstacle.png   paper Fig. 4: prm/inclined-obstacle.prm, the points
      coloured by their depth at t = 0, 3.5, 7 s and 10 s (a second run with End time = 10 s;
      if it stops early at the scene's Courant number, again at 0.4), and the relative
      nodal-versus-point errors of mass and momentum at every step (Eq. 44)
  depth-averaged-dam-break.png           prm/dam-break-channel.prm, Ritter (dry bed) and
      Stoker (h_r = 0.5 m) on cells of 0.25 m at t = 4 s: the points' depth against the
      exact solution for 'Depth update' = strain (Eq. 38) and projection, 2 x 2 and 4 x 4
      points per cell, with the program's relative L1 error of the depth
A run that ends with a non-zero exit status is printed and marked in its panel. 14 or 15
runs of 1-5 s each, one at a time (about 40 s in all with the drawing on two cores)."""
import argparse
import glob
import math
import os
import re
import shutil
import subprocess
import sys
import time

try:
    import numpy as np
    import matplotlib
except ImportError as exc:
    sys.exit(f"{exc}; run this script with a python3 that has numpy and matplotlib "
             "(e.g. /usr/bin/python3)")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after selecting the backend)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_particles import read_particles  # noqa: E402  (reads the grid's .pvtu)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GRAVITY = 9.81

POINTS = "Depth averaged/Output point table=true"
NO_GRID = "Depth averaged/Output grid=false"
Z2 = "Depth averaged/Terrain/Elevation=(x>=4 & x<=8 & y>=4 & y<=8) ? 4 : 0"
STANDARD = ["Depth averaged/Hydrostatic term=standard",
            "Depth averaged/Basal friction/Model=none"]


class Run:
    """One run of the program: its output directory, exit status and printed text."""

    def __init__(self, directory, status, log):
        self.directory = directory
        self.status = status
        self.log = log

    def failure(self):
        """The program's own message of a failed run ('' if it did not fail)."""
        if self.status == 0:
            return ""
        match = re.search(r"run failed at step \d+, t = ([0-9.eE+-]+) s: (.*?);", self.log)
        if match:
            return "stopped at t = %.3g s (%s)" % (float(match.group(1)),
                                                   shorten(match.group(2)))
        return "exit status %d" % self.status

    def stop_time(self):
        match = re.search(r"run failed at step \d+, t = ([0-9.eE+-]+) s", self.log)
        return float(match.group(1)) if match else None

    def points(self, index=None):
        """Columns x, y, elevation, depth, velocity_x, velocity_y of the points of output
        'index' (the last one written if None), and that index."""
        files = sorted(glob.glob(os.path.join(self.directory, "points", "points_*.csv")))
        if not files:
            return None, None
        if index is None:
            path = files[-1]
        else:
            path = os.path.join(self.directory, "points", "points_%05d.csv" % index)
            if not os.path.exists(path):
                return None, None
        data = np.genfromtxt(path, delimiter=",", names=True)
        return data, int(re.search(r"points_(\d+)\.csv", path).group(1))

    def nodal_depth(self, index):
        """Node positions x and the nodal depth (mean over the nodes of the same x) of grid
        output 'index', or None without grid output."""
        path = os.path.join(self.directory, "grid", "grid_%05d.pvtu" % index)
        if not os.path.exists(path):
            return None
        points, data = read_particles(path)
        x, inverse = np.unique(np.round(points[:, 0], 9), return_inverse=True)
        depth = np.bincount(inverse, data["depth"]) / np.bincount(inverse)
        return x, depth

    def statistics(self):
        return np.genfromtxt(os.path.join(self.directory, "statistics.csv"), delimiter=",",
                             names=True)


def shorten(message):
    """'material point 4959 at (45.9 9.4) has a depth that is not positive (depth ...' ->
    'a depth that is not positive at (45.9 9.4)'."""
    match = re.match(r"material point \d+ at \(([^)]*)\) has (.*?)( \(.*)?$", message)
    if match:
        x = " ".join("%.1f" % float(v) for v in match.group(1).split())
        return "%s at (%s) m" % (match.group(2), x)
    return message[:60]


def run(args, name, scene, settings):
    """Run 'scene' with the given '--set' values into WORK/name (unless kept); a non-zero
    exit status is printed, not raised."""
    directory = os.path.join(args.work, name)
    status_file = os.path.join(args.work, name + ".status")
    log_file = os.path.join(args.work, name + ".log")
    if args.keep and os.path.exists(status_file):
        with open(status_file) as f:
            status = int(f.read())
        with open(log_file) as f:
            return Run(directory, status, f.read())
    if os.path.exists(directory):
        shutil.rmtree(directory)  # no stale output of an earlier run
    command = [args.slidewave, "--set", "Output directory=" + directory]
    for s in settings:
        command += ["--set", s]
    command.append(os.path.join(ROOT, scene))
    print(" ".join("'%s'" % c if " " in c or "(" in c else c for c in command), flush=True)
    start = time.time()
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)
    os.makedirs(args.work, exist_ok=True)
    with open(log_file, "w") as f:
        f.write(result.stdout)
    with open(status_file, "w") as f:
        f.write("%d\n" % result.returncode)
    print("  %.1f s, exit status %d" % (time.time() - start, result.returncode), flush=True)
    r = Run(directory, result.returncode, result.stdout)
    if result.returncode != 0:
        print("  NOTE: %s: %s (log: %s)" % (name, r.failure(), log_file), flush=True)
    return r


# --- Lake at rest (paper 001, §4.1, Fig. 3) --------------------------------------------

def lake(args):
    output_interval = 0.25
    terrains = [("Z1", "$Z_1 = 5\\,e^{-0.4|x - (5,5)|^2}$", [],
                 lambda x: 5 * np.exp(-0.4 * (x - 5) ** 2)),
                ("Z2", "$Z_2 = 4$ on $[4, 8]^2$", [Z2],
                 lambda x: np.where((x >= 4) & (x <= 8), 4.0, 0.0))]
    forms = [("still", "still level (Eq. 41), Voellmy", []),
             ("standard", "standard (Eqs. 14-15), no friction", STANDARD)]
    runs = {}
    for tname, _, tset, _ in terrains:
        for fname, _, fset in forms:
            runs[tname, fname] = run(
                args, "lake-%s-%s" % (tname.lower(), fname), "prm/lake-at-rest.prm",
                [POINTS, NO_GRID, "Time/Output interval=%g" % output_interval] + tset + fset)

    fig, axes = plt.subplots(2, 3, figsize=(10, 7), constrained_layout=True,
                             gridspec_kw={"width_ratios": [1, 1.2, 1.2]})
    colors = {"still": "tab:blue", "standard": "tab:red"}
    markers = {"still": "o", "standard": "x"}
    xs = np.linspace(0, 10, 1001)
    limit = 10  # cm, of the departure panels
    sc = None
    for row, (tname, tlabel, _, terrain) in zip(axes, terrains):
        # Plan view of the still-level run: the points coloured by their depth.
        ax = row[0]
        r = runs[tname, "still"]
        data, index = r.points()
        if data is not None:
            sc = ax.scatter(data["x"], data["y"], c=data["depth"], s=3.5, marker="s", lw=0,
                            cmap="viridis", vmin=5, vmax=10, rasterized=True)
            ax.axhline(5, color="w", lw=0.8, ls="--")
        ax.set_aspect("equal")
        ax.set_xlim(0, 10)
        ax.set_ylim(0, 10)
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
        ax.set_title("%s, still level: h at t = %g s\n(dashed: the section y = 5 m)"
                     % (tname, (index or 0) * output_interval), fontsize=9)

        # Section y = 5 m: terrain, h + Z of the points within 0.1 m of it.
        ax, dev = row[1], row[2]
        ax.fill_between(xs, 0, terrain(xs), color="0.8", lw=0, label="terrain Z")
        ax.plot(xs, terrain(xs), color="0.3", lw=1)
        ax.axhline(10, color="k", lw=0.6, ls=":")
        dev.axhline(0, color="k", lw=0.6, ls=":")
        notes = []
        for fname, flabel, _ in forms:
            r = runs[tname, fname]
            data, index = r.points()
            t = (index or 0) * output_interval
            stats = r.statistics()
            err = float(np.atleast_1d(stats["error_h_linf"])[-1])
            label = "%s" % flabel
            if r.status != 0:
                label += "\n[%s; last output t = %g s]" % (r.failure(), t)
                print("  lake %s %s: %s" % (tname, fname, r.failure()))
            notes.append("%s %.2g m" % (fname, err))
            if data is None:
                continue
            near = np.abs(data["y"] - 5) <= 0.1
            order = np.argsort(data["x"][near])
            surface = (data["elevation"] + data["depth"])[near][order]
            x = data["x"][near][order]
            ax.plot(x, surface, markers[fname], ms=3, mfc="none", mew=0.8,
                    color=colors[fname], label=label)
            cm = 100 * (surface - 10)
            dev.plot(x, np.clip(cm, -limit, limit), markers[fname], ms=3, mfc="none",
                     mew=0.8, color=colors[fname], label=fname)
            off = np.abs(cm) > limit
            if off.any():
                for sign, marker in [(1, "^"), (-1, "v")]:
                    side = off & (np.sign(cm) == sign)
                    dev.plot(x[side], np.full(side.sum(), sign * limit * 0.97), marker,
                             ms=5, color=colors[fname])
                dev.text(5, -limit * 0.8, "%d %s points off scale\n(from %+.0f to %+.0f cm)"
                         % (off.sum(), fname, cm[off].min(), cm[off].max()),
                         ha="center", fontsize=7, color=colors[fname])
        ax.set_xlim(0, 10)
        ax.set_ylim(0, 11.5)
        ax.set_xlabel("x [m]")
        ax.set_ylabel("elevation [m]")
        ax.set_title("%s: h + Z of the points\nwithin 0.1 m of y = 5 m, t = 1 s"
                     % tlabel, fontsize=9)
        ax.legend(fontsize=7, loc="lower left")
        dev.set_xlim(0, 10)
        dev.set_ylim(-limit, limit)
        dev.set_xlabel("x [m]")
        dev.set_ylabel("h + Z - 10 [cm]")
        dev.set_title("%s, the same section: surface - 10 m\n$L^\\infty(h)$ at 1 s: %s"
                      % (tname, ", ".join(notes)), fontsize=9)
        dev.legend(fontsize=7, loc="upper right")
        for a in (ax, dev):
            a.grid(alpha=0.3)
    if sc is not None:
        fig.colorbar(sc, ax=axes[:, 0], label="depth h [m]", shrink=0.7,
                     location="bottom", aspect=15)
    fig.suptitle("Lake at rest (paper 001, §4.1, Fig. 3): prm/lake-at-rest.prm, surface "
                 "at 10 m, 2 x 2 points in cells of 0.2 m", fontsize=10)
    save(fig, args, "depth-averaged-lake-at-rest.png")


# --- Inclined plane with an obstacle (paper 001, §4.2, Fig. 4) --------------------------

def obstacle(args):
    output_interval = 0.5
    base = [POINTS, NO_GRID, "Time/Statistics interval=1",
            "Time/Output interval=%g" % output_interval]
    scene = run(args, "obstacle", "prm/inclined-obstacle.prm", base)
    longer = run(args, "obstacle-10s", "prm/inclined-obstacle.prm",
                 base + ["Time/End time=10"])
    longer_note, footnote = "second run, End time = 10 s", ""
    if longer.status != 0:
        print("  obstacle to 10 s: %s; again at Courant number 0.4" % longer.failure())
        longer_note = "second run, End time = 10 s, Courant number 0.4*"
        footnote = ("\n* at the scene's Courant number 0.5 the run to 10 s %s"
                    % longer.failure())
        longer = run(args, "obstacle-10s-courant0.4", "prm/inclined-obstacle.prm",
                     base + ["Time/End time=10", "Depth averaged/Courant number=0.4"])
        if longer.status != 0:
            footnote += "; at 0.4 it %s" % longer.failure()

    fig = plt.figure(figsize=(10, 6.4), constrained_layout=True)
    grid = fig.add_gridspec(4, 2, width_ratios=[1.75, 1])
    views = [(scene, 0.0, ""), (scene, 3.5, ""), (scene, 7.0, " (the scene's end)"),
             (longer, 10.0, " (%s)" % longer_note)]
    gx, gy = np.meshgrid(np.linspace(0, 100, 401), np.linspace(0, 20, 81))
    bump = 15 * np.exp(-((gx - 50) ** 2 + (gy - 10) ** 2) / 7)  # Z - (60 - x/3)
    sc = None
    max_depth0 = float(np.max(scene.statistics()["max_depth"][0]))
    plan_axes = []
    for k, (r, t, note) in enumerate(views):
        ax = fig.add_subplot(grid[k, 0])
        plan_axes.append(ax)
        data, _ = r.points(int(round(t / output_interval)))
        ax.contour(gx, gy, bump, levels=[1, 5, 10], colors="k", linewidths=0.6)
        if data is not None:
            sc = ax.scatter(data["x"], data["y"], c=data["depth"], s=3, lw=0,
                            cmap="viridis", vmin=0, vmax=2, rasterized=True)
            title = "t = %g s%s: %d points, front x = %.1f m" % (
                t, note, len(data), data["x"].max())
        else:
            title = "t = %g s%s: no output" % (t, note)
        ax.set_title(title, fontsize=8)
        ax.set_aspect("equal")
        ax.set_xlim(0, 100)
        ax.set_ylim(0, 20)
        ax.set_ylabel("y [m]")
        if k < 3:
            ax.tick_params(labelbottom=False)
    plan_axes[-1].set_xlabel("x [m]")
    if sc is not None:
        fig.colorbar(sc, ax=plan_axes, label="depth h [m] (up to %.1f m at t = 0)" % max_depth0,
                     shrink=0.6, extend="max")

    ax = fig.add_subplot(grid[:, 1])
    floor = 1e-17
    for r, style, tag in [(scene, "-", "scene, to 7 s"), (longer, ":", "to 10 s")]:
        stats = r.statistics()
        for column, color, label in [("nodal_mass_error", "tab:blue", "mass"),
                                     ("nodal_momentum_error", "tab:red", "momentum")]:
            t = stats["time"][1:]  # row 0 is the initial state before any transfer
            e = stats[column][1:]
            zero = e <= 0
            if style == "-":
                ax.semilogy(t, np.where(zero, floor, e), style, color=color, lw=0.8,
                            label="%s (%s), max %.1e" % (label, tag, e.max()))
                ax.semilogy(t[zero], np.full(zero.sum(), floor), "|", color=color, ms=6,
                            label="%s exactly 0 (%d of %d steps)"
                            % (label, zero.sum(), len(e)))
            else:
                ax.semilogy(t, np.where(zero, floor, e), style, color=color, lw=0.8,
                            alpha=0.6, label="%s (%s), max %.1e" % (label, tag, e.max()))
    ax.axhline(np.finfo(float).eps, color="k", lw=0.6, ls="--")
    ax.text(0.1, np.finfo(float).eps * 1.3, "double epsilon", fontsize=7)
    ax.set_ylim(floor / 3, 1e-13)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("relative error of the nodal totals (0 drawn at 1e-17)")
    ax.set_title("nodal vs point totals at every step (Eq. 44):\n"
                 "|sum_i m_i - sum_p m_p| / sum_p m_p and\n"
                 "|sum_i (mv)_i - sum_p (mv)_p| / (m max|v|)", fontsize=8)
    ax.legend(fontsize=6.5, loc="upper right")
    ax.grid(alpha=0.3, which="both")
    fig.suptitle("Mud down an inclined plane past an obstacle (paper 001, §4.2, Fig. 4): "
                 "prm/inclined-obstacle.prm; contours of the obstacle at 1, 5, 10 m"
                 + footnote, fontsize=10)
    save(fig, args, "depth-averaged-inclined-obstacle.png")


# --- Dam break along a channel (shallow-water limit) -----------------------------------

def dam_break_exact(x, t, h_l, h_r, x0, g=GRAVITY):
    """Depth of Ritter's (h_r = 0) or Stoker's dam break at x, t, as in
    source/water/dam_break_solutions.cc; also the speed s of the front (Ritter, 2 c_l) or of
    the shock (Stoker), and the plateau depth h_m (0 for Ritter)."""
    c_l = math.sqrt(g * h_l)
    if h_r <= 0:
        h_m, s = 0.0, 2 * c_l
        fan_end = 2 * c_l
    else:
        def f(hm):
            return (2 * (c_l - math.sqrt(g * hm))
                    - (hm - h_r) * math.sqrt(0.5 * g * (hm + h_r) / (hm * h_r)))
        a, b = h_r, h_l
        for _ in range(200):
            if b - a <= 1e-16 * h_l:
                break
            m = 0.5 * (a + b)
            if f(m) > 0:
                a = m
            else:
                b = m
        h_m = 0.5 * (a + b)
        u_m = 2 * (c_l - math.sqrt(g * h_m))
        s = h_m * u_m / (h_m - h_r)
        fan_end = u_m - math.sqrt(g * h_m)
    xi = (np.asarray(x, dtype=float) - x0) / t
    return np.select([xi <= -c_l, xi <= fan_end, xi <= s],
                     [h_l, (2 * c_l - xi) ** 2 / (9 * g), h_m], h_r), s, h_m


def dam_break(args):
    grid = ["Depth averaged/Grid/Cell size=0.25", "Depth averaged/Grid/Upper right=100, 1",
            "Depth averaged/Release/Rectangle=0, 0, 100, 1"]
    cases = [("ritter", "Ritter (dry bed, $h_l$ = 1 m)", 0.0, []),
             ("stoker", "Stoker ($h_l$ = 1 m, $h_r$ = 0.5 m)", 0.5,
              ["Depth averaged/Release/Depth=x < 50 ? 1 : 0.5",
               "Depth averaged/Verification/Right depth=0.5"])]
    updates = [("strain", "Depth update = strain (Eq. 38)"),
               ("projection", "Depth update = projection")]
    t_end, x0 = 4.0, 50.0
    fig, axes = plt.subplots(2, 2, figsize=(10, 6.4), sharex=True, constrained_layout=True)
    x = np.linspace(0, 100, 4001)
    for row, (cname, clabel, h_r, cset) in zip(axes, cases):
        exact, s, h_m = dam_break_exact(x, t_end, 1.0, h_r, x0)
        c_l = math.sqrt(GRAVITY)
        for ax, (uname, ulabel) in zip(row, updates):
            ax.plot(x, exact, "k-", lw=1.2, label="exact", zorder=3)
            for n, color in [(2, "tab:blue"), (4, "tab:orange")]:
                r = run(args, "dam-break-%s-%s-%d" % (cname, uname, n),
                        "prm/dam-break-channel.prm",
                        [POINTS, "Depth averaged/Depth update=" + uname,
                         "Depth averaged/Release/Particles per direction=%d" % n]
                        + grid + cset)
                match = re.search(r"relative L1 error of the depth = ([0-9.eE+-]+)", r.log)
                error = float(match.group(1)) if match else float("nan")
                data, index = r.points(int(t_end))
                label = "%d x %d points per cell: L1 error %.3g" % (n, n, error)
                if r.status != 0:
                    label += " [%s]" % r.failure()
                if data is None:
                    ax.plot([], [], ".", color=color, label=label + " (no output at t = 4 s)")
                    continue
                # Ritter: the last point deeper than 1 mm; Stoker: the last point deeper
                # than halfway between the plateau and the still water.
                threshold = 1e-3 if h_r <= 0 else 0.5 * (h_m + h_r)
                front = data["x"][data["depth"] > threshold].max()
                print("  dam break %s %s %dx%d: L1 %.4g, points' %s at x = %.2f m "
                      "(exact %.2f m)" % (cname, uname, n, n, error,
                                          "front" if h_r <= 0 else "shock", front,
                                          x0 + s * t_end))
                ax.plot(data["x"], data["depth"], ".", ms=1.5 if n == 4 else 2.5,
                        color=color, alpha=0.6, label=label, rasterized=True)
                nodes = r.nodal_depth(int(t_end))
                if nodes is not None:
                    ax.plot(nodes[0], nodes[1], "-", color=color, lw=0.7, alpha=0.85,
                            label="its nodal depth (the L1 error's)")
            ax.set_title("%s, %s" % (clabel, ulabel), fontsize=9)
            ax.set_xlim(30, 85)
            ax.set_ylim(-0.02, 1.08)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7, loc="upper right", markerscale=3)
        row[0].set_ylabel("depth h [m]")
        if h_r <= 0:
            row[0].annotate("front $x_0 + 2\\sqrt{g h_l} t$ = %.1f m" % (x0 + 2 * c_l * t_end),
                            (x0 + 2 * c_l * t_end, 0), (60, 0.35), fontsize=7,
                            arrowprops={"arrowstyle": "->", "lw": 0.6})
        else:
            row[0].annotate("shock $x_0 + s t$ = %.1f m" % (x0 + s * t_end),
                            (x0 + s * t_end, h_r), (66, 0.2), fontsize=7,
                            arrowprops={"arrowstyle": "->", "lw": 0.6})
    for ax in axes[1]:
        ax.set_xlabel("x [m]")
    fig.suptitle("Dam break at t = 4 s (prm/dam-break-channel.prm, $\\mu = \\tau_Y$ = 0, "
                 "no friction), cells of 0.25 m on [0, 100] x [0, 1] m:\n"
                 "dots: the depth of every point; lines: the nodal depth", fontsize=10)
    save(fig, args, "depth-averaged-dam-break.png")


def save(fig, args, name):
    path = os.path.join(args.out, name)
    fig.savefig(path, dpi=100)
    plt.close(fig)
    print("wrote", path, flush=True)


FIGURES = {"lake": lake, "obstacle": obstacle, "dam-break": dam_break}


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--slidewave", default=os.path.join(ROOT, "build", "slidewave"),
                        help="the executable (default: build/slidewave of the repository)")
    parser.add_argument("--work", default="/tmp/slidewave-depth-averaged",
                        help="where the runs go (one directory per run)")
    parser.add_argument("--out", default=os.path.join(ROOT, "doc", "figures"))
    parser.add_argument("--only", choices=sorted(FIGURES))
    parser.add_argument("--keep", action="store_true",
                        help="reuse the runs already in --work")
    args = parser.parse_args()
    args.slidewave = os.path.abspath(args.slidewave)
    os.makedirs(args.work, exist_ok=True)
    os.makedirs(args.out, exist_ok=True)
    start = time.time()
    for name, figure in FIGURES.items():
        if args.only and name != args.only:
            continue
        figure(args)
    print("%.0f s in all" % (time.time() - start))


if __name__ == "__main__":
    main()
