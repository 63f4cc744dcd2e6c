#!/usr/bin/env bash
# Compressed outputs: one animation written as .svg, .svgz, .json and
# .lottie. The .svgz must be a valid gzip of exactly the .svg's bytes, the
# .lottie a dotLottie zip (dotlottie_check.py) whose animation is exactly
# the .json's bytes; both must be smaller than what they hold. A second
# export of each must give the same bytes (no dates in the containers).
#   compressed_test.sh CLI OUTDIR MESH -- ANIMATE-OPTIONS...
set -euo pipefail
cli=$1; outdir=$2; mesh=$3
shift 4
here=$(dirname "$0")
dir="$outdir/compressed"
rm -rf "$dir"; mkdir -p "$dir"
for ext in svg svgz json lottie; do
  "$cli" animate "$mesh" -o "$dir/anim.$ext" "$@" > /dev/null
done
status=0
gzip -t "$dir/anim.svgz" || { echo "FAIL: anim.svgz is not valid gzip"; status=1; }
gzip -dc "$dir/anim.svgz" | cmp - "$dir/anim.svg" || { echo "FAIL: anim.svgz does not hold anim.svg's bytes"; status=1; }
python3 "$here/dotlottie_check.py" "$dir/anim.lottie" "$dir/unzipped.json" || status=1
cmp "$dir/unzipped.json" "$dir/anim.json" || { echo "FAIL: anim.lottie does not hold anim.json's bytes"; status=1; }
size() { stat -c %s "$1"; }
echo "svg $(size "$dir/anim.svg") svgz $(size "$dir/anim.svgz") json $(size "$dir/anim.json") lottie $(size "$dir/anim.lottie")"
[ "$(size "$dir/anim.svgz")" -lt "$(size "$dir/anim.svg")" ] || { echo "FAIL: the .svgz is not smaller"; status=1; }
[ "$(size "$dir/anim.lottie")" -lt "$(size "$dir/anim.json")" ] || { echo "FAIL: the .lottie is not smaller"; status=1; }
mkdir -p "$dir/again" # (the same name: a dotLottie's animation is named after its file)
for ext in svgz lottie; do
  "$cli" animate "$mesh" -o "$dir/again/anim.$ext" "$@" > /dev/null
  cmp "$dir/anim.$ext" "$dir/again/anim.$ext" || { echo "FAIL: two exports of the .$ext differ"; status=1; }
done
exit $status
