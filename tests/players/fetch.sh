#!/usr/bin/env bash
# Refreshes the vendored Lottie test players from npm at their pinned
# versions (npm pack checks each tarball against the registry's integrity
# hash, printed here). The files are committed, so a fresh install needs no
# network beyond apt: run this only to change a version.
#   tests/players/fetch.sh
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
LOTTIE_WEB=5.13.0
LOTTIE_SPECS=0.3.2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
npm pack --silent "lottie-web@$LOTTIE_WEB" "@lottie-animation-community/lottie-specs@$LOTTIE_SPECS" >/dev/null
npm view "lottie-web@$LOTTIE_WEB" dist.integrity
npm view "@lottie-animation-community/lottie-specs@$LOTTIE_SPECS" dist.integrity
mkdir web specs
tar -xzf "lottie-web-$LOTTIE_WEB.tgz" -C web
tar -xzf "lottie-animation-community-lottie-specs-$LOTTIE_SPECS.tgz" -C specs
cp web/package/build/player/lottie_svg.min.js web/package/LICENSE.md "$here/vendor/lottie-web/"
cp specs/package/src/data/lottie.schema.json specs/package/COPYING "$here/vendor/lottie-specs/"
echo "lottie-web $LOTTIE_WEB and lottie-specs $LOTTIE_SPECS copied into $here/vendor"
