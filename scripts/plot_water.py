#!/usr/bin/python3
"""Plot the 1D shallow-water output of a SlideWave run.

Usage::

    plot_water.py OUTPUT_DIR [--exact dam-break:h_l,h_r,x0] [--out FILE.png]
                  [--gravity G] [--title TEXT]

OUTPUT_DIR is the run's output directory (the one holding ``water/``). The script reads

* ``water/profile-NNNNN.csv``: first line ``# time = T``, then the columns
  ``x,h,u,hu,bed,eta``; one line per output time is drawn in two panels, the free
  surface eta (with the bed) and the velocity u;
* ``water/gauges.csv`` (if present): ``time`` followed by the free surface at each gauge,
  drawn against time in a third panel.

With ``--exact dam-break:h_l,h_r,x0`` the exact dam-break solution (Stoker for a wet bed,
Ritter when ``h_r = 0``; see /work/shared/VERIFICATION.md) at the time of the last
profile is overlaid as a dashed black line in the first two panels (it assumes a flat
bed at zero elevation, as in prm/dam-break.prm).

The figure is written with matplotlib's non-interactive Agg backend to ``--out``
(default ``OUTPUT_DIR/water-profiles.png``).

Only the Python standard library, numpy and matplotlib are used.
"""

import argparse
import glob
import math
import os
import re
import sys

try:
    import numpy as np
    import matplotlib
except ImportError as exc:  # e.g. a pyenv python3 first in PATH without Debian's packages
    sys.exit(f"{exc}; run this script with a python3 that has numpy and matplotlib "
             f"(Debian's: /usr/bin/python3 {' '.join(sys.argv)})")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after selecting the backend)


# --------------------------------------------------------------------------------------
# Exact dam-break solutions
# --------------------------------------------------------------------------------------

def stoker_middle_state(h_l, h_r, g=9.81, tol=1e-14, max_iter=200):
    """Return (h_m, u_m, S) of Stoker's wet-bed dam break.

    h_m is the depth of the plateau between the rarefaction and the bore, u_m its
    velocity and S the speed of the bore. h_m is the root in (h_r, h_l) of

        f(h_m) = 2 (sqrt(g h_l) - sqrt(g h_m))
                 - (h_m - h_r) sqrt(g (h_m + h_r) / (2 h_m h_r)),

    which is monotone (decreasing) there, so bisection is used.
    """
    if not (0.0 < h_r < h_l):
        raise ValueError("Stoker's solution needs 0 < h_r < h_l")

    def f(hm):
        return (2.0 * (math.sqrt(g * h_l) - math.sqrt(g * hm))
                - (hm - h_r) * math.sqrt(g * (hm + h_r) / (2.0 * hm * h_r)))

    lo, hi = h_r, h_l
    for _ in range(max_iter):
        mid = 0.5 * (lo + hi)
        if f(mid) > 0.0:      # f(h_r) > 0 > f(h_l): the root is above mid
            lo = mid
        else:
            hi = mid
        if hi - lo < tol * h_l:
            break
    h_m = 0.5 * (lo + hi)
    u_m = 2.0 * (math.sqrt(g * h_l) - math.sqrt(g * h_m))
    s = h_m * u_m / (h_m - h_r)
    return h_m, u_m, s


def exact_dam_break(x, t, h_l, h_r, x0, g=9.81):
    """Exact depth and velocity of the 1D dam break on a flat, frictionless bed.

    Parameters
    ----------
    x : array_like
        Positions [m].
    t : float
        Time since the dam was removed [s]; for t <= 0 the initial state is returned.
    h_l, h_r : float
        Depths left and right of the dam [m]; h_r = 0 gives Ritter's dry-bed solution,
        h_r > 0 Stoker's wet-bed solution.
    x0 : float
        Dam position [m].
    g : float
        Gravitational acceleration [m/s^2].

    Returns
    -------
    (h, u) : tuple of numpy arrays, the depth [m] and velocity [m/s] at x.
    """
    x = np.asarray(x, dtype=float)
    h = np.where(x < x0, h_l, h_r).astype(float)
    u = np.zeros_like(x)
    if t <= 0.0:
        return h, u

    xi = (x - x0) / t
    c0 = math.sqrt(g * h_l)
    if h_r <= 0.0:
        # Ritter: rarefaction from -c0 to the dry front at 2 c0.
        tail = 2.0 * c0
        h_m = u_m = s = None
    else:
        h_m, u_m, s = stoker_middle_state(h_l, h_r, g)
        tail = u_m - math.sqrt(g * h_m)

    fan = (xi > -c0) & (xi < tail)
    h = np.where(xi <= -c0, h_l, h)
    h = np.where(fan, (2.0 * c0 - xi) ** 2 / (9.0 * g), h)
    u = np.where(fan, 2.0 / 3.0 * (c0 + xi), u)
    if h_r <= 0.0:
        dry = xi >= tail
        h = np.where(dry, 0.0, h)
        u = np.where(dry, 0.0, u)
    else:
        plateau = (xi >= tail) & (xi <= s)
        h = np.where(plateau, h_m, h)
        u = np.where(plateau, u_m, u)
        right = xi > s
        h = np.where(right, h_r, h)
        u = np.where(right, 0.0, u)
    return h, u


# --------------------------------------------------------------------------------------
# Reading SlideWave output
# --------------------------------------------------------------------------------------

_TIME_RE = re.compile(r"#\s*time\s*=\s*([-+0-9.eE]+)")


def read_profile(path):
    """Read one ``profile-NNNNN.csv``; return (time, dict of column name -> array)."""
    with open(path) as f:
        first = f.readline()
        m = _TIME_RE.match(first.strip())
        if not m:
            raise ValueError(f"{path}: first line is not '# time = T': {first!r}")
        time = float(m.group(1))
        header = f.readline().strip().split(",")
        data = np.loadtxt(f, delimiter=",", ndmin=2)
    if data.size == 0:
        data = np.zeros((0, len(header)))
    return time, {name: data[:, i] for i, name in enumerate(header)}


def read_gauges(path):
    """Read ``gauges.csv``; return (header list, 2D array with one row per record)."""
    with open(path) as f:
        header = f.readline().strip().split(",")
        data = np.loadtxt(f, delimiter=",", ndmin=2)
    return header, data


def parse_exact(spec):
    """Parse ``dam-break:h_l,h_r,x0`` into a tuple (h_l, h_r, x0)."""
    kind, _, values = spec.partition(":")
    if kind != "dam-break":
        raise argparse.ArgumentTypeError(
            f"unknown exact solution '{kind}' (only 'dam-break:h_l,h_r,x0')")
    try:
        h_l, h_r, x0 = (float(v) for v in values.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected dam-break:h_l,h_r,x0 with three numbers, got '{spec}'")
    if h_l <= 0.0 or h_r < 0.0 or h_r >= h_l:
        raise argparse.ArgumentTypeError("need h_l > h_r >= 0")
    return h_l, h_r, x0


# --------------------------------------------------------------------------------------
# Plot
# --------------------------------------------------------------------------------------

def plot(output_dir, exact=None, out=None, gravity=9.81, title=None):
    """Draw the figure for ``output_dir`` and write it to ``out``; return the path."""
    files = sorted(glob.glob(os.path.join(output_dir, "water", "profile-*.csv")))
    if not files:
        raise SystemExit(f"no water/profile-*.csv in {output_dir}")
    profiles = [read_profile(p) for p in files]
    profiles.sort(key=lambda tp: tp[0])

    gauge_path = os.path.join(output_dir, "water", "gauges.csv")
    gauges = read_gauges(gauge_path) if os.path.isfile(gauge_path) else None
    if gauges is not None and (gauges[1].size == 0 or len(gauges[0]) < 2):
        gauges = None

    npanels = 3 if gauges is not None else 2
    fig, axes = plt.subplots(npanels, 1, figsize=(10, 3.2 * npanels),
                             constrained_layout=True)
    ax_eta, ax_u = axes[0], axes[1]

    cmap = plt.get_cmap("viridis")
    n = len(profiles)
    for i, (t, d) in enumerate(profiles):
        colour = cmap(i / max(n - 1, 1) * 0.9)
        label = f"t = {t:g} s"
        ax_eta.plot(d["x"], d["eta"], color=colour, lw=1.4, label=label)
        ax_u.plot(d["x"], d["u"], color=colour, lw=1.4, label=label)

    # The bed is fixed in time: draw it once, from the last profile.
    t_last, d_last = profiles[-1]
    ax_eta.fill_between(d_last["x"], min(d_last["bed"].min(), 0.0),
                        d_last["bed"], color="saddlebrown", alpha=0.35, lw=0)
    ax_eta.plot(d_last["x"], d_last["bed"], color="saddlebrown", lw=1.2, label="bed")

    if exact is not None:
        h_l, h_r, x0 = exact
        x0_dom, x1_dom = d_last["x"].min(), d_last["x"].max()
        xs = np.linspace(x0_dom, x1_dom, 4001)
        he, ue = exact_dam_break(xs, t_last, h_l, h_r, x0, gravity)
        kind = "Ritter" if h_r == 0.0 else "Stoker"
        elabel = f"exact ({kind}), t = {t_last:g} s"
        ax_eta.plot(xs, he, "k--", lw=1.1, label=elabel)
        ax_u.plot(xs, ue, "k--", lw=1.1, label=elabel)

    ax_eta.set_ylabel("free surface η, bed [m]")
    ax_eta.set_xlabel("x [m]")
    ax_eta.grid(alpha=0.3)
    ax_eta.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax_u.set_ylabel("velocity u [m/s]")
    ax_u.set_xlabel("x [m]")
    ax_u.grid(alpha=0.3)
    ax_u.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))

    if gauges is not None:
        header, data = gauges
        ax_g = axes[2]
        for j in range(1, len(header)):
            ax_g.plot(data[:, 0], data[:, j], lw=1.3, label=header[j])
        ax_g.set_xlabel("time [s]")
        ax_g.set_ylabel("η at gauge [m]")
        ax_g.grid(alpha=0.3)
        ax_g.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
        ax_g.set_title("gauges", fontsize=10)

    fig.suptitle(title or f"SlideWave shallow water: {os.path.normpath(output_dir)}",
                 fontsize=11)
    if out is None:
        out = os.path.join(output_dir, "water-profiles.png")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.savefig(out, dpi=130)
    plt.close(fig)
    return out


def main(argv=None):
    """Command-line entry point."""
    parser = argparse.ArgumentParser(
        description="Plot SlideWave 1D shallow-water profiles and gauges.")
    parser.add_argument("output_dir", help="run output directory (contains water/)")
    parser.add_argument("--exact", type=parse_exact, metavar="dam-break:h_l,h_r,x0",
                        help="overlay the exact dam-break solution (Stoker, or Ritter "
                             "if h_r = 0) at the last profile's time")
    parser.add_argument("--out", metavar="FILE.png",
                        help="output image (default OUTPUT_DIR/water-profiles.png)")
    parser.add_argument("--gravity", type=float, default=9.81,
                        help="g for the exact solution [m/s^2] (default 9.81)")
    parser.add_argument("--title", help="figure title")
    args = parser.parse_args(argv)
    out = plot(args.output_dir, args.exact, args.out, args.gravity, args.title)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
