"""Peak memory of `flywheel grade` on a class with one sheet at the size limit (issue 23, item
2): the largest process's peak RSS (``ru_maxrss`` of the one child) and its wall time.

    python benchmarks/bench_grade_memory.py                 # every case below
    python benchmarks/bench_grade_memory.py utf8-default    # some of them

Which flywheel is measured is PYTHONPATH's (``PYTHONPATH=src`` for the working tree). The
sheets are generated (seeded) in a temporary folder: a key of 40 variants × 6 answers, and
  utf8     one UTF-8 sheet just under 50 MB (≈ 380 000 rows: past the 200 000-row limit)
  cp1251   the same in Windows-1251 with Russian names (the charset-normalizer path)
  many     the UTF-8 rows in 20 sheets of 2.5 MB (the memory must not grow with the sheets)
  small    a class of 30 (what an interpreter with flywheel's imports takes anyway)
  wrongkey the UTF-8 sheet graded against another class's key (every row a problem)
each graded with the default report, `--json`, and `--summary --out --gradebook`.
"""
from __future__ import annotations

import json
import os
import platform
import random
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ANSWERS = ["M_C", "J_required", "omega_max", "delta_T", "D_flywheel", "A_cycle"]
LIMIT = 50_000_000
WRAP = ("import resource, subprocess, sys; p = subprocess.run(sys.argv[1:], stdout="
        "subprocess.DEVNULL); print(p.returncode, "
        "resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")


def make_class(d: Path) -> None:
    rng = random.Random(23)
    variants = {f"{i:02d}": {a: round(rng.uniform(1, 500), 6) for a in ANSWERS}
                for i in range(1, 41)}
    (d / "k.json").write_text(json.dumps({"answers": ANSWERS, "variants": variants}))
    ids = list(variants)
    head = "student,variant," + ",".join(ANSWERS) + "\n"

    def rows(names):
        size = len(head)
        i = 0
        while True:
            vid = rng.choice(ids)
            line = (f"{rng.choice(names)} {i},{vid}," + ",".join(
                repr(variants[vid][a] * rng.choice((1, 1, 1.2))) for a in ANSWERS) + "\n")
            size += len(line.encode("cp1251"))
            if size > LIMIT - 1000:
                return
            i += 1
            yield line

    latin = ["Ivanov", "Petrova", "Sidorov", "Kim", "Smirnova"]
    russian = ["Иванов Пётр", "Петрова Анна", "Сидоров Юрий", "Щукина Эльвира", "Смирнова Ольга"]
    lines = list(rows(latin))
    (d / "utf8.csv").write_text(head + "".join(lines), encoding="utf-8")
    (d / "cp1251.csv").write_text(head + "".join(rows(russian)), encoding="cp1251")
    many = d / "many"
    many.mkdir()
    per = len(lines) // 20 + 1
    for j in range(20):
        (many / f"s{j:02d}.csv").write_text(head + "".join(lines[j * per:(j + 1) * per]))
    (d / "small.csv").write_text(head + "".join(lines[:30]))
    other = {f"{i:02d}": {a: 1.0 for a in ANSWERS} for i in range(41, 81)}
    (d / "other.json").write_text(json.dumps({"answers": ANSWERS, "variants": other}))


def measure(d: Path, argv: list[str]) -> tuple[int, float, float]:
    """(exit code, peak RSS [MB], wall time [s]) of `python -m flywheel` + argv in ``d``."""
    t = time.perf_counter()
    out = subprocess.run([sys.executable, "-c", WRAP, sys.executable, "-m", "flywheel", *argv],
                         cwd=d, capture_output=True, text=True, check=True).stdout.split()
    return int(out[0]), int(out[1]) / 1024, time.perf_counter() - t


def main(only: list[str]) -> None:
    print(f"machine: {platform.machine()}, {os.cpu_count()} CPUs, load "
          f"{os.getloadavg()[0]:.1f}, Python {platform.python_version()}, "
          f"PYTHONPATH={os.environ.get('PYTHONPATH', '')}")
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        make_class(d)
        for sheet in ("utf8", "cp1251", "many", "small", "wrongkey"):
            given = {"many": "many", "wrongkey": "utf8.csv"}.get(sheet, f"{sheet}.csv")
            key = "other.json" if sheet == "wrongkey" else "k.json"
            size = sum(p.stat().st_size for p in (d / given).rglob("*")) if sheet == "many" \
                else (d / given).stat().st_size
            for how, extra in (("default", []), ("json", ["--json"]),
                               ("files", ["--summary", "--out", "o.csv", "--gradebook",
                                          "b.csv"])):
                name = f"{sheet}-{how}"
                if only and name not in only:
                    continue
                code, mb, s = measure(d, ["grade", key, given, *extra])
                print(f"{name:16s} {size / 1e6:5.1f} MB of sheets: exit {code}, peak RSS "
                      f"{mb:7.0f} MB, {s:6.1f} s", flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
