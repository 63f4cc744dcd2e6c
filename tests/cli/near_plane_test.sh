#!/usr/bin/env bash
# A camera inside the scene (tests/assets/interior/walk.gltf: a ground far
# larger than the camera's distance, a pillar it passes 0.1 m from): the
# 120-frame move exports with no refusal; at 12 frame times the drawing
# matches the oracle's near-clipped z-buffer (near_plane_check), the static
# frames and the animated SVG alike, and each tracked frame is the frame
# drawn from scratch (a one-frame export starting there), byte for byte.
#   near_plane_test.sh CLI CHECKER SCENE OUTDIR
set -euo pipefail
cli=$1; checker=$2; scene=$3; out=$4
frames=(1 11 21 31 41 51 56 58 60 62 81 101)
rm -rf "$out"; mkdir -p "$out"
"$cli" animate "$scene" --camera WalkCam --kind visual -o "$out/walk.svg" --frames-dir "$out/tracked"
test -f "$out/tracked/frame_00120.svg" || { echo "the export stopped before frame 120"; exit 1; }
for k in "${frames[@]}"; do
  "$cli" animate "$scene" --camera WalkCam --kind visual --start "$k" --frames 1 -o "$out/scratch-$k.svg" \
    --frames-dir "$out/scratch-$k" > /dev/null
  cmp -s "$out/scratch-$k/frame_00000.svg" "$out/tracked/$(printf 'frame_%05d.svg' "$k")" ||
    { echo "frame $k: the tracked frame differs from the frame drawn from scratch"; exit 1; }
done
echo "12 tracked frames equal those drawn from scratch"
"$checker" "$scene" WalkCam 24 "$out/tracked" "$out/walk.svg" 0.95 "${frames[@]}"
