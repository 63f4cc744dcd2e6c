#!/usr/bin/env bash
# No dots and no crawling dashes: the animated SVG seeked in Chromium at
# every frame time draws no ink its static frame lacks (connected
# components of ink farther than 1 px from the static frame's ink, above 2
# square pixels: compare_grid --extra-ink).
#   extra_ink_test.sh CLI COMPARE OUTDIR NAME MESH FRAMES FPS -- ANIMATE-OPTIONS...
# OFFSET (frames, default 0.0002) is how far past each frame time the
# animation is seeked: less than the thousandth of a frame at which a
# segment hands over to the next.
set -euo pipefail
cli=$1; compare=$2; outdir=$3; name=$4; mesh=$5; frames=$6; fps=$7; shift 8
here=$(dirname "$0")
# shellcheck source=grid_pages.sh
. "$here/grid_pages.sh"
dir="$outdir/$name"
rm -rf "$dir"; mkdir -p "$dir"
cell=${CELL:-400}; cols=4; rows=3; shots=$((cols * rows))
offset=${OFFSET:-0.0002}
"$cli" animate "$mesh" --frames "$frames" --fps "$fps" --size ${cell}x${cell} -o "$dir/anim.svg" \
  --frames-dir "$dir/frames" "$@"
status=0
for ((first = 0; first < frames; first += shots)); do
  picks=()
  for ((f = first; f < first + shots; f++)); do picks+=($(( f < frames ? f : frames - 1 ))); done
  seek_page "$dir/animated-$first.html" "$dir/anim.svg" $cols $cell "$fps" "$offset" "${picks[@]}"
  frames_page "$dir/static-$first.html" $cols $cell frames "${picks[@]}"
  bash "$here/render_svg.sh" "$dir/animated-$first.html" "$dir/animated-$first.png" $((cols * cell)) $((rows * cell))
  bash "$here/render_svg.sh" "$dir/static-$first.html" "$dir/static-$first.png" $((cols * cell)) $((rows * cell))
  echo "frames ${picks[*]}:"
  QT_QPA_PLATFORM=offscreen "$compare" --extra-ink "$dir/animated-$first.png" "$dir/static-$first.png" $cols $rows $cell 1 2 |
    grep -v ' 0 components' || true
  QT_QPA_PLATFORM=offscreen "$compare" --extra-ink "$dir/animated-$first.png" "$dir/static-$first.png" $cols $rows $cell 1 2 \
    > /dev/null || status=1
done
exit $status
