"""Whole-process time of `flywheel run CASE --no-plots` for every bundled run case, two source
trees side by side, paired (run by hand, never as a timed test):

    git worktree add --detach /tmp/base 28c5a27
    python benchmarks/bench_run_paired.py /tmp/base/src src [--repeat 7]

Each tree runs its own copy of a case (cases/ beside its src: a case's title or another key may
be written differently at the two commits); a case only the new tree has is timed there alone.
Each repetition runs every case once with each tree, the order of the two trees alternating from
one repetition to the next (a drift of the machine's load falls on both alike); each process
writes into a fresh scratch folder, its output thrown away. Both trees are byte-compiled first
(this environment sets PYTHONDONTWRITEBYTECODE, so an uncompiled tree would pay ≈ 0.15 s of
compiling on every run). Prints the machine, then per case the median wall time and the median
CPU time (user + system, the process's own accounting: far steadier than wall time on a busy
machine) of each tree and the median of the per-repetition ratios new/old; a case the old tree cannot run (a case
added since, or a key it does not know) is listed as such. Exit 0 always: it only measures.
"""
from __future__ import annotations

import argparse
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path



def machine() -> str:
    import numpy

    cpu = "?"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    load = os.getloadavg() if hasattr(os, "getloadavg") else ("?",)
    return (f"{platform.platform()}, {cpu}, {os.cpu_count()} cores, Python "
            f"{platform.python_version()}, numpy {numpy.__version__}; load average at the start "
            f"{' '.join(f'{x:.2f}' for x in load)}")


def run_cases(src: Path) -> list[str]:
    """The names of the tree's bundled cases that are `run` cases (by its own kind_of)."""
    sys.path.insert(0, str(src))
    from flywheel.cases import kind_of

    out = []
    for path in sorted((src.parent / "cases").glob("*.toml")):
        with path.open("rb") as f:
            if kind_of(tomllib.load(f)) == "run":
                out.append(path.name)
    return out


def one(src: Path, name: str) -> tuple[float, float, int] | None:
    """Wall time [s], CPU time (user + system of the process and its children) [s] and exit
    code of one whole `python -m flywheel run CASE --no-plots` of the tree's own case ``name``;
    None if the tree has no such case."""
    case = src.parent / "cases" / name
    if not case.exists():
        return None
    env = dict(os.environ, PYTHONPATH=str(src))
    with tempfile.TemporaryDirectory(prefix="bench-run-") as tmp:
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        p = subprocess.run([sys.executable, "-m", "flywheel", "run", str(case), "--no-plots",
                            "--out", str(Path(tmp) / "out")], env=env, cwd=tmp,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        wall = time.perf_counter() - t0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        return wall, cpu, p.returncode


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("old", type=Path, help="the old tree's src folder")
    ap.add_argument("new", type=Path, help="the new tree's src folder")
    ap.add_argument("--repeat", type=int, default=7)
    a = ap.parse_args()
    old, new = a.old.resolve(), a.new.resolve()
    for src in (old, new):
        subprocess.run([sys.executable, "-m", "compileall", "-q", str(src)], check=True)
        where = subprocess.run([sys.executable, "-c", "import flywheel; print(flywheel.__file__)"],
                               env=dict(os.environ, PYTHONPATH=str(src)), capture_output=True,
                               text=True).stdout.strip()
        if not where.startswith(str(src)):
            sys.exit(f"PYTHONPATH={src} imports flywheel from {where}, not from the tree")
    cases = run_cases(new)
    print(machine())
    print(f"old {old}\nnew {new}\n{a.repeat} paired repetitions, `run CASE --no-plots`\n")
    times = {c: {"old": [], "new": []} for c in cases}
    cpus = {c: {"old": [], "new": []} for c in cases}
    failed = {c: set() for c in cases}
    for r in range(a.repeat):
        for c in cases:
            order = (("old", old), ("new", new)) if r % 2 == 0 else (("new", new), ("old", old))
            for side, src in order:
                got = one(src, c)
                if got is None:
                    failed[c].add(f"no {side} case")
                    continue
                wall, cpu, rc = got
                if rc == 0:
                    times[c][side].append(wall)
                    cpus[c][side].append(cpu)
                else:
                    failed[c].add(f"{side} exit {rc}")
    print(f"{'case':30s} {'wall old':>9s} {'wall new':>9s} {'paired':>7s}   "
          f"{'cpu old':>8s} {'cpu new':>8s} {'paired':>7s}")
    ratios, cpu_ratios = [], []
    for c in cases:
        o, n = times[c]["old"], times[c]["new"]
        if failed[c]:
            med_n = f"{statistics.median(n):9.3f}" if n else f"{'—':>9s}"
            print(f"{c:30s} {'—':>9s} {med_n} ({', '.join(sorted(failed[c]))})")
            continue
        co, cn = cpus[c]["old"], cpus[c]["new"]
        paired = statistics.median(x / y for x, y in zip(n, o))
        paired_cpu = statistics.median(x / y for x, y in zip(cn, co))
        ratios.append(paired)
        cpu_ratios.append(paired_cpu)
        print(f"{c:30s} {statistics.median(o):9.3f} {statistics.median(n):9.3f} {paired:7.3f}   "
              f"{statistics.median(co):8.3f} {statistics.median(cn):8.3f} {paired_cpu:7.3f}")
    if ratios:
        print(f"\nmedian over the cases of the paired ratio new/old: wall "
              f"{statistics.median(ratios):.3f} (largest {max(ratios):.3f}), CPU "
              f"{statistics.median(cpu_ratios):.3f} (largest {max(cpu_ratios):.3f})")
    print(f"load average at the end {' '.join(f'{x:.2f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
