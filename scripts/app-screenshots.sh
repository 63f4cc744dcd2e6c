#!/usr/bin/env bash
# Before/after pictures of the application for docs/app.md: the same
# scripted mouse and keyboard input (xdotool) on two builds of the snaxels
# application, each under its own Xvfb screen, captured with xwd.
#
#   scripts/app-screenshots.sh BEFORE_BIN AFTER_BIN OUTDIR
#
# BEFORE_BIN and AFTER_BIN are two builds of the `snaxels` application (for
# instance one built from an older commit beside the working tree, as
# scripts/compare-outputs.sh builds its command line). OUTDIR receives
# NAME-before.png and NAME-after.png for each scene below. Installs
# xdotool, xwd (x11-apps) and ImageMagick when they are missing (as root).
set -euo pipefail
cd "$(dirname "$0")/.."

if [ $# -ne 3 ]; then
  echo "usage: scripts/app-screenshots.sh BEFORE_BIN AFTER_BIN OUTDIR" >&2
  exit 2
fi
before=$(realpath "$1")
after=$(realpath "$2")
out=$(realpath -m "$3")
for bin in "$before" "$after"; do
  [ -x "$bin" ] || { echo "app-screenshots: $bin is not an executable" >&2; exit 2; }
done
mkdir -p "$out"
missing=()
command -v xdotool >/dev/null || missing+=(xdotool)
command -v xwd >/dev/null || missing+=(x11-apps)
/usr/bin/convert -version 2>/dev/null | grep -q ImageMagick || missing+=(imagemagick)
command -v Xvfb >/dev/null || missing+=(xvfb)
if [ ${#missing[@]} -gt 0 ]; then
  apt-get install -y --no-install-recommends "${missing[@]}"
fi

home=$(mktemp -d) # fresh settings for every run: no saved layout or folders
trap 'rm -rf "$home"' EXIT
# The meshes and styles shown, copied beside a neutral working folder, so
# the pictures show no path of the machine they were made on.
assets=$home/models
styles=$home/styles
mkdir -p "$assets" "$styles" "$home/work"
cp tests/assets/spot.obj tests/assets/horse.ply "$assets/"
cp styles/toon.xml "$styles/"
cd "$home/work"

display=:77
Xvfb "$display" -screen 0 1400x900x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null; rm -rf "$home"' EXIT
export DISPLAY=$display
sleep 1

app=0
launch() { # BIN ARGS...: starts the application and waits for its window
  HOME=$home XDG_CONFIG_HOME=$home/config "$@" >/dev/null 2>&1 &
  app=$!
  xdotool search --sync --onlyvisible --class snaxels >/dev/null
  sleep "${SETTLE:-4}" # the mesh loads and its contours are drawn
}
finish() {
  kill "$app" 2>/dev/null || true
  wait "$app" 2>/dev/null || true
}
shot() { # NAME [GEOMETRY]: the screen (or a part of it) into OUTDIR, at most 900 pixels wide
  xwd -root -silent | /usr/bin/convert xwd:- ${2:+-crop "$2" +repage} -resize '900x>' "png:$out/$1"
}
title() { xdotool search --onlyvisible --class snaxels getwindowname 2>/dev/null | head -1; }
# Xvfb runs no window manager: a click on the 3-D view gives the window the
# keyboard (a click without a drag changes nothing there).
focus() { xdotool mousemove 60 700 click 1; sleep 0.3; }

for which in before after; do
  bin=${!which}

  # 1. A fresh launch and a freshly opened mesh are unmodified: the title,
  # then what quitting asks.
  launch "$bin"
  echo "$(title)" >"$out/documents-title-$which.txt"
  focus
  xdotool key ctrl+q
  sleep 1.5
  shot "documents-quit-$which.png"
  finish

  # 2. An export dialog: where it opens and the name it suggests.
  launch "$bin" "$assets/spot.obj"
  focus
  xdotool key ctrl+shift+e
  sleep 3
  shot "export-dialog-$which.png"
  xdotool key Escape
  finish

  # 3. Play on the horse in the toon preset: the timeline and status bar
  # after five seconds.
  SETTLE=8 launch "$bin" "$assets/horse.ply" --style-file "$styles/toon.xml"
  focus
  xdotool key space
  sleep 5
  shot "play-$which.png" 1400x110+0+790
  xdotool key space
  finish

  # 4. The light turned half a turn (Shift+drag across the view): the
  # shading follows it, and the globe.
  launch "$bin" "$assets/spot.obj"
  xdotool mousemove 500 400 keydown shift mousedown 1
  for x in 460 420 380 340 300 260 220 180; do xdotool mousemove "$x" 400; sleep 0.05; done
  xdotool mouseup 1 keyup shift
  sleep 3
  shot "light-$which.png" 680x745+0+20
  finish

  # 5. The mesh zoomed in past the page in the 3-D view: what the SVG pane
  # shows past the page the export clips to.
  launch "$bin" "$assets/spot.obj"
  xdotool mousemove 340 400
  for _ in 1 2 3 4 5 6 7 8; do xdotool click 4; sleep 0.1; done
  sleep 3
  shot "svg-pane-$which.png" 460x600+680+90
  finish

  # 6. The style dock at the window's own size with the toon preset.
  launch "$bin" "$assets/spot.obj" --style-file "$styles/toon.xml"
  shot "style-dock-$which.png" 262x760+1138+20
  finish
done
echo "app-screenshots: pictures in $out"
