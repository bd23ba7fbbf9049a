#!/usr/bin/env bash
# The contract as a TypeScript client sees it: generates types from api/openapi.yaml with
# the pinned openapi-typescript, writes a client that sends every README.md example
# through them (typed_client.mjs), and compiles both with the pinned TypeScript under
# --strict. Fails when a README example stops matching its generated type, when the
# types stop refusing an unknown member, a ragged point or one of the mistakes the client
# lists (a body with neither or both of `points` and `path`, `t: null`, `curves: []`, a
# /classify of other than four points, a /batch item naming no route...), or when the
# answers' unions stop being told apart by the members that distinguish them. Both tools come from
# package-lock.json here (`npm ci` in this directory, see tools/test.sh): no network.
set -euo pipefail
cd "$(dirname "$0")"
generator=node_modules/.bin/openapi-typescript
tsc=node_modules/.bin/tsc
if [ ! -x "$generator" ] || [ ! -x "$tsc" ]; then
  echo "openapi-typescript or typescript is not installed: run 'npm ci' in tests/contract (tools/test.sh does)" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$generator" ../../api/openapi.yaml --output "$work/api.d.ts"
node typed_client.mjs ../../README.md > "$work/client.ts"
# Only the two files and the ES library: no @types package from anywhere.
cat > "$work/tsconfig.json" <<'EOF'
{
  "compilerOptions": {
    "strict": true,
    "noEmit": true,
    "target": "es2022",
    "lib": ["es2022"],
    "module": "preserve",
    "moduleResolution": "bundler",
    "types": [],
    "skipLibCheck": false
  },
  "files": ["client.ts", "api.d.ts"]
}
EOF
if ! "$tsc" --project "$work/tsconfig.json" --pretty false; then
  echo "typed client: README.md examples against the types generated from api/openapi.yaml (above)" >&2
  exit 1
fi
echo "typed client: $(grep -c '^// README.md line' "$work/client.ts") README examples compile against the generated types, which refuse $(grep -c '^export const mistake_' "$work/client.ts") mistakes"
