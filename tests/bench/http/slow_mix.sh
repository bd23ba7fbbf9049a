#!/usr/bin/env bash
# Head-of-line blocking check: wrk /evaluate at 64 connections for SECONDS while one more
# client sends a slow request back to back (the 400-crossing pair of degree-20 curves,
# (t, T20(2t-1)) against (T20(2s-1), s), about 41 ms of CPU in api::handle: worst_case_bench
# "intersections/hybrid/wave_grid_400"), and a probe asks /healthz every 100 ms. A server
# that runs requests on its I/O threads shows the slow request in every other client's p99.
#   tests/bench/http/slow_mix.sh [service-binary] [seconds]
# The binary must take --port 0 --log-level warn and print "listening on http://HOST:PORT"
# (bezier-service does).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
binary=${1:-$here/../../../build/service/bezier-service}
seconds=${2:-10}
command -v wrk >/dev/null || { echo "wrk is needed: apt-get install wrk" >&2; exit 2; }

work=$(mktemp -d)
"$binary" --port 0 --log-level warn >"$work/log" 2>&1 &
pid=$!
cleanup() { rm -f "$work/flag"; kill $pid 2>/dev/null || true; wait 2>/dev/null || true; rm -rf "$work"; }
trap cleanup EXIT
for _ in $(seq 100); do grep -q "listening on" "$work/log" && break; sleep 0.05; done
url=$(grep -o 'http://[0-9.]*:[0-9]*' "$work/log" | head -1)
cat >"$work/slow.json" <<'JSON'
{"curves":[{"points":[[0.0,1.0],[0.05,-39.0],[0.1,481.0],[0.15,-3367.0],[0.2,15873.0],[0.25,-54673.666666666664],[0.3,144139.66666666666],[0.35,-299367.0],[0.4,498945.0],[0.45,-675043.2352941176],[0.5,746100.4179566563],[0.55,-675043.2352941176],[0.6,498945.0],[0.65,-299367.0],[0.7,144139.66666666666],[0.75,-54673.666666666664],[0.8,15873.0],[0.85,-3367.0],[0.9,481.0],[0.95,-39.0],[1.0,1.0]]},{"points":[[1.0,0.0],[-39.0,0.05],[481.0,0.1],[-3367.0,0.15],[15873.0,0.2],[-54673.666666666664,0.25],[144139.66666666666,0.3],[-299367.0,0.35],[498945.0,0.4],[-675043.2352941176,0.45],[746100.4179566563,0.5],[-675043.2352941176,0.55],[498945.0,0.6],[-299367.0,0.65],[144139.66666666666,0.7],[-54673.666666666664,0.75],[15873.0,0.8],[-3367.0,0.85],[481.0,0.9],[-39.0,0.95],[1.0,1.0]]}],"method":"hybrid"}
JSON
touch "$work/flag"
( slow=0; while [ -e "$work/flag" ]; do
    curl -s -o /dev/null -X POST -H 'Content-Type: application/json' --data-binary @"$work/slow.json" "$url/intersections"
    slow=$((slow + 1))
  done; echo "$slow" >"$work/slow.count" ) &
slow_pid=$!
( while [ -e "$work/flag" ]; do
    curl -s -o /dev/null -m 2 -w '%{time_total}\n' "$url/healthz" || echo 2
    sleep 0.1
  done >"$work/probe" ) &
probe_pid=$!
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
wrk -t2 -c64 -d"${seconds}s" --latency -s "$here/evaluate.lua" "$url/evaluate" | grep -E "Requests/sec|Non-2xx|Socket errors|50%|99%"
rm -f "$work/flag"
wait $slow_pid $probe_pid
echo "slow requests answered: $(cat "$work/slow.count")"
echo "probe: slowest /healthz answer $(sort -g "$work/probe" | tail -1 | awk '{ print $1 * 1000 }') ms over $(wc -l <"$work/probe") probes"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
