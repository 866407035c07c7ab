#!/usr/bin/python3
"""Runs a depth-averaged scene whose columns split on one rank and on two, and compares
the last point tables (points/points_NNNNN.csv, written in the order of the columns'
identifiers): the same identifiers, row for row, and the same positions, depths and
velocities to TOLERANCE times the largest absolute value of their kind (coordinates,
depths, velocity components) (issue 28: the split
columns' identifiers do not depend on the number of ranks, PointCloud::add_points).

    compare_ranks_points.py SLIDEWAVE SCENE.prm DIRECTORY TOLERANCE MPIEXEC NUMPROC_FLAG

Passes (exit 0, "the columns agree on one and two ranks") when they agree and some
columns split (more rows at the end than at the start); prints what it compared.
"""
import csv
import glob
import os
import shutil
import subprocess
import sys


def run(exe, scene, output, launcher):
    shutil.rmtree(output, ignore_errors=True)  # no table of an earlier run
    settings = ["--set", f"Output directory={output}",
                "--set", "Depth averaged/Output point table=true"]
    subprocess.run(launcher + [exe] + settings + [scene], check=True,
                   stdout=subprocess.DEVNULL)
    tables = sorted(glob.glob(os.path.join(output, "points", "points_*.csv")))
    return [read(tables[0]), read(tables[-1])]


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def main():
    exe, scene, directory, tolerance, mpiexec, numproc_flag = sys.argv[1:7]
    tolerance = float(tolerance)
    one = run(exe, scene, os.path.join(directory, "one"), [])
    two = run(exe, scene, os.path.join(directory, "two"),
              [mpiexec, numproc_flag, "2", "--oversubscribe"])
    header, first = one[0]
    _, last_one = one[1]
    _, last_two = two[1]
    print(f"columns: {len(first)} at the start, {len(last_one)} at the end on one rank, "
          f"{len(last_two)} on two")
    ok = len(last_one) > len(first) and len(last_one) == len(last_two)
    ids_one = [row[0] for row in last_one]
    ids_two = [row[0] for row in last_two]
    same_ids = ids_one == ids_two
    print(f"identifiers row for row the same: {same_ids}")
    ok = ok and same_ids
    # The scale of a quantity: the largest of its kind (the coordinates together, the
    # velocity components together: a transverse velocity of round-off against the
    # flow's speed).
    values = {c: [float(row[c]) for row in last_one] for c in range(1, len(header))}
    kinds = {"x": ("x", "y"), "y": ("x", "y"),
             "velocity_x": ("velocity_x", "velocity_y"),
             "velocity_y": ("velocity_x", "velocity_y")}
    for c in range(1, len(header)):
        a = values[c]
        b = [float(row[c]) for row in last_two] if same_ids else a
        together = [header.index(name) for name in kinds.get(header[c], (header[c],))]
        scale = max(max(abs(v) for k in together for v in values[k]), 1e-300)
        difference = max(abs(x - y) for x, y in zip(a, b))
        print(f"{header[c]}: largest difference {difference:.3e} of {scale:.6e}")
        ok = ok and difference <= tolerance * scale
    print("the columns agree on one and two ranks" if ok else "the columns differ")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
