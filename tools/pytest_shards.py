"""The test suite on every core: N pytest processes at once, each a share of the tests
(``--shard K/N``, tests/shards.py: a file's tests together but for the heavy ones, the units
balanced by their measured seconds in tests/durations.json), one verdict for them all.

    python tools/pytest_shards.py              # the quick loop (-m "not slow"), N = the cores
    python tools/pytest_shards.py --all        # the whole suite, slow tests too
    python tools/pytest_shards.py -n 3 -- -x   # pytest's own arguments after --
    python tools/pytest_shards.py --record     # the whole suite, then tests/durations.json
                                               # written from its measured seconds

Each share's output is printed whole as the share ends (never interleaved), then one line per
share, the failed tests' and errors' node ids (``FAILED …``, ``ERROR …``: a file that does not
collect is an error of every share, named once) and one combined line: ``passed: 3180 passed,
12 skipped in 221.0 s wall (2 shares)`` or ``FAILED: 1 failed, … 1 error …``. The quick loop's
guard (every module of src/flywheel imported by a quick test: tests/conftest.py) is checked on
the union of the shares' imports.

Exit 0 when every share passed (and the guard holds); 1 on any failure, error, collection
error, guard failure or a share that ended without its report; 5 when no share selected a
test; 2 for a usage error; 130 when stopped by Ctrl-C (or SIGTERM, SIGHUP): each share is then
interrupted as pytest is by Ctrl-C and killed past :data:`GRACE_S` seconds, the failures so far
named and each share's counts given.

``--record`` writes the table only after a run that passed; it replaces the entries of the
files that ran and keeps the others (one file again: ``--record -- tests/render/test_plots.py``).
"""
from __future__ import annotations

import argparse
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TABLE = "tests/durations.json"

#: a share runs in a session of its own, and Ctrl-C reaches it through the runner alone
POSIX = os.name == "posix"

#: seconds a share has to end after Ctrl-C before it is killed
GRACE_S = 20.0
KILL = getattr(signal, "SIGKILL", signal.SIGTERM)

#: the combined line's counts, in pytest's order and words
SAID = (("failed", "failed"), ("passed", "passed"), ("skipped", "skipped"),
        ("xfailed", "xfailed"), ("xpassed", "xpassed"), ("error", "error"))


@dataclass
class Share:
    k: int
    proc: subprocess.Popen
    log: object
    report: Path
    guard: Path
    started: float
    code: int | None = None
    seconds: float = 0.0
    outcome: dict = field(default_factory=dict)


#: the most shares run at once by default (each pytest process holds matplotlib, numpy and
#: a case's results: a few hundred MB)
MOST_BY_DEFAULT = 8


def usable_cores(cpu_max: Path = Path("/sys/fs/cgroup/cpu.max")) -> int:
    """The processors this process may run on: its affinity (a cpuset), fewer if the cgroup's
    CPU quota (cgroup v2 ``cpu.max``) allows less — what a container's 2 cores are, where
    ``os.cpu_count()`` tells the host's."""
    try:
        cores = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        cores = os.cpu_count() or 1
    try:
        quota, period = cpu_max.read_text().split()[:2]
        if quota != "max":
            cores = min(cores, max(1, int(int(quota) / int(period))))
    except (OSError, ValueError):
        pass
    return max(1, cores)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("-n", type=int, default=min(MOST_BY_DEFAULT, usable_cores()),
                    help=f"shares run at once (default: the usable processors, at most "
                         f"{MOST_BY_DEFAULT})")
    ap.add_argument("--all", action="store_true", help="the whole suite, slow tests too")
    ap.add_argument("--record", action="store_true",
                    help=f"the whole suite (as --all), then {TABLE} written from its seconds")
    ap.add_argument("--root", type=Path, default=ROOT, help=argparse.SUPPRESS)  # tests' trees
    ap.add_argument("pytest_args", nargs="*", help="after --: passed to each pytest")
    a = ap.parse_args(argv)
    if not 1 <= a.n <= 64:
        ap.error(f"-n {a.n}: allowed 1 … 64")
    whole = a.all or a.record
    marks = [] if whole else ["-m", "not slow"]
    with tempfile.TemporaryDirectory(prefix="flywheel-shards-") as tmp:
        t0 = time.monotonic()
        shares = [_start(a, k, Path(tmp), marks, whole) for k in range(1, a.n + 1)]
        try:
            with _interrupts_raised():
                _wait_and_print(shares)
        except KeyboardInterrupt:
            _stop(shares)
            outcomes = [_read_json(s.report) for s in shares]
            for line in sorted({f"FAILED {t}" for o in outcomes for t in o.get("failed", ())}) + \
                    sorted({f"ERROR {t}" for o in outcomes for t in o.get("errors", ())}):
                print(line)
            said = [combined_words(o.get("counts", {})) or "no test ended" for o in outcomes]
            print(f"interrupted after {time.monotonic() - t0:.1f} s: " + ", ".join(
                f"share {s.k}/{a.n} exit {s.code} ({w})" for s, w in zip(shares, said)),
                flush=True)
            return 130
        for s in shares:
            s.outcome = _read_json(s.report)
        code = _verdict(shares, a.n, whole, time.monotonic() - t0)
    if a.record and code == 0:
        path = a.root / TABLE
        write_table(path, record(read_table(path), [s.outcome for s in shares], a.root))
        print(f"{TABLE}: written from this run's seconds")
    return code


def _start(a, k: int, tmp: Path, marks: list[str], whole: bool) -> Share:
    log = open(tmp / f"share{k}.log", "w+", encoding="utf-8")
    report, guard = tmp / f"report{k}.json", tmp / f"guard{k}.json"
    cmd = [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", *marks,
           "--shard", f"{k}/{a.n}", "--report-out", str(report),
           *([] if whole else ["--guard-out", str(guard)]), *a.pytest_args]
    proc = subprocess.Popen(cmd, cwd=a.root, stdout=log, stderr=subprocess.STDOUT,
                            stdin=subprocess.DEVNULL, start_new_session=POSIX)
    return Share(k, proc, log, report, guard, time.monotonic())


class _Interrupted(KeyboardInterrupt):
    pass


class _interrupts_raised:
    """SIGTERM and SIGHUP raise KeyboardInterrupt as Ctrl-C does, while the shares run."""

    def __enter__(self):
        def raise_(signum, frame):
            raise _Interrupted(signum)
        sigs = [getattr(signal, name) for name in ("SIGTERM", "SIGHUP") if hasattr(signal, name)]
        self.old = {sig: signal.signal(sig, raise_) for sig in sigs}

    def __exit__(self, *exc):
        for sig, handler in self.old.items():
            signal.signal(sig, handler)


def _wait_and_print(shares: list[Share]) -> None:
    """Each share's output printed whole as it ends, the first to end first."""
    running = list(shares)
    while running:
        for s in list(running):
            code = s.proc.poll()
            if code is None:
                continue
            s.code, s.seconds = code, time.monotonic() - s.started
            running.remove(s)
            s.log.seek(0)
            sys.stdout.write(f"{'=' * 30} share {s.k}/{len(shares)}: exit {code} "
                             f"in {s.seconds:.1f} s {'=' * 30}\n")
            sys.stdout.write(s.log.read())
            sys.stdout.flush()
        if running:
            time.sleep(0.1)


def _stop(shares: list[Share]) -> None:
    """Ctrl-C to every share still running (its process group: the processes a test started
    too), as pytest takes a Ctrl-C; killed if still running after :data:`GRACE_S` s."""
    for s in shares:
        if s.proc.poll() is None:
            _signal_group(s.proc, signal.SIGINT)
    end = time.monotonic() + GRACE_S
    for s in shares:
        try:
            s.code = s.proc.wait(timeout=max(0.0, end - time.monotonic()))
        except subprocess.TimeoutExpired:
            _signal_group(s.proc, KILL)
            s.code = s.proc.wait()
        except KeyboardInterrupt:            # a second Ctrl-C: no more waiting
            _signal_group(s.proc, KILL)
            s.code = s.proc.wait()


def _signal_group(proc: subprocess.Popen, sig: int) -> None:
    """``sig`` to the share's process group (POSIX); elsewhere the share is ended."""
    try:
        if POSIX:
            os.killpg(proc.pid, sig)
        elif sig == signal.SIGINT:
            proc.terminate()
        else:
            proc.kill()
    except (ProcessLookupError, PermissionError):
        pass


def _read_json(path: Path) -> dict:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}


def _verdict(shares: list[Share], n: int, whole: bool, wall: float) -> int:
    """The lines per share, the failures' node ids, the guard, the combined line; the exit."""
    failed, failures, errors = False, [], set()
    total = {key: 0 for key, _ in SAID}
    for s in shares:
        out = s.outcome
        counts = out.get("counts", {})
        said = combined_words(counts) or "no test ran"
        if not out:
            said = "ended without its report (see its output above)"
        print(f"share {s.k}/{n}: exit {s.code} in {s.seconds:.1f} s: {said}")
        failed |= s.code not in (0, 5) or not out      # 5: a share with no test selected
        for key, _ in SAID:
            if key != "error":
                total[key] += counts.get(key, 0)
        failures += out.get("failed", [])
        errors |= set(out.get("errors", []))
    total["error"] = len(errors)
    for nodeid in sorted(failures):
        print(f"FAILED {nodeid}")
    for nodeid in sorted(errors):
        print(f"ERROR {nodeid}")
    failed |= bool(failures or errors)
    if not whole and not failed:
        failed |= not _guard_holds(shares)
    no_tests = all(s.code == 5 for s in shares)
    verdict = "no tests ran" if no_tests else "FAILED" if failed else "passed"
    print(f"{verdict}: {combined_words(total) or 'no tests'} in {wall:.1f} s wall "
          f"({n} shares)", flush=True)
    return 5 if no_tests else 1 if failed else 0


def combined_words(counts: dict) -> str:
    """``1 failed, 30 passed, 2 errors`` (pytest's words; zero counts left out)."""
    words = []
    for key, word in SAID:
        c = counts.get(key, 0)
        if c:
            words.append(f"{c} {word}{'s' if key == 'error' and c != 1 else ''}")
    return ", ".join(words)


def _guard_holds(shares: list[Share]) -> bool:
    every, imported = set(), set()
    for s in shares:
        d = _read_json(s.guard)
        every |= set(d.get("every", ()))
        imported |= set(d.get("imported", ()))
    missing = sorted(every - imported)
    if not every:
        print("the guard did not run (the whole tests/ tree was not collected)")
    elif missing:
        print("the quick loop imports no quick test of these modules:", *missing, sep="\n  ")
        return False
    else:
        print(f"the guard: each of the {len(every)} modules of src/flywheel imported "
              "by a quick test")
    return True


# -- the durations table ---------------------------------------------------------------------------

def read_table(path: Path) -> tuple[dict, dict]:
    """The table's files and heavy tests (tests/shards.py), empty without one."""
    try:
        table = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        return {}, {}
    return table["files"], table.get("tests", {})


def record(table: tuple[dict, dict], outcomes: list[dict], root: Path) -> tuple[dict, dict]:
    """The table with the entries of the files that ran replaced by this run's: each file's
    count and seconds of its quick tests and of its slow ones, the heavy tests (a call of
    tests/shards.py's HEAVY_S or more) apart with their own seconds; the entries of the files
    that did not run kept, but for files that no longer exist."""
    files, heavy = table
    ran: dict[str, dict[str, list]] = {}
    now_heavy: dict[str, float] = {}
    for out in outcomes:
        slow, big = set(out.get("slow", ())), set(out.get("heavy", ()))
        for nodeid, seconds in out.get("seconds", {}).items():
            path = nodeid.split("::", 1)[0]
            entry = ran.setdefault(path, {"quick": [0, 0.0], "slow": [0, 0.0]})
            if nodeid in big:
                now_heavy[nodeid] = seconds
                continue
            kind = entry["slow" if nodeid in slow else "quick"]
            kind[0] += 1
            kind[1] += seconds

    def kept(path):
        return path not in ran and (root / path).exists()

    return ({p: e for p, e in files.items() if kept(p)} | ran,
            {t: s for t, s in heavy.items() if kept(t.split("::", 1)[0])} | now_heavy)


def write_table(path: Path, table: tuple[dict, dict]) -> None:
    """A line per file and per heavy test, sorted, seconds to 0.01 s; written whole (a
    temporary renamed)."""
    files, heavy = table
    lines = []
    for p in sorted(files):
        e = {kind: [int(files[p][kind][0]), round(float(files[p][kind][1]), 2)]
             for kind in ("quick", "slow") if files[p].get(kind, (0, 0))[0]}
        lines.append(f"    {json.dumps(p, ensure_ascii=False)}: {json.dumps(e)}")
    tests = [f"    {json.dumps(t, ensure_ascii=False)}: {round(float(heavy[t]), 2)}"
             for t in sorted(heavy)]
    text = ('{\n  "about": "the split of --shard K/N (tests/shards.py): seconds (setup + call + '
            'teardown) per test file, its quick tests and its slow ones apart, and of each '
            'heavy test (its call HEAVY_S of tests/shards.py or longer: a unit of the split '
            'by itself, not counted in its file); written by python tools/pytest_shards.py '
            '--record",\n'
            '  "files": {\n' + ",\n".join(lines) + '\n  },\n'
            '  "tests": {\n' + ",\n".join(tests) + "\n  }\n}\n")
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


if __name__ == "__main__":
    sys.exit(main())
