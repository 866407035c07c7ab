"""The problems and the lines (option sets) of the depth-averaged work-precision studies
(benchmarks/depth_averaged_work_precision.py, depth_averaged_front.py): the scenes, cell
sizes, line names shape-transfer-update-N[-sX] and the settings each line and cell size
give the program."""

import os
import re

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

PROBLEMS = ["rigid", "Stoker", "Ritter", "slope", "block"]
CELL_SIZES = {"rigid": [0.25, 0.125, 0.0625], "Stoker": [1.0, 0.5, 0.25, 0.125, 0.0625],
              "Ritter": [1.0, 0.5, 0.25, 0.125, 0.0625], "slope": [0.5, 0.25, 0.125, 0.0625],
              "block": [0.5]}
QUICK_CELL_SIZES = {"rigid": [0.25, 0.125], "Stoker": [1.0, 0.5, 0.25],
                    "Ritter": [1.0, 0.5, 0.25], "slope": [0.5, 0.25], "block": [0.5]}
SCENES = {"rigid": os.path.join("tests", "depth_averaged", "rigid_translation_q1_strain.prm"),
          "Stoker": os.path.join("prm", "dam-break-channel.prm"),
          "Ritter": os.path.join("prm", "dam-break-channel.prm"),
          "slope": os.path.join("prm", "dam-break-on-slope.prm"),
          "block": os.path.join("tests", "depth_averaged", "sliding_block_40.prm")}
TITLES = {"rigid": "rigid translation (weightless layer, 2 s): L1 of the columns' depth",
          "Stoker": "Stoker (1 m | 0.5 m, t = 4 s): L1 of the nodal depth",
          "Ritter": "Ritter (1 m | dry, t = 4 s): L1 of the nodal depth",
          "slope": "dam break on 40 deg, phi = 20 deg (t = 2 s): L1 of the nodal depth",
          "block": "sliding block on 40 deg: error of the acceleration"}
FRONT_PROBLEMS = ["Ritter", "slope"]

SHAPES = ["q1", "gimp", "cpgimp"]
UPDATES = {"strain": "strain", "proj": "projection"}

DEFAULTS = "gimp-flip80-proj-4-s1.5"
PAPER_001 = "q1-pic-strain-2-s0"
DEFAULT_LINES = [DEFAULTS, "gimp-flip80-proj-4-s0", "gimp-pic-proj-4-s1.5", "gimp-flip80-proj-4-s2",
                 "q1-flip80-proj-4-s1.5", "gimp-flip80-strain-4-s1.5", "gimp-flip80-proj-2-s1.5",
                 "gimp-pic-proj-4-s0", PAPER_001]
QUICK_LINES = [DEFAULTS, PAPER_001]


def split_of(name):
    """The 'Split stretch' of a line name ending in -sX (e.g. gimp-pic-proj-4-s2), or None
    (the program's default) without that ending."""
    parts = name.split("-")
    return float(parts[4][1:]) if len(parts) == 5 else None


def parse_line(name):
    """(shape, FLIP fraction, depth update, points per direction) of a line name."""
    shape, transfer, update, ppd = name.split("-")[:4]
    if shape not in SHAPES:
        raise ValueError(shape)
    if transfer == "pic":
        flip = 0.0
    elif transfer == "flip":
        flip = 1.0
    elif re.fullmatch(r"flip\d\d", transfer):
        flip = int(transfer[4:]) / 100.
    else:
        raise ValueError(transfer)
    return shape, flip, UPDATES[update], int(ppd)


def settings_for(problem, line, cell_size):
    """--set overrides of the problem's scene for one run."""
    shape, flip, update, ppd = parse_line(line)
    s = {
        "Time/Output interval": 100,
        "Time/Statistics interval": 100000,
        "Test/Enable": "false",
        "Depth averaged/Output grid": "false",
        "Depth averaged/Grid/Cell size": repr(cell_size),
        "Depth averaged/Shape functions": shape,
        "Depth averaged/FLIP fraction": repr(flip),
        "Depth averaged/Depth update": update,
        "Depth averaged/Release/Particles per direction": ppd,
        "Depth averaged/Verification/Tolerance": 0,
    }
    if split_of(line) is not None:
        s["Depth averaged/Split stretch"] = repr(split_of(line))
    width = float(f"{4 * cell_size:.12g}")
    if problem in ("Stoker", "Ritter"):
        s["Time/End time"] = "4.0"
        s["Depth averaged/Grid/Upper right"] = f"100, {width!r}"
        s["Depth averaged/Release/Rectangle"] = f"0, 0, 100, {width!r}"
    if problem == "Stoker":
        s["Depth averaged/Release/Depth"] = "x < 50 ? 1 : 0.5"
        s["Depth averaged/Verification/Right depth"] = 0.5
    if problem == "slope":
        s["Depth averaged/Grid/Upper right"] = f"64, {width!r}"
        s["Depth averaged/Release/Rectangle"] = f"8, 0, 28, {width!r}"
    return s
