#!/usr/bin/env bash
# Installs the Debian packages bezier-service needs, skipping what is already there.
#   tools/install-deps.sh run    build and run the service
#   tools/install-deps.sh test   also everything the test suite uses
set -euo pipefail
profile=${1:-run}

# python3 and python3-yaml build the JSON form of the spec (GET /openapi.json,
# tools/openapi_to_json.py at configure time).
packages=(build-essential cmake ninja-build pkg-config ccache
          libcpp-httplib-dev nlohmann-json3-dev libspdlog-dev libcli11-dev python3 python3-yaml)
if [ "$profile" = test ]; then
  packages+=(libgtest-dev libgmock-dev libbenchmark-dev libvalijson-dev curl python3-kubernetes docker-compose
             chromium chromium-driver)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# node and npm: the machines come with them; Debian's packages otherwise.
if [ "$profile" = test ] && ! command -v npm >/dev/null; then
  missing+=(nodejs npm)
fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
