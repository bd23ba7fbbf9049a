#!/bin/sh
# Boolean operations on the glyph-outline pairs: ours and lib2geom (one executable) and the
# JavaScript peers (Skia PathOps, Paper.js), alternating round by round so that the native and
# the JavaScript figures share the machine's state. Prints each round's raw output; the
# figures to report are the medians over rounds of each benchmark's median.
#
#   tests/bench/peers/regions_rounds.sh ROUNDS build-lib2geom/bezier_lib2geom_bench build/tests/bezier_peer_shapes
set -eu
rounds=$1
lib2geom_bench=$2
shapes=$3
here=$(dirname "$0")
r=1
while [ "$r" -le "$rounds" ]; do
  echo "== round $r, load: $(cut -d' ' -f1-3 /proc/loadavg)"
  "$lib2geom_bench" --benchmark_filter='Regions_|Contains_' --benchmark_repetitions=3 \
    --benchmark_report_aggregates_only=true --benchmark_enable_random_interleaving=true 2>&1 | grep -E '_median|^--|^Benchmark'
  node "$here/peers_bench.mjs" "$shapes" booleans --rounds 3
  r=$((r + 1))
done
