#!/usr/bin/env bash
# The quality report over a corpus of real files (docs/quality.md): every
# independent check of the test suite (tests/quality/quality.cpp) on every
# asset of the corpus, the worst asset and view of each check first.
#
#   scripts/quality.sh                 the whole corpus; writes docs/quality.md,
#                                      docs/quality.json and the worst cases'
#                                      pictures (docs/images/quality/)
#   scripts/quality.sh --ci            the ratchet: the subset of
#                                      tests/quality/ratchet.json, each check's
#                                      worst view held to its threshold
#   scripts/quality.sh --ci --update   the same, writing the thresholds measured
#
# The corpus (docs/quality.md, "The corpus"): the bundled meshes and scenes
# of tests/assets, the scenes tests/quality/make_scenes.py writes with
# Blender, a procedural scan, and every file of Debian's assimp-testmodels
# that loads and has faces, read where the package installs them.
# Environment: BUILD (default SNAXELS_BUILD_DIR, else build), QUALITY_OUT (default BUILD/quality),
# QUALITY_JOBS (default 2), QUALITY_TIMEOUT (seconds per asset, default 300).
set -euo pipefail

here="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD:-${SNAXELS_BUILD_DIR:-$here/build}}"
out="${QUALITY_OUT:-$build/quality}"
jobs="${QUALITY_JOBS:-2}"
timeout="${QUALITY_TIMEOUT:-300}"
ci=0
update=0
for a in "$@"; do
  case "$a" in
    --ci) ci=1 ;;
    --update) update=1 ;;
    *) echo "quality.sh: unknown option $a (--ci, --update)" >&2; exit 2 ;;
  esac
done

if [ "$ci" = 0 ]; then bash "$here/scripts/install-deps.sh" --quality; fi
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
fi
cmake --build "$build" -j2 --target snaxels-quality
tool="$build/tests/snaxels-quality"
mkdir -p "$out/results"

corpus="$out/corpus.txt"
if [ "$ci" = 1 ]; then
  python3 "$here/tests/quality/report.py" ci-corpus "$here" > "$corpus"
else
  # The Blender scenes, written again when their script changes.
  stamp="$(sha1sum "$here/tests/quality/make_scenes.py" | cut -c1-12)"
  if [ ! -f "$out/scenes/.stamp-$stamp" ]; then
    rm -rf "$out/scenes"
    mkdir -p "$out/scenes"
    echo "quality: writing the Blender scenes"
    blender -b -P "$here/tests/quality/make_scenes.py" -- "$out/scenes" > "$out/scenes.log" 2>&1 ||
      { echo "quality: Blender failed, see $out/scenes.log" >&2; exit 1; }
    touch "$out/scenes/.stamp-$stamp"
  fi
  python3 "$here/tests/quality/report.py" corpus "$here" "$out/scenes" > "$corpus"
fi

n=$(wc -l < "$corpus")
echo "quality: $n assets, $jobs at a time, results in $out/results"
rm -f "$out/results/"*.json
start=$(date +%s)
# One process per asset: its peak memory is its own. An asset that fails or
# runs out of time is recorded as such (the report lists it).
parallel -j"$jobs" --colsep '\t' --joblog "$out/joblog.txt" \
  bash "$here/tests/quality/run_one.sh" "$tool" "$out/results" "$timeout" {1} {2} < <(cut -f1,2 "$corpus")
echo "quality: checks done in $(( $(date +%s) - start )) s"

if [ "$ci" = 1 ]; then
  args=()
  if [ "$update" = 1 ]; then args+=(--update); fi
  python3 "$here/tests/quality/report.py" ratchet "$here" "$corpus" "$out/results" "${args[@]}"
else
  python3 "$here/tests/quality/report.py" report "$here" "$corpus" "$out/results" "$tool" "$out"
fi
