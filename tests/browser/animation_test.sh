#!/usr/bin/env bash
# The animated SVG, seeked in Chromium (pauseAnimations, setCurrentTime) to
# 12 frame times, against the same frames' static SVGs.
#   animation_test.sh CLI COMPARE OUTDIR NAME MESH FRAMES FPS -- ANIMATE-OPTIONS...
# With FILLS="#RRGGBB ..." in the environment the fills of those colours are
# compared too (a style with region fills); FILLS=auto takes every fill
# colour of the static frames but white (fills of material colours), and
# FILL_SLACK=N lets a colour agree in a cell where at most N of its pixels
# do not (fills under a pixel or two wide, whose antialiased pixels reach
# the colour or not as the outline moves by a fraction of a pixel).
set -euo pipefail
cli=$1; compare=$2; outdir=$3; name=$4; mesh=$5; frames=$6; fps=$7; shift 8
here=$(dirname "$0")
# shellcheck source=grid_pages.sh
. "$here/grid_pages.sh"
dir="$outdir/$name"
rm -rf "$dir"; mkdir -p "$dir"
cell=400; cols=4; rows=3; shots=$((cols * rows))
"$cli" animate "$mesh" --frames "$frames" --fps "$fps" --size ${cell}x${cell} -o "$dir/anim.svg" \
  --frames-dir "$dir/frames" "$@"

# FILLS=auto: every fill colour the static frames use but the background's.
if [ "${FILLS:-}" = auto ]; then
  FILLS=$(grep -oh 'fill="#[0-9a-fA-F]\{6\}"' "$dir"/frames/*.svg | tr 'A-F' 'a-f' | sort -u |
    sed 's/fill="\(.*\)"/\1/' | grep -v '^#ffffff$' | tr '\n' ' ')
  echo "fill colours: $FILLS"
fi

# Frame numbers spread over the animation, including the first and the last.
picks=()
for ((i = 0; i < shots; i++)); do picks+=($(( i * (frames - 1) / (shots - 1) ))); done

# One page with the animated SVG inlined once per cell, each seeked to its frame.
seek_page "$dir/animated.html" "$dir/anim.svg" $cols $cell "$fps" 0.02 "${picks[@]}"
frames_page "$dir/static.html" $cols $cell frames "${picks[@]}"

bash "$here/render_svg.sh" "$dir/animated.html" "$dir/animated.png" $((cols * cell)) $((rows * cell))
bash "$here/render_svg.sh" "$dir/static.html" "$dir/static.png" $((cols * cell)) $((rows * cell))
echo "frames compared: ${picks[*]}"
# shellcheck disable=SC2086 # FILLS is a list of colours
slack=()
[ -n "${FILL_SLACK:-}" ] && slack=(--fill-slack "$FILL_SLACK")
QT_QPA_PLATFORM=offscreen "$compare" "${slack[@]}" "$dir/animated.png" "$dir/static.png" $cols $rows $cell 2 0.97 ${FILLS:-}

# Fills half way between frames: within what the two frames cover, and
# covering what both do (interpolated outlines must not bleed or tear).
if [ -n "${FILLS:-}" ]; then
  between=()
  for f in "${picks[@]}"; do between+=($(( f < frames - 1 ? f : frames - 2 ))); done
  seek_page "$dir/between.html" "$dir/anim.svg" $cols $cell "$fps" 0.5 "${between[@]}"
  for which in 0 1; do
    shifted=()
    for g in "${between[@]}"; do shifted+=($((g + which))); done
    frames_page "$dir/static$which.html" $cols $cell frames "${shifted[@]}"
    bash "$here/render_svg.sh" "$dir/static$which.html" "$dir/static$which.png" $((cols * cell)) $((rows * cell))
  done
  bash "$here/render_svg.sh" "$dir/between.html" "$dir/between.png" $((cols * cell)) $((rows * cell))
  # shellcheck disable=SC2086
  QT_QPA_PLATFORM=offscreen "$compare" "${slack[@]}" --between "$dir/between.png" "$dir/static0.png" "$dir/static1.png" $cols $rows $cell 2 0.97 $FILLS
fi
