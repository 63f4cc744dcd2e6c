#!/usr/bin/env bash
# Makes the Debian packages with CPack and checks what a user installs:
# the package names and computed dependencies, the files and where they go,
# the desktop entry (desktop-file-validate) and MIME types, and the programs
# run from the unpacked package (the CLI with its import helper from
# libexec, the application under Xvfb with its data from share/).
#   deb_test.sh BUILD_DIR VERSION WORK_DIR [gui]
set -euo pipefail
build=$1 version=$2 work=$3 gui=${4:-}
rm -rf "$work"
mkdir -p "$work"
cpack --config "$build/CPackConfig.cmake" -B "$work" >"$work/cpack.log" 2>&1 || { cat "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/snaxels_"$version"_*.deb)
dev=$(ls "$work"/snaxels-dev_"$version"_*.deb)
echo "packages: ${deb##*/} ${dev##*/}"

depends=$(dpkg-deb -f "$deb" Depends)
echo "snaxels Depends: $depends"
# Computed from the linked libraries (dpkg-shlibdeps), not written by hand.
for lib in libassimp5 libembree3 libtbb libpugixml libpolyclipping libc6 libstdc++6; do
  grep -q "$lib" <<<"$depends" || { echo "Depends lacks $lib"; exit 1; }
done
if [ -n "$gui" ]; then
  for lib in libqt6widgets6 libqt6svg6 qt6-qpa-plugins; do
    grep -q "$lib" <<<"$depends" || { echo "Depends lacks $lib"; exit 1; }
  done
fi
grep -q "libassimp-dev" <<<"$(dpkg-deb -f "$dev" Depends)"

dpkg-deb -c "$deb" | awk '{print $6}' >"$work/files.txt"
expect=(./usr/bin/snaxels-cli ./usr/libexec/snaxels/snaxels-import
  ./usr/share/snaxels/resources/spot.obj ./usr/share/snaxels/styles/toon.xml
  ./usr/share/applications/snaxels.desktop ./usr/share/icons/hicolor/scalable/apps/snaxels.svg
  ./usr/share/mime/packages/snaxels.xml ./usr/share/doc/snaxels/README.md ./usr/share/doc/snaxels/cli.md
  ./usr/share/doc/snaxels/copyright ./usr/share/doc/snaxels/LICENSE)
[ -n "$gui" ] && expect+=(./usr/bin/snaxels)
for f in "${expect[@]}"; do
  grep -qx "$f" "$work/files.txt" || { echo "the package lacks $f"; exit 1; }
done
if grep -q "include\|\.a$\|cmake" "$work/files.txt"; then
  echo "development files in the runtime package:"; grep "include\|\.a$\|cmake" "$work/files.txt"; exit 1
fi
dpkg-deb -c "$dev" | awk '{print $6}' | grep -q "/usr/include/snaxels/version.h"
dpkg-deb -c "$dev" | awk '{print $6}' | grep -qx "./usr/share/doc/snaxels-dev/copyright"
dpkg-deb -c "$dev" | awk '{print $6}' | grep -qx "./usr/include/snaxels/snaxels.h"
# A real maintainer, not a placeholder address.
maintainer=$(dpkg-deb -f "$deb" Maintainer)
case "$maintainer" in *@invalid*|"") echo "placeholder maintainer: $maintainer"; exit 1 ;; esac

root="$work/root"
dpkg-deb -x "$deb" "$root"
# The programs are stripped; the library keeps the symbols linking needs.
for program in usr/bin/snaxels-cli usr/libexec/snaxels/snaxels-import; do
  file "$root/$program" | grep -q ", stripped" || { echo "$program is not stripped"; file "$root/$program"; exit 1; }
done
dpkg-deb -x "$dev" "$work/dev-root"
archive=$(find "$work/dev-root" -name 'libsnaxels*.a' | head -1)
nm "$archive" >"$work/symbols.txt" 2>/dev/null
grep -q "extract_fronts" "$work/symbols.txt" || { echo "the library in snaxels-dev lost its symbols"; exit 1; }
desktop-file-validate "$root/usr/share/applications/snaxels.desktop"
python3 - "$root/usr/share/mime/packages/snaxels.xml" "$root/usr/share/icons/hicolor/scalable/apps/snaxels.svg" \
  "$root/usr/share/applications/snaxels.desktop" <<'PY'
import sys, xml.etree.ElementTree as ET
ns = {"m": "http://www.freedesktop.org/standards/shared-mime-info"}
mime = ET.parse(sys.argv[1]).getroot()
types = {t.get("type"): [g.get("pattern") for g in t.findall("m:glob", ns)] for t in mime.findall("m:mime-type", ns)}
assert types.get("application/x-snaxels-project") == ["*.snaxels"], types
svg = ET.parse(sys.argv[2]).getroot()
assert svg.tag.endswith("svg") and svg.get("viewBox"), svg.attrib
desktop = open(sys.argv[3]).read()
line = [l for l in desktop.splitlines() if l.startswith("MimeType=")][0]
assert "application/x-snaxels-project" in line and "model/obj" in line, line
assert "Exec=snaxels %f" in desktop
print("MIME types:", ", ".join(sorted(types)))
PY

"$root/usr/bin/snaxels-cli" --version | tee "$work/version.txt"
grep -qx "snaxels-cli $version" "$work/version.txt"
"$root/usr/bin/snaxels-cli" contours proc:torus --svg "$work/torus.svg"
grep -q "<path" "$work/torus.svg"
# A mesh file goes through the helper the package puts in libexec.
cp "$root/usr/share/snaxels/resources/spot.obj" "$work/spot.obj"
"$root/usr/bin/snaxels-cli" contours "$work/spot.obj" --svg "$work/spot.svg"
grep -q "<path" "$work/spot.svg"
mv "$root/usr/libexec/snaxels/snaxels-import" "$work/helper-away"
if "$root/usr/bin/snaxels-cli" info "$work/spot.obj" 2>"$work/nohelper.txt"; then
  echo "the CLI read a mesh without its helper"; exit 1
fi
mv "$work/helper-away" "$root/usr/libexec/snaxels/snaxels-import"
if [ -n "$gui" ]; then
  # The application starts from the package, finds its default scene in
  # share/snaxels and draws it.
  xvfb-run -a -s "-screen 0 1280x800x24" "$root/usr/bin/snaxels" --screenshot "$work/app.png"
  test -s "$work/app.png"
fi
echo "the packages install what a user needs"
