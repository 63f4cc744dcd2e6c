#!/usr/bin/env bash
# Loads a page in headless Chromium and prints its DOM once the page's
# scripts have run (the scripts write their results into it).
#   dump_dom.sh PAGE.html WIDTH HEIGHT
set -euo pipefail
in=$(realpath "$1"); w=$2; h=$3
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "chromium is not installed (scripts/install-deps.sh installs it)" >&2; exit 1; }
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
timeout 300 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync \
  --hide-scrollbars --user-data-dir="$profile" --window-size="$w,$h" \
  --dump-dom "file://$in" 2>/dev/null
