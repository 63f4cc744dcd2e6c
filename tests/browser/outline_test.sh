#!/usr/bin/env bash
# contours --svg, rendered by Chromium, traces the mesh's silhouette.
#   outline_test.sh CLI CHECKER MESH OUTDIR NAME VIEW [UP]
set -euo pipefail
cli=$1; checker=$2; mesh=$3; outdir=$4; name=$5; view=$6; up=${7:-0,1,0}
here=$(dirname "$0")
mkdir -p "$outdir"
"$cli" contours "$mesh" --view-dir "$view" --up "$up" --kind visual --svg "$outdir/$name.svg"
bash "$here/render_svg.sh" "$outdir/$name.svg" "$outdir/$name.png" 800 800
QT_QPA_PLATFORM=offscreen "$checker" "$mesh" "$outdir/$name.png" "$view" "$up"
