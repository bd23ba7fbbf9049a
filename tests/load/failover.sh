#!/usr/bin/env bash
# Three bezier-service instances behind nginx (Debian package, started here
# with its own config on loopback); one instance is killed in the middle of a wrk run.
# nginx retries the next upstream on error or timeout, POSTs included (every route is a
# pure computation, so a retry is safe): the run must end with zero failed requests.
#   tests/load/failover.sh [service-binary] [seconds]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
binary=${1:-$root/build/test/service/bezier-service}
seconds=${2:-20}
for tool in nginx wrk; do
  command -v $tool >/dev/null || [ -x /usr/sbin/$tool ] ||
    { echo "$tool is needed: apt-get install nginx wrk" >&2; exit 2; }
done
nginx_bin=$(command -v nginx || echo /usr/sbin/nginx)

work=$(mktemp -d)
pids=()
cleanup() {
  [ -f "$work/nginx.pid" ] && kill "$(cat "$work/nginx.pid")" 2>/dev/null || true
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

ports=()
for i in 1 2 3; do
  "$binary" --port 0 --log-level warn >"$work/svc$i.log" 2>&1 &
  pids+=($!)
  for _ in $(seq 100); do grep -q "listening on" "$work/svc$i.log" && break; sleep 0.05; done
  ports+=("$(grep -o 'listening on http://[0-9.]*:[0-9]*' "$work/svc$i.log" | sed 's/.*://')")
done
proxy_port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')

cat >"$work/nginx.conf" <<CONF
worker_processes 1;
pid $work/nginx.pid;
error_log $work/nginx-error.log warn;
events { worker_connections 4096; }
http {
  access_log off;
  client_body_temp_path $work/body;
  proxy_temp_path $work/proxy;
  fastcgi_temp_path $work/fastcgi;
  uwsgi_temp_path $work/uwsgi;
  scgi_temp_path $work/scgi;
  upstream bezier {
    server 127.0.0.1:${ports[0]} max_fails=1 fail_timeout=5s;
    server 127.0.0.1:${ports[1]} max_fails=1 fail_timeout=5s;
    server 127.0.0.1:${ports[2]} max_fails=1 fail_timeout=5s;
    keepalive 64;
  }
  server {
    listen 127.0.0.1:$proxy_port;
    location / {
      proxy_pass http://bezier;
      proxy_http_version 1.1;
      proxy_set_header Connection "";
      proxy_connect_timeout 1s;
      proxy_read_timeout 5s;
      proxy_next_upstream error timeout http_502 http_503 non_idempotent;
      proxy_next_upstream_tries 3;
    }
  }
}
CONF
"$nginx_bin" -c "$work/nginx.conf" -e "$work/nginx-error.log"
for _ in $(seq 100); do curl -fs "http://127.0.0.1:$proxy_port/healthz" >/dev/null && break; sleep 0.05; done

echo "instances on ports ${ports[*]}, nginx on $proxy_port; killing instance 2 (SIGKILL) after $((seconds / 2)) s"
( sleep $((seconds / 2)); kill -KILL "${pids[1]}" ) &
wrk -t2 -c64 -d"${seconds}s" --latency -s "$root/tests/bench/http/evaluate.lua" \
  "http://127.0.0.1:$proxy_port/evaluate" | tee "$work/wrk.txt"
if grep -qE "Non-2xx|Socket errors" "$work/wrk.txt"; then
  echo "FAILED: some requests failed"
  exit 1
fi
echo "OK: zero failed requests while an instance died"
