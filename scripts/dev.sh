#!/usr/bin/env bash
# One entry point for developers and CI.
#   scripts/dev.sh run [MESH]   install what is missing, build, start the application
#   scripts/dev.sh test         install what is missing, build, run every test (ctest)
#   scripts/dev.sh build        install what is missing and build
#   scripts/dev.sh robot SECONDS [SEED]  install, build, and let the seeded
#                               robot use the window (tests/ui/robot.cpp) under
#                               Xvfb for SECONDS; its log goes to robot-SEED.log
#   scripts/dev.sh sanitize     clang build with AddressSanitizer and
#                               UndefinedBehaviorSanitizer (build-sanitize/);
#                               runs the core and cli test labels
#   scripts/dev.sh sanitize-robot SECONDS [SEED]  the robot in a clang
#                               build with AddressSanitizer and
#                               UndefinedBehaviorSanitizer of the window, the
#                               importer and snaxels-cli (build-sanitize-gui/)
#   scripts/dev.sh fuzz [SECONDS]  builds the libFuzzer targets (fuzz/) in
#                               build-sanitize/ and runs each for SECONDS
#                               (default 60) on its corpus
# The build goes to ./build (override with SNAXELS_BUILD_DIR). With CI=true
# compiler warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."

action=${1:-}
case "$action" in
  run|test|build|sanitize|fuzz|robot|sanitize-robot) shift ;;
  *) echo "usage: scripts/dev.sh run [MESH] | test | build | sanitize | fuzz [SECONDS] | robot SECONDS [SEED] | sanitize-robot SECONDS [SEED]" >&2; exit 2 ;;
esac

bash scripts/install-deps.sh

if [ "$action" = sanitize-robot ]; then
  san_dir=${SNAXELS_SANITIZE_GUI_BUILD_DIR:-build-sanitize-gui}
  CC=clang CXX=clang++ cmake -S . -B "$san_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DSNAXELS_SANITIZE=ON -DSNAXELS_BUILD_BENCH=OFF -DSNAXELS_WERROR=OFF
  cmake --build "$san_dir" -j2 --target snaxels-robot snaxels-import snaxels-cli
  # Leaks are reported at exit; Qt, fontconfig and Mesa keep caches of
  # their own until then (scripts/lsan-gui.supp names each, with Assimp's).
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  export LSAN_OPTIONS=suppressions=$PWD/scripts/lsan-gui.supp:print_suppressions=0
  # Mesa unloads its software driver as the window closes, which leaves
  # the driver's own small allocations unnamed (an unknown module) when
  # LeakSanitizer reports at exit; kept loaded, they stay reachable.
  preload=
  for dri in /usr/lib/*/dri/swrast_dri.so; do [ -e "$dri" ] && preload=$dri; done
  seed=${2:-$RANDOM}
  exec xvfb-run -a -s "-screen 0 1280x800x24" env ${preload:+LD_PRELOAD=$preload} "$san_dir/bin/snaxels-robot" \
    --seconds "${1:-60}" --seed "$seed" --log "robot-sanitize-$seed.log"
fi

if [ "$action" = sanitize ] || [ "$action" = fuzz ]; then
  san_dir=${SNAXELS_SANITIZE_BUILD_DIR:-build-sanitize}
  CC=clang CXX=clang++ cmake -S . -B "$san_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DSNAXELS_FUZZ=ON -DSNAXELS_BUILD_GUI=OFF -DSNAXELS_BUILD_BENCH=OFF -DSNAXELS_WERROR=OFF
  cmake --build "$san_dir" -j2
  # strict_string_checks makes AddressSanitizer report a string function
  # given a buffer without a terminating NUL even when it reads nothing past
  # the end. Our code is held to that in the test run; Assimp's readers call
  # strtol on unterminated line buffers (a digit followed by a newline at the
  # end of the buffer: fuzz/regressions/mesh/obj-strtol-unterminated), so the
  # fuzzers, which run Assimp in-process, report only bytes really read out
  # of bounds.
  if [ "$action" = sanitize ]; then
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:strict_string_checks=1
  else
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0
  fi
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  export LSAN_OPTIONS=suppressions=$PWD/scripts/lsan.supp:print_suppressions=0
  export SNAXELS_SANITIZER_BUILD=1 # tests/cli/importer_limits.sh: no memory limit to check
  if [ "$action" = sanitize ]; then
    cd "$san_dir" && exec ctest --output-on-failure -j2 --timeout 1800 -L 'core|cli'
  fi
  exec bash scripts/fuzz.sh "$san_dir/fuzz" "${1:-60}"
fi

build_dir=${SNAXELS_BUILD_DIR:-build}
werror=OFF
if [ "${CI:-}" = "true" ]; then werror=ON; fi
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSNAXELS_WERROR="$werror"
cmake --build "$build_dir" -j2

case "$action" in
  run) exec "$build_dir/bin/snaxels" "$@" ;;
  # The 10,000-frame soak (label soak) is left out: ctest -L soak runs it.
  test) cd "$build_dir" && exec ctest --output-on-failure -j2 --timeout 900 -LE '^soak$' ;;
  build) ;;
  robot)
    seed=${2:-$RANDOM}
    exec xvfb-run -a -s "-screen 0 1280x800x24" "$build_dir/bin/snaxels-robot" --seconds "${1:-60}" --seed "$seed" \
      --log "robot-$seed.log" ;;
esac
