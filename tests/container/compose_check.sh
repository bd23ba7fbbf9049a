#!/usr/bin/env bash
# Compose test: brings up docker/compose.yaml (three bezier-service replicas behind nginx)
# with Debian's docker-compose talking to podman's Docker-compatible API, then
#   - GET /healthz through nginx is 200, and every replica serves requests;
#   - while four clients send POST /evaluate through nginx, one replica is killed
#     (SIGKILL) and later another one is stopped (SIGTERM): every request answers 200,
#     the stopped replica exits 0;
# and takes the stack down again.
#
# Usage: tests/container/compose_check.sh [REPO_DIR]     (needs root)
# Needs podman and the local debian:bookworm base image, which
# tests/container/docker_check.sh (../shared/tools/docker-check) installs and makes, and
# Debian's docker-compose and curl. podman runs no periodic health checks without
# systemd, so this script runs `podman healthcheck run` on the replicas itself while
# compose waits for them to be healthy.
# Exit status: 0 all checks passed, 1 a check failed or a prerequisite is missing,
# 77 skipped: no container engine can run here (not root, or neither podman nor the
# docker-check helper that installs it, found as tests/container/docker_check.sh finds it),
# the reason printed (ctest's SKIP_RETURN_CODE).
set -euo pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "${1:-$script_dir/../..}" && pwd)
compose_file=$repo/docker/compose.yaml
cache=${DOCKER_CHECK_CACHE:-/var/cache/docker-check}
requests_per_client=300

say() { printf '[compose-test] %s\n' "$*" >&2; }
fail() { say "FAIL: $*"; exit 1; }
skip() { say "SKIPPED: $*"; exit 77; }

# Where docker-check could have set podman up, a missing piece is a failure; elsewhere no
# container engine can run, and the test is skipped.
docker_check=${BEZIER_DOCKER_CHECK:-$repo/../shared/tools/docker-check}
[ "$(id -u)" = 0 ] || skip "not root: the stack runs on rootful podman"
if ! command -v podman >/dev/null && [ ! -x "$docker_check" ]; then
  skip "no container engine: neither podman nor docker-check (at $docker_check; BEZIER_DOCKER_CHECK names another) is here"
fi
command -v podman >/dev/null || fail "podman missing: run tests/container/docker_check.sh first (docker-check installs it)"
command -v docker-compose >/dev/null || fail "docker-compose missing: apt-get install docker-compose"
command -v curl >/dev/null || fail "curl missing"
[ -f "$cache/containers.conf" ] || fail "no $cache/containers.conf: run tests/container/docker_check.sh first"
export CONTAINERS_CONF=$cache/containers.conf
podman image exists docker.io/library/debian:bookworm-slim \
  || fail "no local debian:bookworm-slim image: run tests/container/docker_check.sh first"

port_is_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
port=""
for _ in $(seq 1 100); do
  candidate=$(( 20000 + RANDOM % 20000 ))
  if port_is_free "$candidate"; then port=$candidate; break; fi
done
[ -n "$port" ] || fail "no free port found"
export BEZIER_HTTP_PORT=$port
base=http://127.0.0.1:$port
project=bezierct$$
work=$(mktemp -d)
sock=$work/podman.sock
compose=(docker-compose -p "$project" -f "$compose_file")
service_pid="" up_pid=""

cleanup() {
  local rc=$?
  if [ -n "$up_pid" ]; then kill "$up_pid" 2>/dev/null || true; wait "$up_pid" 2>/dev/null || true; fi
  if [ -n "$service_pid" ]; then
    if [ $rc != 0 ]; then
      say "nginx log:"; podman logs "${project}_nginx_1" 2>&1 | tail -20 | sed 's/^/  | /' >&2 || true
    fi
    timeout 120 "${compose[@]}" down --remove-orphans >/dev/null 2>&1 || true
    kill "$service_pid" 2>/dev/null || true
    wait "$service_pid" 2>/dev/null || true
  fi
  rm -rf "$work"
  exit $rc
}
trap cleanup EXIT

podman system service --time=0 "unix://$sock" >"$work/podman-service.log" 2>&1 &
service_pid=$!
export DOCKER_HOST=unix://$sock
for _ in $(seq 1 100); do
  curl -fsS --unix-socket "$sock" http://d/_ping >/dev/null 2>&1 && break
  sleep 0.1
done
curl -fsS --unix-socket "$sock" http://d/_ping >/dev/null 2>&1 || fail "podman API service did not start"

replicas=(bezier-1 bezier-2 bezier-3)
container_of() { printf '%s_%s_1' "$project" "$1"; }

say "docker-compose up (project $project, nginx on port $port)"
"${compose[@]}" up -d --build >"$work/up.log" 2>&1 &
up_pid=$!
# Stand-in for the engine's periodic health checks while compose waits for them.
deadline=$(( $(date +%s) + 900 ))
while kill -0 "$up_pid" 2>/dev/null; do
  [ "$(date +%s)" -lt $deadline ] || { tail -30 "$work/up.log" >&2; fail "docker-compose up did not finish in 900 s"; }
  for r in "${replicas[@]}"; do podman healthcheck run "$(container_of "$r")" >/dev/null 2>&1 || true; done
  sleep 1
done
up_rc=0; wait "$up_pid" || up_rc=$?; up_pid=""
[ $up_rc = 0 ] || { tail -30 "$work/up.log" >&2; fail "docker-compose up exited with $up_rc"; }
say "stack is up"

checks=0
pass() { checks=$((checks + 1)); say "ok: $*"; }

ready=0
for _ in $(seq 1 100); do
  if curl -fsS -m 2 "$base/healthz" >/dev/null 2>&1; then ready=1; break; fi
  sleep 0.1
done
[ $ready = 1 ] || fail "nginx does not answer on $base"
body=$(curl -fsS -m 5 "$base/healthz")
[[ "$body" =~ \"status\"[[:space:]]*:[[:space:]]*\"ok\" ]] || fail "GET /healthz through nginx: '$body'"
pass "GET /healthz through nginx -> $body"
for _ in $(seq 1 30); do curl -fsS -m 5 -o /dev/null "$base/healthz" || fail "GET /healthz through nginx failed"; done
for r in "${replicas[@]}"; do
  served=$(podman logs "$(container_of "$r")" 2>&1 | grep -c '"path":"/healthz"' || true)
  [ "$served" -gt 0 ] || fail "$r served none of the requests"
done
pass "every replica serves requests"

# Four clients, each a fresh connection per request; replicas go away mid-run.
request='{"points": [[0,0],[2,4],[4,0]], "t": [0.25, 0.5]}'
client_loop() {
  local i
  for i in $(seq 1 "$requests_per_client"); do
    curl -sS -m 30 -o /dev/null -w '%{http_code}\n' -H 'Content-Type: application/json' \
      -d "$request" "$base/evaluate" 2>/dev/null || echo "curl-failed"
  done
}
clients=()
for c in 1 2 3 4; do client_loop >"$work/codes-$c" & clients+=($!); done
answered() { cat "$work"/codes-* 2>/dev/null | wc -l; }
wait_for_answers() {
  while [ "$(answered)" -lt "$1" ]; do
    kill -0 "${clients[0]}" 2>/dev/null || break
    sleep 0.05
  done
}
wait_for_answers $(( requests_per_client ))
say "SIGKILL bezier-2 after $(answered) answers"
"${compose[@]}" kill -s SIGKILL bezier-2 >/dev/null 2>&1 || fail "docker-compose kill bezier-2"
wait_for_answers $(( requests_per_client * 2 ))
say "stopping bezier-3 (SIGTERM) after $(answered) answers"
"${compose[@]}" stop -t 30 bezier-3 >/dev/null 2>&1 || fail "docker-compose stop bezier-3"
for pid in "${clients[@]}"; do wait "$pid"; done
total=$(answered)
ok=$(cat "$work"/codes-* | grep -c '^200$' || true)
say "answers: $(cat "$work"/codes-* | sort | uniq -c | tr -s ' \n' ' ')"
[ "$total" = $(( 4 * requests_per_client )) ] || fail "$total answers, expected $(( 4 * requests_per_client ))"
[ "$ok" = "$total" ] || fail "$(( total - ok )) of $total requests failed while replicas went away"
pass "$total POST /evaluate through nginx, all 200, with bezier-2 killed and bezier-3 stopped"
killed=$(podman inspect -f '{{.State.Running}}' "$(container_of bezier-2)")
[ "$killed" = false ] || fail "bezier-2 is still running after SIGKILL"
stopped_code=$(podman inspect -f '{{.State.ExitCode}}' "$(container_of bezier-3)")
[ "$stopped_code" = 0 ] || fail "bezier-3 exit status $stopped_code after SIGTERM (want 0)"
pass "bezier-3 exited 0 after SIGTERM"
retried=$(podman logs "$(container_of nginx)" 2>/dev/null | grep -c 'upstream=[^ ]*, ' || true)
say "nginx retried $retried requests on another replica"

say "PASS: $checks checks"
