#!/usr/bin/env bash
# Installs snaxels' library into a temporary prefix, builds examples/embed
# against it with find_package(snaxels) in a copy outside the source tree,
# and checks that its SVG of MESH is the one `snaxels-cli contours` writes.
#   embed_test.sh BUILD_DIR SOURCE_DIR CLI MESH WORK_DIR
set -euo pipefail
build=$1 src=$2 cli=$3 mesh=$4 work=$5
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" --component development >"$work/install.log"
# What a user of the library gets: headers under include/snaxels (no detail/),
# the static library and the CMake package.
test -f "$work/prefix/include/snaxels/version.h"
test -f "$work/prefix/include/snaxels/animation/still.h"
if find "$work/prefix/include" -path '*detail*' | grep -q .; then
  echo "internal headers were installed:"; find "$work/prefix/include" -path '*detail*'; exit 1
fi
# Internal headers say so in their first lines; none may be installed.
if grep -rlE '^// *Internal to core' "$work/prefix/include" | grep -q .; then
  echo "headers marked internal were installed:"; grep -rlE '^// *Internal to core' "$work/prefix/include"; exit 1
fi
# The example embeds the library with one include.
test "$(grep -c '^#include <snaxels/' "$src"/examples/embed/*.cpp)" = 1
ls "$work"/prefix/lib*/libsnaxels.a "$work"/prefix/lib*/cmake/snaxels/snaxelsConfig.cmake >/dev/null
# No installed text file (headers, the CMake package) may point back into
# the source or build tree (the library's debug information may).
if grep -rlIF -e "$src" -e "$build" "$work/prefix" 2>/dev/null | grep -q .; then
  echo "installed files name the source or build tree:"; grep -rlIF -e "$src" -e "$build" "$work/prefix"; exit 1
fi
cp -r "$src/examples/embed" "$work/embed-src"
cmake -S "$work/embed-src" -B "$work/embed-build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/configure.log"
cmake --build "$work/embed-build" >"$work/build.log"
"$work/embed-build/embed" "$mesh" "$work/embed.svg"
"$cli" contours "$mesh" --svg "$work/cli.svg"
if ! cmp "$work/embed.svg" "$work/cli.svg"; then
  echo "the embedded engine's SVG differs from snaxels-cli contours'"; exit 1
fi
grep -c "<path" "$work/embed.svg" | sed 's/^/paths in the SVG: /'
"$work/embed-build/embed" "$work/no-such-mesh.obj" "$work/never.svg" 2>"$work/err.txt" && exit 1
grep -q "no-such-mesh.obj: no such file" "$work/err.txt"
test ! -e "$work/never.svg"
echo "embed built against the installed snaxels::core and matches snaxels-cli"
