#!/usr/bin/python3
"""Make the figures of doc/coupled.md: runs the coupled scenes with build/slidewave (into
/tmp/slidewave-figures) and draws them with matplotlib, in the manner of paper 000's
Figs. 8-11 and 13-16: the soil coloured by its vertical stress under the water surface at
t = 0, 0.5, 1 and 5 s for each water depth (scripts/plot_coupled_scene.py), and the
free-surface histories at the gauges x = 4 m and x = 8 m for the three depths of each scene.

  /usr/bin/python3 scripts/coupled_figures.py [--build build] [--out doc/figures]
      [--only NAME] [--keep] [--pressure {excess over initial level,hydrostatic}]

NAME: in-water, dam-break. --pressure sets 'Coupling/Water pressure on soil' (default: the
scenes' own, the paper's excess over the initial level); the runs go to
/tmp/slidewave-figures/NAME-VALUE-{excess,hydrostatic}, and --keep reuses those already
there. Figures (in --out), for the excess form:
  coupled-in-water-hw{1.0,1.5,2.0}-snapshots.png   (paper Figs. 8, 9, 10)
  coupled-in-water-gauges.png                      (Fig. 11)
  coupled-dam-break-hl{0.5,1.0,2.0}-snapshots.png  (Figs. 13, 14, 15)
  coupled-dam-break-gauges.png                     (Fig. 16)
and for the hydrostatic form the same with '-hydrostatic' before '-snapshots'/'-gauges'.
Six runs of 6-20 s each per form, one at a time (about 1.5 minutes with drawing)."""
import argparse
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_coupled_scene import draw  # noqa: E402
from plot_water import read_gauges  # noqa: E402  (selects the Agg backend)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WORK = "/tmp/slidewave-figures"
PRESSURES = {"excess over initial level": "excess", "hydrostatic": "hydrostatic"}
PAPER_PRESSURE = "excess over initial level"

# Scene, the constants that set the water, the values of the varied one, its name in the
# figure names and its label.
SCENES = {
    "in-water": ("prm/clay-column-in-water.prm", "hw=%g", [1.0, 1.5, 2.0], "hw",
                 "$h_w$ = %g m"),
    "dam-break": ("prm/clay-column-dam-break.prm", "hl=%g, hr=1.0, h0=1.0, l0=2",
                  [0.5, 1.0, 2.0], "hl", "$h_l$ = %g m"),
}


def run_directory(name, value, pressure):
    return os.path.join(WORK, "%s-%g-%s" % (name, value, PRESSURES[pressure]))


def run(build, name, value, pressure, keep):
    """Run one scene at one depth and pressure form (unless kept); returns its directory."""
    scene, constants = SCENES[name][:2]
    directory = run_directory(name, value, pressure)
    if keep and os.path.exists(os.path.join(directory, "statistics.csv")):
        return directory
    command = [os.path.join(build, "slidewave"),
               "--set", "Output directory=" + directory,
               "--set", "Shallow water/Initial condition/Function constants=" + constants % value,
               "--set", "Coupling/Water pressure on soil=" + pressure,
               os.path.join(ROOT, scene)]
    print(" ".join(command), flush=True)
    start = time.time()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    print("  %.0f s" % (time.time() - start), flush=True)
    return directory


def gauges(plt, runs, title, path):
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.6), sharey=True, constrained_layout=True)
    for label, directory in runs:
        header, data = read_gauges(os.path.join(directory, "water", "gauges.csv"))
        for ax, column in zip(axes, (1, 2)):
            # Delta h / h_s with h_s = 1 m: the departure from the first record (still level).
            ax.plot(data[:, 0], data[:, column] - data[0, column], lw=1, label=label)
            ax.set_title("gauge at x = %s m" % header[column].split("=")[-1].rstrip(")"),
                         fontsize=10)
            ax.set_xlabel("t [s]")
    axes[0].set_ylabel("$\\Delta h / h_s$ ($h_s$ = 1 m)")
    axes[1].legend(fontsize=8)
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.suptitle(title, fontsize=10)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print("wrote", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", default=os.path.join(ROOT, "doc", "figures"))
    parser.add_argument("--only", choices=sorted(SCENES))
    parser.add_argument("--keep", action="store_true")
    parser.add_argument("--pressure", choices=sorted(PRESSURES), default=PAPER_PRESSURE)
    args = parser.parse_args()
    import matplotlib.pyplot as plt

    os.makedirs(args.out, exist_ok=True)
    form = "" if args.pressure == PAPER_PRESSURE else "-" + PRESSURES[args.pressure]
    for name, (scene, _, values, short, label) in SCENES.items():
        if args.only and name != args.only:
            continue
        runs = []
        for value in values:
            directory = run(args.build, name, value, args.pressure, args.keep)
            runs.append((label % value, directory))
            title = "%s, %s, water pressure on soil: %s" % (os.path.basename(scene),
                                                             label % value, args.pressure)
            path = os.path.join(args.out, "coupled-%s-%s%.1f%s-snapshots.png"
                                % (name, short, value, form))
            print("wrote", draw(directory, path, title=title))
        gauges(plt, runs, "%s, water pressure on soil: %s" % (os.path.basename(scene),
                                                             args.pressure),
               os.path.join(args.out, "coupled-%s%s-gauges.png" % (name, form)))


if __name__ == "__main__":
    main()
