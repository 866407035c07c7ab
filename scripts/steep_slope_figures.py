#!/usr/bin/python3
"""Draw the steep-slope verification of the depth-averaged model (issue 28,
doc/depth-averaged.md, "Slope correction"): runs build/slidewave on prm/block-on-steep-slope.prm
and prm/dam-break-on-slope.prm with 'Slope correction' = bed normal (the default) and none
(paper 001's plan-view form), into --work, and draws one figure with matplotlib.

  /usr/bin/python3 scripts/steep_slope_figures.py [--slidewave build/slidewave]
      [--work /tmp/slidewave-steep-slope] [--out doc/figures] [--keep]

Figure (in --out): depth-averaged-steep-slope.png
  left: the horizontal acceleration of a slab sliding down planes of 25 to 75 deg with
      friction phi = 20 deg (its momentum over mass and time after 1 s, as the program
      prints it) against the exact g cos^2 theta (tan theta - tan phi) and paper 001's
      g (tan theta - tan phi);
  right: Mangeney et al.'s dam break down 40 deg (phi = 20 deg) at t = 2 s: the columns'
      vertical depth against the exact solution, both forms, with the program's errors.
About 24 runs of about a second each. Reuses depth_averaged_figures.py's runner."""
import argparse
import math
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from depth_averaged_figures import GRAVITY, POINTS, ROOT, np, plt, run, save  # noqa: E402

FORMS = [("bed normal", "bed normal (default)", "tab:blue", "o"),
         ("none", "none (paper 001)", "tab:red", "s")]
PHI = math.radians(20.0)


def block(args, ax):
    angles = list(range(25, 80, 5))
    theta = np.radians(np.linspace(21, 77, 200))
    ax.plot(np.degrees(theta), GRAVITY * np.cos(theta) ** 2 * (np.tan(theta) - math.tan(PHI)),
            "k-", lw=1.2, label="exact: $g \\cos^2\\theta\\,(\\tan\\theta - \\tan\\phi)$")
    ax.plot(np.degrees(theta), GRAVITY * (np.tan(theta) - math.tan(PHI)), "k--", lw=0.8,
            label="$g\\,(\\tan\\theta - \\tan\\phi)$")
    for form, label, color, marker in FORMS:
        measured = []
        for angle in angles:
            slope = math.tan(math.radians(angle))
            r = run(args, "block-%s-%d" % (form.replace(" ", "-"), angle),
                    "prm/block-on-steep-slope.prm",
                    ["Depth averaged/Slope correction=" + form, "Time/End time=1",
                     "Time/Output interval=1", "Depth averaged/Output grid=false",
                     "Depth averaged/Terrain/Elevation=%.17g * x" % -slope,
                     "Depth averaged/Verification/Slope angle=%d" % angle,
                     "Depth averaged/Verification/Tolerance=0"])
            match = re.search(r"momentum_x / \(M t\) = ([0-9.eE+-]+) m/s\^2.*relative error "
                              r"([0-9.eE+-]+)", r.log)
            value = float(match.group(1)) if match else float("nan")
            error = float(match.group(2)) if match else float("nan")
            print("  block %s %d deg: %.9f m/s^2, relative error %.3g" % (form, angle, value,
                                                                          error))
            measured.append(value)
        ax.plot(angles, measured, marker, color=color, ms=5, mfc="none",
                label="SlideWave, Slope correction = " + label)
    ax.set_xlabel("slope angle $\\theta$ [deg]")
    ax.set_ylabel("horizontal acceleration [m/s$^2$]")
    ax.set_ylim(0, 20)
    ax.set_title("Slab sliding down a plane, $\\phi$ = 20 deg, after 1 s", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")


def mangeney(x, t, theta, phi, h0, x0, g=GRAVITY):
    """Mangeney et al. (2000) on the plane Z = -x tan(theta), projected on the plan view:
    the vertical depth at the horizontal positions x (as InclinedPlaneSolutions)."""
    c = math.cos(theta)
    m = g * (math.sin(theta) - c * math.tan(phi))
    c0 = math.sqrt(g * c * h0 * c)
    xi = x / c - x0 / c - 0.5 * m * t * t
    T = np.where(xi <= -c0 * t, h0 * c, (2 * c0 - xi / t) ** 2 / (9 * g * c))
    T = np.where(xi > 2 * c0 * t, 0.0, T)
    return T / c, (x0 / c - c0 * t + 0.5 * m * t * t) * c


def dam_break(args, ax):
    t_end, theta = 2.0, math.radians(40.0)
    x = np.linspace(0, 64, 6401)
    exact, tail = mangeney(x, t_end, theta, PHI, 1.0, 28.0)
    valid = x >= tail
    ax.plot(x[valid], exact[valid], "k-", lw=1.2, label="exact (Mangeney et al. 2000)")
    ax.axvline(tail, color="0.5", lw=0.6, ls=":")
    ax.annotate("errors measured from here on", (tail, 0.04), (tail + 0.5, 0.04), fontsize=7,
                va="center")
    for form, label, color, _ in FORMS:
        r = run(args, "dam-break-%s" % form.replace(" ", "-"), "prm/dam-break-on-slope.prm",
                [POINTS, "Depth averaged/Slope correction=" + form,
                 "Depth averaged/Output grid=false"])
        match = re.search(r"error of the depth = ([0-9.eE+-]+), of the velocity = "
                          r"([0-9.eE+-]+); front x = ([0-9.eE+-]+)", r.log)
        errors = [float(v) for v in match.groups()] if match else [float("nan")] * 3
        print("  dam break %s: depth %.4g, velocity %.4g, front %.2f m" % (form, *errors))
        data, _ = r.points(int(round(t_end / 0.5)))
        if data is None:
            continue
        ax.plot(data["x"], data["depth"], ".", ms=1.5, color=color, alpha=0.5,
                rasterized=True,
                label="%s: L1 error of h %.3f, of u %.3f, front %.1f m" % (label, *errors))
    ax.set_xlim(0, 50)
    ax.set_ylim(-0.02, 1.25)
    ax.set_xlabel("x (horizontal) [m]")
    ax.set_ylabel("vertical depth h [m]")
    ax.set_title("Dam break down 40 deg, $\\phi$ = 20 deg, t = 2 s (reservoir [8, 28] m, "
                 "1 m deep)", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper right", markerscale=4)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--slidewave", default=os.path.join(ROOT, "build", "slidewave"))
    parser.add_argument("--work", default="/tmp/slidewave-steep-slope")
    parser.add_argument("--out", default=os.path.join(ROOT, "doc", "figures"))
    parser.add_argument("--keep", action="store_true", help="reuse the runs in --work")
    args = parser.parse_args()
    args.slidewave = os.path.abspath(args.slidewave)
    os.makedirs(args.work, exist_ok=True)
    os.makedirs(args.out, exist_ok=True)
    start = time.time()
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    block(args, axes[0])
    dam_break(args, axes[1])
    save(fig, args, "depth-averaged-steep-slope.png")
    print("%.0f s in all" % (time.time() - start))


if __name__ == "__main__":
    main()
