#!/usr/bin/env bash
# Viewers without SMIL (rsvg-convert here, as in Inkscape and image
# previews) must show the animated SVG's frame 0 and nothing else: its
# rendering against the static frame 0's, stroke pixels within 2 px both
# ways (99%), and the paths visible without SMIL exactly those shown at
# frame 0 (svg_persistence --frame0-only).
#   rsvg_frame0_test.sh CLI COMPARE PERSISTENCE OUTDIR NAME MESH FRAMES -- ANIMATE-OPTIONS...
set -euo pipefail
cli=$1; compare=$2; persistence=$3; outdir=$4; name=$5; mesh=$6; frames=$7
shift 8
command -v rsvg-convert >/dev/null || { echo "rsvg-convert is not installed (scripts/install-deps.sh installs librsvg2-bin)"; exit 1; }
dir="$outdir/$name"
rm -rf "$dir"; mkdir -p "$dir"
size=400
"$cli" animate "$mesh" --frames "$frames" --size ${size}x${size} -o "$dir/anim.svg" --frames-dir "$dir/frames" "$@"
rsvg-convert -w $size -h $size -b white "$dir/anim.svg" -o "$dir/anim.png"
rsvg-convert -w $size -h $size -b white "$dir/frames/frame_00000.svg" -o "$dir/frame0.png"
status=0
QT_QPA_PLATFORM=offscreen "$compare" "$dir/anim.png" "$dir/frame0.png" 1 1 $size 2 0.99 || status=1
"$persistence" "$dir/anim.svg" "$frames" --frame0-only || status=1
exit $status
