#!/usr/bin/python3
"""Fuzz test of the raster and vector files a depth-averaged scene reads (issue 29).

Writes a small scene over a terrain raster (an ESRI ASCII grid with a .prj of UTM zone 16N),
a release polygon (a GeoJSON in EPSG:32616) and a release depth raster (another ESRI grid),
checks that it runs as it is, then damages one of the four files at random, with a fixed
seed so that every run of the test tries the same mutants, and runs each mutant for a
fraction of a second of flow. Each must complete (0), be refused with one clean message
(1, "slidewave: error in 'FILE': parameter ...") or stop with a run-time diagnostic (2,
"slidewave: run failed at step ...").

Anything else fails the test: a signal (a crash), another exit status (4: an internal
error), a stack trace or an uncaught-exception text, or a run that does not finish within
its time limit. Mutations: a value or a header entry of a grid replaced by a hostile one
(nan, inf, 1e300, -3.4e38, 0, negative, huge, text), a line of a grid deleted or
duplicated, a file truncated or garbled, the .prj replaced (degrees, feet, garbage,
empty), a coordinate of the polygon replaced, the polygon made a bow tie, its 'crs'
member dropped.

  fuzz_terrain_files.py SLIDEWAVE WORK_DIRECTORY [--count N] [--seed S]
"""
import argparse
import os
import random
import re
import subprocess
import sys

BAD_TEXT = re.compile(r"terminate called|Stacktrace|Aborting|Segmentation|core dumped|"
                      r"An error occurred in line|Assertion|free\(\)|double free|"
                      r"internal error")
HOSTILE_NUMBERS = ["nan", "inf", "-inf", "1e300", "-1e300", "-3.4e38", "0", "-1", "-9999",
                   "1e-300", "abc", "", "2147483648", "600000", "1e308", "0.5.5"]
UTM16 = ('PROJCS["WGS_1984_UTM_Zone_16N",GEOGCS["GCS_WGS_1984",DATUM["D_WGS_1984",'
         'SPHEROID["WGS_1984",6378137.0,298.257223563]],PRIMEM["Greenwich",0.0],'
         'UNIT["Degree",0.0174532925199433]],PROJECTION["Transverse_Mercator"],'
         'PARAMETER["False_Easting",500000.0],PARAMETER["False_Northing",0.0],'
         'PARAMETER["Central_Meridian",-87.0],PARAMETER["Scale_Factor",0.9996],'
         'PARAMETER["Latitude_Of_Origin",0.0],UNIT["Meter",1.0]]\n')
PRJ_REPLACEMENTS = [
    'GEOGCS["GCS_WGS_1984",DATUM["D_WGS_1984",SPHEROID["WGS_1984",6378137.0,298.257223563]],'
    'PRIMEM["Greenwich",0.0],UNIT["Degree",0.0174532925199433]]\n',
    UTM16.replace('UNIT["Meter",1.0]', 'UNIT["Foot_US",0.3048006096012192]'),
    "garbage\n", "", UTM16[:80]]

SCENE = """set Physics = depth averaged
subsection Time
  set End time        = 0.3
  set Output interval = 0.3
end
subsection Depth averaged
  set Output grid = false
  subsection Grid
    set Lower left  = 10, 10
    set Upper right = 100, 100
    set Cell size   = 5
  end
  subsection Terrain
    set Source      = raster
    set Raster file = terrain.asc
  end
  subsection Release
    set Shape        = vector file
    set Vector file  = release.geojson
    set Depth raster = depth.asc
  end
  subsection Hazard maps
    set Enable = true
  end
end
"""


def grid(x0, y0, n, cell, value):
    """An ESRI ASCII grid of n x n pixels of side cell at (x0, y0), value(x, y) at centres."""
    lines = ["ncols %d\n" % n, "nrows %d\n" % n, "xllcorner %g\n" % x0, "yllcorner %g\n" % y0,
             "cellsize %g\n" % cell, "NODATA_value -9999\n"]
    for r in range(n):
        y = y0 + (n - r - 0.5) * cell
        lines.append(" ".join("%g" % value(x0 + (c + 0.5) * cell, y) for c in range(n)) + "\n")
    return lines


def release(ring, crs=True):
    member = (' "crs": { "type": "name", "properties": { "name": '
              '"urn:ogc:def:crs:EPSG::32616" } },' if crs else "")
    coordinates = ", ".join("[%s, %s]" % p for p in ring)
    return ['{ "type": "FeatureCollection",%s\n' % member,
            '  "features": [ { "type": "Feature", "properties": {},\n',
            '    "geometry": { "type": "Polygon", "coordinates": [ [ %s ] ] } } ] }\n'
            % coordinates]


SQUARE = [("40", "40"), ("70", "40"), ("70", "70"), ("40", "70"), ("40", "40")]
ORIGINAL = {
    "terrain.asc": grid(0, 0, 11, 10, lambda x, y: 100 - 0.3 * x),
    "terrain.prj": [UTM16],
    "depth.asc": grid(30, 30, 5, 10, lambda x, y: 2),
    "depth.prj": [UTM16],
    "release.geojson": release(SQUARE),
}


def mutate(files, rng):
    """One random mutation of one of the files; returns (files, description)."""
    files = {k: list(v) for k, v in files.items()}
    name = rng.choice(["terrain.asc", "terrain.asc", "depth.asc", "depth.asc", "terrain.prj",
                       "release.geojson", "release.geojson"])
    lines = files[name]
    if name.endswith(".prj"):
        text = rng.choice(PRJ_REPLACEMENTS)
        files[name] = [text]
        return files, "%s replaced by %r" % (name, text[:40])
    if name.endswith(".asc"):
        kind = rng.choice(["value", "value", "value", "header", "header", "delete",
                           "duplicate", "truncate", "garbage"])
        if kind == "value":
            r = rng.randrange(6, len(lines))
            tokens = lines[r].split()
            c = rng.randrange(len(tokens))
            tokens[c] = rng.choice(HOSTILE_NUMBERS)
            lines[r] = " ".join(tokens) + "\n"
            return files, "%s line %d value %d = %r" % (name, r + 1, c + 1, tokens[c])
        if kind == "header":
            r = rng.randrange(6)
            key = lines[r].split()[0]
            value = rng.choice(HOSTILE_NUMBERS + ["3", "12", "4.5"])
            lines[r] = "%s %s\n" % (key, value)
            return files, "%s %s = %r" % (name, key, value)
        if kind == "delete":
            r = rng.randrange(len(lines))
            del lines[r]
            return files, "%s line %d deleted" % (name, r + 1)
        if kind == "duplicate":
            r = rng.randrange(len(lines))
            lines.insert(r, lines[r])
            return files, "%s line %d duplicated" % (name, r + 1)
        if kind == "truncate":
            text = "".join(lines)
            at = rng.randrange(len(text))
            files[name] = [text[:at]]
            return files, "%s truncated at byte %d" % (name, at)
        r = rng.randrange(len(lines) + 1)
        lines.insert(r, "\x00\x01 garbage\n")
        return files, "%s garbage at line %d" % (name, r + 1)
    kind = rng.choice(["coordinate", "coordinate", "bow tie", "no crs", "truncate", "open",
                       "degenerate"])
    ring = list(SQUARE)
    if kind == "coordinate":
        i = rng.randrange(len(ring) - 1)
        value = rng.choice(["nan", "1e308", "-1e308", "748050", "1e-300", "-40", "\"40\"",
                            "null"])
        ring[i] = (value, ring[i][1])
        if i == 0:
            ring[-1] = ring[0]
        files[name] = release(ring)
        return files, "release vertex %d x = %s" % (i, value)
    if kind == "bow tie":
        files[name] = release([("40", "40"), ("70", "70"), ("70", "40"), ("40", "70"),
                               ("40", "40")])
        return files, "release a bow tie"
    if kind == "no crs":
        files[name] = release(SQUARE, crs=False)
        return files, "release without its crs member"
    if kind == "open":
        files[name] = release(SQUARE[:-1])
        return files, "release ring not closed"
    if kind == "degenerate":
        files[name] = release([("40", "40"), ("70", "40"), ("40", "40")])
        return files, "release ring of two vertices"
    text = "".join(lines)
    at = rng.randrange(len(text))
    files[name] = [text[:at]]
    return files, "release.geojson truncated at byte %d" % at


def run(command, timeout):
    try:
        result = subprocess.run(command, capture_output=True, text=True, timeout=timeout,
                                errors="replace")
        return result.returncode, result.stdout, result.stderr
    except subprocess.TimeoutExpired:
        return None, "", ""


def check(status, err):
    """What is wrong with a run that ended with @p status and printed @p err, or None."""
    if status is None:
        return "the run did not finish in time"
    if BAD_TEXT.search(err):
        return "a crash text: %s" % err.strip()[:300]
    if status == 1 and not err.startswith("slidewave: error"):
        return "exit 1 without a clean message: %s" % err.strip()[:300]
    if status == 2 and "slidewave: run failed at step" not in err:
        return "exit 2 without a diagnostic: %s" % err.strip()[:300]
    if status not in (0, 1, 2):
        return "exit status %d: %s" % (status, err.strip()[:300])
    return None


def write(directory, files):
    os.makedirs(directory, exist_ok=True)
    for name, lines in files.items():
        with open(os.path.join(directory, name), "w") as f:
            f.writelines(lines)
    with open(os.path.join(directory, "scene.prm"), "w") as f:
        f.write(SCENE)
    return os.path.join(directory, "scene.prm")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("slidewave")
    parser.add_argument("work_directory")
    parser.add_argument("--count", type=int, default=60, help="number of mutants")
    parser.add_argument("--seed", type=int, default=20261204)
    parser.add_argument("--timeout", type=float, default=60., help="seconds per run")
    args = parser.parse_args()

    def output(directory):
        return ["--set", "Output directory=" + os.path.join(directory, "output")]

    # The scene as written must run: the mutants then test the damage, not the scene.
    directory = os.path.join(args.work_directory, "original")
    scene = write(directory, ORIGINAL)
    status, _, err = run([args.slidewave] + output(directory) + [scene], args.timeout)
    if status != 0:
        print("the undamaged scene did not run (exit %s): %s" % (status, err.strip()[:300]))
        return 1
    print("the undamaged scene runs")

    rng = random.Random(args.seed)
    failures, outcomes = [], {}
    for n in range(args.count):
        files, what = mutate(ORIGINAL, rng)
        directory = os.path.join(args.work_directory, "mutant-%03d" % n)
        scene = write(directory, files)
        status, _, err = run([args.slidewave] + output(directory) + [scene], args.timeout)
        problem = check(status, err)
        outcome = {0: "ran", 1: "refused", 2: "stopped"}.get(status, "?")
        outcomes[outcome] = outcomes.get(outcome, 0) + 1
        print("%3d %-8s %s" % (n, outcome if problem is None else "FAILED", what))
        if status == 1 and problem is None:
            print("    " + err.strip().split("allowed: ", 1)[-1][:160])
        if problem:
            print("    " + problem)
            failures.append((what, problem))

    print("\n%d mutants (seed %d): %s" % (args.count, args.seed,
                                          ", ".join("%d %s" % (v, k)
                                                    for k, v in sorted(outcomes.items()))))
    if failures:
        print("%d FAILED" % len(failures))
        return 1
    print("every mutant was refused cleanly or ran cleanly")
    return 0


if __name__ == "__main__":
    sys.exit(main())
