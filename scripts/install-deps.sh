#!/usr/bin/env bash
# Installs every Debian 12 package snaxels needs to build, run and test, and
# the test players from npm (lottie-web, the Lottie schema, puppeteer-core),
# pinned by tests/players/package-lock.json, into tests/players/node_modules.
# Safe to run repeatedly: apt skips what is already installed, npm runs only
# when the lock file changed since the last install.
#   scripts/install-deps.sh          install the packages that are missing
#   scripts/install-deps.sh --list   print the package list, one a line
# The test deps.packages checks that every system file the build reads comes
# from these packages or their dependencies.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  qt6-base-dev libqt6opengl6-dev qt6-svg-dev libgl-dev libglx-dev
  libopenmesh-dev libglm-dev libassimp-dev zlib1g-dev
  libembree-dev libtbb-dev libpolyclipping-dev libpugixml-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth libgl1-mesa-dri mesa-utils
  chromium fonts-dejavu-core librsvg2-bin
  librlottie-dev nodejs
)
# npm: Debian's package, unless the installed node brings its own (NodeSource's
# nodejs does, and conflicts with Debian's npm).
if ! command -v npm >/dev/null 2>&1; then PACKAGES+=(npm); fi

if [ "${1:-}" = --list ]; then
  printf '%s\n' "${PACKAGES[@]}"
  exit 0
fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]})); then
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  echo "snaxels: installing ${#missing[@]} missing packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

root=$(cd "$(dirname "$0")/.." && pwd)
players="$root/tests/players"
if ! cmp -s "$players/package-lock.json" "$players/node_modules/.snaxels-lock.json"; then
  echo "snaxels: installing the test players from npm into tests/players/node_modules"
  (cd "$players" && npm ci --no-audit --no-fund --loglevel=error)
  cp "$players/package-lock.json" "$players/node_modules/.snaxels-lock.json"
fi
