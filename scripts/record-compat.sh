#!/usr/bin/env bash
# Records the project-compatibility folder (tests/assets/projects/compat,
# see its README.md).
#   scripts/record-compat.sh projects VERSION   writes this snaxels' projects
#                                               into compat/vVERSION (when the
#                                               project format changes)
#   scripts/record-compat.sh renders            records what every project
#                                               renders (when a change of the
#                                               engine changes it on purpose)
# Both use the build in build/ (scripts/dev.sh builds it).
set -euo pipefail
cd "$(dirname "$0")/.."
compat=tests/assets/projects/compat
case "${1:-}" in
  projects)
    version=${2:?the project format version}
    cmake --build build -j2 --target record_compat_projects
    mkdir -p "$compat/v$version"
    build/tests/record_compat_projects "$compat/v$version" styles
    ;;
  renders)
    cmake --build build -j2 --target snaxels-cli
    for project in "$compat"/v*/*.snaxels; do
      build/bin/snaxels-cli render "$project" --still -o "${project%.snaxels}.svg"
    done
    ;;
  *) sed -n '2,12p' "$0"; exit 2 ;;
esac
