"""CPU seconds per figure of `flywheel run`, build and save apart (issue 26; run by hand, never
as a timed test):

    python benchmarks/bench_figures.py                       # compressor and engine_inline4
    python benchmarks/bench_figures.py cases/press.toml      # another case
    python benchmarks/bench_figures.py --profile 12          # and the top 12 of savefig's profile

Each figure is built and saved in this one process, in the fixed style the workers use; the
time is the process's CPU time (``time.process_time``) around the build (``figure_*``, its
layout included) and around the save (``savefig`` to PNG at the default dpi, into memory), the
best of ``--repeat`` rounds (default 3): CPU time is much less disturbed than wall time by the
other work of a shared machine. The first figure of a process also pays matplotlib's first
font and mathtext loading: a warm-up round draws every figure once before measuring. That
first round is what a plot worker of `run` pays (each figure drawn once, in a fresh process,
after ``figure.prepare()`` — the import the first worker makes before forking the second — not
counted): its total is printed too ("first round").
"""
from __future__ import annotations

import argparse
import cProfile
import io
import os
import platform
import pstats
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CASES = [ROOT / "cases" / "compressor.toml", ROOT / "cases" / "engine_inline4.toml"]


def machine() -> str:
    import matplotlib
    import numpy

    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    return (f"{platform.platform()}, {os.cpu_count()} cores, load {load:.1f}, Python "
            f"{platform.python_version()}, numpy {numpy.__version__}, matplotlib "
            f"{matplotlib.__version__}")


def measure(case: Path, repeat: int, profile: int) -> None:
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render import figure as fg
    from flywheel.render.plots import _release, all_figures

    results = analyze(load_case(case))
    specs = all_figures(results, "en")
    fg.prepare()                                     # as a worker: matplotlib imported
    rows: dict[str, list[float]] = {name: [1e9, 1e9] for name, _ in specs}
    first = [0.0, 0.0]                               # round 0: build, save
    with fg.style():
        for rnd in range(repeat + 1):                # round 0: the warm-up
            for name, build in specs:
                t0 = time.process_time()
                fig = build()
                t1 = time.process_time()
                fg.save(fig, io.BytesIO(), "png")
                t2 = time.process_time()
                _release(fig)
                if rnd:
                    rows[name][0] = min(rows[name][0], t1 - t0)
                    rows[name][1] = min(rows[name][1], t2 - t1)
                else:
                    first[0] += t1 - t0
                    first[1] += t2 - t1
        print(f"\n{case.name}: {len(specs)} figures, CPU seconds, best of {repeat}")
        print(f"  {'figure':34s} {'build':>7s} {'save':>7s} {'total':>7s}")
        tb = ts = 0.0
        for name, (b, s) in sorted(rows.items(), key=lambda kv: -sum(kv[1])):
            print(f"  {name:34s} {b:7.3f} {s:7.3f} {b + s:7.3f}")
            tb, ts = tb + b, ts + s
        print(f"  {'all':34s} {tb:7.3f} {ts:7.3f} {tb + ts:7.3f}")
        print(f"  {'first round (a worker, cold)':34s} {first[0]:7.3f} {first[1]:7.3f} "
              f"{sum(first):7.3f}")
        if profile:
            for name, build in specs:
                fig = build()
                prof = cProfile.Profile()
                prof.enable()
                fg.save(fig, io.BytesIO(), "png")
                prof.disable()
                _release(fig)
                out = io.StringIO()
                pstats.Stats(prof, stream=out).sort_stats("tottime").print_stats(profile)
                print(f"\n--- savefig of {name}: top {profile} by own time")
                print("\n".join(ln for ln in out.getvalue().splitlines()
                                if ln.strip() and not ln.startswith(("   Ordered", "   List"))))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("cases", nargs="*", type=Path, default=CASES)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--profile", type=int, default=0, metavar="N",
                    help="also profile each figure's savefig: the top N functions")
    a = ap.parse_args()
    print(machine())
    for c in a.cases:
        measure(c.resolve(), a.repeat, a.profile)
    sys.stdout.flush()


if __name__ == "__main__":
    main()
