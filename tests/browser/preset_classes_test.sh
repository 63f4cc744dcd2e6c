#!/usr/bin/env bash
# A filled style preset rendered through the CLI and Chromium paints each
# class where the tests' own z-buffer reference puts it.
#   preset_classes_test.sh CLI CHECKER PRESET.xml MESH OUTDIR NAME VIEW UP MARGIN -- CLASS=COLOUR... [-- OTHER...]
set -euo pipefail
cli=$1; checker=$2; preset=$3; mesh=$4; outdir=$5; name=$6; view=$7; up=$8; margin=$9; shift 10
here=$(dirname "$0")
mkdir -p "$outdir"
"$cli" contours "$mesh" --style "$preset" --view-dir "$view" --up "$up" --svg "$outdir/$name.svg"
bash "$here/render_svg.sh" "$outdir/$name.svg" "$outdir/$name.png" 800 800
QT_QPA_PLATFORM=offscreen "$checker" "$outdir/$name.png" "$mesh" "$view" "$up" "$margin" "$@"
