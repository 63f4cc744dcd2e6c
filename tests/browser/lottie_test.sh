#!/usr/bin/env bash
# The Lottie export played by lottie-web (in headless Chromium) and rlottie:
# valid against the Lottie community schema; lottie-web at 12 frame times
# against the same frames' static SVGs, rlottie against lottie-web (98% of
# stroke pixels within 2 px both ways, and each fill colour given, all but
# 8 of its pixels in a cell if fewer than 2%: see compare_grid).
#   lottie_test.sh CLI COMPARE RLOTTIE PLAYERS OUTDIR NAME MESH FRAMES FPS -- ANIMATE-OPTIONS...
# PLAYERS is tests/players (the vendored lottie-web and schema, validate.py).
# FRAMES 0: the clip's own length. FILLS="#RRGGBB ..." in the environment:
# fill colours to compare. TIME_MS=LIMIT: also export at the style's canvas
# size and time goToAndStop over every frame in lottie-web, with the style
# and layout it causes; the median must be under LIMIT. DOTLOTTIE=1: export
# the dotLottie container (.lottie) instead, check its zip and manifest, and
# play the animation unzipped from it.
set -euo pipefail
cli=$1; compare=$2; rlottie=$3; players=$4; outdir=$5; name=$6; mesh=$7; frames=$8; fps=$9; shift 10
here=$(dirname "$0")
# shellcheck source=grid_pages.sh
. "$here/grid_pages.sh"
# shellcheck source=../players/lottie_pages.sh
. "$players/lottie_pages.sh"
dir="$outdir/$name"
rm -rf "$dir"; mkdir -p "$dir"
cell=400; cols=4; rows=3; shots=$((cols * rows))
frame_args=()
if [ "$frames" != 0 ]; then frame_args=(--frames "$frames"); fi
if [ "${DOTLOTTIE:-}" = 1 ]; then
  "$cli" animate "$mesh" "${frame_args[@]}" --fps "$fps" --size ${cell}x${cell} -o "$dir/anim.lottie" \
    --frames-dir "$dir/frames" "$@"
  python3 "$here/../outputs/dotlottie_check.py" "$dir/anim.lottie" "$dir/anim.json"
else
  "$cli" animate "$mesh" "${frame_args[@]}" --fps "$fps" --size ${cell}x${cell} -o "$dir/anim.json" \
    --frames-dir "$dir/frames" "$@"
fi
count=$(ls "$dir/frames" | wc -l)

"$players/validate.py" "$dir/anim.json"

picks=()
for ((i = 0; i < shots; i++)); do picks+=($(( i * (count - 1) / (shots - 1) ))); done
echo "frames compared: ${picks[*]}"
lottie_grid_page "$dir/lottie-web.html" "$dir/anim.json" $cols $cell "${picks[@]}"
result=$(bash "$here/dump_dom.sh" "$dir/lottie-web.html" $((cols * cell)) $((rows * cell)) | lottie_result)
[ "$result" = ok ] || { echo "FAIL: lottie-web: $result"; exit 1; }
bash "$here/render_svg.sh" "$dir/lottie-web.html" "$dir/lottie-web.png" $((cols * cell)) $((rows * cell))
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
  lottie_timing_page "$dir/timing.html" "$dir/full.json" 3
  w=$(grep -o '"w":[0-9]*' "$dir/full.json" | head -1 | cut -d: -f2)
  timing=$(bash "$here/dump_dom.sh" "$dir/timing.html" 1000 1000 | lottie_result)
  echo "goToAndStop at the style's canvas size, ${w}px wide ($(stat -c %s "$dir/full.json") bytes): $timing"
  # The median of goToAndStop with the style and layout it causes.
  median=$(echo "$timing" | sed -n 's/.*"with_layout":{"median_ms":\([0-9.e-]*\).*/\1/p')
  [ -n "$median" ] || { echo "FAIL: no timing from the page"; exit 1; }
  awk -v m="$median" -v limit="$TIME_MS" 'BEGIN { exit !(m < limit) }' ||
    { echo "FAIL: median goToAndStop $median ms, the limit is $TIME_MS ms"; exit 1; }
fi
