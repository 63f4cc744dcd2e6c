#!/usr/bin/env bash
# The Lottie export played by lottie-web (in headless Chromium) and rlottie:
# valid against the Lottie community schema; lottie-web at 12 frame times
# against the same frames' static SVGs, rlottie against lottie-web (98% of
# stroke pixels within 2 px both ways, and each fill colour given, all but
# 8 of its pixels in a cell if fewer than 2%: see compare_grid).
#   lottie_test.sh CLI COMPARE RLOTTIE PLAYERS OUTDIR NAME MESH FRAMES FPS -- ANIMATE-OPTIONS...
# PLAYERS is tests/players (its node_modules installed by scripts/install-deps.sh).
# FILLS="#RRGGBB ..." in the environment: fill colours to compare.
# TIME_MS=LIMIT: also export at the style's canvas size and time
# goToAndStop over every frame in lottie-web, with the style and layout it
# causes; the median must be under LIMIT.
set -euo pipefail
cli=$1; compare=$2; rlottie=$3; players=$4; outdir=$5; name=$6; mesh=$7; frames=$8; fps=$9; shift 10
here=$(dirname "$0")
# shellcheck source=grid_pages.sh
. "$here/grid_pages.sh"
for m in lottie-web puppeteer-core ajv @lottie-animation-community/lottie-specs; do
  [ -d "$players/node_modules/$m" ] || { echo "FAIL: $players/node_modules/$m is missing: run scripts/install-deps.sh"; exit 1; }
done
command -v node >/dev/null || { echo "FAIL: node is not installed: run scripts/install-deps.sh"; exit 1; }
dir="$outdir/$name"
rm -rf "$dir"; mkdir -p "$dir"
cell=400; cols=4; rows=3; shots=$((cols * rows))
frame_args=()
if [ "$frames" != 0 ]; then frame_args=(--frames "$frames"); fi
"$cli" animate "$mesh" "${frame_args[@]}" --fps "$fps" --size ${cell}x${cell} -o "$dir/anim.json" \
  --frames-dir "$dir/frames" "$@"
count=$(ls "$dir/frames" | wc -l)

node "$players/validate.js" "$dir/anim.json" | tail -3

picks=()
for ((i = 0; i < shots; i++)); do picks+=($(( i * (count - 1) / (shots - 1) ))); done
echo "frames compared: ${picks[*]}"
node "$players/play.js" grid "$dir/anim.json" "$dir/lottie-web.png" $cell $cols "${picks[@]}"
frames_page "$dir/static.html" $cols $cell frames "${picks[@]}"
bash "$here/render_svg.sh" "$dir/static.html" "$dir/static.png" $((cols * cell)) $((rows * cell))
echo "lottie-web against the static frames:"
# shellcheck disable=SC2086 # FILLS is a list of colours
QT_QPA_PLATFORM=offscreen "$compare" --fill-slack 8 "$dir/lottie-web.png" "$dir/static.png" $cols $rows $cell 2 0.98 ${FILLS:-}

"$rlottie" "$dir/anim.json" "$dir/rlottie.png" $cell $cols "${picks[@]}"
echo "rlottie against lottie-web:"
# shellcheck disable=SC2086
QT_QPA_PLATFORM=offscreen "$compare" --fill-slack 8 "$dir/rlottie.png" "$dir/lottie-web.png" $cols $rows $cell 2 0.98 ${FILLS:-}

if [ -n "${TIME_MS:-}" ]; then
  "$cli" animate "$mesh" "${frame_args[@]}" --fps "$fps" -o "$dir/full.json" "$@" >/dev/null
  timing=$(node "$players/play.js" time "$dir/full.json" 3)
  echo "goToAndStop at the style's canvas size ($(stat -c %s "$dir/full.json") bytes): $timing"
  # The median of goToAndStop with the style and layout it causes.
  median=$(echo "$timing" | sed 's/.*"with_layout":{"median_ms":\([0-9.e-]*\).*/\1/')
  awk -v m="$median" -v limit="$TIME_MS" 'BEGIN { exit !(m < limit) }' ||
    { echo "FAIL: median goToAndStop $median ms, the limit is $TIME_MS ms"; exit 1; }
fi
