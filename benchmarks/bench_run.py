"""Speed and memory of `flywheel run` on the compressor (run by hand: `python benchmarks/bench_run.py`;
another case as the argument: `python benchmarks/bench_run.py cases/engine_inline4.toml`).

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
CASE = Path(sys.argv[1]).resolve() if len(sys.argv) > 1 else ROOT / "cases" / "compressor.toml"


def machine() -> str:
    import numpy

    return (f"{platform.platform()}, {platform.machine()}, {os.cpu_count()} cores, "
            f"Python {platform.python_version()}, numpy {numpy.__version__}")


def best(stmt, number=20, repeat=5) -> float:
    return min(timeit.repeat(stmt, number=number, repeat=repeat)) / number


def in_process() -> None:
    import numpy as np

    from flywheel.cases.run import load_case, to_mechanism
    from flywheel.linkage import solve
    from flywheel.linkage.deadcentres import dead_centres
    from flywheel.dynamics.pipeline import analyze

    case = load_case(CASE)
    mech = to_mechanism(case)
    phi = np.linspace(0, case.machine.cycle, 3601)
    sliders = [d.slider for d in mech.dyads if hasattr(d, "guide")]
    print(f"  load_case                      {best(lambda: load_case(CASE)) * 1e3:8.3f} ms")
    print(f"  kinematics, 3601 nodes         {best(lambda: solve(mech, phi)) * 1e3:8.3f} ms")
    print(f"  dead centres ({len(sliders)} sliders)       {best(lambda: [dead_centres(mech, s) for s in sliders]) * 1e3:8.3f} ms")
    print(f"  whole analyze(), default grid  {best(lambda: analyze(case)) * 1e3:8.3f} ms")


def _tree(pid: int) -> list[int]:
    """pid and all its descendants (Linux /proc)."""
    out, todo = [], [pid]
    while todo:
        p = todo.pop()
        out.append(p)
        try:
            for task in os.listdir(f"/proc/{p}/task"):
                with open(f"/proc/{p}/task/{task}/children") as f:
                    todo += [int(c) for c in f.read().split()]
        except OSError:
            pass
    return out


def _pss_mb(pids: list[int]) -> float:
    """Summed proportional set size [MB]: shared pages counted once across forked workers."""
    total = 0
    for p in pids:
        try:
            with open(f"/proc/{p}/smaps_rollup") as f:
                total += sum(int(line.split()[1]) for line in f if line.startswith("Pss:"))
        except OSError:
            pass
    return total / 1024


def whole_process(args: list[str]) -> tuple[float, float, float]:
    """Best wall time of 3 runs [s], the largest single process's peak RSS [MB], and the peak of
    the whole process tree's summed PSS [MB] (the plot workers are forked), sampled every 20 ms
    in a 4th run so that the sampling does not slow the timed ones."""
    cmd = [sys.executable, "-m", "flywheel", "run", str(CASE), *args]
    times, pss = [], 0.0
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(3):
            t0 = time.perf_counter()
            subprocess.run(cmd + ["--out", f"{tmp}/o"], check=True, stdout=subprocess.DEVNULL)
            times.append(time.perf_counter() - t0)
        proc = subprocess.Popen(cmd + ["--out", f"{tmp}/o"], stdout=subprocess.DEVNULL)
        while proc.poll() is None:
            pss = max(pss, _pss_mb(_tree(proc.pid)))
            time.sleep(0.02)
        if proc.returncode != 0:
            raise SystemExit(f"flywheel run failed ({proc.returncode})")
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    return min(times), peak, pss


if __name__ == "__main__":
    print("machine:", machine())
    print("in-process (best of 5×20):")
    in_process()
    t, mem, pss = whole_process(["--no-plots", "--json"])
    print(f"whole process, run --no-plots --json: {t:.3f} s  (largest process {mem:.0f} MB RSS, "
          f"tree {pss:.0f} MB PSS)")
    t, mem, pss = whole_process([])
    print(f"whole process, run with plots:        {t:.3f} s  (largest process {mem:.0f} MB RSS, "
          f"tree {pss:.0f} MB PSS)")
