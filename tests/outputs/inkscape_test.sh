#!/usr/bin/env bash
# Editors: Inkscape (Debian's) opens the static and the animated SVG. Its
# PNG export of each must match Chromium's frame 0 of the animation (97% of
# ink pixels within 2 px both ways, each fill colour given likewise), and
# the layers the SVG names (fills, hidden and visible lines, a sublayer per
# kind) must be layers in the document Inkscape saves back, with their labels.
#   inkscape_test.sh CLI COMPARE BROWSER OUTDIR MESH FRAMES FILLS -- ANIMATE-OPTIONS...
set -euo pipefail
cli=$1; compare=$2; browser=$3; outdir=$4; mesh=$5; frames=$6; fills=$7
shift 8
here=$(dirname "$0")
command -v inkscape >/dev/null || { echo "inkscape is not installed (scripts/install-deps.sh installs it)"; exit 1; }
# shellcheck source=../browser/grid_pages.sh
. "$browser/grid_pages.sh"
dir="$outdir/inkscape"
rm -rf "$dir"; mkdir -p "$dir"
size=400
export HOME="$dir/home" # Inkscape keeps its preferences there
mkdir -p "$HOME"
"$cli" animate "$mesh" --frames "$frames" --size ${size}x${size} -o "$dir/anim.svg" --frames-dir "$dir/frames" "$@"
cp "$dir/frames/frame_00000.svg" "$dir/static.svg"
seek_page "$dir/frame0.html" "$dir/anim.svg" 1 $size 24 0 0
bash "$browser/render_svg.sh" "$dir/frame0.html" "$dir/chromium.png" $size $size
status=0
for name in static anim; do
  inkscape --export-type=png --export-filename="$dir/$name-inkscape.png" --export-width=$size --export-height=$size \
    --export-background=white --export-background-opacity=1 "$dir/$name.svg" 2> "$dir/$name-inkscape.log" ||
    { echo "FAIL: inkscape could not export $name.svg: $(tail -3 "$dir/$name-inkscape.log")"; status=1; continue; }
  echo "$name.svg: Inkscape against Chromium's frame 0:"
  # shellcheck disable=SC2086 # FILLS is a list of colours
  QT_QPA_PLATFORM=offscreen "$compare" --fill-slack 8 "$dir/$name-inkscape.png" "$dir/chromium.png" 1 1 $size 2 0.97 $fills || status=1
  inkscape --export-type=svg --export-filename="$dir/$name-saved.svg" "$dir/$name.svg" 2> /dev/null ||
    { echo "FAIL: inkscape could not save $name.svg"; status=1; continue; }
  python3 "$here/layers_check.py" "$dir/$name.svg" "$dir/$name-saved.svg" || status=1
done
exit $status
