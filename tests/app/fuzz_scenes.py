#!/usr/bin/python3
"""Fuzz test of the scene reader and the run-time guards (issue 7).

Mutates the scene files shipped in prm/ at random, with a fixed seed so that every run of the
test tries the same mutants, and runs each mutant twice:

1. ``slidewave --validate MUTANT`` must either accept it (exit 0, ": valid") or refuse it with
   one clean message (exit 1, "slidewave: error in 'FILE': parameter ..." for values, or
   "slidewave: error: Line <N> of file <FILE>: ..." for syntax the reader cannot parse);
2. a mutant that validates is run for a short time (End time cut to a few steps with --set)
   and must complete (0), be refused at setup (1, the same clean message) or stop with a
   run-time diagnostic (2, "slidewave: run failed at step ...").

Anything else fails the test: a signal (a crash), another exit status, a stack trace or an
uncaught-exception text on the error stream, or a run that does not finish within its time
limit without progress (a hang). A run still stepping at the limit (its progress lines
"step N t = ..." advancing: a mutant that only made the scene large, e.g. cells 10 times
smaller under a viscous time step) is stopped there and counted as "slow", not failed. Mutations: a number scaled by 1e-3 ... 1e3 or negated, a value replaced by a hostile one (negative, zero, huge, tiny,
nan, inf, text, empty, a list), a line deleted or duplicated, an 'end' dropped, a parameter
name misspelt, the file truncated, a subsection renamed, a line of garbage inserted.

  fuzz_scenes.py SLIDEWAVE PRM_DIRECTORY WORK_DIRECTORY [--count N] [--seed S]
"""
import argparse
import os
import random
import re
import subprocess
import sys

HOSTILE_VALUES = ["-1", "0", "-0", "1e308", "-1e308", "1e-300", "nan", "inf", "-inf", "abc",
                  "", "1, 2, 3", "0.5.5", "1e", "2147483648", "-2147483649", "0x10", "1/0",
                  "true", "none", ";;", "1e-12", "1e12", "3.0e+400"]
SHORT_END_TIME = {"shallow water": "0.002", "material points": "0.0005", "coupled": "0.002",
                  "depth averaged": "0.02", "free surface flow": "0.01",
                  "granular water": "0.001"}
BAD_TEXT = re.compile(r"terminate called|Stacktrace|Aborting|Segmentation|core dumped|"
                      r"An error occurred in line|Assertion|free\(\)|double free")


def mutate(lines, rng):
    """One random mutation of a scene; returns (new lines, description)."""
    lines = list(lines)
    settable = [i for i, l in enumerate(lines) if re.match(r"\s*set\s+.+=", l)]
    kind = rng.choice(["value", "value", "value", "scale", "scale", "scale", "delete",
                       "duplicate", "end",
                       "misspell", "truncate", "subsection", "garbage"])
    if kind == "value" and settable:
        i = rng.choice(settable)
        name, _ = lines[i].split("=", 1)
        value = rng.choice(HOSTILE_VALUES)
        lines[i] = "%s= %s\n" % (name, value)
        return lines, "line %d: %s= %s" % (i + 1, name.strip(), value)
    numeric = [i for i in settable
               if re.fullmatch(r"\s*[-+0-9.eE]+\s*", lines[i].split("=", 1)[1])]
    if kind == "scale" and numeric:
        i = rng.choice(numeric)
        name, value = lines[i].split("=", 1)
        factor = rng.choice([1e-3, 0.1, 0.5, 2., 10., 1e3, -1.])
        new = "%.6g" % (float(value) * factor)
        lines[i] = "%s= %s\n" % (name, new)
        return lines, "line %d: %s= %s (x %g)" % (i + 1, name.strip(), new, factor)
    if kind == "delete" and lines:
        i = rng.randrange(len(lines))
        return lines[:i] + lines[i + 1:], "line %d deleted" % (i + 1)
    if kind == "duplicate" and lines:
        i = rng.randrange(len(lines))
        return lines[:i + 1] + [lines[i]] + lines[i + 1:], "line %d duplicated" % (i + 1)
    if kind == "end":
        ends = [i for i, l in enumerate(lines) if l.strip() == "end"]
        if ends:
            i = rng.choice(ends)
            return lines[:i] + lines[i + 1:], "'end' on line %d dropped" % (i + 1)
    if kind == "misspell" and settable:
        i = rng.choice(settable)
        name, value = lines[i].split("=", 1)
        word = name.replace("set", "", 1).strip()
        if len(word) > 2:
            j = rng.randrange(len(word) - 1)
            word = word[:j] + word[j + 1] + word[j] + word[j + 2:]
        lines[i] = "  set %s =%s" % (word, value)
        return lines, "line %d misspelt: %s" % (i + 1, word)
    if kind == "truncate" and lines:
        i = rng.randrange(len(lines))
        return lines[:i], "truncated after line %d" % i
    if kind == "subsection":
        subs = [i for i, l in enumerate(lines) if l.strip().startswith("subsection")]
        if subs:
            i = rng.choice(subs)
            lines[i] = lines[i].rstrip("\n") + "x\n"
            return lines, "subsection on line %d renamed" % (i + 1)
    i = rng.randrange(len(lines) + 1)
    garbage = rng.choice(["set", "= 3", "subsection", "end end", "set = ", "\x01\x02",
                          "set Physics = material points", "set Physics = shallow water"])
    return lines[:i] + [garbage + "\n"] + lines[i:], "line %r inserted at %d" % (garbage, i + 1)


def run(command, timeout):
    try:
        result = subprocess.run(command, capture_output=True, text=True, timeout=timeout,
                                errors="replace")
        return result.returncode, result.stdout, result.stderr
    except subprocess.TimeoutExpired as timeout_expired:
        # What the program printed before it was stopped (its progress lines).
        out = timeout_expired.stdout or ""
        if isinstance(out, bytes):
            out = out.decode(errors="replace")
        return None, out, ""


def still_stepping(out):
    """True when the progress lines of a run stopped at its time limit show its step count
    advancing: a slow run, not a hang."""
    steps = [int(s) for s in re.findall(r"^step\s+(\d+)\s+t = ", out, re.MULTILINE)]
    return len(set(steps)) >= 2 and steps == sorted(steps)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("slidewave")
    parser.add_argument("prm_directory")
    parser.add_argument("work_directory")
    parser.add_argument("--count", type=int, default=60, help="number of mutants")
    parser.add_argument("--seed", type=int, default=20261123)
    parser.add_argument("--timeout", type=float, default=60., help="seconds per run")
    args = parser.parse_args()

    rng = random.Random(args.seed)
    scenes = sorted(os.path.join(args.prm_directory, f) for f in os.listdir(args.prm_directory)
                    if f.endswith(".prm"))
    os.makedirs(args.work_directory, exist_ok=True)
    failures, outcomes = [], {}
    for n in range(args.count):
        scene = scenes[n % len(scenes)]
        lines = open(scene).readlines()
        physics = next((k for k in SHORT_END_TIME
                        if any(re.match(r"\s*set\s+Physics\s*=\s*" + k, l) for l in lines)),
                       None)
        mutant_lines, what = mutate(lines, rng)
        mutant = os.path.join(args.work_directory, "mutant-%03d.prm" % n)
        with open(mutant, "w") as f:
            f.writelines(mutant_lines)
        label = "%s [%s]" % (os.path.basename(scene), what)

        status, out, err = run([args.slidewave, "--validate", mutant], args.timeout)
        problem = None
        if status is None:
            problem = "--validate did not finish within %g s" % args.timeout
        elif BAD_TEXT.search(err):
            problem = "--validate printed a crash text: %s" % err.strip()[:300]
        elif status == 0 and ": valid" not in out:
            problem = "--validate exit 0 without ': valid'"
        elif status == 1 and not err.startswith("slidewave: error"):
            problem = "--validate exit 1 without a clean message: %s" % err.strip()[:300]
        elif status not in (0, 1):
            problem = "--validate exit status %d: %s" % (status, err.strip()[:300])
        outcome = "refused" if status == 1 else "valid"

        if problem is None and status == 0:
            command = [args.slidewave, "--set",
                       "Output directory=" + os.path.join(args.work_directory, "run-%03d" % n)]
            if physics:
                command += ["--set", "Time/End time=" + SHORT_END_TIME[physics]]
            status, out, err = run(command + [mutant], args.timeout)
            if status is None and still_stepping(out):
                status = "slow"
            elif status is None:
                problem = "the run did not finish within %g s" % args.timeout
            elif BAD_TEXT.search(err):
                problem = "the run printed a crash text: %s" % err.strip()[:300]
            elif status == 1 and not err.startswith("slidewave: error"):
                problem = "run exit 1 without a clean message: %s" % err.strip()[:300]
            elif status == 2 and "slidewave: run failed at step" not in err:
                problem = "run exit 2 without a diagnostic: %s" % err.strip()[:300]
            elif status not in (0, 1, 2):
                problem = "run exit status %d: %s" % (status, err.strip()[:300])
            outcome = {0: "ran", 1: "refused at setup", 2: "stopped",
                       "slow": "slow (still stepping at the limit)"}.get(status, "?")
        outcomes[outcome] = outcomes.get(outcome, 0) + 1
        print("%3d %-16s %s" % (n, outcome if problem is None else "FAILED", label))
        if problem:
            print("    " + problem)
            failures.append((label, problem))

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
