"""The quick loop on every core: ``pytest -m "not slow"`` in N processes at once, each a share
of the test files (tests/conftest.py ``--shard K/N``: a file's tests stay together), and the
quick loop's guard — every module of src/flywheel imported by a quick test — checked on the
union of the shares' imports. Only pytest: no plugin beyond the project's own conftest.

    python tools/pytest_shards.py              # N = the machine's cores, -m "not slow"
    python tools/pytest_shards.py -n 3 -- -x   # pytest's own arguments after --
    python tools/pytest_shards.py --all        # the whole suite (slow tests too), N shares

Each share's output is printed whole when it ends (in order, not interleaved), then one line
per share and the verdict. Exit 0 when every share passed and (for the quick loop) the guard
holds; else 1 (2 for a usage error).
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("-n", type=int, default=os.cpu_count() or 2, help="shares run at once")
    ap.add_argument("--all", action="store_true", help="the whole suite, slow tests too")
    ap.add_argument("pytest_args", nargs="*", help="after --: passed to each pytest")
    a = ap.parse_args(argv)
    if not 1 <= a.n <= 64:
        ap.error(f"-n {a.n}: allowed 1 … 64")
    marks = [] if a.all else ["-m", "not slow"]
    with tempfile.TemporaryDirectory(prefix="flywheel-shards-") as tmp:
        runs, t0 = [], time.monotonic()
        for k in range(1, a.n + 1):
            log = open(Path(tmp) / f"share{k}.log", "w+", encoding="utf-8")
            guard = Path(tmp) / f"guard{k}.json"
            cmd = [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", *marks,
                   "--shard", f"{k}/{a.n}", "--guard-out", str(guard), *a.pytest_args]
            runs.append((k, subprocess.Popen(cmd, cwd=ROOT, stdout=log, stderr=subprocess.STDOUT),
                         log, guard))
        lines, failed = [], False
        for k, proc, log, guard in runs:
            code = proc.wait()
            log.seek(0)
            text = log.read()
            sys.stdout.write(text)
            last = [ln for ln in text.splitlines() if ln.strip()][-1:] or ["(no output)"]
            lines.append(f"share {k}/{a.n}: exit {code}: {last[0].strip(' =')}")
            failed |= code not in (0, 5)             # 5: a share with no test selected
        print(*lines, sep="\n")
        if not a.all and not failed:
            every, imported = set(), set()
            for *_, guard in runs:
                if guard.exists():
                    d = json.loads(guard.read_text(encoding="utf-8"))
                    every |= set(d["every"])
                    imported |= set(d["imported"])
            missing = sorted(every - imported)
            if not every:
                print("the guard did not run (the whole tests/ tree was not collected)")
            elif missing:
                print("the quick loop imports no quick test of these modules:", *missing,
                      sep="\n  ")
                failed = True
            else:
                print(f"the guard: each of the {len(every)} modules of src/flywheel imported "
                      "by a quick test")
        print(f"{'FAILED' if failed else 'passed'} in {time.monotonic() - t0:.1f} s wall "
              f"({a.n} shares)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
