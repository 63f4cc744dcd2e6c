#!/usr/bin/env bash
# Faithful in-betweens: an animation exported at twice the step (2 degrees a
# frame, or half the frame rate for a clip), seeked in Chromium half way
# between two of its frames, against the static frame of the export at the
# single step at that moment; and at its frame times against the frames
# that coincide. At least MIN of the stroke pixels of each must lie within
# 2 px of the other's, in every cell.
#   inbetween_test.sh CLI COMPARE PERSISTENCE OUTDIR NAME MESH FRAMES FPS SOURCE STEP MIN -- ANIMATE-OPTIONS...
# SOURCE: turntable or light-orbit (STEP degrees a frame at the fine step),
# or clip:NAME (FRAMES and STEP ignored: the clip at FPS and at 2 x FPS).
# FRAMES counts the coarse export's frames. The coarse export's paths are
# also measured from the SVG (svg_persistence): with PERSIST="MIN_FRAMES
# SHARE MAX_ONE_FRAME" set, the stroke length carried by long-lived paths
# and the share of one-frame paths are checked too.
set -euo pipefail
cli=$1; compare=$2; persistence=$3; outdir=$4; name=$5; mesh=$6; frames=$7; fps=$8; source=$9; step=${10}; min=${11}
shift 12
here=$(dirname "$0")
# shellcheck source=grid_pages.sh
. "$here/grid_pages.sh"
dir="$outdir/$name"
rm -rf "$dir"; mkdir -p "$dir"
cell=400; cols=4; rows=3; shots=$((cols * rows))
case "$source" in
  clip:*)
    clip=${source#clip:}
    coarse=(--clip "$clip" --fps "$fps"); fine=(--clip "$clip" --fps "$(awk "BEGIN{print 2*$fps}")")
    ;;
  turntable | light-orbit)
    coarse=(--"$source" "$(awk "BEGIN{print 2*$step}")" --frames "$frames" --fps "$fps")
    fine=(--"$source" "$step" --frames $((2 * frames)) --fps "$fps")
    ;;
  *) echo "unknown source $source"; exit 2 ;;
esac
"$cli" animate "$mesh" "${coarse[@]}" --size ${cell}x${cell} -o "$dir/coarse.svg" "$@" | tee "$dir/coarse.txt"
"$cli" animate "$mesh" "${fine[@]}" --size ${cell}x${cell} -o "$dir/fine.svg" --frames-dir "$dir/frames" "$@" >/dev/null
frames=$(sed -n 's/.*: \([0-9]*\) frames at.*/\1/p' "$dir/coarse.txt")
fps_used=$(sed -n 's/.* frames at \([0-9.]*\) fps.*/\1/p' "$dir/coarse.txt")

picks=()
for ((i = 0; i < shots; i++)); do picks+=($(( i * (frames - 2) / (shots - 1) ))); done

odd=(); even=()
for f in "${picks[@]}"; do odd+=($((2 * f + 1))); even+=($((2 * f))); done
seek_page "$dir/half.html" "$dir/coarse.svg" $cols $cell "$fps_used" 0.5 "${picks[@]}"
frames_page "$dir/half-static.html" $cols $cell frames "${odd[@]}"
seek_page "$dir/at.html" "$dir/coarse.svg" $cols $cell "$fps_used" 0.02 "${picks[@]}"
frames_page "$dir/at-static.html" $cols $cell frames "${even[@]}"
for p in half half-static at at-static; do
  bash "$here/render_svg.sh" "$dir/$p.html" "$dir/$p.png" $((cols * cell)) $((rows * cell))
done
echo "coarse frames (seeked half way after each): ${picks[*]}"
status=0
echo "half way between frames:"
QT_QPA_PLATFORM=offscreen "$compare" "$dir/half.png" "$dir/half-static.png" $cols $rows $cell 2 "$min" || status=1
echo "at frame times:"
QT_QPA_PLATFORM=offscreen "$compare" "$dir/at.png" "$dir/at-static.png" $cols $rows $cell 2 0.99 || status=1
if [ -n "${PERSIST:-}" ]; then
  read -r pmin pshare pone <<<"$PERSIST"
  "$persistence" "$dir/coarse.svg" "$frames" --strokes "$pmin" "$pshare" --one-frame "$pone" --frame0-only || status=1
fi
exit $status
