#!/usr/bin/env bash
# Takes the README's screenshot of the application under Xvfb: the default
# scene with the toon preset, all panes populated.
#   scripts/screenshot.sh [OUT.png]   (default docs/screenshot.png; build first)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/screenshot.png}
build_dir=${SNAXELS_BUILD_DIR:-build}
settings=$(mktemp -d)
trap 'rm -rf "$settings"' EXIT
# A fresh settings folder: the default window layout, not the last one used.
XDG_CONFIG_HOME="$settings" xvfb-run -a -s "-screen 0 1500x900x24" \
  "$build_dir/bin/snaxels" --style-file styles/toon.xml --screenshot "$out"
echo "wrote $out"
