"""What `--report pdf` and `--report docx` add to a Russian run with plots (issue 28's speed
limit: at most 1 s each on 2 cores). Run by hand, never as a test:

    python benchmarks/bench_reports.py [CASE] [ROUNDS]

Whole processes (`python -m flywheel run CASE --lang ru --report md [--report pdf|docx]`, the
figures drawn), the three variants run in a rotating order in each round so that the machine's
load falls on all alike; prints the machine, each variant's median and the median of the paired
differences (the variant minus the base of the same round), with the spread of the pairs, for
the wall time and for the CPU time (user + system of the process and its plot workers: the
better measure on a loaded machine, where the wall time mostly says how busy the others were).
"""
from __future__ import annotations

import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CASE = Path(sys.argv[1]).resolve() if len(sys.argv) > 1 else ROOT / "cases" / "compressor.toml"
ROUNDS = int(sys.argv[2]) if len(sys.argv) > 2 else 7
VARIANTS = {"base": ["--report", "md"], "pdf": ["--report", "md", "--report", "pdf"],
            "docx": ["--report", "md", "--report", "docx"]}


def once(args: list[str], out: Path) -> tuple[float, float]:
    """(wall [s], CPU [s]: user + system of the process and its plot workers)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    subprocess.run([sys.executable, "-m", "flywheel", "run", str(CASE), "--lang", "ru",
                    "--out", str(out), *args], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> None:
    print(f"{platform.platform()}, {os.cpu_count()} cores, Python {platform.python_version()}, "
          f"load average at start {os.getloadavg()[0]:.1f}")
    times: dict[str, list[tuple[float, float]]] = {k: [] for k in VARIANTS}
    names = list(VARIANTS)
    with tempfile.TemporaryDirectory() as tmp:
        once(VARIANTS["base"], Path(tmp) / "warm")         # the file cache warm
        for r in range(ROUNDS):
            order = names[r % 3:] + names[:r % 3]
            for k in order:
                times[k].append(once(VARIANTS[k], Path(tmp) / f"{k}{r}"))
    print(f"load average at end {os.getloadavg()[0]:.1f}; {ROUNDS} rounds")
    for j, what in enumerate(("wall", "CPU")):
        for k in names:
            xs = [t[j] for t in times[k]]
            print(f"  {what:4s} {k:5s} median {statistics.median(xs):6.2f} s  "
                  f"(min {min(xs):.2f}, max {max(xs):.2f})")
        for k in ("pdf", "docx"):
            d = sorted(a[j] - b[j] for a, b in zip(times[k], times["base"]))
            print(f"  {what:4s} {k} adds: median {statistics.median(d):+.2f} s  "
                  f"(pairs {d[0]:+.2f} … {d[-1]:+.2f})")


if __name__ == "__main__":
    main()
