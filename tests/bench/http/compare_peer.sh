#!/usr/bin/env bash
# bezier-service against the peer in the same run. The peer is a Node.js service that is not
# part of this repository: Paper.js 0.12 behind node's http (cluster of 2 workers), answering
# POST /evaluate, /intersections, /classify and GET /healthz with the same JSON shapes for
# cubics, its request bodies in its wrk/*.lua. PEER_SERVICE names its directory (default:
# ../shared/tools/peer-service beside the checkout).
# The script runs wrk at 64 connections, alternating the two servers per round, on /evaluate,
# /intersections and /classify with the peer's request bodies. While each load runs
# a 65th client probes /healthz every 100 ms: a req/s figure counts only if every probe is
# answered (all connections served). Prints one line per run and the medians.
# cpu_us is the server's CPU time per request (user + system, all its processes: ours, or
# the peer's cluster primary and workers, from /proc): less sensitive than req/s to other
# load on the machine, since both share the 2 cores with wrk and with whatever else runs.
#   tests/bench/http/compare_peer.sh [service-binary] [seconds] [rounds]
#   ROUTES="evaluate classify" tests/bench/http/compare_peer.sh ...   (a subset of routes)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
binary=${1:-$root/build/test/service/bezier-service}
seconds=${2:-10}
rounds=${3:-3}
peer_src=${PEER_SERVICE:-$root/../shared/tools/peer-service}
[ -d "$peer_src" ] || { echo "peer service not found at $peer_src (set PEER_SERVICE)" >&2; exit 2; }
command -v wrk >/dev/null || { echo "wrk is needed: apt-get install wrk" >&2; exit 2; }

work=$(mktemp -d)
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; wait 2>/dev/null || true; rm -rf "$work"; }
trap cleanup EXIT

# The peer is copied, so its node_modules never land in the shared folder.
cp -r "$peer_src" "$work/peer"
(cd "$work/peer" && npm install --no-audit --no-fund --silent >/dev/null)
free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
peer_port=$(free_port)
(cd "$work/peer" && exec node peer_service.mjs "$peer_port" --workers 2) >"$work/peer.log" 2>&1 &
peer_pid=$!
pids+=($peer_pid)
"$binary" --port 0 --log-level warn >"$work/ours.log" 2>&1 &
ours_pid=$!
pids+=($ours_pid)
for _ in $(seq 200); do
  grep -q "listening on" "$work/ours.log" && curl -fs "http://127.0.0.1:$peer_port/healthz" >/dev/null && break
  sleep 0.05
done
ours_url=$(grep -o 'http://[0-9.]*:[0-9]*' "$work/ours.log" | head -1)
peer_url="http://127.0.0.1:$peer_port"

routes=${ROUTES:-evaluate intersections classify}
clk_tck=$(getconf CLK_TCK)
cpu_ticks() {  # utime + stime of $1 and its children (the peer's cluster workers)
  local total=0 p
  for p in $1 $(pgrep -P "$1" || true); do
    [ -r "/proc/$p/stat" ] && total=$((total + $(awk '{ print $14 + $15 }' "/proc/$p/stat")))
  done
  echo $total
}

probe() {  # until $1 disappears: prints the slowest /healthz answer (ms) and failures
  local worst=0 failed=0 t
  while [ -e "$1" ]; do
    if t=$(curl -s -o /dev/null -m 2 -w '%{time_total}' "$2/healthz"); then
      worst=$(awk -v a="$worst" -v b="$t" 'BEGIN { print (b * 1000 > a) ? b * 1000 : a }')
    else
      failed=$((failed + 1))
    fi
    sleep 0.1
  done
  echo "$worst $failed"
}

run() {  # name url route pid -> "rps p99_ms probe_ms probe_failed errors cpu_us"
  local flag="$work/flag" out
  touch "$flag"
  probe "$flag" "$2" >"$work/probe" &
  local probe_pid=$!
  local ticks_before ticks_after
  ticks_before=$(cpu_ticks "$4")
  out=$(wrk -t2 -c64 -d"${seconds}s" --latency -s "$peer_src/wrk/$3.lua" "$2/$3")
  ticks_after=$(cpu_ticks "$4")
  rm -f "$flag"
  wait $probe_pid
  local rps p99 errors requests cpu_us
  rps=$(echo "$out" | awk '/Requests\/sec/ { print $2 }')
  requests=$(echo "$out" | awk '/requests in/ { print $1 }')
  cpu_us=$(awk -v t=$((ticks_after - ticks_before)) -v hz="$clk_tck" -v n="$requests" 'BEGIN { printf "%.1f", t / hz * 1e6 / n }')
  p99=$(echo "$out" | awk '$1 == "99%" { v = $2; if (v ~ /us$/) { sub(/us/, "", v); v /= 1000 } else if (v ~ /ms$/) { sub(/ms/, "", v) } else if (v ~ /s$/) { sub(/s/, "", v); v *= 1000 } print v }')
  errors=$(echo "$out" | grep -cE "Non-2xx|Socket errors" || true)
  echo "$rps $p99 $(cat "$work/probe") $errors $cpu_us"
}

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-14s %-6s %5s %10s %8s %9s %6s %7s\n' route server round req/s p99_ms probe_ms errors cpu_us
for route in $routes; do
  for round in $(seq "$rounds"); do
    for server in ours peer; do
      url=$ours_url pid=$ours_pid
      [ $server = peer ] && url=$peer_url pid=$peer_pid
      read -r rps p99 probe_ms probe_failed errors cpu_us < <(run $server "$url" $route $pid)
      echo "$route $server $rps $p99 $probe_ms $probe_failed $errors $cpu_us" >>"$work/results"
      printf '%-14s %-6s %5s %10s %8s %9s %6s %7s\n' $route $server "$round" "$rps" "$p99" "$probe_ms" "$((errors + probe_failed))" "$cpu_us"
    done
  done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "medians over $rounds rounds (req/s, p99 ms, CPU us per request); ratio = ours / peer (req/s), peer / ours (CPU)"
for route in $routes; do
  med() { grep "^$route $1 " "$work/results" | awk "{ print \$$2 }" | sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
  o=$(med ours 3); p=$(med peer 3); op=$(med ours 4); pp=$(med peer 4); oc=$(med ours 8); pc=$(med peer 8)
  printf '%-14s ours %10s %8s %7s   peer %10s %8s %7s   ratio %.2f  cpu ratio %.2f\n' $route "$o" "$op" "$oc" "$p" "$pp" "$pc" \
    "$(awk -v a="$o" -v b="$p" 'BEGIN { print a / b }')" "$(awk -v a="$oc" -v b="$pc" 'BEGIN { print b / a }')"
done
