#!/usr/bin/env bash
# From a fresh clone: install what is missing, build everything, run every test; then
# the unit and integration tests again under AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh test
jobs=$(nproc)
# ccache (CMakeLists.txt uses it when installed) keys objects by paths relative to the
# clone, so a second clone or a CI checkout elsewhere reuses what an earlier build compiled.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
# Node packages of the browser and contract tests, exactly as locked.
for dir in tests/browser tests/contract; do
  if [ -f "$dir/package-lock.json" ]; then (cd "$dir" && npm ci --no-audit --no-fund --loglevel=error); fi
done

cmake -S . -B build/test -G Ninja -DCMAKE_BUILD_TYPE=Release -DBEZIER_WERROR=ON >/dev/null
cmake --build build/test -j "$jobs"
ctest --test-dir build/test --output-on-failure -j "$jobs"

# Sanitizers: the same tests, built again with -fsanitize=address,undefined (any report
# fails the test). Benchmarks are left out; so are the labels that test packaging or the
# source layout, not code.
cmake -S . -B build/asan -G Ninja -DCMAKE_BUILD_TYPE=Release -DBEZIER_WERROR=ON \
  -DBEZIER_SANITIZE=ON -DBEZIER_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build/asan -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build/asan --output-on-failure -j "$jobs" -LE "container|browser|contract|layering"
