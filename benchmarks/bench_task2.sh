#!/usr/bin/env bash
# Whole-process time of `flywheel task2 --json` (issue 4: under 0.4 s), also with --delta (the
# J for δ comes from flywheel.dynamics.sizing, whose module loads numpy: only then) and of the
# Russian summary (rich's table on top).
# Run by hand or in CI from the repository root with the venv active:
#     bash benchmarks/bench_task2.sh [runs]
# Prints the machine (nproc, uname -m, python version), every run's wall time and the median.
set -euo pipefail
runs=${1:-10}
echo "machine: $(nproc) CPUs, $(uname -m), $(python --version 2>&1)"
for args in "task2 --json" "task2 --profile rectangle --json" \
            "task2 --case cases/task2_khurmi_16_12.toml --json" "task2 --delta 0.05 --json" \
            "task2 --lang ru"; do
  times=()
  flywheel $args > /dev/null   # warm the file cache
  for _ in $(seq "$runs"); do
    s=$(date +%s.%N)
    flywheel $args > /dev/null
    e=$(date +%s.%N)
    times+=("$(echo "$e - $s" | bc -l)")
  done
  median=$(printf '%s\n' "${times[@]}" | sort -n | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}')
  printf 'flywheel %-55s median %.3f s  (runs: %s)\n' "$args" "$median" "$(printf '%.3f ' "${times[@]}")"
done
