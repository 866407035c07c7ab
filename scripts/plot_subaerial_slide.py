#!/usr/bin/python3
"""Waveforms of the subaerial slide (paper 002, §4.3; prm/subaerial-slide.prm).

  scripts/plot_subaerial_slide.py DIR [DIR ...] --out doc/figures/granular-subaerial-gauges.png
      [--labels ...] [--depth 0.148] [--threshold 0.001] [--csv first_wave.csv]

Each DIR is a granular-water scene's output directory with free_surface/gauges.csv. One
panel per gauge: the water surface's rise eta - depth over time, one line per DIR. For each
gauge and DIR it prints (and with --csv writes) the first wave: its arrival, the first time
the rise exceeds --threshold, and its height, the largest rise before the surface first
falls back below the still level after the arrival (the whole record if it never does)."""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read_gauges(directory):
    with open(os.path.join(directory, "free_surface", "gauges.csv")) as f:
        rows = list(csv.reader(f))
    names = rows[0][1:]
    time = [float(r[0]) for r in rows[1:]]
    series = [[float(r[j + 1]) for r in rows[1:]] for j in range(len(names))]
    return names, time, series


def first_wave(time, rise, threshold):
    """(arrival, height, time of the crest); None where the rise never exceeds threshold."""
    start = next((i for i, r in enumerate(rise) if r > threshold), None)
    if start is None:
        return None, None, None
    end = next((i for i in range(start, len(rise)) if rise[i] < 0.0), len(rise))
    crest = max(range(start, end), key=lambda i: rise[i])
    return time[start], rise[crest], time[crest]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    parser.add_argument("dirs", nargs="+")
    parser.add_argument("--out", required=True)
    parser.add_argument("--labels", nargs="+")
    parser.add_argument("--depth", type=float, default=0.148, help="still water depth [m]")
    parser.add_argument("--threshold", type=float, default=0.001, help="rise of an arrival [m]")
    parser.add_argument("--csv", help="write the first waves' table here")
    args = parser.parse_args()
    labels = args.labels or [os.path.basename(os.path.normpath(d)) for d in args.dirs]
    if len(labels) != len(args.dirs):
        parser.error("one label per directory")

    data = [read_gauges(d) for d in args.dirs]
    names = data[0][0]
    fig, axes = plt.subplots(len(names), 1, figsize=(7, 1.8 * len(names)), sharex=True)
    if len(names) == 1:
        axes = [axes]
    table = [("scene", "gauge", "arrival_s", "first_wave_height_m", "crest_time_s")]
    for label, (gauge_names, time, series) in zip(labels, data):
        for j, name in enumerate(gauge_names):
            rise = [eta - args.depth for eta in series[j]]
            axes[j].plot(time, [1000 * r for r in rise], label=label, lw=1)
            axes[j].set_ylabel("rise [mm]")
            axes[j].set_title(name, fontsize=9)
            arrival, height, crest = first_wave(time, rise, args.threshold)
            table.append((label, name,
                          "" if arrival is None else "%.4f" % arrival,
                          "" if height is None else "%.5f" % height,
                          "" if crest is None else "%.4f" % crest))
    axes[-1].set_xlabel("t [s]")
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    for row in table:
        print("%-20s %-16s %10s %20s %14s" % row)
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            csv.writer(f).writerows(table)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
