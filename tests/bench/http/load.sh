#!/usr/bin/env bash
# HTTP load figures for the README and BENCHMARKS.md: wrk at 64 connections against
# a freshly started bezier-service, /evaluate (one cubic, one t) then /healthz, while a
# 65th client probes /healthz every 100 ms. A req/s figure counts only if that probe is
# answered throughout (every connection served). The service's RSS is sampled every second
# during each run (first and last sample, smallest and largest), to show it stays flat.
#   tests/bench/http/load.sh [service-binary] [seconds] [connections]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
binary=${1:-$here/../../../build/test/service/bezier-service}
seconds=${2:-30}
connections=${3:-64}
command -v wrk >/dev/null || { echo "wrk is needed: apt-get install wrk" >&2; exit 2; }

log=$(mktemp)
"$binary" --port 0 >"$log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null; wait $pid 2>/dev/null; rm -f "$log"' EXIT
for _ in $(seq 100); do grep -q "listening on" "$log" && break; sleep 0.05; done
url=$(grep -o 'http://[0-9.]*:[0-9]*' "$log" | head -1)
echo "service: $url (pid $pid), rss before: $(ps -o rss= -p $pid) kB"

probe() {  # prints the slowest of the probe's answers, in ms, and failures
  local worst=0 failed=0 t
  while [ -e "$1" ]; do
    if t=$(curl -s -o /dev/null -m 2 -w '%{time_total}' "$url/healthz"); then
      worst=$(awk -v a="$worst" -v b="$t" 'BEGIN { print (b * 1000 > a) ? b * 1000 : a }')
    else
      failed=$((failed + 1))
    fi
    sleep 0.1
  done
  echo "probe: slowest /healthz answer ${worst} ms, failed probes: $failed"
}

rss_sampler() {  # until $1 disappears: first, last, smallest and largest RSS (kB), 1 s apart
  local first="" last="" min="" max="" r
  while [ -e "$1" ]; do
    r=$(ps -o rss= -p $pid | tr -d ' ')
    [ -n "$r" ] || break
    [ -n "$first" ] || first=$r
    last=$r
    { [ -z "$min" ] || [ "$r" -lt "$min" ]; } && min=$r
    { [ -z "$max" ] || [ "$r" -gt "$max" ]; } && max=$r
    sleep 1
  done
  echo "rss during the run: first $first kB, last $last kB, min $min kB, max $max kB"
}

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for route in evaluate healthz; do
  flag=$(mktemp)
  probe "$flag" > "$flag.out" &
  probe_pid=$!
  rss_sampler "$flag" > "$flag.rss" &
  rss_pid=$!
  echo "== wrk -t2 -c$connections -d${seconds}s --latency -s $route.lua $url/$route"
  wrk -t2 -c"$connections" -d"${seconds}s" --latency -s "$here/$route.lua" "$url/$route" |
    grep -E "Requests/sec|requests in|Non-2xx|Socket errors|50%|99%"
  rm -f "$flag"
  wait $probe_pid $rss_pid
  cat "$flag.out" "$flag.rss"
  rm -f "$flag.out" "$flag.rss"
done
echo "rss after: $(ps -o rss= -p $pid) kB"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
