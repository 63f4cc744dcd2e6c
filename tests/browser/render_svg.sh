#!/usr/bin/env bash
# Renders an SVG file in headless Chromium to a PNG of the given size.
#   render_svg.sh IN.svg OUT.png WIDTH HEIGHT
set -euo pipefail
in=$(realpath "$1"); out=$2; w=$3; h=$4
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "chromium is not installed (scripts/install-deps.sh installs it)"; exit 1; }
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
rm -f "$out"
timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync \
  --hide-scrollbars --user-data-dir="$profile" --window-size="$w,$h" \
  --screenshot="$out" "file://$in" >/dev/null 2>&1 || true
[ -s "$out" ] || { echo "chromium wrote no screenshot of $in"; exit 1; }
