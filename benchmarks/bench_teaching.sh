#!/usr/bin/env bash
# A class of 1000: `flywheel variants` of the compressor (1000 variants, 1440-interval grids,
# the chain of issue 27 in the key) and `flywheel grade` of a sheet with every variant
# answered (issue 16: both in ≤ 20 s), then (issue 27) a sheet where every student has one
# early answer wrong — half of them ΔT_нб off by 30 % with the later answers computed from it
# (error carried forward), half J_I from δ/2 (a classic mistake to name) — graded with
# --carried-forward 0.5, the gradebook with its diagnosis column (aim: all in < 30 s).
# Then the same with tables graded cell by cell (issue 27, step 4).
# Run by hand from the repository root with the venv active:  bash benchmarks/bench_teaching.sh
# (PYTHONPATH=src to time a worktree's code: python -m flywheel is used, not the installed one)
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "machine: $(nproc) CPUs, $(uname -m), $(python --version 2>&1)"
s=$(date +%s.%N)
python -m flywheel -q variants cases/variants_compressor.toml --count 1000 --seed 1 --out "$tmp/v"
m=$(date +%s.%N)
python - "$tmp" <<'PY'
import csv, json, math, sys, tomllib
from pathlib import Path
d = Path(sys.argv[1])
key = json.loads((d / "v" / "answers.json").read_text())
rows = [["student", "variant", *key["answers"]]]
wrong = [["student", "variant", *key["answers"]]]
for i, (vid, ans) in enumerate(key["variants"].items()):
    rows.append([f"student {i}", vid, *(repr(ans[a]) for a in key["answers"])])
    data = tomllib.loads((d / "v" / f"variant_{vid}.toml").read_text())
    m = data["machine"]
    w = 2 * math.pi * m["speed_rps"]
    x = dict(ans)
    if i % 2:
        x["delta_T_max"] *= 1.3
        x["J_required"] = x["delta_T_max"] / (w ** 2 * m["delta"])
        x["J_flywheel"] = x["J_required"] - sum(m["first_group"].values())
        x["flywheel_disk.D"] = (32 * x["J_flywheel"] / (math.pi * 7800 * 0.2)) ** 0.2
    else:
        x["J_required"] *= 2
    wrong.append([f"student {i}", vid, *(repr(x[a]) for a in key["answers"])])
for name, r in (("sheet.csv", rows), ("wrong.csv", wrong)):
    with open(d / name, "w", newline="", encoding="utf-8") as f:
        csv.writer(f).writerows(r)
PY
g=$(date +%s.%N)
python -m flywheel grade "$tmp/v/answers.json" "$tmp/sheet.csv" --summary --gradebook "$tmp/book.csv" > /dev/null
e=$(date +%s.%N)
python -m flywheel grade "$tmp/v/answers.json" "$tmp/wrong.csv" --summary --carried-forward 0.5 \
  --gradebook "$tmp/book2.csv" > /dev/null
x=$(date +%s.%N)
python - "$tmp/book2.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], encoding="utf-8")))
carried = sum(int(r["carried forward"]) for r in rows)
named = sum(bool(r["diagnosis"]) for r in rows)
print(f"graded {len(rows)}: {carried} answers carried forward, {named} students with a mistake named")
PY
printf 'variants 1000: %.2f s; grade 1000 right (summary + gradebook): %.2f s; grade 1000 with one wrong early answer each (carried forward, diagnosis): %.2f s; made and graded with carried-forward and diagnosis: %.2f s\n' \
  "$(echo "$m - $s" | bc -l)" "$(echo "$e - $g" | bc -l)" "$(echo "$x - $e" | bc -l)" "$(echo "$m - $s + $x - $e" | bc -l)"
ls -la "$tmp/v/answers.json" | awk '{print "answers.json: " $5 " bytes"}'
# Tables cell by cell (issue 27, step 4): the same template asking the analogues, ΔT_I and the
# reactions (134 answers a variant: 5 + 72 + 36 + 21 cells), 1000 variants made, then graded
# from a sheet where every other student has one cell off
sed 's/^answers = \(.*\)$/answers = \1\ntables = ["analogues", "delta_T", "reactions"]/' \
  cases/variants_compressor.toml > "$tmp/with_tables.toml"
t0=$(date +%s.%N)
python -m flywheel -q variants "$tmp/with_tables.toml" --count 1000 --seed 1 --out "$tmp/t"
t1=$(date +%s.%N)
python - "$tmp" <<'PY'
import csv, json, sys
from pathlib import Path
d = Path(sys.argv[1])
key = json.loads((d / "t" / "answers.json").read_text())
names = list(next(iter(key["variants"].values())))
rows = [["student", "variant", *names]]
for i, (vid, ans) in enumerate(key["variants"].items()):
    x = dict(ans)
    if i % 2:
        x["analogues.3.vq_B"] *= 1.1
    rows.append([f"student {i}", vid, *(repr(x[a]) for a in names)])
with open(d / "cells.csv", "w", newline="", encoding="utf-8") as f:
    csv.writer(f).writerows(rows)
PY
t2=$(date +%s.%N)
python -m flywheel grade "$tmp/t/answers.json" "$tmp/cells.csv" --summary --carried-forward 0.5 \
  --gradebook "$tmp/book3.csv" > /dev/null
t3=$(date +%s.%N)
python - "$tmp/book3.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], encoding="utf-8")))
print(f"graded {len(rows)} with tables: {sum('rows 3' in r['diagnosis'] or 'row 3' in r['diagnosis'] for r in rows)} with a cell off named")
PY
printf 'with tables (134 answers a variant): variants 1000: %.2f s; grade 1000 (cells, carried forward, diagnosis, gradebook): %.2f s; made and graded: %.2f s\n' \
  "$(echo "$t1 - $t0" | bc -l)" "$(echo "$t3 - $t2" | bc -l)" "$(echo "$t1 - $t0 + $t3 - $t2" | bc -l)"
ls -la "$tmp/t/answers.json" | awk '{print "answers.json with tables: " $5 " bytes"}'
