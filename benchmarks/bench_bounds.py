"""Timings of issue 23's bounded work, by hand (never as timed tests): task2 graphs at their
limits (a harmonic series of 1000 terms, a piecewise-linear graph of 100 000 points), in-process
and as whole processes, and the two aggregate timings the tests used to assert (a fixed end
against a free end; the stiff start-ups by LSODA). The tests count the same work instead
(tests/test_bounds.py, tests/test_work_bounds.py, tests/elastic/test_aggregate_modes.py)."""
from __future__ import annotations

import math
import random
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))


def best(f, n=3) -> float:
    times = []
    for _ in range(n):
        t = time.process_time()
        f()
        times.append(time.process_time() - t)
    return min(times)


def task2_case(kind: str, n: int) -> str:
    rnd = random.Random(1)
    head = '[speed]\nmean_rpm = 150.0\n[flywheel]\nJ = 10.0\n[resistance]\nkind = "constant"\n' \
           'value = "balance"\n[driving]\n'
    if kind == "harmonic":
        a = [round(rnd.uniform(-50, 50), 3) for _ in range(n)]
        return head + f'kind = "harmonic"\na0 = 5000.0\na = {a}\n'
    pts = [[360.0 * i / (n - 1), round(1000 + 500 * math.sin(0.37 * i), 3)] for i in range(n)]
    pts[-1][0] = 360.0
    return head + f'kind = "points"\npoints = {pts}\n'


def main() -> None:
    from flywheel.cases.task2 import parse_task2_case, solve_case
    from flywheel.io.toml import read_toml

    with tempfile.TemporaryDirectory() as tmp:
        for kind, n in (("harmonic", 100), ("harmonic", 1000), ("points", 10_000),
                        ("points", 100_000)):
            path = Path(tmp) / f"{kind}{n}.toml"
            path.write_text(task2_case(kind, n), encoding="utf-8")
            case = parse_task2_case(read_toml(path), str(path))
            solve_t = best(lambda: solve_case(case, str(path)), 1)
            t = time.perf_counter()
            subprocess.run([sys.executable, "-m", "flywheel", "task2", "--case", str(path),
                            "--json"], check=True, stdout=subprocess.DEVNULL)
            print(f"task2 {kind} {n}: solve_case {solve_t:.2f} s CPU; whole process "
                  f"`task2 --case --json` {time.perf_counter() - t:.2f} s wall")

    from test_aggregate_modes import _chain_doc, model
    from flywheel.elastic.model import analyze
    for name, doc in (("free", _chain_doc(False, 1e8)), ("fixed", _chain_doc(True))):
        ch, drive = model(doc)
        print(f"aggregate analyze, {name} end: {best(lambda: analyze(ch, drive), 5) * 1e3:.1f} "
              "ms CPU (best of 5)")
    from test_work_bounds import _stiff_aggregate
    ch, drive = _stiff_aggregate(10.0)
    print(f"aggregate, stiff start-up by LSODA: {best(lambda: analyze(ch, drive), 1):.2f} s CPU")


if __name__ == "__main__":
    main()
