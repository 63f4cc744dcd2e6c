#!/usr/bin/env bash
# Every system file the build read, and every program the tests run, must come
# from a Debian package that scripts/install-deps.sh brings in: a package it
# lists, one of their dependencies (recursively, without recommends or
# suggests), or one every Debian system has (priority required). A file that
# only a hand install put there makes a green build here and a broken one on a
# fresh machine.
#
#   check_packages.sh BUILD_DIR SOURCE_DIR [PROGRAM...]
#
# What the build read, gathered from the build tree:
#   - files CMake read while configuring (build.ninja's re-run dependencies:
#     package configs, find modules),
#   - headers the compiler read (ninja -t deps),
#   - libraries and tools on the compile and link lines (absolute paths, and
#     -lNAME resolved the way the compiler resolves it),
#   - programs and files CMake found (CMakeCache.txt FILEPATH entries) that
#     the build rules or the tests use,
#   - shared libraries the built programs load (ldd),
#   - the programs given on the command line (what test scripts call by name).
# Each is mapped to the package that ships it (dpkg -S). The package list comes
# from `install-deps.sh --list`; SNAXELS_DEPS_PACKAGES (space separated) stands
# in for it, which is how the self-test shows that a missing package fails.
set -euo pipefail
build=$(realpath "$1"); src=$(realpath "$2"); shift 2
programs=("$@")
cd "$build"
[ -f build.ninja ] || { echo "check_packages: $build has no build.ninja (the check reads Ninja's records)"; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

if [ -n "${SNAXELS_DEPS_PACKAGES:-}" ]; then
  read -r -a listed <<<"$SNAXELS_DEPS_PACKAGES"
else
  mapfile -t listed < <(bash "$src/scripts/install-deps.sh" --list)
fi
((${#listed[@]})) || { echo "check_packages: the package list is empty"; exit 1; }

# --- what the build read -----------------------------------------------------
{
  # Configure: build.ninja's RERUN_CMAKE line lists every file CMake read.
  awk '/^build build\.ninja: RERUN_CMAKE/{p=1} p{print; if (!/\$$/) exit}' build.ninja | tr ' ' '\n'
  # Compile: every header the compiler read.
  ninja -t deps | awk '/^    /{print $1}'
  # Compile and link lines: absolute paths, and -lNAME through the compiler.
  ninja -t commands >"$work/commands"
  tr ' ' '\n' <"$work/commands" | sed -n 's|^\(-I\|-isystem\)\?\(/[^ ]*\)$|\2|p'
  cxx=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' CMakeCache.txt)
  for lib in $(tr ' ' '\n' <"$work/commands" | sed -n 's/^-l\([A-Za-z0-9_+.-]*\)$/\1/p' | sort -u); do
    found=$("$cxx" -print-file-name="lib$lib.so")
    [ "$found" = "lib$lib.so" ] && found=$("$cxx" -print-file-name="lib$lib.a")
    echo "$found"
  done
  # CMake's cache: programs and files it found that the build or the tests
  # use (a find module may record a library nothing links).
  find . -name CTestTestfile.cmake >"$work/ctest-files"
  sed -n 's/^[^#/][^:]*:FILEPATH=\(\/.*\)$/\1/p' CMakeCache.txt | while IFS= read -r f; do
    if grep -qF -- "$f" build.ninja CMakeFiles/rules.ninja || xargs grep -qF -- "$f" <"$work/ctest-files"; then echo "$f"; fi
  done
  # Run time: what the built programs load.
  find bin -maxdepth 1 -type f -perm -u+x -print0 | xargs -0 -r ldd 2>/dev/null | awk '$2 == "=>" && $3 ~ /^\// {print $3}'
  for p in "${programs[@]}"; do command -v "$p" || echo "MISSING-PROGRAM:$p"; done
} >"$work/raw"

if grep -q '^MISSING-PROGRAM:' "$work/raw"; then
  echo "check_packages: the tests run programs that are not installed:"
  sed -n 's/^MISSING-PROGRAM:/  /p' "$work/raw"
  exit 1
fi

# Normalize (.. and .), keep existing files outside the project, drop the
# project's own source and build trees.
grep '^/' "$work/raw" | sort -u | while IFS= read -r f; do
  [ -f "$f" ] && echo "$f"
done | xargs -r -d '\n' realpath -s -m | sort -u |
  grep -v -e "^$src/" -e "^$build/" >"$work/files" || true

[ -s "$work/files" ] || { echo "check_packages: found no system file the build read (is $build built?)"; exit 1; }

# --- which package ships each file ---------------------------------------------
# dpkg knows a file by the name its package ships it under; on a merged /usr
# system that may be the /lib, /bin or /sbin alias, and a symlink (an
# alternative, a .so link) may belong to no package while its target does.
# Candidates in order of preference: the name as read, its alias, then the
# resolved target and its alias. One dpkg-query call answers them all.
xargs -r -d '\n' realpath -m <"$work/files" | paste -d ' ' "$work/files" - |
while read -r f r; do
  for c in "$f" "$r"; do
    echo "$f $c"
    case "$c" in
      /usr/lib/* | /usr/lib64/* | /usr/bin/* | /usr/sbin/*) echo "$f ${c#/usr}" ;;
      /lib/* | /lib64/* | /bin/* | /sbin/*) echo "$f /usr$c" ;;
    esac
  done
done >"$work/candidates"
awk '{print $2}' "$work/candidates" | sort -u | xargs -r dpkg-query -S 2>/dev/null | grep -v "^diversion" |
  sed -n 's/^\(.*\): \(\/.*\)$/\2 \1/p' >"$work/dpkg" || true
# "path pkg1:amd64, pkg2" -> owned: "pkg path-as-read" for the first candidate
# dpkg knows; unowned: files none of whose candidates it knows.
awk -v owned="$work/owned" -v unowned="$work/unowned" '
  NR == FNR { path = $1; $1 = ""; pk[path] = $0; next }
  { order[$1] = order[$1] " " $2 }
  END {
    printf "" >owned; printf "" >unowned
    for (f in order) {
      n = split(order[f], cand, " "); hit = ""
      for (i = 1; i <= n && hit == ""; i++) if (cand[i] in pk) hit = pk[cand[i]]
      if (hit == "") { print f >>unowned; continue }
      m = split(hit, names, ","); for (j = 1; j <= m; j++) {
        p = names[j]; gsub(/^ +| +$/, "", p); sub(/:.*$/, "", p); print p, f >>owned
      }
    }
  }' "$work/dpkg" "$work/candidates"
sort -o "$work/unowned" "$work/unowned"

# --- the packages a fresh machine gets -----------------------------------------
# The listed packages and their dependencies, recursively (installed ones: the
# list was just installed), plus what every Debian system has.
apt-cache depends --recurse --installed --no-recommends --no-suggests --no-conflicts \
  --no-breaks --no-replaces --no-enhances "${listed[@]}" 2>/dev/null |
  sed 's/^ *|\?[A-Za-z]*: *//; s/^ *//; s/[<>]//g; s/:.*$//' | grep -v '^$' >"$work/closure" || true
dpkg-query -W -f='${Package} ${Priority} ${Essential}\n' |
  awk '$2 == "required" || $3 == "yes" {print $1}' >>"$work/closure"
printf '%s\n' "${listed[@]}" >>"$work/closure"
sort -u -o "$work/closure" "$work/closure"

# A file passes when any package that ships it is in the closure.
awk 'NR == FNR {ok[$1] = 1; next} {if (ok[$1]) good[$2] = 1; else bad[$2] = bad[$2] " " $1}
     END {for (f in bad) if (!good[f]) print f ":" bad[f]}' "$work/closure" "$work/owned" |
  sort >"$work/outside"

nfiles=$(wc -l <"$work/files")
npk=$(awk '{print $1}' "$work/owned" | sort -u | wc -l)
status=0
if [ -s "$work/outside" ]; then
  echo "check_packages: the build read files from packages that scripts/install-deps.sh does not bring in:"
  awk -F: '{printf "  %s (package%s)\n", $1, $2}' "$work/outside" | head -40
  echo "  packages to add to install-deps.sh (or a package that depends on them):"
  awk -F: '{print $2}' "$work/outside" | tr ' ' '\n' | grep -v '^$' | sort -u | sed 's/^/    /'
  status=1
fi
if [ -s "$work/unowned" ]; then
  echo "check_packages: the build read files that no Debian package ships (installed by hand?):"
  sed 's/^/  /' "$work/unowned" | head -40
  status=1
fi
echo "check_packages: $nfiles system files from $npk packages; ${#listed[@]} packages listed, $(wc -l <"$work/closure") in their closure"
exit $status
