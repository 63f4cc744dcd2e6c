#!/usr/bin/env bash
# Shows that a change changed no output: builds snaxels-cli at a reference
# commit beside the working tree, runs the same fixed set of commands with
# both builds (every bundled mesh x every preset x both planar maps, two
# views; contours JSON with every kind; info reports; turntables, orbiting
# lights and clips as animated SVG and Lottie; a project render) and
# compares the outputs byte for byte, leaving aside only the timing fields
# of JSON outputs ("ms" and keys ending in "_ms").
#
#   scripts/compare-outputs.sh [REF]        REF: a commit (default HEAD)
#
# Environment:
#   SNAXELS_BUILD_DIR     the working tree's build (default build/); its
#                         snaxels-cli and snaxels-import are rebuilt first
#   SNAXELS_COMPARE_DIR   where the reference source, build and outputs go
#                         (default build-compare/)
#   SNAXELS_COMPARE_QUICK=1  one mesh per preset instead of all (a smoke run)
#   SNAXELS_COMPARE_REF_CLI  a snaxels-cli already built from REF (with its
#                         snaxels-import beside it), used instead of
#                         building REF again
#
# The reference's outputs are kept in SNAXELS_COMPARE_DIR keyed by its
# commit and by a hash of the inputs (commands, meshes, styles), so a second
# comparison against the same commit reuses them. Both sides read the
# working tree's inputs, so only the programs differ. Exit 0 when every
# output is identical, 1 when one differs (each is named), 2 on a usage or
# build error.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

ref=${1:-HEAD}
if ! sha=$(git rev-parse --verify --quiet "$ref^{commit}"); then
  echo "compare-outputs: '$ref' is not a commit" >&2
  exit 2
fi
work=${SNAXELS_COMPARE_DIR:-build-compare}
new_build=${SNAXELS_BUILD_DIR:-build}
mkdir -p "$work"
work=$(cd "$work" && pwd)

# The fixed set: one line per output, "NAME<TAB>ARGS" where ARGS is a
# snaxels-cli command line whose output file is written as @OUT@.
command_list() {
  local meshes=(tests/assets/spot.obj tests/assets/teapot.obj tests/assets/fandisk.obj
                tests/assets/suzanne.obj tests/assets/stanford-bunny.obj tests/assets/horse.ply)
  if [ "${SNAXELS_COMPARE_QUICK:-}" = 1 ]; then meshes=(tests/assets/spot.obj); fi
  local presets=(styles/*.xml)
  local m p base style map
  for m in "${meshes[@]}"; do
    base=$(basename "${m%.*}")
    printf 'info-%s.json\tinfo %s --json\n' "$base" "$m"
    printf 'kinds-%s.json\tcontours %s --view-dir 1,-0.5,-2 --kind visual --kind shadow --kind isophote:0.4 --kind gleam:0.9 --kind crease --kind border --kind suggestive --json @OUT@\n' "$base" "$m"
    printf 'kinds-novis-%s.json\tcontours %s --eye 0,0.5,3 --kind visual --kind suggestive --no-visibility --json @OUT@\n' "$base" "$m"
    for p in "${presets[@]}"; do
      style=$(basename "${p%.xml}")
      # parabolic-folds searches the whole view sphere: once per mesh is enough.
      for map in snaxel post; do
        printf '%s-%s-%s.svg\tcontours %s --style %s --planar-map %s --view-dir -0.3,-0.2,-1 --svg @OUT@\n' \
          "$base" "$style" "$map" "$m" "$p" "$map"
      done
      if [ "$style" != parabolic-folds ]; then
        printf '%s-%s-persp.json\tcontours %s --style %s --planar-map snaxel --eye 1.5,1,2.5 --json @OUT@\n' \
          "$base" "$style" "$m" "$p"
      fi
    done
  done
  local anim_meshes=(tests/assets/spot.obj tests/assets/horse.ply tests/assets/teapot.obj)
  local anim_styles=(toon ink-outline coherent-dashes technical-drawing)
  if [ "${SNAXELS_COMPARE_QUICK:-}" = 1 ]; then anim_meshes=(tests/assets/spot.obj); anim_styles=(toon); fi
  for m in "${anim_meshes[@]}"; do
    base=$(basename "${m%.*}")
    for style in "${anim_styles[@]}"; do
      printf 'turntable-%s-%s.svg\tanimate %s --style styles/%s.xml --turntable 3 --frames 40 -o @OUT@\n' "$base" "$style" "$m" "$style"
      printf 'turntable-%s-%s.json\tanimate %s --style styles/%s.xml --turntable 3 --frames 40 -o @OUT@\n' "$base" "$style" "$m" "$style"
    done
    printf 'lightorbit-%s.svg\tanimate %s --style styles/shading-lines.xml --light-orbit 6 --frames 30 -o @OUT@\n' "$base" "$m"
    printf 'stats-%s.json\tanimate %s --kind visual --kind shadow --turntable 2 --frames 60 --planar-map post -o @OUT@.svg --stats @OUT@\n' "$base" "$m"
    printf 'events-%s.json\tanimate %s --kind visual --kind suggestive --turntable 2 --frames 60 -o @OUT@.json --events @OUT@\n' "$base" "$m"
  done
  local clip
  for clip in "tests/assets/anim/Testwuson.X" "tests/assets/anim/morph-ball.gltf" "tests/assets/anim/skinned-bar.gltf"; do
    base=$(basename "${clip%.*}")
    printf 'clip-%s.svg\tanimate %s --clip 0 --frames 30 --style styles/pencil-sketch.xml -o @OUT@\n' "$base" "$clip"
    printf 'clip-%s.json\tanimate %s --clip 0 --frames 30 --style styles/toon.xml -o @OUT@\n' "$base" "$clip"
  done
  printf 'render-spot-turntable.svg\trender tests/assets/projects/spot-turntable.snaxels -o @OUT@\n'
  printf 'render-spot-turntable.json\trender tests/assets/projects/spot-turntable.snaxels -o @OUT@\n'
  printf 'render-spot-still.svg\trender tests/assets/projects/spot-turntable.snaxels --still -o @OUT@\n'
  printf 'parabolic-spot.json\tparabolic tests/assets/spot.obj --samples 300 --json @OUT@\n'
  printf 'parabolic-fandisk.json\tparabolic tests/assets/fandisk.obj --samples 300 --smoothing 0.05 --json @OUT@\n'
}

# Runs the set with the snaxels-cli in $1 into folder $2 (two at a time).
run_set() {
  local cli=$1 out=$2
  rm -rf "$out"
  mkdir -p "$out"
  command_list | while IFS=$'\t' read -r name args; do
    printf '%s\t%s\n' "$name" "${args//@OUT@/$out/$name}"
  done > "$out.commands"
  # Each line: run it, keeping its exit code and messages beside the output.
  # shellcheck disable=SC2016
  tr '\n' '\0' < "$out.commands" | xargs -0 -P 2 -I{} bash -c '
    line=$1; name=${line%%$'"'"'\t'"'"'*}; args=${line#*$'"'"'\t'"'"'}
    cd "$3"
    # shellcheck disable=SC2086
    if [ "${name#info-}" != "$name" ]; then
      "$2" $args > "$4/$name" 2> "$4/$name.err"; echo $? > "$4/$name.exit"
    else
      "$2" $args > /dev/null 2> "$4/$name.err"; echo $? > "$4/$name.exit"
    fi' _ {} "$cli" "$root" "$out"
}

inputs_hash() {
  { command_list; git -C "$root" ls-files -s styles tests/assets resources; git -C "$root" diff HEAD -- styles tests/assets resources
    } | sha256sum | cut -c1-16
}

build_cli() { # build_cli SOURCE BUILD
  if [ ! -f "$2/build.ninja" ]; then
    cmake -S "$1" -B "$2" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSNAXELS_BUILD_TESTS=OFF \
      -DSNAXELS_BUILD_BENCH=OFF -DSNAXELS_BUILD_GUI=OFF > "$2.configure.log" 2>&1 ||
      { echo "compare-outputs: configuring $1 failed: see $2.configure.log" >&2; exit 2; }
  fi
  cmake --build "$2" -j2 --target snaxels-cli snaxels-import > "$2.build.log" 2>&1 ||
    { echo "compare-outputs: building $1 failed: see $2.build.log" >&2; exit 2; }
}

short=${sha:0:12}
hash=$(inputs_hash)
ref_out="$work/out-$short-$hash"
if [ ! -f "$ref_out.done" ] && [ -n "${SNAXELS_COMPARE_REF_CLI:-}" ]; then
  echo "compare-outputs: running the set with $SNAXELS_COMPARE_REF_CLI as $short"
  run_set "$(cd "$(dirname "$SNAXELS_COMPARE_REF_CLI")" && pwd)/$(basename "$SNAXELS_COMPARE_REF_CLI")" "$ref_out"
  touch "$ref_out.done"
elif [ ! -f "$ref_out.done" ]; then
  src="$work/src-$short"
  if [ ! -d "$src" ]; then
    mkdir -p "$src.tmp"
    git archive "$sha" | tar -x -C "$src.tmp"
    mv "$src.tmp" "$src"
  fi
  echo "compare-outputs: building $short in $work/build-$short"
  build_cli "$src" "$work/build-$short"
  echo "compare-outputs: running the set with $short"
  run_set "$work/build-$short/bin/snaxels-cli" "$ref_out"
  touch "$ref_out.done"
fi

echo "compare-outputs: building the working tree in $new_build"
if [ -f "$new_build/build.ninja" ]; then
  cmake --build "$new_build" -j2 --target snaxels-cli snaxels-import > "$work/new.build.log" 2>&1 ||
    { echo "compare-outputs: building the working tree failed: see $work/new.build.log" >&2; exit 2; }
else
  build_cli "$root" "$new_build"
fi
new_out="$work/out-working"
echo "compare-outputs: running the set with the working tree"
run_set "$root/$new_build/bin/snaxels-cli" "$new_out"

python3 - "$ref_out" "$new_out" "$short" <<'EOF'
import json, os, sys
ref, new, short = sys.argv[1:4]

def strip_timing(v):
    if isinstance(v, dict):
        return {k: strip_timing(x) for k, x in v.items() if not (k == "ms" or k.endswith("_ms"))}
    if isinstance(v, list):
        return [strip_timing(x) for x in v]
    return v

def same(a, b):
    with open(a, "rb") as f: da = f.read()
    with open(b, "rb") as f: db = f.read()
    if da == db:
        return True
    if a.endswith(".json"):
        try:
            return strip_timing(json.loads(da)) == strip_timing(json.loads(db))
        except ValueError:
            return False
    return False

names = sorted(n for n in os.listdir(ref) if not n.endswith((".err", ".exit")))
runs = sorted(n[:-5] for n in os.listdir(ref) if n.endswith(".exit"))
differ, failed = [], []
for n in runs:
    code = open(os.path.join(ref, n + ".exit")).read().strip()
    if code != "0":
        failed.append(n)
    if not os.path.exists(os.path.join(new, n + ".exit")) or open(os.path.join(new, n + ".exit")).read().strip() != code:
        differ.append(n + " (exit code)")
for n in names:
    if not os.path.exists(os.path.join(new, n)):
        differ.append(n + " (missing)")
    elif not same(os.path.join(ref, n), os.path.join(new, n)):
        differ.append(n)
for n in failed:
    print(f"compare-outputs: note: {n} failed with {short} too: " + open(os.path.join(ref, n + '.err')).read().strip()[:200])
print(f"compare-outputs: {len(names) - len(differ)} of {len(names)} outputs identical to {short}'s"
      + (" (timing fields aside)" if names else ""))
for d in differ:
    print(f"  differs: {d}")
sys.exit(1 if differ or not names else 0)
EOF
