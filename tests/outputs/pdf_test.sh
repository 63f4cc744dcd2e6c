#!/usr/bin/env bash
# Print: a frame written as PDF by `contours --pdf` and by `render --still`
# must be vector (pdf_check.py) and, rendered by poppler (pdftoppm), match
# Chromium's render of the same frame's static SVG: 97% of ink pixels within
# 2 px both ways and each fill colour given likewise (compare_grid).
#   pdf_test.sh CLI COMPARE BROWSER OUTDIR PROJECT MESH FILLS -- CONTOURS-OPTIONS...
# FILLS: "#RRGGBB ..." (the style's fill colours) or "".
set -euo pipefail
cli=$1; compare=$2; browser=$3; outdir=$4; project=$5; mesh=$6; fills=$7
shift 8
here=$(dirname "$0")
command -v pdftoppm >/dev/null || { echo "pdftoppm is not installed (scripts/install-deps.sh installs poppler-utils)"; exit 1; }
dir="$outdir/pdf"
rm -rf "$dir"; mkdir -p "$dir"
size=400
status=0
compare_pdf() { # NAME: NAME.pdf against Chromium's NAME.svg
  python3 "$here/pdf_check.py" "$dir/$1.pdf" 10 || status=1
  pdftoppm -png -r 72 -singlefile "$dir/$1.pdf" "$dir/$1-poppler"
  bash "$browser/render_svg.sh" "$dir/$1.svg" "$dir/$1-chromium.png" $size $size
  echo "$1: poppler against Chromium:"
  # shellcheck disable=SC2086 # FILLS is a list of colours
  QT_QPA_PLATFORM=offscreen "$compare" --fill-slack 8 "$dir/$1-poppler.png" "$dir/$1-chromium.png" 1 1 $size 2 0.97 $fills || status=1
}
"$cli" contours "$mesh" --size ${size}x${size} --svg "$dir/contours.svg" --pdf "$dir/contours.pdf" "$@"
compare_pdf contours
# A project's still as PDF: the same page its SVG has.
"$cli" render "$project" --still -o "$dir/still.svg"
"$cli" render "$project" --still -o "$dir/still.pdf"
pages=$(pdfinfo "$dir/still.pdf" | sed -n 's/^Page size: *\([0-9.]*\) x \([0-9.]*\) pts.*/\1x\2/p')
want=$(sed -n 's/.*<svg[^>]* width="\([0-9]*\)" height="\([0-9]*\)".*/\1x\2/p' "$dir/still.svg" | head -1)
[ "$pages" = "$want" ] || { echo "FAIL: the still's PDF page is $pages pt, its SVG $want px"; status=1; }
python3 "$here/pdf_check.py" "$dir/still.pdf" 10 || status=1
exit $status
