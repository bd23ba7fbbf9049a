#!/usr/bin/env bash
# From a fresh clone: install what is missing, build Release, serve on 127.0.0.1:8080.
# Extra arguments go to bezier-service (e.g. --port 9000, --log-format json).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh run
# ccache keys objects by paths relative to the clone (tools/test.sh does the same).
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DBEZIER_BUILD_TESTS=OFF -DBEZIER_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build/release --target bezier-service
# The defaults are 127.0.0.1:8080; flags given here (--port 9000) override them.
exec build/release/service/bezier-service "$@"
