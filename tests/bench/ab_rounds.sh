#!/bin/bash
# Alternating A/B timing for a noisy machine: per round, every benchmark matching FILTER
# runs in A's binary, then in B's; the report gives, per benchmark, the minimum and median
# of each side's time per pair (its time_per_pair counter, else its CPU time per
# iteration) and the ratio of the minima and the median of the per-round ratios.
#
#   tests/bench/ab_rounds.sh 5 IntersectCubicPairs A/tests/bezier_bench B/tests/bezier_bench
set -euo pipefail
if [ $# -ne 4 ]; then
  echo "usage: $0 ROUNDS FILTER A_BENCH B_BENCH" >&2
  exit 2
fi
rounds=$1 filter=$2 a=$3 b=$4
for _ in $(seq "$rounds"); do
  for side in A B; do
    bin=$a
    [ "$side" = B ] && bin=$b
    "$bin" --benchmark_filter="$filter" --benchmark_min_time=0.2 2>/dev/null | grep '^BM' |
      while read -r name _ _ cpu unit rest; do
        time=$(grep -o 'time_per_pair=[0-9.]*[unm]s' <<<"$rest" | sed 's/time_per_pair=//' || true)
        [ -n "$time" ] || time=$cpu$unit
        steps=$(grep -o 'steps_per_pair=[0-9.]*' <<<"$rest" | sed 's/steps_per_pair=//' || true)
        echo "$side $name $time ${steps:--}"
      done
  done
done | python3 -c '
import statistics, sys
times, steps = {}, {}
for line in sys.stdin:
    side, name, t, s = line.split()
    scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3}[t[-2:]]
    us = float(t[:-2]) * scale
    times.setdefault(name, {"A": [], "B": []})[side].append(us)
    steps.setdefault(name, {})[side] = s
for name, d in times.items():
    a, b = d["A"], d["B"]
    per_round = statistics.median(y / x for x, y in zip(a, b))
    steps_a, steps_b = steps[name].get("A"), steps[name].get("B")
    print(f"{name:42} A min {min(a):.3f} med {statistics.median(a):.3f} | "
          f"B min {min(b):.3f} med {statistics.median(b):.3f} | "
          f"B/A min {min(b) / min(a):.3f} rounds {per_round:.3f} | "
          f"steps {steps_a} -> {steps_b}")
'
