"""Speed of the kinematics engine on the compressor (issue 2; run by hand, never a timed test):

    python benchmarks/bench_kinematics.py [--points N] [--repeat R]

Times ``solve(to_mechanism(load_case("cases/compressor.toml")), φ grid of N points)`` in-process,
the best of many repeats (timeit), as the issue states it; also the solve alone on a mechanism
built once, and the case loading alone. Prints the machine and a sample of the result.
Target (issue 2): under 5 ms for N = 3600.
"""
from __future__ import annotations

import argparse
import os
import platform
import sys
import timeit
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "cases" / "compressor.toml"
TARGET_MS = 5.0


def cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "?"


def machine() -> str:
    try:
        nproc = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        nproc = os.cpu_count()
    return (f"{platform.platform()} ({platform.machine()}), {cpu_model()}; "
            f"nproc {nproc}; Python {platform.python_version()}; numpy {np.__version__}")


def best_ms(stmt, repeat: int) -> float:
    """Best time of one call [ms]: timeit picks a loop count for ~0.2 s, best of ``repeat``."""
    timer = timeit.Timer(stmt)
    number, _ = timer.autorange()
    return min(timer.repeat(repeat=repeat, number=number)) / number * 1e3


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=3600, help="φ grid size (default 3600)")
    ap.add_argument("--repeat", type=int, default=15, help="timeit repeats (default 15)")
    args = ap.parse_args()

    from flywheel.cases.run import load_case, to_mechanism
    from flywheel.linkage import solve

    phi = np.linspace(0.0, 2 * np.pi, args.points, endpoint=False)
    mech = to_mechanism(load_case(CASE))

    whole = best_ms(lambda: solve(to_mechanism(load_case(CASE)), phi), args.repeat)
    solve_only = best_ms(lambda: solve(mech, phi), args.repeat)
    load_only = best_ms(lambda: to_mechanism(load_case(CASE)), args.repeat)

    k = solve(mech, phi)
    i75 = int(round(75 / 360 * args.points)) if args.points % 360 == 0 else None
    print(f"machine: {machine()}")
    print(f"case: {CASE.relative_to(ROOT)}; grid: {args.points} points over 2π; "
          f"{len(k.points)} points, {len(k.links)} links")
    print(f"load + to_mechanism + solve: {whole:8.3f} ms  (best of {args.repeat}; target < {TARGET_MS:g} ms)")
    print(f"  solve alone:               {solve_only:8.3f} ms  ({solve_only / args.points * 1e6:.0f} ns per point)")
    print(f"  load + to_mechanism alone: {load_only:8.3f} ms")
    if i75 is not None:
        print(f"result at φ = 75°: |v_qB| = {np.linalg.norm(k.points['B'].v_q[i75]):.6f} m, "
              f"ω_q2 = {k.links['2'].omega_q[i75]:.6f}, ε_q2 = {k.links['2'].eps_q[i75]:.6f} "
              f"(seed 000: 0.103, 0.067, −0.248)")
    ok = whole < TARGET_MS
    print("target met" if ok else "TARGET MISSED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
