#!/usr/bin/env bash
# Two builds of bezier-service side by side: alternating wrk runs (-t2 -c64, /evaluate,
# one cubic at one t) against each freshly started binary at --log-level warn and
# --io-threads 0. Per run: req/s, p99, the service's CPU per request (utime + stime
# from /proc/PID/stat over the run), and each of its threads' CPU ticks (how the
# connections spread over the event loops). Alternating evens out a shared machine's
# load; compare medians.
#   tests/bench/http/compare_binaries.sh SECONDS ROUNDS BINARY_A BINARY_B
set -euo pipefail
[ $# -eq 4 ] || { echo "usage: $0 SECONDS ROUNDS BINARY_A BINARY_B" >&2; exit 2; }
command -v wrk >/dev/null || { echo "wrk is needed: apt-get install wrk" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
seconds=$1
rounds=$2
shift 2

cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }

run() {
  local binary=$1 log pid url before after out requests
  log=$(mktemp)
  "$binary" --port 0 --log-level warn --io-threads 0 >"$log" 2>&1 &
  pid=$!
  for _ in $(seq 100); do grep -q "listening on" "$log" && break; sleep 0.05; done
  url=$(grep -o 'http://[0-9.]*:[0-9]*' "$log" | head -1)
  before=$(cpu_ticks $pid)
  out=$(wrk -t2 -c64 -d"${seconds}s" --latency -s "$here/evaluate.lua" "$url/evaluate")
  after=$(cpu_ticks $pid)
  local threads=""
  for task in /proc/$pid/task/*; do threads+="$(awk '{print $14 + $15}' "$task/stat") "; done
  kill $pid
  wait $pid 2>/dev/null || true
  rm -f "$log"
  requests=$(echo "$out" | awk '/requests in/ {print $1}')
  printf '%s %s req/s=%s p99=%s cpu_us_per_request=%s load=%s thread_ticks=[%s] %s\n' \
    "$binary" "$(date +%H:%M:%S)" \
    "$(echo "$out" | awk '/Requests\/sec/ {print $2}')" \
    "$(echo "$out" | awk '$1 == "99%" {print $2}')" \
    "$(awk -v a="$before" -v b="$after" -v n="$requests" -v hz="$(getconf CLK_TCK)" 'BEGIN { printf "%.1f", (b - a) / hz * 1e6 / n }')" \
    "$(cut -d' ' -f1 /proc/loadavg)" "${threads% }" \
    "$(echo "$out" | grep -E 'Non-2xx|Socket errors' | tr '\n' ' ')"
}

for _ in $(seq "$rounds"); do
  for binary in "$@"; do run "$binary"; done
done
