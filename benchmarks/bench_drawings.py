"""What `--drawings` adds to a run (issue 25): the ЕСКД sheets of cases/compressor.toml written
in-process (best of 3, CPU and wall), and the whole `flywheel run` with and without
--drawings (plots on). Run by hand: python benchmarks/bench_drawings.py"""
from __future__ import annotations

import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "cases" / "compressor.toml"


def in_process() -> None:
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze

    case = load_case(CASE)
    results = analyze(case)
    t = time.process_time()
    import ezdxf  # noqa: F401 — its import counted apart

    print(f"import ezdxf: {time.process_time() - t:.2f} s CPU")
    from flywheel.render.drawings import write_drawings

    best = None
    for k in range(3):
        with tempfile.TemporaryDirectory() as tmp:
            c, w = time.process_time(), time.perf_counter()
            write_drawings(results, Path(tmp) / "drawings", case.document, lang="ru")
            got = (time.process_time() - c, time.perf_counter() - w)
        best = got if best is None or got[1] < best[1] else best
    print(f"write_drawings (2 sheets × PDF, SVG, DXF): {best[0]:.2f} s CPU, {best[1]:.2f} s wall")


def whole(extra: list[str]) -> float:
    with tempfile.TemporaryDirectory() as tmp:
        t = time.perf_counter()
        subprocess.run([sys.executable, "-m", "flywheel", "run", str(CASE), "--out",
                        str(Path(tmp) / "o"), *extra], check=True, capture_output=True)
        return time.perf_counter() - t


if __name__ == "__main__":
    in_process()
    for extra in ([], ["--drawings"]):
        print(f"flywheel run {' '.join(extra) or '(plots)'}: "
              f"best of 3 {min(whole(extra) for _ in range(3)):.2f} s")
