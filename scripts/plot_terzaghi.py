#!/usr/bin/python3
"""Terzaghi consolidation of a granular-water run: the pore pressure profiles of
OUTPUT_DIR/terzaghi_profiles.csv (written by a scene with 'Granular water/Verification/
Exact solution = Terzaghi') against the series, and the average degree of consolidation of
OUTPUT_DIR/statistics.csv against the exact one (doc/granular-water.md).

    /usr/bin/python3 scripts/plot_terzaghi.py OUTPUT_DIR [--png FILE]

The PNG goes to OUTPUT_DIR/terzaghi.png unless --png says otherwise.
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output_dir")
    parser.add_argument("--png", default=None)
    args = parser.parse_args()
    with open(os.path.join(args.output_dir, "terzaghi_profiles.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(args.output_dir, "statistics.csv")) as f:
        stats = [r for r in csv.DictReader(f) if float(r["step"]) > 0]
    load = max(float(r["exact"]) for r in rows)  # p0: the exact profile's largest value
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.5))
    for tv in sorted({r["time_factor"] for r in rows}, key=float):
        profile = [r for r in rows if r["time_factor"] == tv]
        y = [float(r["y"]) for r in profile]
        line, = left.plot([float(r["exact"]) / load for r in profile], y, "-", lw=1)
        left.plot([float(r["pore_pressure"]) / load for r in profile], y, "o", ms=3,
                  color=line.get_color(), label=f"T_v = {float(tv):.2f}")
    left.set_xlabel("pore pressure / p0")
    left.set_ylabel("y [m]")
    left.set_title("pore pressure: points SlideWave, lines Terzaghi")
    left.legend(fontsize=8)
    left.grid(alpha=0.3)
    tv = [float(r["time_factor"]) for r in stats]
    right.semilogx(tv, [float(r["consolidation_degree_exact"]) for r in stats], "-",
                   label="Terzaghi")
    right.semilogx(tv, [float(r["consolidation_degree"]) for r in stats], "o", ms=3,
                   label="SlideWave (from the pore pressure)")
    right.set_xlabel("T_v = c_v t / H^2")
    right.set_ylabel("average degree of consolidation U")
    right.set_title("degree of consolidation")
    right.legend(fontsize=8)
    right.grid(alpha=0.3, which="both")
    fig.tight_layout()
    png = args.png or os.path.join(args.output_dir, "terzaghi.png")
    fig.savefig(png, dpi=120)
    print("figure:", png)


if __name__ == "__main__":
    main()
