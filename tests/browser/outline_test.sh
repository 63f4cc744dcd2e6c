#!/usr/bin/env bash
# contours --svg, rendered by Chromium, traces the mesh's silhouette.
#   outline_test.sh CLI CHECKER MESH OUTDIR NAME VIEW [UP [hidden]]
# With 'hidden', dashed hidden lines must appear too: the SVG is rendered a
# second time with its hidden group switched off and the two compared.
set -euo pipefail
cli=$1; checker=$2; mesh=$3; outdir=$4; name=$5; view=$6; up=${7:-0,1,0}; hidden=${8:-}
here=$(dirname "$0")
mkdir -p "$outdir"
"$cli" contours "$mesh" --view-dir "$view" --up "$up" --kind visual --svg "$outdir/$name.svg"
bash "$here/render_svg.sh" "$outdir/$name.svg" "$outdir/$name.png" 800 800
if [ "$hidden" = hidden ]; then
  grep -q '<g id="hidden"' "$outdir/$name.svg" || { echo "the SVG has no hidden group"; exit 1; }
  sed 's/<g id="hidden"/<g id="hidden" display="none"/' "$outdir/$name.svg" > "$outdir/$name-visible.svg"
  bash "$here/render_svg.sh" "$outdir/$name-visible.svg" "$outdir/$name-visible.png" 800 800
  QT_QPA_PLATFORM=offscreen "$checker" "$mesh" "$outdir/$name.png" "$view" "$up" "$outdir/$name-visible.png"
else
  QT_QPA_PLATFORM=offscreen "$checker" "$mesh" "$outdir/$name.png" "$view" "$up"
fi
