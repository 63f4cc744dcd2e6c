#!/usr/bin/env bash
# Times Blender's Freestyle SVG exporter against `snaxels-cli animate` on the
# same generated meshes, in one run, and prints a Markdown table (the one in
# docs/performance.md). Optional, not part of CI: it installs Blender from
# Debian (as root) if it is missing, and takes several minutes.
#
#   bash bench/peer/run.sh [FACES...]        default: 20000 100000
# Environment: FRAMES (default 120), DEGREES per frame (default 3),
# SNAXELS_CLI (default build/bin/snaxels-cli), WORK (default a temporary dir).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
cli=${SNAXELS_CLI:-$root/build/bin/snaxels-cli}
frames=${FRAMES:-120}
degrees=${DEGREES:-3}
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(20000 100000)

if ! command -v blender >/dev/null; then
  if [ "$(id -u)" -ne 0 ]; then echo "bench/peer: Blender is not installed; run as root to install it from Debian" >&2; exit 1; fi
  DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends blender >/dev/null
fi
[ -x "$cli" ] || { echo "bench/peer: $cli not found: build first (scripts/dev.sh build)" >&2; exit 1; }

work=${WORK:-$(mktemp -d)}
mkdir -p "$work"
blender_version=$(blender --version 2>/dev/null | head -1)
cores=$(nproc)
now() { date +%s.%N; }
mb() { awk -v b="$(stat -c %s "$1")" 'BEGIN { printf "%.2f", b / 1e6 }'; }

echo "| mesh | faces | frames | tool | seconds | output (MB) | paths |"
echo "|---|---:|---:|---|---:|---:|---:|"
for faces in "${sizes[@]}"; do
  mesh="$work/bumpy_$faces.obj"
  python3 "$here/make_mesh.py" "$faces" "$mesh"
  real_faces=$(grep -c '^f ' "$mesh")

  out="$work/snaxels_$faces.svg"
  t0=$(now)
  "$cli" animate "$mesh" --turntable "$degrees" --frames "$frames" --view-dir 0,0,-1 --up 0,1,0 \
    --style "$here/outline.xml" -o "$out" >/dev/null
  t1=$(now)
  paths=$(grep -o '<path' "$out" | wc -l)
  printf '| bumpy sphere | %d | %d | snaxels-cli animate | %.1f | %s | %d |\n' "$real_faces" "$frames" \
    "$(awk -v a="$t0" -v b="$t1" "BEGIN { print b - a }")" "$(mb "$out")" "$paths"

  dir="$work/freestyle_$faces"
  rm -rf "$dir" && mkdir -p "$dir"
  t0=$(now)
  blender -b --factory-startup --python "$here/freestyle_svg.py" -- "$mesh" "$dir" "$frames" "$degrees" \
    >"$dir/blender.log" 2>&1 || { echo "bench/peer: Blender failed; see $dir/blender.log" >&2; exit 1; }
  t1=$(now)
  svg=$(ls "$dir"/*.svg 2>/dev/null | head -1)
  [ -n "$svg" ] || { echo "bench/peer: Blender wrote no SVG; see $dir/blender.log" >&2; exit 1; }
  paths=$(grep -o '<path' "$svg" | wc -l)
  printf '| bumpy sphere | %d | %d | Blender Freestyle SVG (animation) | %.1f | %s | %d |\n' "$real_faces" "$frames" \
    "$(awk -v a="$t0" -v b="$t1" "BEGIN { print b - a }")" "$(mb "$svg")" "$paths"
done
echo
echo "$blender_version (Debian), Cycles at 1 sample for the render Freestyle needs; snaxels $("$cli" --version 2>/dev/null || git -C "$root" rev-parse --short HEAD); $cores cores; outputs in $work"
