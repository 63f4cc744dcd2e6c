#!/usr/bin/env bash
# A camera inside the scene (tests/assets/interior/walk.gltf: a ground far
# larger than the camera's distance, a pillar it passes 0.1 m from): the
# 120-frame move exports with no refusal; at 14 frame times (every tenth
# frame, and the two where the pillar's outline crosses the near plane) the
# drawing matches the oracle's near-clipped z-buffer (near_plane_check),
# the static frames and the animated SVG alike, and each tracked frame is
# the frame drawn from scratch (a one-frame export starting there), byte
# for byte. (Frames 110 and 111, the eye 3 to 15 cm from the ring's tube of
# 12 facets, are beyond a faceted oracle: the drawn arc and the facets'
# outline are the same curve 5 to 10 px apart there.)
#   near_plane_test.sh CLI CHECKER SCENE OUTDIR
set -euo pipefail
cli=$1; checker=$2; scene=$3; out=$4
frames=(5 15 25 35 45 55 58 60 65 75 85 95 105 115)
rm -rf "$out"; mkdir -p "$out"
"$cli" animate "$scene" --camera WalkCam --kind visual -o "$out/walk.svg" --frames-dir "$out/tracked"
test -f "$out/tracked/frame_00120.svg" || { echo "the export stopped before frame 120"; exit 1; }
for k in "${frames[@]}"; do
  "$cli" animate "$scene" --camera WalkCam --kind visual --start "$k" --frames 1 -o "$out/scratch-$k.svg" \
    --frames-dir "$out/scratch-$k" > /dev/null
  cmp -s "$out/scratch-$k/frame_00000.svg" "$out/tracked/$(printf 'frame_%05d.svg' "$k")" ||
    { echo "frame $k: the tracked frame differs from the frame drawn from scratch"; exit 1; }
done
echo "${#frames[@]} tracked frames equal those drawn from scratch"
"$checker" "$scene" WalkCam 24 "$out/tracked" "$out/walk.svg" 0.95 "${frames[@]}"
