#!/usr/bin/env bash
# A video's settings: --video-width sets the frames' width (the height by
# the canvas's aspect, here a 16:9 canvas), and --crf its quality: a lower
# CRF makes a bigger file of the same frames. ffprobe reads what was written.
#   video_settings_test.sh CLI MESH OUTDIR
set -euo pipefail
cli=$1; mesh=$2; outdir=$3
command -v ffprobe >/dev/null || { echo "ffprobe is not installed (scripts/install-deps.sh installs ffmpeg)"; exit 1; }
dir="$outdir/video-settings"
rm -rf "$dir"; mkdir -p "$dir"
for crf in 12 40; do
  "$cli" animate "$mesh" --turntable 6 --frames 8 --size 800x450 --video-width 320 --crf "$crf" -o "$dir/spot-$crf.mp4" >/dev/null
done
size=$(ffprobe -v error -select_streams v:0 -show_entries stream=width,height -of csv=p=0 "$dir/spot-12.mp4")
[ "$size" = "320,180" ] || { echo "frames are $size, expected 320,180"; exit 1; }
fine=$(stat -c %s "$dir/spot-12.mp4"); coarse=$(stat -c %s "$dir/spot-40.mp4")
[ "$fine" -gt "$coarse" ] || { echo "--crf 12 wrote $fine bytes, --crf 40 $coarse: a lower CRF must be bigger"; exit 1; }
# Out of range: refused before any work, nothing written.
if "$cli" animate "$mesh" --turntable 6 --frames 2 --crf 99 -o "$dir/bad.mp4" 2>"$dir/err.txt"; then
  echo "--crf 99 was taken"; exit 1
fi
grep -q "crf" "$dir/err.txt" || { echo "the error does not name --crf: $(cat "$dir/err.txt")"; exit 1; }
[ ! -e "$dir/bad.mp4" ] || { echo "a refused video was written"; exit 1; }
echo "320x180 frames; CRF 12: $fine bytes, CRF 40: $coarse bytes"
