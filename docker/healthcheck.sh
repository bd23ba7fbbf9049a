#!/bin/bash
# bezier-healthcheck [PATH]: exit 0 when GET PATH (default /healthz) on the local
# bezier-service answers 200, 1 otherwise.
#
# The container's HEALTHCHECK and the compose file's health checks run this. It speaks
# HTTP through bash's /dev/tcp, so the runtime image needs neither curl nor wget (curl
# would add libcurl4 and a dozen libraries). Address and port come from the same
# BEZIER_HOST / BEZIER_PORT the service reads; a wildcard bind address is reached on
# loopback. Every wait is bounded: connecting to loopback fails at once when nothing
# listens, and the status line is awaited for at most BEZIER_HEALTHCHECK_TIMEOUT seconds
# (default 2; the engine's HEALTHCHECK --timeout bounds the whole run as well).
set -u

path=${1:-/healthz}
host=${BEZIER_HOST:-127.0.0.1}
port=${BEZIER_PORT:-8080}
wait_s=${BEZIER_HEALTHCHECK_TIMEOUT:-2}
case "$host" in
  ''|0.0.0.0|'*') host=127.0.0.1 ;;
  ::|'[::]') host=::1 ;;
esac

if ! exec 3<>"/dev/tcp/$host/$port"; then
  echo "bezier-healthcheck: cannot connect to $host:$port" >&2
  exit 1
fi
printf 'GET %s HTTP/1.1\r\nHost: localhost\r\nUser-Agent: bezier-healthcheck\r\nConnection: close\r\n\r\n' \
  "$path" >&3
status=""
IFS= read -r -t "$wait_s" status <&3
exec 3<&-
status=${status%$'\r'}
case "$status" in
  "HTTP/1.1 200 "*|"HTTP/1.0 200 "*) exit 0 ;;
esac
echo "bezier-healthcheck: GET $path on $host:$port answered '${status:-nothing}'" >&2
exit 1
