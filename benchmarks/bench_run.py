"""Speed and memory of `flywheel run` on the compressor (run by hand: `python benchmarks/bench_run.py`).

Prints the machine, in-process timings of the stages and of the whole computation at the
default grid, and whole-process wall time and peak memory of the CLI with and without plots.
Targets (issue 3): computation < 20 ms in-process; `run --no-plots --json` < 0.8 s;
with plots < 4 s; peak memory < 200 MB. Never run as a timed test.
"""
from __future__ import annotations

import os
import platform
import resource
import subprocess
import sys
import tempfile
import time
import timeit
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "cases" / "compressor.toml"


def machine() -> str:
    import numpy

    return (f"{platform.platform()}, {platform.machine()}, {os.cpu_count()} cores, "
            f"Python {platform.python_version()}, numpy {numpy.__version__}")


def best(stmt, number=20, repeat=5) -> float:
    return min(timeit.repeat(stmt, number=number, repeat=repeat)) / number


def in_process() -> None:
    import numpy as np

    from flywheel.case import load_case, to_mechanism
    from flywheel.kinematics import solve
    from flywheel.kinematics.deadcentres import dead_centres
    from flywheel.pipeline import analyze

    case = load_case(CASE)
    mech = to_mechanism(case)
    phi = np.linspace(0, 2 * np.pi, 3601)
    print(f"  load_case                      {best(lambda: load_case(CASE)) * 1e3:8.3f} ms")
    print(f"  kinematics, 3601 nodes         {best(lambda: solve(mech, phi)) * 1e3:8.3f} ms")
    print(f"  dead centres (2 sliders)       {best(lambda: [dead_centres(mech, s) for s in ('3', '5')]) * 1e3:8.3f} ms")
    print(f"  whole analyze(), default grid  {best(lambda: analyze(case)) * 1e3:8.3f} ms")


def whole_process(args: list[str]) -> tuple[float, float]:
    """Best wall time of 3 runs [s] and peak RSS of the child [MB]."""
    times = []
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(3):
            t0 = time.perf_counter()
            subprocess.run([sys.executable, "-m", "flywheel", "run", str(CASE), "--out", f"{tmp}/o", *args],
                           check=True, stdout=subprocess.DEVNULL)
            times.append(time.perf_counter() - t0)
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    return min(times), peak


if __name__ == "__main__":
    print("machine:", machine())
    print("in-process (best of 5×20):")
    in_process()
    t, mem = whole_process(["--no-plots", "--json"])
    print(f"whole process, run --no-plots --json: {t:.3f} s  (peak RSS so far {mem:.0f} MB)")
    t, mem = whole_process([])
    print(f"whole process, run with plots:        {t:.3f} s  (peak RSS so far {mem:.0f} MB)")
