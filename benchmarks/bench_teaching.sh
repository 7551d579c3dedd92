#!/usr/bin/env bash
# A class of 1000: `flywheel variants` of the compressor (1000 variants, 1440-interval grids)
# and `flywheel grade` of a sheet with every variant answered (issue 16: both in ≤ 20 s).
# Run by hand from the repository root with the venv active:  bash benchmarks/bench_teaching.sh
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "machine: $(nproc) CPUs, $(uname -m), $(python --version 2>&1)"
s=$(date +%s.%N)
flywheel -q variants cases/variants_compressor.toml --count 1000 --seed 1 --out "$tmp/v"
m=$(date +%s.%N)
python - "$tmp" <<'PY'
import csv, json, sys
from pathlib import Path
d = Path(sys.argv[1])
key = json.loads((d / "v" / "answers.json").read_text())
rows = [["student", "variant", *key["answers"]]]
for i, (vid, ans) in enumerate(key["variants"].items()):
    rows.append([f"student {i}", vid, *(repr(ans[a]) for a in key["answers"])])
with open(d / "sheet.csv", "w", newline="", encoding="utf-8") as f:
    csv.writer(f).writerows(rows)
PY
g=$(date +%s.%N)
flywheel grade "$tmp/v/answers.json" "$tmp/sheet.csv" --summary --gradebook "$tmp/book.csv" > /dev/null
e=$(date +%s.%N)
printf 'variants 1000: %.2f s; grade 1000 (summary + gradebook): %.2f s; both: %.2f s\n' \
  "$(echo "$m - $s" | bc -l)" "$(echo "$e - $g" | bc -l)" "$(echo "$m - $s + $e - $g" | bc -l)"
