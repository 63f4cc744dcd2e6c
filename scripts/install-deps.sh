#!/usr/bin/env bash
# Installs every Debian 12 package snaxels needs to build, run and test.
# Safe to run repeatedly: apt skips what is already installed. (The Lottie
# tests' lottie-web and schema are vendored in tests/players/vendor, pinned;
# tests/players/fetch.sh refreshes them from npm.)
#   scripts/install-deps.sh          install the packages that are missing
#   scripts/install-deps.sh --list   print the package list, one a line
#   scripts/install-deps.sh --quality  also what the quality corpus's full run
#                                      needs (scripts/quality.sh): Blender, which
#                                      writes the corpus's scenes, and numpy for
#                                      its glTF exporter
# The test deps.packages checks that every system file the build reads comes
# from these packages or their dependencies.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  qt6-base-dev libqt6opengl6-dev qt6-svg-dev libgl-dev libglx-dev
  libopenmesh-dev libglm-dev libassimp-dev zlib1g-dev
  libembree-dev libtbb-dev libpolyclipping-dev libpugixml-dev nlohmann-json3-dev
  librsvg2-dev libcairo2-dev libminizip-dev ffmpeg
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth libgl1-mesa-dri mesa-utils
  chromium fonts-dejavu-core librsvg2-bin inkscape poppler-utils parallel
  librlottie-dev python3-jsonschema
  clang libclang-rt-14-dev llvm
  dpkg-dev file desktop-file-utils
  assimp-testmodels
)
# scripts/quality.sh's full run only (not CI's ratchet).
QUALITY_PACKAGES=(blender python3-numpy)
if [ "${1:-}" = --quality ]; then
  PACKAGES+=("${QUALITY_PACKAGES[@]}")
fi

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

