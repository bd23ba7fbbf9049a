#!/usr/bin/env bash
# Lints api/openapi.yaml with the pinned Redocly CLI (package-lock.json here; installed
# by `npm ci` in this directory, see tools/test.sh). Fails on any error or warning.
set -euo pipefail
# No telemetry and no update check: CI reaches only the package registries.
export REDOCLY_TELEMETRY=off REDOCLY_SUPPRESS_UPDATE_NOTICE=true
cd "$(dirname "$0")"
redocly=node_modules/.bin/redocly
if [ ! -x "$redocly" ]; then
  echo "Redocly CLI is not installed: run 'npm ci' in tests/contract (tools/test.sh does)" >&2
  exit 1
fi
output=$("$redocly" lint --config redocly.yaml ../../api/openapi.yaml 2>&1) || status=$?
echo "$output"
if [ "${status:-0}" -ne 0 ]; then
  echo "openapi lint: errors (exit status $status)" >&2
  exit 1
fi
if grep -qE 'You have [0-9]+ warnings?' <<<"$output"; then
  echo "openapi lint: warnings count as failures" >&2
  exit 1
fi
grep -q 'Your API description is valid' <<<"$output"
