#!/usr/bin/env bash
# The package check must fail when a needed package is left out of the list.
#   check_missing_package.sh PACKAGE FILE_REGEX CHECK_PACKAGES_COMMAND...
# Runs the check with install-deps.sh's list less PACKAGE and expects it to
# exit non-zero, naming PACKAGE and a file matching FILE_REGEX.
set -uo pipefail
package=$1; file_regex=$2; shift 2
src=$3
all=$(bash "$src/scripts/install-deps.sh" --list)
grep -qx "$package" <<<"$all" ||
  { echo "FAIL: $package is not in install-deps.sh's list, so leaving it out shows nothing"; exit 1; }
list=$(grep -vx "$package" <<<"$all" | tr '\n' ' ')
out=$(SNAXELS_DEPS_PACKAGES="$list" bash "$@" 2>&1); rc=$?
echo "$out"
[ $rc -ne 0 ] || { echo "FAIL: the check passed with $package left out of the list"; exit 1; }
grep -Eq "$file_regex.*$package" <<<"$out" ||
  { echo "FAIL: the check failed but did not name a file matching '$file_regex' from $package"; exit 1; }
echo "OK: with $package left out the check fails and names it"
