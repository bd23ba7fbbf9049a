#!/usr/bin/env bash
# Container test: builds docker/Dockerfile with docker-check, a helper that is not part of
# this repository (it drives podman, so no Docker daemon is needed, and builds the Debian
# base image locally; see the lookup below), waits until /healthz answers, then checks the
# running container:
#   - GET /healthz is 200 {"status":"ok"} and /readyz is 200;
#   - the image declares a non-root USER, STOPSIGNAL SIGTERM, EXPOSE 8080 and a HEALTHCHECK;
#   - the process runs as a non-root uid and the image holds no compiler;
#   - the image's own HEALTHCHECK passes, and fails when pointed at a closed port;
#   - SIGTERM (what `docker stop` and Kubernetes send) reaches the service as PID 1:
#     /readyz turns 503 while /healthz stays 200 during the drain, then the container
#     exits with status 0.
#
# Usage: tests/container/docker_check.sh [REPO_DIR]     (needs root, like docker-check)
# REPO_DIR defaults to the checkout holding this script; docker-check is the command
# BEZIER_DOCKER_CHECK names, else REPO_DIR/../shared/tools/docker-check (where the CI puts it).
# Exit status: 0 all checks passed, 1 a check failed or a prerequisite is missing,
# 77 skipped: no container engine can run here (no docker-check, or not root), the reason
# printed (ctest reports the test as skipped: SKIP_RETURN_CODE in tests/CMakeLists.txt).
set -euo pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "${1:-$script_dir/../..}" && pwd)
docker_check=${BEZIER_DOCKER_CHECK:-$repo/../shared/tools/docker-check}
tag=localhost/bezier-service:container-test
drain_seconds=10

say() { printf '[container-test] %s\n' "$*" >&2; }
fail() { say "FAIL: $*"; exit 1; }
skip() { say "SKIPPED: $*"; exit 77; }

[ -x "$docker_check" ] || skip "no container engine helper: docker-check is not at $docker_check (set BEZIER_DOCKER_CHECK to a copy to run this test)"
[ "$(id -u)" = 0 ] || skip "not root: docker-check drives rootful podman"
[ -f "$repo/docker/Dockerfile" ] || fail "no docker/Dockerfile under $repo"
command -v curl >/dev/null || fail "curl is needed on the host"

# A free loopback port (the container uses host networking, so it must not be taken).
port_is_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
port=""
for _ in $(seq 1 100); do
  candidate=$(( 20000 + RANDOM % 20000 ))
  if port_is_free "$candidate"; then port=$candidate; break; fi
done
[ -n "$port" ] || fail "no free port found"
base=http://127.0.0.1:$port

work=$(mktemp -d)
name=""
cleanup() {
  local rc=$?
  if [ -n "$name" ]; then
    if [ $rc != 0 ]; then
      say "container logs:"; podman logs "$name" 2>&1 | tail -30 | sed 's/^/  | /' >&2 || true
    fi
    podman rm -f "$name" >/dev/null 2>&1 || true
  fi
  rm -rf "$work"
  exit $rc
}
trap cleanup EXIT

say "docker-check: building $repo/docker/Dockerfile as $tag, service on port $port"
set +e
"$docker_check" -f "$repo/docker/Dockerfile" -t "$tag" --keep --timeout 120 \
  -e "BEZIER_PORT=$port" -e "BEZIER_DRAIN_SECONDS=$drain_seconds" \
  "$repo" "$base/healthz" 2> >(tee "$work/docker-check.log" >&2)
rc=$?
set -e
wait  # for tee
case $rc in
  0) ;;
  3) fail "docker-check setup failed (exit 3: podman/debootstrap/base image)" ;;
  4) fail "image build failed (exit 4; build log in ${DOCKER_CHECK_CACHE:-/var/cache/docker-check}/last-build.log)" ;;
  5) fail "container did not start or exited (exit 5)" ;;
  6) fail "/healthz did not answer in time (exit 6)" ;;
  *) fail "docker-check exited with $rc" ;;
esac
name=$(grep -o 'container docker-check-[0-9]* left running' "$work/docker-check.log" | awk '{print $2}' | tail -1)
[ -n "$name" ] || fail "could not find the kept container's name in docker-check's output"
# docker-check's podman settings (runc runtime, ulimits) for the commands below.
conf=${DOCKER_CHECK_CACHE:-/var/cache/docker-check}/containers.conf
[ -f "$conf" ] && export CONTAINERS_CONF=$conf
say "container $name is up"

checks=0
pass() { checks=$((checks + 1)); say "ok: $*"; }

# --- the service answers
body=$(curl -fsS -m 5 "$base/healthz") || fail "GET /healthz failed"
[[ "$body" =~ \"status\"[[:space:]]*:[[:space:]]*\"ok\" ]] || fail "GET /healthz body is '$body'"
pass "GET /healthz -> $body"
status=$(curl -sS -m 5 -o /dev/null -w '%{http_code}' "$base/readyz")
[ "$status" = 200 ] || fail "GET /readyz -> $status before SIGTERM"
pass "GET /readyz -> 200"

# --- image metadata
user=$(podman image inspect -f '{{.Config.User}}' "$tag")
uid=${user%%:*}
[ -n "$uid" ] && [ "$uid" != 0 ] && [ "$uid" != root ] || fail "image USER is '$user' (want non-root)"
pass "image USER $user"
stopsignal=$(podman image inspect -f '{{.Config.StopSignal}}' "$tag")
[ "$stopsignal" = SIGTERM ] || [ "$stopsignal" = 15 ] || fail "image STOPSIGNAL is '$stopsignal'"
pass "image STOPSIGNAL $stopsignal"
ports=$(podman image inspect -f '{{range $p, $_ := .Config.ExposedPorts}}{{$p}} {{end}}' "$tag")
[[ " $ports " == *" 8080/tcp "* ]] || fail "image EXPOSE is '$ports' (want 8080/tcp)"
pass "image EXPOSE $ports"
health=$(podman image inspect -f '{{if .Config.Healthcheck}}{{join .Config.Healthcheck.Test " "}}{{end}}' "$tag")
[ -n "$health" ] || fail "image has no HEALTHCHECK"
pass "image HEALTHCHECK $health"

# --- inside the container
run_uid=$(podman exec "$name" id -u)
[ "$run_uid" != 0 ] || fail "the service runs as root"
pass "process uid $run_uid"
compilers=$(podman exec "$name" sh -c 'for c in cc gcc g++ c++ cmake ninja; do command -v $c; done; true')
[ -z "$compilers" ] || fail "runtime image holds build tools: $compilers"
pass "no compiler or build tool in the runtime image"
podman healthcheck run "$name" >/dev/null || fail "the image's HEALTHCHECK fails on a healthy container"
pass "podman healthcheck run: healthy"
if podman exec -e BEZIER_PORT=1 "$name" bezier-healthcheck >/dev/null 2>&1; then
  fail "bezier-healthcheck passes against a closed port"
fi
pass "bezier-healthcheck fails against a closed port"

# --- SIGTERM: drain, then a clean exit
podman kill --signal TERM "$name" >/dev/null
saw_503=0
for _ in $(seq 1 $(( drain_seconds * 10 ))); do
  status=$(curl -sS -m 2 -o /dev/null -w '%{http_code}' "$base/readyz" 2>/dev/null || true)
  if [ "$status" = 503 ]; then saw_503=1; break; fi
  sleep 0.1
done
[ $saw_503 = 1 ] || fail "/readyz never answered 503 after SIGTERM (last: '$status')"
pass "/readyz -> 503 while draining"
status=$(curl -sS -m 2 -o /dev/null -w '%{http_code}' "$base/healthz" 2>/dev/null || true)
[ "$status" = 200 ] || fail "/healthz -> '$status' while draining (liveness must stay 200)"
pass "/healthz -> 200 while draining"
timeout $(( drain_seconds + 60 )) podman wait "$name" >/dev/null || fail "container did not stop after SIGTERM"
exit_code=$(podman inspect -f '{{.State.ExitCode}}' "$name")
[ "$exit_code" = 0 ] || fail "container exit status $exit_code after SIGTERM (want 0)"
pass "exit status 0 after SIGTERM"

say "PASS: $checks checks on $tag ($(podman image inspect -f '{{.Size}}' "$tag") bytes)"
