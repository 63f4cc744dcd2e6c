# Sourced by the browser tests: pages of a grid of COLS cells of CELL pixels.
#   seek_page OUT.html SVG COLS CELL FPS OFFSET FRAME...
#     the animated SVG inlined once per cell, each paused at (FRAME + OFFSET) / FPS seconds
#   frames_page OUT.html COLS CELL FRAMES_DIR FRAME...
#     the static frame SVGs FRAMES_DIR/frame_NNNNN.svg, one per cell
seek_page() {
  local out=$1 svg=$2 cols=$3 cell=$4 fps=$5 offset=$6
  shift 6
  {
    echo '<!DOCTYPE html><html><head><style>body{margin:0;background:#fff}div{display:grid;grid-template-columns:repeat('"$cols"','"$cell"'px);}svg{display:block}</style></head><body><div>'
    for f in "$@"; do sed '1d' "$svg" | sed "s/<svg /<svg data-frame=\"$f\" /"; done
    echo '</div><script>'
    echo "for (const s of document.querySelectorAll('svg[data-frame]')) { s.pauseAnimations(); s.setCurrentTime((Number(s.dataset.frame) + $offset) / $fps); }"
    echo '</script></body></html>'
  } > "$out"
}
frames_page() {
  local out=$1 cols=$2 cell=$3 dir=$4
  shift 4
  {
    echo '<!DOCTYPE html><html><head><style>body{margin:0;background:#fff}div{display:grid;grid-template-columns:repeat('"$cols"','"$cell"'px);}img{display:block}</style></head><body><div>'
    for f in "$@"; do printf '<img src="%s/frame_%05d.svg" width="%d" height="%d">\n' "$dir" "$f" "$cell" "$cell"; done
    echo '</div></body></html>'
  } > "$out"
}
