"""Helpers shared by SlideWave's benchmark scripts (Python standard library only)."""
import csv
import os
import subprocess
import sys
import threading
import time


def fmt(value, spec):
    """Format ``value`` with ``spec``, or '-' if it is None."""
    return "-" if value is None else format(value, spec)


def find_executable(path, wait_s):
    """Return ``path`` once it is an executable file, waiting up to ``wait_s`` seconds."""
    deadline = time.monotonic() + wait_s
    while not (os.path.isfile(path) and os.access(path, os.X_OK)):
        if time.monotonic() >= deadline:
            sys.exit(f"SlideWave executable not found: {path} (option --exe)")
        time.sleep(5)
    return path


def library_of(executable):
    """The libslidewave.so that ``executable`` loads (as ``ldd`` resolves it); None for an
    executable linked without it. Exits when ``ldd`` cannot find it."""
    try:
        out = subprocess.run(["ldd", executable], capture_output=True, text=True).stdout
    except FileNotFoundError:
        sys.exit("ldd not found: it tells which libslidewave.so each build loads")
    for line in out.splitlines():
        if "libslidewave" in line and "=>" in line:
            target = line.split("=>", 1)[1].strip()
            if target.startswith("not found"):
                sys.exit(f"{executable}: its libslidewave.so is not found (ldd)")
            return os.path.realpath(target.rsplit(" (0x", 1)[0].strip())
    return None


def check_distinct_builds(executables):
    """Exit when two of the executables (name -> path) load the same libslidewave.so.

    An executable finds the library of its own build tree through its run path, so a
    copy of build/slidewave still runs build/libslidewave.so: two copies of one executable
    compare a build with itself. Compare two build trees (e.g. a git worktree's)."""
    libraries = {name: library_of(path) for name, path in executables.items()}
    paths = [lib for lib in libraries.values() if lib is not None]
    if len(paths) != len(set(paths)):
        sys.exit("the builds to compare load the same library "
                 + ", ".join(f"{name}: {lib}" for name, lib in libraries.items())
                 + ": build each in its own tree (a copy of an executable loads the"
                   " library of the tree it was built in)")


def write_csv(path, rows, columns):
    """Write the result rows to ``path`` with ``columns`` (directories created as needed)."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        for row in rows:
            w.writerow({k: ("" if row.get(k) is None else row[k]) for k in columns})


def _cpu_ticks():
    """The machine's CPU times so far, in clock ticks: the 'cpu' line of /proc/stat (user,
    nice, system, idle, iowait, irq, softirq, steal, ...)."""
    with open("/proc/stat") as f:
        return [int(v) for v in f.readline().split()[1:]]


def cpu_busy_seconds():
    """CPU seconds spent by all processes of the machine so far (from /proc/stat)."""
    user, nice, system, _idle, _iowait, irq, softirq, steal = _cpu_ticks()[:8]
    return (user + nice + system + irq + softirq + steal) / os.sysconf("SC_CLK_TCK")


def cpu_steal_seconds():
    """CPU seconds the hypervisor has taken from this virtual machine's cores so far
    (/proc/stat's 'steal': a core wanted to run and the host ran something else)."""
    ticks = _cpu_ticks()
    return (ticks[7] if len(ticks) > 7 else 0) / os.sysconf("SC_CLK_TCK")


def background_load(seconds):
    """Average number of busy cores over ``seconds`` (the caller is idle meanwhile)."""
    b0, t0 = cpu_busy_seconds(), time.perf_counter()
    time.sleep(seconds)
    return (cpu_busy_seconds() - b0) / (time.perf_counter() - t0)


def wait_until_idle(max_wait_s, threshold=0.25):
    """Wait until the machine runs less than ``threshold`` cores of other work.

    Returns the background load measured last (cores). Gives up after ``max_wait_s``.
    """
    deadline = time.monotonic() + max_wait_s
    load = background_load(1.0)
    while load > threshold and time.monotonic() < deadline:
        time.sleep(4.0)
        load = background_load(1.0)
    return load


def on_both_cores(run):
    """``run(core)`` for cores 0 and 1 at the same time (two threads); their results."""
    results = [None, None]

    def one(core):
        results[core] = run(core)

    threads = [threading.Thread(target=one, args=(core,)) for core in (0, 1)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return results


def retry_once(run, exe, wait_s):
    """``run()``, once more after a failure that is not the program's own (the executable
    being rebuilt meanwhile: missing, busy, or no timer table): a result whose "status"
    is neither "ok" nor a message of slidewave's."""
    r = run()
    if r["status"] != "ok" and "slidewave:" not in r["status"]:
        find_executable(exe, wait_s)
        time.sleep(2)
        r = run()
    return r


def interleaved_pairs(run, pairs):
    """Runs ``run(which)`` for the two builds, "base" and "new", ``pairs`` times, the order
    alternating from pair to pair (base new, new base, ...) so that a drift of the machine
    within a pair favours neither. ``run`` returns its result, or None when the run failed
    (that pair is then dropped). Returns ([(pair, order, {which: result})], failed)."""
    done, failed = [], False
    for pair in range(pairs):
        order = ("base", "new") if pair % 2 == 0 else ("new", "base")
        results = {}
        for which in order:
            result = run(which)
            if result is None:
                failed = True
                break
            results[which] = result
        if len(results) == 2:
            done.append((pair, "-".join(order), results))
    return done, failed


def add_orders(rows, error="error", order="order"):
    """Observed order of convergence of each row (a dict with "problem", "line",
    "cell_size", the error under the key ``error`` and "status") against the next coarser
    cell size of its line, in row[``order``] (None where either run failed or has no
    positive error)."""
    import math
    groups = {}
    for row in rows:
        groups.setdefault((row["problem"], row["line"]), []).append(row)
    for group in groups.values():
        group.sort(key=lambda r: -r["cell_size"])
        previous = None
        for row in group:
            row[order] = None
            if (previous and previous.get(error) and row.get(error)
                    and row["status"] == "ok" and previous["status"] == "ok"
                    and previous[error] > 0 and row[error] > 0):
                row[order] = (math.log(previous[error] / row[error])
                              / math.log(previous["cell_size"] / row["cell_size"]))
            previous = row

