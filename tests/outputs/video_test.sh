#!/usr/bin/env bash
# Video and image outputs: the animation exported as MP4, WebM and GIF and
# as a folder of PNGs. ffprobe must report the frame count, size and rate
# asked for; 12 frames decoded from each (and 12 of the PNGs), tiled 4 x 3,
# must match Chromium's render of the same static frame SVGs (at least 97%
# of ink pixels within 2 px both ways, in every cell: compare_grid).
#   video_test.sh CLI COMPARE BROWSER OUTDIR MESH FRAMES -- ANIMATE-OPTIONS...
# BROWSER is tests/browser (render_svg.sh, grid_pages.sh).
set -euo pipefail
cli=$1; compare=$2; browser=$3; outdir=$4; mesh=$5; frames=$6
shift 7
for p in ffmpeg ffprobe; do
  command -v $p >/dev/null || { echo "$p is not installed (scripts/install-deps.sh installs ffmpeg)"; exit 1; }
done
# shellcheck source=../browser/grid_pages.sh
. "$browser/grid_pages.sh"
dir="$outdir/video"
rm -rf "$dir"; mkdir -p "$dir"
cell=400; cols=4; rows=3; shots=$((cols * rows))
picks=()
for ((i = 0; i < shots; i++)); do picks+=($(( i * (frames - 1) / (shots - 1) ))); done
select=""
for f in "${picks[@]}"; do select+="${select:+ + }eq(n\\,$f)"; done
echo "frames compared: ${picks[*]}"

# Chromium's render of the static frames (written by the MP4 run).
status=0
check_probe() { # FILE FPS: frame count, size and rate
  local got want
  got=$(ffprobe -v error -count_frames -select_streams v:0 \
    -show_entries stream=width,height,r_frame_rate,nb_read_frames -of csv=p=0 "$1")
  want="$cell,$cell,$2/1,$frames"
  if [ "$got" = "$want" ]; then echo "$(basename "$1"): $got (width,height,rate,frames)"
  else echo "FAIL: $(basename "$1"): ffprobe says $got (width,height,rate,frames), asked for $want"; status=1; fi
}
check_frames() { # INPUT... : 12 frames of INPUT tiled, against Chromium's static frames
  local name=$1; shift
  ffmpeg -v error -y "$@" -vf "select='$select',tile=${cols}x${rows}" -frames:v 1 "$dir/$name-grid.png"
  echo "$name against Chromium's static frames:"
  QT_QPA_PLATFORM=offscreen "$compare" "$dir/$name-grid.png" "$dir/static.png" $cols $rows $cell 2 0.97 || status=1
}

"$cli" animate "$mesh" --frames "$frames" --size ${cell}x${cell} -o "$dir/anim.mp4" --frames-dir "$dir/frames" "$@"
frames_page "$dir/static.html" $cols $cell frames "${picks[@]}"
bash "$browser/render_svg.sh" "$dir/static.html" "$dir/static.png" $((cols * cell)) $((rows * cell))
check_probe "$dir/anim.mp4" 24
check_frames mp4 -i "$dir/anim.mp4"

"$cli" animate "$mesh" --frames "$frames" --size ${cell}x${cell} -o "$dir/anim.webm" --png-dir "$dir/pngs" "$@"
check_probe "$dir/anim.webm" 24
check_frames webm -i "$dir/anim.webm"
count=$(find "$dir/pngs" -name 'frame_*.png' | wc -l)
[ "$count" = "$frames" ] || { echo "FAIL: --png-dir wrote $count PNGs for $frames frames"; status=1; }
check_frames png -framerate 24 -i "$dir/pngs/frame_%05d.png"

# A GIF's delays are hundredths of a second: 25 fps is exact.
"$cli" animate "$mesh" --frames "$frames" --fps 25 --size ${cell}x${cell} -o "$dir/anim.gif" "$@"
check_probe "$dir/anim.gif" 25
check_frames gif -i "$dir/anim.gif"

# An unwritable place fails before the work and leaves nothing behind.
if "$cli" animate "$mesh" --frames "$frames" -o "$dir/no/such/folder/anim.mp4" "$@" 2> "$dir/err.txt"; then
  echo "FAIL: a video into a missing folder succeeded"; status=1
fi
grep -q "does not exist" "$dir/err.txt" || { echo "FAIL: the message does not name the problem: $(cat "$dir/err.txt")"; status=1; }
exit $status
