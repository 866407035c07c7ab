"""Damaged checkpoints (issue 29): each is caught before deal.II or p4est reads it.

The scene (tests/common/restart_depth_averaged_maps.prm: the depth-averaged collapse with
hazard maps, checkpoints every 20 steps) runs once on RANKS ranks and leaves two
checkpoints, `checkpoint` (the newest) and `checkpoint.previous`. Then, each on a fresh copy
of that output:

- reference: the newest checkpoint removed (a run killed while writing it), --resume takes
  the previous one; its statistics rows, statistics.csv and maps must be the uninterrupted
  run's, byte for byte (on one rank; on two, the rows but the columns of round-off of the
  sums' order, as the resumed run's partition differs);
- for each damage (a file truncated, emptied, deleted, a byte flipped, the manifest gone,
  record.txt with a missing or absurd count or an impossible value, its manifest entry
  rewritten so that only the record's own check can catch it):
  - the newest damaged: --resume must exit 0 and print one message naming the folder, the
    file and what is wrong, and its rows and files must be the reference's (it resumed
    from the previous checkpoint: a run from the newest prints fewer rows);
  - both damaged: --resume must exit 1 with a message naming both folders and what is
    wrong with each.

Then FUZZ_CASES seeded random damages (a random file of the newest checkpoint truncated at
a random length, a random byte changed, deleted, emptied or grown by garbage) must each be
caught the same way.

The messages (folder paths replaced by OUTPUT, the scene's by its name, byte counts and checksums by N and CRC,
which depend on the number of ranks) and the verdicts make a report that must equal
EXPECTED. Without the checks each case fails: the damaged newest checkpoint would be read
(a crash, an abort in p4est, bad_alloc, or fewer rows than the reference).

Usage: checkpoint_damage.py EXECUTABLE MPIEXEC RANKS SCENE DIRECTORY EXPECTED
"""

import difflib
import os
import random
import re
import shutil
import subprocess
import sys
import zlib

executable, mpiexec, ranks, scene, directory, expected = sys.argv[1:7]
ranks = int(ranks)
OUTPUT_FILES = ["statistics.csv", "maps/summary.csv", "maps/peak_flow_thickness.tif",
                "maps/peak_flow_velocity.tif", "maps/peak_pressure_dynamic.tif",
                "maps/peak_pressure_static.tif", "maps/arrival_time.tif",
                "maps/deposit_thickness.tif"]


FUZZ_CASES = 10
ROUND_OFF = r" (load_imbalance|momentum_y|nodal_mass_error|nodal_momentum_error)=[^ ]*"


def run(output, resume):
    command = [executable, "--set", "Output directory=" + output]
    if resume:
        command.append("--resume")
    if ranks > 1:
        command = [mpiexec, "-np", str(ranks), "--oversubscribe"] + command
    result = subprocess.run(command + [scene], capture_output=True, text=True, timeout=600)
    rows = [line for line in result.stdout.splitlines() if line.startswith("time=")]
    return result.returncode, rows, result.stderr


def read(path):
    with open(path, "rb") as f:
        return f.read()


def same_files(first, second):
    return all(read(os.path.join(first, n)) == read(os.path.join(second, n))
               for n in OUTPUT_FILES)


def rewrite_manifest_entry(folder, name):
    """The manifest made to agree with a changed file: only the file's own check remains."""
    path = os.path.join(folder, "manifest.txt")
    lines = open(path).read().splitlines()
    data = read(os.path.join(folder, name))
    for i, line in enumerate(lines):
        words = line.split()
        if words[:2] == ["file", name]:
            lines[i] = "file %s %d %08x" % (name, len(data), zlib.crc32(data))
    open(path, "w").write("\n".join(lines) + "\n")


def truncate(name, size=None):
    def damage(folder):
        path = os.path.join(folder, name)
        length = os.path.getsize(path)
        os.truncate(path, length // 2 if size is None else size)
    return damage


def delete(name):
    return lambda folder: os.remove(os.path.join(folder, name))


def flip_byte(name):
    def damage(folder):
        path = os.path.join(folder, name)
        data = bytearray(read(path))
        data[len(data) // 2] ^= 0xFF
        open(path, "wb").write(bytes(data))
    return damage


def cut_manifest(n_files):
    """The manifest ends at a line's end, listing only the first files (all intact)."""
    def damage(folder):
        path = os.path.join(folder, "manifest.txt")
        lines = open(path).read().splitlines()
        open(path, "w").write("\n".join(lines[:2 + n_files]) + "\n")
    return damage


def edit_record(pattern, replacement):
    def damage(folder):
        path = os.path.join(folder, "record.txt")
        text, n = re.subn(pattern, replacement, open(path).read(), flags=re.M)
        assert n == 1, pattern
        open(path, "w").write(text)
        rewrite_manifest_entry(folder, "record.txt")
    return damage


DAMAGES = [
    ("state_variable.data truncated", truncate("state_variable.data")),
    ("state_fixed.data emptied", truncate("state_fixed.data", 0)),
    ("state.info deleted", delete("state.info")),
    ("state (p4est) truncated", truncate("state")),
    ("state_hazard_maps.data truncated", truncate("state_hazard_maps.data")),
    ("a byte of state_variable.data flipped", flip_byte("state_variable.data")),
    ("manifest.txt deleted", delete("manifest.txt")),
    ("manifest.txt cut short after its third file", cut_manifest(3)),
    ("record.txt: run/step without its count", edit_record(r"^run/step 1 ", "run/step ")),
    ("record.txt: run/step with an absurd count",
     edit_record(r"^run/step 1 ", "run/step 1000000000000000 ")),
    ("record.txt: step nan", edit_record(r"^run/step 1 .*$", "run/step 1 nan")),
    ("record.txt: step -3", edit_record(r"^run/step 1 .*$", "run/step 1 -3")),
    ("record.txt: output counter 1e300",
     edit_record(r"^run/output_index 1 .*$", "run/output_index 1 1e300")),
    ("record.txt: time -1 (before the start)", edit_record(r"^run/time 1 .*$", "run/time 1 -1")),
]


def normalized(text, folder):
    # SlideWave's own lines (mpiexec adds its notes when a rank exits non-zero).
    text = " | ".join(line for line in text.splitlines() if line.startswith("slidewave:"))
    text = text.replace(folder, "OUTPUT").replace(scene, os.path.basename(scene))
    text = re.sub(r"CRC-32 [0-9a-f]{8}, (\S+) says [0-9a-f]{8}", r"CRC-32 CRC, \1 says CRC", text)
    text = re.sub(r"\b\d+ bytes, (\S+) says \d+", r"N bytes, \1 says N", text)
    return text.strip()


def main():
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    full = os.path.join(directory, "full")
    status, full_rows, err = run(full, False)
    if status != 0:
        sys.exit("the uninterrupted run failed (%d):\n%s" % (status, err))
    pristine = os.path.join(directory, "pristine")
    shutil.copytree(full, pristine)

    def fresh(name):
        folder = os.path.join(directory, name)
        shutil.copytree(pristine, folder)
        return folder

    report = []
    failures = []
    reference = fresh("reference")
    shutil.rmtree(os.path.join(reference, "checkpoint"))
    status, reference_rows, err = run(reference, True)
    report.append("newest checkpoint missing: exit %d, %d rows, %s" % (
        status, len(reference_rows), normalized(err, reference)))
    # On one rank the run from the previous checkpoint is the uninterrupted one, byte for
    # byte; on two, the resumed run's partition differs and with it the order of sums over
    # the ranks: the columns that show it are left out and the maps not compared.
    def comparable(rows):
        return rows if ranks == 1 else [re.sub(ROUND_OFF, "", row) for row in rows]
    if (status != 0 or not reference_rows
            or comparable(reference_rows) != comparable(full_rows[-len(reference_rows):])):
        failures.append("the run from the previous checkpoint is not the uninterrupted one")
    if ranks == 1 and not same_files(reference, full):
        failures.append("the files of the run from the previous checkpoint differ from the "
                        "uninterrupted run's")

    for index, (what, damage) in enumerate(DAMAGES):
        case = fresh("case%02d" % index)
        damage(os.path.join(case, "checkpoint"))
        status, rows, err = run(case, True)
        equal = rows == reference_rows and status == 0 and same_files(case, reference)
        report.append("%s:\n  newest damaged: exit %d, %s\n  rows and files as from the "
                      "previous checkpoint: %s" % (what, status, normalized(err, case),
                                                   "yes" if equal else "no"))
        both = fresh("case%02d-both" % index)
        damage(os.path.join(both, "checkpoint"))
        damage(os.path.join(both, "checkpoint.previous"))
        status, rows, err = run(both, True)
        report.append("  both damaged: exit %d, %s" % (status, normalized(err, both)))

    # Seeded random damage of a random file of the newest checkpoint: each must be caught.
    generator = random.Random(29)
    names = sorted(os.listdir(os.path.join(pristine, "checkpoint")))
    for index in range(FUZZ_CASES):
        name = generator.choice(names)
        kind = generator.choice(["truncated", "a byte flipped", "deleted", "emptied",
                                 "grown by garbage"])
        case = fresh("fuzz%02d" % index)
        path = os.path.join(case, "checkpoint", name)
        data = read(path)
        if kind == "truncated":
            data = data[:generator.randrange(len(data))]
        elif kind == "a byte flipped":
            at = generator.randrange(len(data))
            data = data[:at] + bytes([data[at] ^ (1 + generator.randrange(255))]) + data[at + 1:]
        elif kind == "emptied":
            data = b""
        elif kind == "grown by garbage":
            data += bytes(generator.randrange(256) for _ in range(1 + generator.randrange(64)))
        if kind == "deleted":
            os.remove(path)
        else:
            open(path, "wb").write(data)
        status, rows, err = run(case, True)
        caught = (status == 0 and rows == reference_rows and same_files(case, reference)
                  and normalized(err, case).startswith(
                      "slidewave: the checkpoint 'OUTPUT/checkpoint' is damaged: "))
        report.append("fuzz %d: %s %s: resumed from the previous checkpoint with a message: %s"
                      % (index, name, kind, "yes" if caught else "no"))

    text = "\n".join(report) + "\n"
    open(os.path.join(directory, "report.txt"), "w").write(text)
    wanted = open(expected).read()
    if text != wanted:
        failures.append("the report differs from %s:\n%s" % (expected, "".join(
            difflib.unified_diff(wanted.splitlines(True), text.splitlines(True),
                                 "expected", "actual"))))
    if failures:
        sys.exit("\n".join(failures))
    print(text + "checkpoint_damage: every damaged checkpoint was caught")


main()
