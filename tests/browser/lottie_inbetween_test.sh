#!/usr/bin/env bash
# Faithful in-betweens in lottie-web: a Lottie export at twice the step (2
# degrees a frame) seeked half way between its frames (goToAndStop at
# FRAME + 0.5) against the static frames of the export at the single step
# at that moment, and at its frame times against the frames that coincide;
# at least MIN of the stroke pixels of each within 2 px of the other's in
# every cell.
#   lottie_inbetween_test.sh CLI COMPARE PLAYERS OUTDIR NAME MESH FRAMES FPS SOURCE STEP MIN -- ANIMATE-OPTIONS...
# SOURCE: turntable or light-orbit, STEP degrees a frame at the fine step;
# FRAMES counts the coarse export's frames.
set -euo pipefail
cli=$1; compare=$2; players=$3; outdir=$4; name=$5; mesh=$6; frames=$7; fps=$8; source=$9; step=${10}; min=${11}
shift 12
here=$(dirname "$0")
# shellcheck source=grid_pages.sh
. "$here/grid_pages.sh"
# shellcheck source=../players/lottie_pages.sh
. "$players/lottie_pages.sh"
dir="$outdir/$name"
rm -rf "$dir"; mkdir -p "$dir"
cell=400; cols=4; rows=3; shots=$((cols * rows))
"$cli" animate "$mesh" --"$source" "$(awk "BEGIN{print 2*$step}")" --frames "$frames" --fps "$fps" \
  --size ${cell}x${cell} -o "$dir/coarse.json" "$@"
"$cli" animate "$mesh" --"$source" "$step" --frames $((2 * frames)) --fps "$fps" \
  --size ${cell}x${cell} -o "$dir/fine.svg" --frames-dir "$dir/frames" "$@" >/dev/null
"$players/validate.py" "$dir/coarse.json"
picks=()
for ((i = 0; i < shots; i++)); do picks+=($(( i * (frames - 2) / (shots - 1) ))); done
half=(); odd=(); even=()
for f in "${picks[@]}"; do half+=("$f.5"); odd+=($((2 * f + 1))); even+=($((2 * f))); done
echo "coarse frames (seeked half way after each): ${picks[*]}"
status=0
for which in half at; do
  if [ $which = half ]; then seek=("${half[@]}"); static=("${odd[@]}"); else seek=("${picks[@]}"); static=("${even[@]}"); fi
  lottie_grid_page "$dir/$which.html" "$dir/coarse.json" $cols $cell "${seek[@]}"
  result=$(bash "$here/dump_dom.sh" "$dir/$which.html" $((cols * cell)) $((rows * cell)) | lottie_result)
  [ "$result" = ok ] || { echo "FAIL: lottie-web: $result"; exit 1; }
  bash "$here/render_svg.sh" "$dir/$which.html" "$dir/$which.png" $((cols * cell)) $((rows * cell))
  frames_page "$dir/$which-static.html" $cols $cell frames "${static[@]}"
  bash "$here/render_svg.sh" "$dir/$which-static.html" "$dir/$which-static.png" $((cols * cell)) $((rows * cell))
  echo "lottie-web $which against the static frames:"
  QT_QPA_PLATFORM=offscreen "$compare" "$dir/$which.png" "$dir/$which-static.png" $cols $rows $cell 2 "$min" || status=1
done
exit $status
