#!/usr/bin/env bash
# One entry point for developers and CI.
#   scripts/dev.sh run [MESH]   install what is missing, build, start the application
#   scripts/dev.sh test         install what is missing, build, run every test (ctest)
#   scripts/dev.sh build        install what is missing and build
# The build goes to ./build (override with SNAXELS_BUILD_DIR). With CI=true
# compiler warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."

action=${1:-}
case "$action" in
  run|test|build) shift ;;
  *) echo "usage: scripts/dev.sh run [MESH] | test | build" >&2; exit 2 ;;
esac

bash scripts/install-deps.sh

build_dir=${SNAXELS_BUILD_DIR:-build}
werror=OFF
if [ "${CI:-}" = "true" ]; then werror=ON; fi
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSNAXELS_WERROR="$werror"
cmake --build "$build_dir" -j2

case "$action" in
  run) exec "$build_dir/bin/snaxels" "$@" ;;
  test) cd "$build_dir" && exec ctest --output-on-failure -j2 --timeout 900 ;;
  build) ;;
esac
